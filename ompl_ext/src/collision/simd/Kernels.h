// Forward kinematics and sphere collision kernels, written once for any 8-lane backend V.
// Single configuration: scalar FK, then vectorized over spheres. Batch: one configuration per lane.
#ifndef ROPRAS_OMPL_EXT_SIMD_KERNELS_H
#define ROPRAS_OMPL_EXT_SIMD_KERNELS_H

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <type_traits>

#include "KinematicProgram.h"
#include "SinCos.h"
#include "ropras/ompl_ext/scene/Environment.h"

namespace ropras::ompl_ext::simd
{
    // ---------------------------------------------------------------- exact sphere-vs-obstacle tests
    // (x, y, z, r): WIDTH spheres; each returns the lanes whose sphere touches the obstacle.

    template <class V>
    inline typename V::Mask boundTest(const V &x, const V &y, const V &z, const V &r, float cx, float cy, float cz,
                                      float cr) noexcept
    {
        const V dx = x - V::broadcast(cx), dy = y - V::broadcast(cy), dz = z - V::broadcast(cz);
        const V rr = r + V::broadcast(cr);
        return cmpLe(fma(dx, dx, fma(dy, dy, dz * dz)), rr * rr);
    }

    template <class V>
    inline typename V::Mask hitSphere(const V &x, const V &y, const V &z, const V &r, const SphereObstacle &o) noexcept
    {
        return boundTest(x, y, z, r, o.x, o.y, o.z, o.r);
    }

    template <class V>
    inline typename V::Mask hitBox(const V &x, const V &y, const V &z, const V &r, const BoxObstacle &o) noexcept
    {
        const V dx = x - V::broadcast(o.cx), dy = y - V::broadcast(o.cy), dz = z - V::broadcast(o.cz);
        // p_box = R^T d; R row-major, so (R^T d)_i = sum_j rot[3j + i] d_j
        const V px = fma(V::broadcast(o.rot[0]), dx, fma(V::broadcast(o.rot[3]), dy, V::broadcast(o.rot[6]) * dz));
        const V py = fma(V::broadcast(o.rot[1]), dx, fma(V::broadcast(o.rot[4]), dy, V::broadcast(o.rot[7]) * dz));
        const V pz = fma(V::broadcast(o.rot[2]), dx, fma(V::broadcast(o.rot[5]), dy, V::broadcast(o.rot[8]) * dz));
        const V zero = V::zero();
        const V qx = max(abs(px) - V::broadcast(o.hx), zero);
        const V qy = max(abs(py) - V::broadcast(o.hy), zero);
        const V qz = max(abs(pz) - V::broadcast(o.hz), zero);
        return cmpLe(fma(qx, qx, fma(qy, qy, qz * qz)), r * r);
    }

    template <class V>
    inline typename V::Mask hitCylinder(const V &x, const V &y, const V &z, const V &r,
                                        const CylinderObstacle &o) noexcept
    {
        const V dx = x - V::broadcast(o.cx), dy = y - V::broadcast(o.cy), dz = z - V::broadcast(o.cz);
        const V h = fma(V::broadcast(o.ax), dx, fma(V::broadcast(o.ay), dy, V::broadcast(o.az) * dz));
        const V zero = V::zero();
        const V rho2 = max(fnma(h, h, fma(dx, dx, fma(dy, dy, dz * dz))), zero);
        const V dr = max(sqrt(rho2) - V::broadcast(o.radius), zero);
        const V dh = max(abs(h) - V::broadcast(o.halfLength), zero);
        return cmpLe(fma(dr, dr, dh * dh), r * r);
    }

    template <class V>
    inline typename V::Mask hitCapsule(const V &x, const V &y, const V &z, const V &r,
                                       const CapsuleObstacle &o) noexcept
    {
        const V ddx = V::broadcast(o.dx), ddy = V::broadcast(o.dy), ddz = V::broadcast(o.dz);
        const V px = x - V::broadcast(o.ax), py = y - V::broadcast(o.ay), pz = z - V::broadcast(o.az);
        const V t =
            min(max(fma(px, ddx, fma(py, ddy, pz * ddz)) * V::broadcast(o.invLengthSq), V::zero()), V::broadcast(1.0f));
        const V ex = fnma(t, ddx, px), ey = fnma(t, ddy, py), ez = fnma(t, ddz, pz);
        const V rr = r + V::broadcast(o.radius);
        return cmpLe(fma(ex, ex, fma(ey, ey, ez * ez)), rr * rr);
    }

    /// the exact test for any primitive obstacle type (overloads of the functions above), for loops over all types
    template <class V>
    inline typename V::Mask hitObstacle(const V &x, const V &y, const V &z, const V &r,
                                        const SphereObstacle &o) noexcept
    {
        return hitSphere(x, y, z, r, o);
    }
    template <class V>
    inline typename V::Mask hitObstacle(const V &x, const V &y, const V &z, const V &r, const BoxObstacle &o) noexcept
    {
        return hitBox(x, y, z, r, o);
    }
    template <class V>
    inline typename V::Mask hitObstacle(const V &x, const V &y, const V &z, const V &r,
                                        const CylinderObstacle &o) noexcept
    {
        return hitCylinder(x, y, z, r, o);
    }
    template <class V>
    inline typename V::Mask hitObstacle(const V &x, const V &y, const V &z, const V &r,
                                        const CapsuleObstacle &o) noexcept
    {
        return hitCapsule(x, y, z, r, o);
    }

    /// lanes in \a candidates (bit set) whose sphere touches the cloud
    template <class V>
    inline unsigned hitCloud(const V &x, const V &y, const V &z, const V &r, const CloudObstacle &o,
                             unsigned candidates) noexcept
    {
        float fx[WIDTH], fy[WIDTH], fz[WIDTH], fr[WIDTH];
        x.store(fx);
        y.store(fy);
        z.store(fz);
        r.store(fr);
        unsigned hit = 0;
        while (candidates != 0u)
        {
            const int i = __builtin_ctz(candidates);
            candidates &= candidates - 1u;
            const Eigen::Vector3f p = o.worldToCloud * Eigen::Vector3f(fx[i], fy[i], fz[i]);
            if (o.cloud->intersectsSphere(p.x(), p.y(), p.z(), fr[i]))
                hit |= 1u << i;
        }
        return hit;
    }

    // ---------------------------------------------------------------- scalar transforms (single path)

