// The kernels' broad phase: the box around the robot's link bounds against obstacle boxes, and the walk of an
// Environment's obstacle tree (ObstacleIndex) for the primitives near that box.
#ifndef ROPRAS_OMPL_EXT_SIMD_BROAD_PHASE_H
#define ROPRAS_OMPL_EXT_SIMD_BROAD_PHASE_H

#include <cstddef>
#include <cstdint>

#include "ForceInline.h"
#include "ropras/ompl_ext/scene/Environment.h"

namespace ropras::ompl_ext::simd
{
    /// axis-aligned box around every link bounding sphere (of every lane): obstacles outside it are skipped
    struct Aabb
    {
        float lo[3], hi[3];
    };

    /// world axis-aligned box around an obstacle (Environment computes it with the query form)
    using ObstacleBox = ObstacleAabb;

    template <class O>
    inline const ObstacleBox &obstacleBox(const O &o) noexcept
    {
        return o.aabb;
    }

    /// lanes whose sphere (x, y, z, r) touches the box: the exact sphere-versus-axis-aligned-box test
    template <class V>
    ROPRAS_SIMD_FORCE_INLINE typename V::Mask sphereTouchesBox(const V &x, const V &y, const V &z, const V &r,
                                                               const ObstacleBox &b) noexcept
    {
        const V zero = V::zero();
        const V dx = max(abs(x - V::broadcast(b.cx)) - V::broadcast(b.ex), zero);
        const V dy = max(abs(y - V::broadcast(b.cy)) - V::broadcast(b.ey), zero);
        const V dz = max(abs(z - V::broadcast(b.cz)) - V::broadcast(b.ez), zero);
        return cmpLe(fma(dx, dx, fma(dy, dy, dz * dz)), r * r);
    }

    /// true when the robot box \a a and the obstacle box \a b overlap
    ROPRAS_SIMD_FORCE_INLINE bool overlaps(const Aabb &a, const ObstacleBox &b) noexcept
    {
        return a.lo[0] <= b.cx + b.ex && a.hi[0] >= b.cx - b.ex && a.lo[1] <= b.cy + b.ey && a.hi[1] >= b.cy - b.ey &&
               a.lo[2] <= b.cz + b.ez && a.hi[2] >= b.cz - b.ez;
    }

    /** \brief Calls visit(k) for each primitive k of \a tree (ObstacleTree) whose box overlaps \a box, eight
        children of a node with one vector test; stops and returns true as soon as visit does. */
    template <class V, class Visit>
    inline bool forEachNearPrimitive(const ObstacleTree &tree, const Aabb &box, const Visit &visit) noexcept
    {
        const V lox = V::broadcast(box.lo[0]), loy = V::broadcast(box.lo[1]), loz = V::broadcast(box.lo[2]);
        const V hix = V::broadcast(box.hi[0]), hiy = V::broadcast(box.hi[1]), hiz = V::broadcast(box.hi[2]);
        // depth <= 10 for 2^31 primitives, and each node popped pushes at most 8: 7 * 10 + 1 entries
        std::int32_t stack[96];
        int top = 0;
        stack[top++] = tree.root();
        while (top > 0)
        {
            const std::int32_t n = stack[--top];
            const ObstacleIndexNode &node = tree.nodes[static_cast<std::size_t>(n)];
            unsigned bits =
                (cmpLe(V::load(node.lox), hix) & cmpGe(V::load(node.hix), lox) & cmpLe(V::load(node.loy), hiy) &
                 cmpGe(V::load(node.hiy), loy) & cmpLe(V::load(node.loz), hiz) & cmpGe(V::load(node.hiz), loz))
                    .bits();
            const bool leaf = tree.isLeaf(n);
            while (bits != 0u)
            {
                const std::int32_t child = node.child[__builtin_ctz(bits)];
                bits &= bits - 1u;
                if (!leaf)
                    stack[top++] = child;
                else if (visit(static_cast<std::size_t>(child)))
                    return true;
            }
        }
        return false;
    }

    /// f(obstacle) for primitive \a k of \a env (its query-form entry of the right type)
    template <class F>
    inline bool withPrimitive(const Environment &env, std::size_t k, const F &f) noexcept
    {
        const PrimitiveRef &r = env.primitiveRef(k);
        const auto i = static_cast<std::size_t>(r.slot);
        switch (r.type)
        {
            case ShapeType::Sphere:
                return f(env.spheres()[i]);
            case ShapeType::Box:
                return f(env.boxes()[i]);
            case ShapeType::Cylinder:
                return f(env.cylinders()[i]);
            case ShapeType::Capsule:
                return f(env.capsules()[i]);
            case ShapeType::PointCloud:
                break;
        }
        return f(env.clouds()[i]);
    }
}  // namespace ropras::ompl_ext::simd

#endif
