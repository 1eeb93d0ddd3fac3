// Exact sphere-versus-obstacle tests for any 8-lane backend V: WIDTH spheres (x, y, z, r) against one primitive
// obstacle or a point cloud, each returning the lanes whose sphere touches it.
#ifndef ROPRAS_OMPL_EXT_SIMD_OBSTACLE_TESTS_H
#define ROPRAS_OMPL_EXT_SIMD_OBSTACLE_TESTS_H

#include <Eigen/Core>

#include "ForceInline.h"
#include "KinematicProgram.h"
#include "ropras/ompl_ext/scene/Environment.h"

namespace ropras::ompl_ext::simd
{
    template <class V>
    ROPRAS_SIMD_FORCE_INLINE typename V::Mask boundTest(const V &x, const V &y, const V &z, const V &r, float cx,
                                                        float cy, float cz, float cr) noexcept
    {
        const V dx = x - V::broadcast(cx), dy = y - V::broadcast(cy), dz = z - V::broadcast(cz);
        const V rr = r + V::broadcast(cr);
        return cmpLe(fma(dx, dx, fma(dy, dy, dz * dz)), rr * rr);
    }

    template <class V>
    ROPRAS_SIMD_FORCE_INLINE typename V::Mask hitSphere(const V &x, const V &y, const V &z, const V &r,
                                                        const SphereObstacle &o) noexcept
    {
        return boundTest(x, y, z, r, o.x, o.y, o.z, o.r);
    }

    template <class V>
    ROPRAS_SIMD_FORCE_INLINE typename V::Mask hitBox(const V &x, const V &y, const V &z, const V &r,
                                                     const BoxObstacle &o) noexcept
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
    ROPRAS_SIMD_FORCE_INLINE typename V::Mask hitCylinder(const V &x, const V &y, const V &z, const V &r,
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
    ROPRAS_SIMD_FORCE_INLINE typename V::Mask hitCapsule(const V &x, const V &y, const V &z, const V &r,
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
    ROPRAS_SIMD_FORCE_INLINE typename V::Mask hitObstacle(const V &x, const V &y, const V &z, const V &r,
                                                          const SphereObstacle &o) noexcept
    {
        return hitSphere(x, y, z, r, o);
    }
    template <class V>
    ROPRAS_SIMD_FORCE_INLINE typename V::Mask hitObstacle(const V &x, const V &y, const V &z, const V &r,
                                                          const BoxObstacle &o) noexcept
    {
        return hitBox(x, y, z, r, o);
    }
    template <class V>
    ROPRAS_SIMD_FORCE_INLINE typename V::Mask hitObstacle(const V &x, const V &y, const V &z, const V &r,
                                                          const CylinderObstacle &o) noexcept
    {
        return hitCylinder(x, y, z, r, o);
    }
    template <class V>
    ROPRAS_SIMD_FORCE_INLINE typename V::Mask hitObstacle(const V &x, const V &y, const V &z, const V &r,
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
}  // namespace ropras::ompl_ext::simd

#endif