    /// out = a * b (12-float transforms)
    inline void compose(const float *a, const float *b, float *out) noexcept
    {
        for (int i = 0; i < 3; ++i)
        {
            const float a0 = a[3 * i], a1 = a[3 * i + 1], a2 = a[3 * i + 2];
            out[3 * i] = a0 * b[0] + a1 * b[3] + a2 * b[6];
            out[3 * i + 1] = a0 * b[1] + a1 * b[4] + a2 * b[7];
            out[3 * i + 2] = a0 * b[2] + a1 * b[5] + a2 * b[8];
            out[9 + i] = a0 * b[9] + a1 * b[10] + a2 * b[11] + a[9 + i];
        }
    }

    /// the float joint value fed to sin/cos: continuous joints far from zero are reduced in double first
    inline float angleArgument(double v) noexcept
    {
        if (std::abs(v) > 64.0)
            v = std::remainder(v, 6.283185307179586476925);
        return static_cast<float>(v);
    }

    /// 4 floats with GCC/Clang vector extensions (SSE where available, plain code elsewhere)
    typedef float Row4 __attribute__((vector_size(16)));
    /// 8 floats with GCC/Clang vector extensions (AVX where available): two 4-float columns side by side
    typedef float Row8 __attribute__((vector_size(32)));

    /// a Row4 or Row8 from unaligned memory
    template <class R = Row4>
    inline R loadRow(const float *p) noexcept
    {
        R r;
        std::memcpy(&r, p, sizeof(r));
        return r;
    }

    template <class R>
    inline void storeRow(float *p, const R &r) noexcept
    {
        std::memcpy(p, &r, sizeof(r));
    }

    typedef int Index8 __attribute__((vector_size(32)));
    constexpr Index8 LOW_TWICE = {0, 1, 2, 3, 0, 1, 2, 3};
    constexpr Index8 HIGH_TWICE = {4, 5, 6, 7, 4, 5, 6, 7};
    constexpr Index8 SWAP_HALVES = {4, 5, 6, 7, 0, 1, 2, 3};
    /// with a second operand of zeros: (0 | high half)
    constexpr Index8 ZERO_LOW = {8, 9, 10, 11, 4, 5, 6, 7};

    inline Row4 lowHalf(const Row8 &r) noexcept
    {
        return Row4{r[0], r[1], r[2], r[3]};
    }

    inline Row4 highHalf(const Row8 &r) noexcept
    {
        return Row4{r[4], r[5], r[6], r[7]};
    }

    /// world boxes (x, y, z, unused) of the link groups (LinkGroup) of one configuration
    struct GroupBoxesSingle
    {
        Row4 lo[MAX_LINK_GROUPS], hi[MAX_LINK_GROUPS];
    };

    /// links whose spheres are placed (bit per link); models with more than 64 links place all at once
    struct Placed
    {
        std::uint64_t bits{0};
        bool all{false};
        bool has(int li) const noexcept { return all || ((bits >> li) & 1u) != 0u; }
        void set(int li) noexcept { bits |= std::uint64_t{1} << li; }
    };

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
    inline typename V::Mask sphereTouchesBox(const V &x, const V &y, const V &z, const V &r,
                                             const ObstacleBox &b) noexcept
    {
        const V zero = V::zero();
        const V dx = max(abs(x - V::broadcast(b.cx)) - V::broadcast(b.ex), zero);
        const V dy = max(abs(y - V::broadcast(b.cy)) - V::broadcast(b.ey), zero);
        const V dz = max(abs(z - V::broadcast(b.cz)) - V::broadcast(b.ez), zero);
        return cmpLe(fma(dx, dx, fma(dy, dy, dz * dz)), r * r);
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

    template <class V>
    struct AttachedKernels;

    template <class V>
    struct Kernels
    {
        using Mask = typename V::Mask;

        // ------------------------------------------------------------ single configuration

        /** \brief Scalar FK into buf: frames and world link bounds, and the link group boxes into \a groups when
            given. q must be finite. Spheres: placeLink / placeAll. */
        static void framesSingle(const KinematicProgram &p, const double *q, float *buf,
                                 GroupBoxesSingle *groups = nullptr) noexcept
        {
            const ScratchLayout &l = p.single;
            float *sn = buf + l.sin, *cs = buf + l.cos, *qf = buf + l.q;
            for (int j = 0; j < p.dof; j += WIDTH)
            {
                const int n = std::min(WIDTH, p.dof - j);
                float in[WIDTH] = {0, 0, 0, 0, 0, 0, 0, 0};
                for (int k = 0; k < n; ++k)
                {
                    const double v = q[j + k];
                    qf[j + k] = static_cast<float>(v);
                    in[k] = p.rotational[static_cast<std::size_t>(j + k)] ? angleArgument(v) : 0.0f;
                }
                V s, c;
                sinCos(V::load(in), s, c);
                s.store(sn + j);  // the regions are padded to a multiple of WIDTH
                c.store(cs + j);
            }
            // frames as four 4-float columns (c0 c1 c2 t, w = 0): column j of P * O is sum_k P.c_k O_kj, the
            // translation sum_k P.c_k O_k3 + P.t; a frame whose parent is the previous frame stays in registers,
            // and its link bounds are placed from the registers (R b + t: three FMAs per link)
            float *t = buf + l.frames;
            float *lx = buf + l.lx, *ly = buf + l.ly, *lz = buf + l.lz;
            GroupBoxesSingle scratchGroups;
            GroupBoxesSingle &g = groups != nullptr ? *groups : scratchGroups;
            const Row4 far = {1e30f, 1e30f, 1e30f, 1e30f};
            for (std::size_t gi = 0; gi < p.groups.size(); ++gi)
            {
                g.lo[gi] = far;
                g.hi[gi] = -far;
            }
            // the program's arrays in locals: the stores below may alias anything (members would be reloaded)
            const FrameOp *frames = p.frames.data();
            const LinkOp *links = p.links.data();
            const float *boundPairs = p.linkBoundPairs.data();
            const int *frameLinks = p.frameLinks.data(), *groupOfLink = p.groupOfLink.data();
            const int nFrames = static_cast<int>(p.frames.size());
            // a frame as two 8-float vectors: a = (c0 | c1), b = (c2 | t), the same memory as four columns; a
            // frame without parent has the identity as parent
            const Row8 identityA = {1, 0, 0, 0, 0, 1, 0, 0}, identityB = {0, 0, 1, 0, 0, 0, 0, 0};
            Row8 pa = identityA, pb = identityB;
            const Row8 zero = {};
            for (int f = 0; f < nFrames; ++f)
            {
                const FrameOp &op = frames[f];
                if (op.parent < 0)
                {
                    pa = identityA;
                    pb = identityB;
                }
                else if (op.parent != f - 1)
                {
                    pa = loadRow<Row8>(t + 16 * op.parent);
                    pb = loadRow<Row8>(t + 16 * op.parent + 8);
                }
                // column k of the parent in both halves, times the offset's pairs (FrameOp::offsetPairs)
                const Row8 c0 = __builtin_shuffle(pa, LOW_TWICE), c1 = __builtin_shuffle(pa, HIGH_TWICE);
                const Row8 c2 = __builtin_shuffle(pb, LOW_TWICE);
                const float *k = op.offsetPairs;
                Row8 a = c0 * loadRow<Row8>(k) + c1 * loadRow<Row8>(k + 8) + c2 * loadRow<Row8>(k + 16);
                Row8 b = c0 * loadRow<Row8>(k + 24) + c1 * loadRow<Row8>(k + 32) + c2 * loadRow<Row8>(k + 40) +
                         __builtin_shuffle(pb, zero, ZERO_LOW);
                if (op.motion == Motion::RotateZ)
                {
                    // (c0 | c1) <- c (c0 | c1) + (s | -s) (c1 | c0)
                    const float cv = cs[op.variable], sv = sn[op.variable];
                    const Row8 sPair = {sv, sv, sv, sv, -sv, -sv, -sv, -sv};
                    a = a * cv + sPair * __builtin_shuffle(a, SWAP_HALVES);
                }
                else if (op.motion == Motion::TranslateZ)
                {
                    // t += q c2: (c2 | t) + (0 | q) (c2 | c2)
                    const float d = qf[op.variable];
                    const Row8 dPair = {0.0f, 0.0f, 0.0f, 0.0f, d, d, d, d};
                    b += dPair * __builtin_shuffle(b, LOW_TWICE);
                }
                storeRow(t + 16 * f, a);
                storeRow(t + 16 * f + 8, b);
                pa = a;
                pb = b;
                for (int k = op.linkBegin; k < op.linkEnd; ++k)
                {
                    const int li = frameLinks[k];
                    // (c0 bx + c2 bz | c1 by + t): the bound centre is the sum of the halves
                    const float *bp = boundPairs + 16 * li;
                    const Row8 h = a * loadRow<Row8>(bp) + b * loadRow<Row8>(bp + 8);
                    const Row4 w = lowHalf(h) + highHalf(h);
                    lx[li] = w[0];
                    ly[li] = w[1];
                    lz[li] = w[2];
                    const int gi = groupOfLink[li];
                    const float br = links[li].br;
                    const Row4 lo = w - br, hi = w + br;
                    g.lo[gi] = g.lo[gi] < lo ? g.lo[gi] : lo;
                    g.hi[gi] = g.hi[gi] > hi ? g.hi[gi] : hi;
                }
            }
            // padding (one more WIDTH past linkPadded for the self-pair rows): never near anything; the padded
            // range [links, linkPadded + WIDTH) is shorter than 2 WIDTH
            const V pad = V::broadcast(1e18f);
            const int nLinks = static_cast<int>(p.links.size());
            for (float *a : {lx, ly, lz})
            {
                pad.store(a + nLinks);
                pad.store(a + nLinks + WIDTH);
            }
        }

        /// world centres of one link's spheres (whole padded block)
        static void placeLink(const KinematicProgram &p, float *buf, int li) noexcept
        {
            const ScratchLayout &l = p.single;
            const LinkOp &link = p.links[static_cast<std::size_t>(li)];
            const float *m = buf + l.frames + 16 * link.frame;  // columns (c0 c1 c2 t), 4 floats each
            const V r00 = V::broadcast(m[0]), r01 = V::broadcast(m[4]), r02 = V::broadcast(m[8]);
            const V r10 = V::broadcast(m[1]), r11 = V::broadcast(m[5]), r12 = V::broadcast(m[9]);
            const V r20 = V::broadcast(m[2]), r21 = V::broadcast(m[6]), r22 = V::broadcast(m[10]);
            const V tx = V::broadcast(m[12]), ty = V::broadcast(m[13]), tz = V::broadcast(m[14]);
            for (int s = link.first; s < link.first + link.padded; s += WIDTH)
            {
                const V x = V::load(p.sx.data() + s), y = V::load(p.sy.data() + s), z = V::load(p.sz.data() + s);
                fma(r00, x, fma(r01, y, fma(r02, z, tx))).store(buf + l.sx + s);
                fma(r10, x, fma(r11, y, fma(r12, z, ty))).store(buf + l.sy + s);
                fma(r20, x, fma(r21, y, fma(r22, z, tz))).store(buf + l.sz + s);
            }
        }

        static void ensure(const KinematicProgram &p, float *buf, Placed &placed, int li) noexcept
        {
            if (!placed.has(li))
            {
                placeLink(p, buf, li);
                placed.set(li);
            }
        }

        static void placeAll(const KinematicProgram &p, float *buf, Placed &placed) noexcept
        {
            for (int li = 0; li < static_cast<int>(p.links.size()); ++li)
                placeLink(p, buf, li);
            placed.all = true;
        }

        /// true when any link's spheres touch the obstacle; candidates: link bounds touching the obstacle's box
        template <class Exact>
        static bool obstacleSingle(const KinematicProgram &p, float *buf, Placed &placed, const ObstacleBox &ob,
                                   const Exact &exact) noexcept
        {
            const ScratchLayout &l = p.single;
            for (int c = 0; c < p.linkPadded; c += WIDTH)
            {
                const V bx = V::load(buf + l.lx + c), by = V::load(buf + l.ly + c), bz = V::load(buf + l.lz + c),
                        br = V::load(p.linkRadius.data() + c);
                unsigned bits = sphereTouchesBox(bx, by, bz, br, ob).bits();
                if (bits == 0u)
                    continue;
                // the exact test on the link bounding spheres: far tighter than sphere-vs-sphere for boards
                bits &= exact(bx, by, bz, br);
                while (bits != 0u)
                {
                    const int li = c + __builtin_ctz(bits);
                    bits &= bits - 1u;
                    ensure(p, buf, placed, li);
                    const LinkOp &link = p.links[static_cast<std::size_t>(li)];
                    for (int s = link.first; s < link.first + link.padded; s += WIDTH)
                        if (exact(V::load(buf + l.sx + s), V::load(buf + l.sy + s), V::load(buf + l.sz + s),
                                  V::load(p.sr.data() + s)) != 0u)
                            return true;
                }
            }
            return false;
        }

        /// the box around every link bound, from the group boxes
        static Aabb aabbSingle(const KinematicProgram &p, const GroupBoxesSingle &g) noexcept
        {
            Row4 lo = g.lo[0], hi = g.hi[0];
            for (std::size_t gi = 1; gi < p.groups.size(); ++gi)
            {
                lo = lo < g.lo[gi] ? lo : g.lo[gi];
                hi = hi > g.hi[gi] ? hi : g.hi[gi];
            }
            return Aabb{{lo[0], lo[1], lo[2]}, {hi[0], hi[1], hi[2]}};
        }

        static bool overlaps(const Aabb &a, const ObstacleBox &b) noexcept
        {
            return a.lo[0] <= b.cx + b.ex && a.hi[0] >= b.cx - b.ex && a.lo[1] <= b.cy + b.ey &&
                   a.hi[1] >= b.cy - b.ey && a.lo[2] <= b.cz + b.ez && a.hi[2] >= b.cz - b.ez;
        }

        /// the robot box culls the obstacle, then its link bounds and spheres are tested
        template <class O, class Exact>
        static bool obstacleSingleCulled(const KinematicProgram &p, float *buf, Placed &placed, const Aabb &box,
                                         const O &o, const Exact &exact) noexcept
        {
            const ObstacleBox ob = obstacleBox(o);
            return overlaps(box, ob) && obstacleSingle(p, buf, placed, ob, exact);
        }

        static bool envSingle(const KinematicProgram &p, const Environment &env, float *buf, Placed &placed,
                              const Aabb &box) noexcept
        {
            const auto hits = [&](const auto &o)
            {
                if constexpr (std::is_same_v<std::decay_t<decltype(o)>, CloudObstacle>)
                    return o.boundRadius >= 0.0f &&
                           obstacleSingleCulled(p, buf, placed, box, o,
                                                [&](const V &x, const V &y, const V &z, const V &r)
                                                {
                                                    const unsigned cand =
                                                        boundTest(x, y, z, r, o.cx, o.cy, o.cz, o.boundRadius).bits();
                                                    return cand != 0u ? hitCloud(x, y, z, r, o, cand) : 0u;
                                                });
                else
                    return obstacleSingleCulled(p, buf, placed, box, o,
                                                [&](const V &x, const V &y, const V &z, const V &r)
                                                { return hitObstacle(x, y, z, r, o).bits(); });
            };
            const auto anyHit = [&](const auto &obstacles)
            {
                for (const auto &o : obstacles)
                    if (hits(o))
                        return true;
                return false;
            };
            for (const Environment *e = &env; e != nullptr; e = e->base())  // the overlay, then its bases
            {
                if (const ObstacleTree *tree = e->obstacleTree())
                {
                    // the broad phase: only the primitives whose boxes overlap the robot's
                    if (forEachNearPrimitive<V>(*tree, box, [&](std::size_t k) { return withPrimitive(*e, k, hits); }))
                        return true;
                    continue;
                }
                if (anyHit(e->spheres()) || anyHit(e->boxes()) || anyHit(e->cylinders()) || anyHit(e->capsules()) ||
                    anyHit(e->clouds()))
                    return true;
            }
            return false;
        }

        static bool selfSingle(const KinematicProgram &p, const double *q, float *buf, Placed &placed,
                               const GroupBoxesSingle &g) noexcept
        {
            const ScratchLayout &l = p.single;
            const float *lx = buf + l.lx, *ly = buf + l.ly, *lz = buf + l.lz;
            // per grid of free cells (SpherePairFreeCells): is q in a free cell? Looked up when first needed
            std::uint32_t gridKnown = 0u, gridFree = 0u;
            const auto inFreeCell = [&](int gi)
            {
                if (((gridKnown >> gi) & 1u) == 0u)
                {
                    const SelfGrid &sg = p.selfGrids[static_cast<std::size_t>(gi)];
                    const auto cellOf = [&](int d)
                    {
                        const double x = (q[sg.var[d]] - static_cast<double>(sg.lower[d])) * sg.inv[d];
                        return static_cast<std::uint32_t>(std::min(std::max(x, 0.0), sg.cells - 1.0));
                    };
                    const std::uint32_t cell =
                        sg.var[1] < 0 ? cellOf(0) : cellOf(0) * static_cast<std::uint32_t>(sg.cells) + cellOf(1);
                    gridFree |= (p.cellFree(sg, cell) ? 1u : 0u) << gi;
                    gridKnown |= 1u << gi;
                }
                return ((gridFree >> gi) & 1u) != 0u;
            };
            for (const SelfPairRange &range : p.selfPairRanges)
            {
                // no pair of the range touches when the boxes of the two groups are apart
                const int ga = range.groupA, gb = range.groupB;
                if (g.lo[ga][0] > g.hi[gb][0] || g.lo[gb][0] > g.hi[ga][0] || g.lo[ga][1] > g.hi[gb][1] ||
                    g.lo[gb][1] > g.hi[ga][1] || g.lo[ga][2] > g.hi[gb][2] || g.lo[gb][2] > g.hi[ga][2])
                    continue;
                // the link bounds of up to WIDTH pairs (one link against consecutive links) per vector
                for (int row = range.rowBegin; row < range.rowEnd; ++row)
                {
                    const SelfPairRow &r = p.selfPairRows[static_cast<std::size_t>(row)];
                    const V dx = V::load(lx + r.bFirst) - V::broadcast(lx[r.a]);
                    const V dy = V::load(ly + r.bFirst) - V::broadcast(ly[r.a]);
                    const V dz = V::load(lz + r.bFirst) - V::broadcast(lz[r.a]);
                    unsigned bits = cmpLe(fma(dx, dx, fma(dy, dy, dz * dz)),
                                          V::load(p.selfRowReach2.data() + static_cast<std::size_t>(WIDTH) * row))
                                        .bits();
                    while (bits != 0u)
                    {
                        const int k = r.pairBegin + __builtin_ctz(bits);
                        bits &= bits - 1u;
                        const int grid = p.selfPairGrid[static_cast<std::size_t>(k)];
                        if (grid >= 0 && inFreeCell(grid))
                            continue;
                        if (selfPairSingle(p, buf, placed, k))
                            return true;
                    }
                }
            }
            return false;
        }

        /// the spheres of self pair k (whose bounds touch)
        static bool selfPairSingle(const KinematicProgram &p, float *buf, Placed &placed, int k) noexcept
        {
            const ScratchLayout &l = p.single;
            const float *wx = buf + l.sx, *wy = buf + l.sy, *wz = buf + l.sz;
            const float *lx = buf + l.lx, *ly = buf + l.ly, *lz = buf + l.lz;
            const auto &pair = p.selfPairs[static_cast<std::size_t>(k)];
            const LinkOp &a = p.links[static_cast<std::size_t>(pair.first)];
            const LinkOp &b = p.links[static_cast<std::size_t>(pair.second)];
            if (p.selfPairUseNear[static_cast<std::size_t>(k)] != 0)
            {
                // the spheres around the members that can touch, placed from the frames (columns c0 c1 c2 t)
                const float *near = p.selfPairNear.data() + 8 * static_cast<std::size_t>(k);
                const float *fa = buf + l.frames + 16 * a.frame, *fb = buf + l.frames + 16 * b.frame;
                const Row4 d =
                    loadRow(fa) * near[0] + loadRow(fa + 4) * near[1] + loadRow(fa + 8) * near[2] + loadRow(fa + 12) -
                    (loadRow(fb) * near[4] + loadRow(fb + 4) * near[5] + loadRow(fb + 8) * near[6] + loadRow(fb + 12));
                if (d[0] * d[0] + d[1] * d[1] + d[2] * d[2] > p.selfPairNearReach2[static_cast<std::size_t>(k)])
                    return false;
            }
            ensure(p, buf, placed, pair.first);
            ensure(p, buf, placed, pair.second);
            // spheres of a that can touch b within the joint limits and reach b's bounding sphere, then those
            // against the spheres of b they can touch (every program link has at most WIDTH spheres: one vector)
            const std::uint8_t *masks = p.selfPairSphereMasks.data() + static_cast<std::size_t>(WIDTH) * k;
            unsigned near =
                boundTest(V::load(wx + a.first), V::load(wy + a.first), V::load(wz + a.first),
                          V::load(p.sr.data() + a.first), lx[pair.second], ly[pair.second], lz[pair.second], b.br)
                    .bits() &
                p.selfPairSlotsA[static_cast<std::size_t>(k)];
            if (near == 0u)
                return false;
            const V bx = V::load(wx + b.first), by = V::load(wy + b.first), bz = V::load(wz + b.first),
                    br = V::load(p.sr.data() + b.first);
            while (near != 0u)
            {
                const int t = __builtin_ctz(near);
                near &= near - 1u;
                const int i = a.first + t;
                if ((boundTest(bx, by, bz, br, wx[i], wy[i], wz[i], p.sr[static_cast<std::size_t>(i)]).bits() &
                     masks[t]) != 0u)
                    return true;
            }
            return false;
        }

        /// q within bounds and finite
        static bool validSingle(const KinematicProgram &p, const Environment &env, const double *q, float *buf) noexcept
        {
            GroupBoxesSingle groups;
            framesSingle(p, q, buf, &groups);
            Placed placed;
            if (p.links.size() > 64)
                placeAll(p, buf, placed);
            const Aabb box = aabbSingle(p, groups);
            return !envSingle(p, env, buf, placed, box) && !selfSingle(p, q, buf, placed, groups) &&
                   !(env.hasAttachedBodies() && AttachedKernels<V>::collideSingle(p, env, buf, placed));
        }

        // ------------------------------------------------------------ batch: one configuration per lane

        /// the rotation columns of m (rows r00 r01 r02, r10 ...) reordered in place: new column j = old column Cj
        template <int C0, int C1, int C2>
        static void permuteColumns(V *m) noexcept
        {
            for (int i = 0; i < 3; ++i)
            {
                const V a = m[3 * i + C0], b = m[3 * i + C1], c = m[3 * i + C2];
                m[3 * i] = a;
                m[3 * i + 1] = b;
                m[3 * i + 2] = c;
            }
        }

        /** \brief m = m * offset (12-float transforms, WIDTH lanes each) in place. The translation goes first (it
            uses m's rotation) and only for the offset's non-zero components; a signed-permutation rotation is
            column moves and sign-bit XORs of the flipped columns; any other rotation is three FMAs per entry,
            row by row (three live values, not a second matrix). */
        static void applyOffset(const FrameOp &op, V *m) noexcept
        {
            const float *o = op.offset;
            for (int k = 0; k < 3; ++k)
                if ((op.translationMask >> k) & 1u)
                {
                    const V ok = V::broadcast(o[9 + k]);
                    for (int i = 0; i < 3; ++i)
                        m[9 + i] = fma(m[3 * i + k], ok, m[9 + i]);
                }
            if (op.permutation)
            {
                switch (op.permId)
                {
                    case 0:
                        break;
                    case 1:
                        permuteColumns<0, 2, 1>(m);
                        break;
                    case 2:
                        permuteColumns<1, 0, 2>(m);
                        break;
                    case 3:
                        permuteColumns<1, 2, 0>(m);
                        break;
                    case 4:
                        permuteColumns<2, 0, 1>(m);
                        break;
                    default:
                        permuteColumns<2, 1, 0>(m);
                        break;
                }
                for (int j = 0; j < 3; ++j)
                    if ((op.flipColumns >> j) & 1u)
                    {
                        const V sg = V::broadcast(-0.0f);
                        for (int i = 0; i < 3; ++i)
                            m[3 * i + j] = flipSign(m[3 * i + j], sg);
                    }
                return;
            }
            for (int i = 0; i < 3; ++i)
            {
                const V a = m[3 * i], b = m[3 * i + 1], c = m[3 * i + 2];
                for (int j = 0; j < 3; ++j)
                    m[3 * i + j] =
                        fma(a, V::broadcast(o[j]), fma(b, V::broadcast(o[3 + j]), c * V::broadcast(o[6 + j])));
            }
        }

        /** \brief FK of WIDTH configurations: per variable joint values in buf + batch.q (WIDTH floats each,
            angles already reduced); writes frames and link bounds (WIDTH floats each). Spheres: placeLinkBatch.
            One frame lives in registers and is updated in place (a frame whose parent is the previous frame does
            not reload it); the offset is applied with only the work its form needs (applyOffset); each frame's
            link bounds are placed while it is in registers. */
        static void framesBatch(const KinematicProgram &p, float *buf) noexcept
        {
            const ScratchLayout &l = p.batch;
            constexpr int W = WIDTH;
            for (int j = 0; j < p.dof; ++j)
                if (p.rotational[static_cast<std::size_t>(j)])
                {
                    V s, c;
                    sinCos(V::load(buf + l.q + W * j), s, c);
                    s.store(buf + l.sin + W * j);
                    c.store(buf + l.cos + W * j);
                }
            float *t = buf + l.frames;
            float *lx = buf + l.lx, *ly = buf + l.ly, *lz = buf + l.lz;
            // the program's arrays in locals: the stores below may alias anything (members would be reloaded)
            const FrameOp *frames = p.frames.data();
            const LinkOp *links = p.links.data();
            const int *frameLinks = p.frameLinks.data();
            V m[12];  // frame 0 has no parent: never read before it is set
            for (V &v : m)
                v = V::zero();
            const int nFrames = static_cast<int>(p.frames.size());
            for (int f = 0; f < nFrames; ++f)
            {
                const FrameOp &op = frames[f];
                float *tf = t + 12 * W * f;
                if (op.parent < 0)
                {
                    for (int i = 0; i < 12; ++i)
                        m[i] = V::broadcast(op.offset[i]);
                }
                else
                {
                    if (op.parent != f - 1)
                    {
                        const float *pt = t + 12 * W * op.parent;
                        for (int i = 0; i < 12; ++i)
                            m[i] = V::load(pt + W * i);
                    }
                    applyOffset(op, m);
                }
                if (op.motion == Motion::RotateZ)
                {
                    const V c = V::load(buf + l.cos + W * op.variable), s = V::load(buf + l.sin + W * op.variable);
                    for (int i = 0; i < 3; ++i)
                    {
                        const V a = m[3 * i], b = m[3 * i + 1];
                        m[3 * i] = fma(c, a, s * b);
                        m[3 * i + 1] = fnma(s, a, c * b);
                    }
                }
                else if (op.motion == Motion::TranslateZ)
                {
                    const V d = V::load(buf + l.q + W * op.variable);
                    for (int i = 0; i < 3; ++i)
                        m[9 + i] = fma(d, m[3 * i + 2], m[9 + i]);
                }
                for (int i = 0; i < 12; ++i)
                    m[i].store(tf + W * i);
                for (int k = op.linkBegin; k < op.linkEnd; ++k)
                {
                    const int li = frameLinks[k];
                    const LinkOp &link = links[li];
                    const V vx = V::broadcast(link.bx), vy = V::broadcast(link.by), vz = V::broadcast(link.bz);
                    fma(m[0], vx, fma(m[1], vy, fma(m[2], vz, m[9]))).store(lx + W * li);
                    fma(m[3], vx, fma(m[4], vy, fma(m[5], vz, m[10]))).store(ly + W * li);
                    fma(m[6], vx, fma(m[7], vy, fma(m[8], vz, m[11]))).store(lz + W * li);
                }
            }
        }

        /// world position (WIDTH lanes per axis) of the point \a b (3 floats, in the frame stored at \a frame)
        static void placePointBatch(const float *frame, const float *b, V *out) noexcept
        {
            constexpr int W = WIDTH;
            const V vx = V::broadcast(b[0]), vy = V::broadcast(b[1]), vz = V::broadcast(b[2]);
            for (int i = 0; i < 3; ++i)
                out[i] = fma(V::load(frame + W * (3 * i)), vx,
                             fma(V::load(frame + W * (3 * i + 1)), vy,
                                 fma(V::load(frame + W * (3 * i + 2)), vz, V::load(frame + W * (9 + i)))));
        }

        /// world centres (WIDTH lanes each) of one link's real spheres
        static void placeLinkBatch(const KinematicProgram &p, float *buf, int li) noexcept
        {
            const ScratchLayout &l = p.batch;
            constexpr int W = WIDTH;
            const LinkOp &link = p.links[static_cast<std::size_t>(li)];
            const float *pt = buf + l.frames + 12 * W * link.frame;
            V m[12];
            for (int i = 0; i < 12; ++i)
                m[i] = V::load(pt + W * i);
            // everything the loop reads through p in locals: vector stores may alias anything, so members read
            // in the loop would be reloaded after every store
            const float *px = p.sx.data(), *py = p.sy.data(), *pz = p.sz.data();
            float *wx = buf + l.sx, *wy = buf + l.sy, *wz = buf + l.sz;
            const int first = link.first, end = link.first + link.count;
            for (int s = first; s < end; ++s)
            {
                const V vx = V::broadcast(px[s]), vy = V::broadcast(py[s]), vz = V::broadcast(pz[s]);
                fma(m[0], vx, fma(m[1], vy, fma(m[2], vz, m[9]))).store(wx + W * s);
                fma(m[3], vx, fma(m[4], vy, fma(m[5], vz, m[10]))).store(wy + W * s);
                fma(m[6], vx, fma(m[7], vy, fma(m[8], vz, m[11]))).store(wz + W * s);
            }
        }

        static void ensureBatch(const KinematicProgram &p, float *buf, Placed &placed, int li) noexcept
        {
            if (!placed.has(li))
            {
                placeLinkBatch(p, buf, li);
                placed.set(li);
            }
        }

        static void placeAllBatch(const KinematicProgram &p, float *buf, Placed &placed) noexcept
        {
            for (int li = 0; li < static_cast<int>(p.links.size()); ++li)
                placeLinkBatch(p, buf, li);
            placed.all = true;
        }

        /// lanes (bits) of \a active that collide with one obstacle, for one link
        template <class Exact>
        static unsigned obstacleBatch(const KinematicProgram &p, float *buf, Placed &placed, int li, unsigned active,
                                      const ObstacleBox &ob, const Exact &exact) noexcept
        {
            const ScratchLayout &l = p.batch;
            constexpr int W = WIDTH;
            const LinkOp &link = p.links[static_cast<std::size_t>(li)];
            const unsigned cand = sphereTouchesBox(V::load(buf + l.lx + W * li), V::load(buf + l.ly + W * li),
                                                   V::load(buf + l.lz + W * li), V::broadcast(link.br), ob)
                                      .bits() &
                                  active;
            if (cand == 0u)
                return 0u;
            // the exact test on the link bounding sphere before its spheres
            const unsigned near = exact(V::load(buf + l.lx + W * li), V::load(buf + l.ly + W * li),
                                        V::load(buf + l.lz + W * li), V::broadcast(link.br), cand) &
                                  cand;
            if (near == 0u)
                return 0u;
            ensureBatch(p, buf, placed, li);
            unsigned hit = 0u;
            for (int s = link.first; s < link.first + link.count; ++s)
            {
                hit |= exact(V::load(buf + l.sx + W * s), V::load(buf + l.sy + W * s), V::load(buf + l.sz + W * s),
                             V::broadcast(p.sr[static_cast<std::size_t>(s)]), near & ~hit);
                if ((near & ~hit) == 0u)
                    break;
            }
            return hit & near;
        }

        /// per-lane axis-aligned boxes around the link bounds of each link group (LinkGroup), WIDTH lanes each
        struct GroupBoxes
        {
            V lo[MAX_LINK_GROUPS][3], hi[MAX_LINK_GROUPS][3];
        };

        /// the group boxes of every lane, and the box around every link bound of the \a active lanes
        static Aabb groupBoxesBatch(const KinematicProgram &p, const float *buf, unsigned active,
                                    GroupBoxes &g) noexcept
        {
            const ScratchLayout &l = p.batch;
            constexpr int W = WIDTH;
            const Mask lanes = Mask::fromBits(active);
            const V far = V::broadcast(1e30f), nfar = V::broadcast(-1e30f);
            V lo[3] = {far, far, far}, hi[3] = {nfar, nfar, nfar};
            const std::size_t offsets[3] = {l.lx, l.ly, l.lz};
            for (std::size_t gi = 0; gi < p.groups.size(); ++gi)
            {
                const LinkGroup &grp = p.groups[gi];
                V glo[3] = {far, far, far}, ghi[3] = {nfar, nfar, nfar};
                for (int li = grp.begin; li < grp.end; ++li)
                {
                    const V r = V::broadcast(p.links[static_cast<std::size_t>(li)].br);
                    for (int i = 0; i < 3; ++i)
                    {
                        const V c = V::load(buf + offsets[i] + W * li);
                        glo[i] = min(glo[i], c - r);
                        ghi[i] = max(ghi[i], c + r);
                    }
                }
                for (int i = 0; i < 3; ++i)
                {
                    g.lo[gi][i] = glo[i];
                    g.hi[gi][i] = ghi[i];
                    lo[i] = min(lo[i], select(lanes, glo[i], far));
                    hi[i] = max(hi[i], select(lanes, ghi[i], nfar));
                }
            }
            Aabb box;
            for (int i = 0; i < 3; ++i)
            {
                box.lo[i] = hmin(lo[i]);
                box.hi[i] = hmax(hi[i]);
            }
            return box;
        }

        /// lanes whose group box overlaps the obstacle box
        static unsigned groupTouches(const GroupBoxes &g, int gi, const ObstacleBox &b) noexcept
        {
            const Mask x =
                cmpLe(g.lo[gi][0], V::broadcast(b.cx + b.ex)) & cmpGe(g.hi[gi][0], V::broadcast(b.cx - b.ex));
            const Mask y =
                cmpLe(g.lo[gi][1], V::broadcast(b.cy + b.ey)) & cmpGe(g.hi[gi][1], V::broadcast(b.cy - b.ey));
            const Mask z =
                cmpLe(g.lo[gi][2], V::broadcast(b.cz + b.ez)) & cmpGe(g.hi[gi][2], V::broadcast(b.cz - b.ez));
            return (x & y & z).bits();
        }

        /// lanes where the boxes of groups a and b overlap
        static unsigned groupsOverlap(const GroupBoxes &g, int a, int b) noexcept
        {
            Mask m = cmpLe(g.lo[a][0], g.hi[b][0]) & cmpLe(g.lo[b][0], g.hi[a][0]);
            for (int i = 1; i < 3; ++i)
                m = m & cmpLe(g.lo[a][i], g.hi[b][i]) & cmpLe(g.lo[b][i], g.hi[a][i]);
            return m.bits();
        }

        /// lanes of \a lanes where some self-collision pair touches
        static unsigned selfBatch(const KinematicProgram &p, float *buf, Placed &placed, const GroupBoxes &g,
                                  unsigned lanes, bool stopOnAny) noexcept
        {
            const ScratchLayout &l = p.batch;
            constexpr int W = WIDTH;
            unsigned hit = 0u;
            const float *lx = buf + l.lx, *ly = buf + l.ly, *lz = buf + l.lz;
            // lanes in a free cell of each grid (SpherePairFreeCells), computed when a pair first needs it
            unsigned gridLanes[MAX_SELF_GRIDS];
            std::uint32_t gridKnown = 0u;
            const auto gridFree = [&](int gi)
            {
                if ((gridKnown >> gi) & 1u)
                    return gridLanes[gi];
                const SelfGrid &g = p.selfGrids[static_cast<std::size_t>(gi)];
                const V top = V::broadcast(static_cast<float>(g.cells - 1));
                const auto cellOf = [&](int d)
                {
                    const V x = (V::load(buf + l.q + W * g.var[d]) - V::broadcast(g.lower[d])) * V::broadcast(g.inv[d]);
                    return floor(min(max(x, V::zero()), top));
                };
                // cell numbers are integers below 2^24: exact in float
                const V cell =
                    g.var[1] < 0 ? cellOf(0) : fma(cellOf(0), V::broadcast(static_cast<float>(g.cells)), cellOf(1));
                float c[W];
                cell.store(c);
                unsigned lanes = 0u;
                for (int i = 0; i < W; ++i)
                    lanes |= (p.cellFree(g, static_cast<std::uint32_t>(c[i])) ? 1u : 0u) << i;
                gridLanes[gi] = lanes;
                gridKnown |= 1u << gi;
                return lanes;
            };
            for (const SelfPairRange &range : p.selfPairRanges)
            {
                // the boxes of the two link groups first: no pair of the range can touch where they are apart
                const unsigned groupLanes = groupsOverlap(g, range.groupA, range.groupB) & lanes & ~hit;
                if (groupLanes == 0u)
                    continue;
                for (int base = range.begin; base < range.end; base += 64)
                {
                    const int end = std::min(range.end, base + 64);
                    unsigned cand[64];
                    std::uint64_t any = 0u;
                    // the link bounds of every pair first, without branches
                    for (int k = base; k < end; ++k)
                    {
                        const auto kk = static_cast<std::size_t>(k);
                        const int a = p.selfPairOffsetA[kk], b = p.selfPairOffsetB[kk];
                        const V dx = V::load(lx + a) - V::load(lx + b);
                        const V dy = V::load(ly + a) - V::load(ly + b);
                        const V dz = V::load(lz + a) - V::load(lz + b);
                        const unsigned c =
                            cmpLe(fma(dx, dx, fma(dy, dy, dz * dz)), V::broadcast(p.selfPairReach2[kk])).bits() &
                            groupLanes;
                        cand[k - base] = c;
                        any |= static_cast<std::uint64_t>(c != 0u) << (k - base);
                    }
                    while (any != 0u)
                    {
                        const int k = base + __builtin_ctzll(any);
                        any &= any - 1u;
                        const auto &pair = p.selfPairs[static_cast<std::size_t>(k)];
                        unsigned c = cand[k - base] & ~hit;
                        if (c == 0u)
                            continue;
                        const int grid = p.selfPairGrid[static_cast<std::size_t>(k)];
                        if (grid >= 0)
                        {
                            c &= ~gridFree(grid);
                            if (c == 0u)
                                continue;
                        }
                        const LinkOp &a = p.links[static_cast<std::size_t>(pair.first)];
                        const LinkOp &b = p.links[static_cast<std::size_t>(pair.second)];
                        if (p.selfPairUseNear[static_cast<std::size_t>(k)] != 0)
                        {
                            // the spheres around the members that can touch, placed from the frames
                            const float *near = p.selfPairNear.data() + 8 * static_cast<std::size_t>(k);
                            V ca[3], cb[3];
                            placePointBatch(buf + l.frames + 12 * W * a.frame, near, ca);
                            placePointBatch(buf + l.frames + 12 * W * b.frame, near + 4, cb);
                            const V dx = ca[0] - cb[0], dy = ca[1] - cb[1], dz = ca[2] - cb[2];
                            c &= cmpLe(fma(dx, dx, fma(dy, dy, dz * dz)),
                                       V::broadcast(p.selfPairNearReach2[static_cast<std::size_t>(k)]))
                                     .bits();
                            if (c == 0u)
                                continue;
                        }
                        ensureBatch(p, buf, placed, pair.first);
                        ensureBatch(p, buf, placed, pair.second);
                        const V bx = V::load(buf + l.lx + W * pair.second), by = V::load(buf + l.ly + W * pair.second),
                                bz = V::load(buf + l.lz + W * pair.second);
                        // only the sphere pairs that can touch within the joint limits (selfPairSphereMasks)
                        const std::uint8_t *masks = p.selfPairSphereMasks.data() + static_cast<std::size_t>(W) * k;
                        for (unsigned slots = p.selfPairSlotsA[static_cast<std::size_t>(k)]; slots != 0u && c != 0u;
                             slots &= slots - 1u)
                        {
                            const int t = __builtin_ctz(slots);
                            const int i = a.first + t;
                            const V x = V::load(buf + l.sx + W * i), y = V::load(buf + l.sy + W * i),
                                    z = V::load(buf + l.sz + W * i);
                            const float ri = p.sr[static_cast<std::size_t>(i)];
                            unsigned partners = masks[t];
                            unsigned near = c;
                            if ((partners & (partners - 1u)) != 0u)
                            {
                                // two or more partners: first the lanes where sphere i reaches b's bounding sphere
                                const V ex = x - bx, ey = y - by, ez = z - bz;
                                const float rb = ri + b.br;
                                near &= cmpLe(fma(ex, ex, fma(ey, ey, ez * ez)), V::broadcast(rb * rb)).bits();
                            }
                            for (; partners != 0u && near != 0u; partners &= partners - 1u)
                            {
                                const int j = b.first + __builtin_ctz(partners);
                                const V fx = x - V::load(buf + l.sx + W * j), fy = y - V::load(buf + l.sy + W * j),
                                        fz = z - V::load(buf + l.sz + W * j);
                                const float rs = ri + p.sr[static_cast<std::size_t>(j)];
                                const unsigned h =
                                    cmpLe(fma(fx, fx, fma(fy, fy, fz * fz)), V::broadcast(rs * rs)).bits() & near;
                                near &= ~h;
                                c &= ~h;
                                hit |= h;
                            }
                        }
                        if ((lanes & ~hit) == 0u || (stopOnAny && hit != 0u))
                            return hit;
                    }
                }
            }
            return hit;
        }

        /** \brief Collision lanes of a batch after framesBatch. \a active: lanes to check (bits); stops as soon
            as every active lane collides, or at the first collision when \a stopOnAny. */
        static unsigned collideBatch(const KinematicProgram &p, const Environment &env, float *buf, unsigned active,
                                     bool stopOnAny) noexcept
        {
            Placed placed;
            if (p.links.size() > 64)
                placeAllBatch(p, buf, placed);
            unsigned hit = 0u;
            const auto done = [&] { return stopOnAny ? hit != 0u : (active & ~hit) == 0u; };
            GroupBoxes groups;
            const Aabb box = groupBoxesBatch(p, buf, active, groups);
            const int nGroups = static_cast<int>(p.groups.size());
            // obstacle-major: the robot box rejects far obstacles once, then the per-lane group boxes, then the
            // links of the groups that touch (only in the lanes that touch); returns true when decided (done())
            const auto obstacle = [&](const ObstacleBox &ob, const auto &exact)
            {
                if (!overlaps(box, ob))
                    return false;
                for (int gi = 0; gi < nGroups; ++gi)
                {
                    const unsigned lanes = groupTouches(groups, gi, ob) & active & ~hit;
                    if (lanes == 0u)
                        continue;
                    const LinkGroup &grp = p.groups[static_cast<std::size_t>(gi)];
                    for (int li = grp.begin; li < grp.end; ++li)
                    {
                        hit |= obstacleBatch(p, buf, placed, li, lanes & ~hit, ob, exact);
                        if (done())
                            return true;
                    }
                }
                return false;
            };
            const auto decides = [&](const auto &o)
            {
                if constexpr (std::is_same_v<std::decay_t<decltype(o)>, CloudObstacle>)
                    return o.boundRadius >= 0.0f &&
                           obstacle(obstacleBox(o),
                                    [&](const V &x, const V &y, const V &z, const V &r, unsigned cand)
                                    {
                                        const unsigned near =
                                            boundTest(x, y, z, r, o.cx, o.cy, o.cz, o.boundRadius).bits() & cand;
                                        return near != 0u ? hitCloud(x, y, z, r, o, near) : 0u;
                                    });
                else
                    return obstacle(obstacleBox(o), [&](const V &x, const V &y, const V &z, const V &r, unsigned)
                                    { return hitObstacle(x, y, z, r, o).bits(); });
            };
            const auto sweep = [&](const auto &obstacles)
            {
                for (const auto &o : obstacles)
                    if (decides(o))
                        return true;
                return false;
            };
            for (const Environment *e = &env; e != nullptr; e = e->base())  // the overlay, then its bases
            {
                if (const ObstacleTree *tree = e->obstacleTree())
                {
                    // the broad phase: only the primitives whose boxes overlap the box around every active lane
                    if (forEachNearPrimitive<V>(*tree, box,
                                                [&](std::size_t k) { return withPrimitive(*e, k, decides); }))
                        return hit;
                    continue;
                }
                if (sweep(e->spheres()) || sweep(e->boxes()) || sweep(e->cylinders()) || sweep(e->capsules()) ||
                    sweep(e->clouds()))
                    return hit;
            }
            if (env.hasAttachedBodies())
            {
                hit |= AttachedKernels<V>::collideBatch(p, env, buf, placed, active & ~hit, stopOnAny);
                if (done())
                    return hit;
            }
            hit |= selfBatch(p, buf, placed, groups, active & ~hit, stopOnAny);
            return hit;
        }
    };
}  // namespace ropras::ompl_ext::simd

#include "AttachedKernels.h"

#endif
