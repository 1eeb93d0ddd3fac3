// Exact first-contact tests of a segment a + t d, t in [0, tMax], with solid primitives (double arithmetic),
// and the conservative float cull of a segment against an ObstacleAabb. Shared by EnvironmentQueries (firstHit)
// and PointCloud (firstSegmentHit). Every test returns true and sets t (0 when a is inside) when the segment
// touches the solid at some t <= tMax.
#ifndef ROPRAS_OMPL_EXT_SRC_SCENE_SEGMENT_TESTS_H
#define ROPRAS_OMPL_EXT_SRC_SCENE_SEGMENT_TESTS_H

#include <Eigen/Core>
#include <algorithm>
#include <cmath>

#include "ropras/ompl_ext/scene/Environment.h"

namespace ropras::ompl_ext::segment
{
    /// the two roots (lo <= hi) of A t^2 + 2 B t + C = 0 for A > 0, or false when there is none; the stable form
    /// (no cancellation between -B and the square root)
    inline bool quadraticRoots(double A, double B, double C, double &lo, double &hi) noexcept
    {
        const double disc = B * B - A * C;
        if (disc < 0.0)
            return false;
        const double q = -(B + std::copysign(std::sqrt(disc), B));
        if (q == 0.0)  // B == 0 and disc == 0: a double root at 0
        {
            lo = hi = 0.0;
            return true;
        }
        const double r1 = q / A, r2 = C / q;
        lo = std::min(r1, r2);
        hi = std::max(r1, r2);
        return true;
    }

    /// solid sphere (centre c, radius r)
    inline bool sphere(const Eigen::Vector3d &a, const Eigen::Vector3d &d, const Eigen::Vector3d &c, double r,
                       double tMax, double &t) noexcept
    {
        const Eigen::Vector3d m = a - c;
        const double C = m.squaredNorm() - r * r;
        if (C <= 0.0)
        {
            t = 0.0;
            return true;
        }
        const double B = m.dot(d);
        if (B >= 0.0)  // outside and not approaching
            return false;
        const double A = d.squaredNorm();
        const double disc = B * B - A * C;
        if (disc < 0.0)
            return false;
        const double t0 = C / (-B + std::sqrt(disc));  // the smaller root, stable
        if (t0 > tMax)
            return false;
        t = t0;
        return true;
    }

    /// narrows [tNear, tFar] to the slab lo <= o + t v <= hi; false when it becomes empty
    inline bool clipSlab(double o, double v, double lo, double hi, double &tNear, double &tFar) noexcept
    {
        if (v == 0.0)
            return o >= lo && o <= hi;
        const double inv = 1.0 / v;
        double t1 = (lo - o) * inv, t2 = (hi - o) * inv;
        if (t1 > t2)
            std::swap(t1, t2);
        tNear = std::max(tNear, t1);
        tFar = std::min(tFar, t2);
        return tNear <= tFar;
    }

    /// solid box given in its own frame: o, v are the segment's start and direction there, h the half extents
    inline bool localBox(const Eigen::Vector3d &o, const Eigen::Vector3d &v, const Eigen::Vector3d &h, double tMax,
                         double &t) noexcept
    {
        double tNear = 0.0, tFar = tMax;
        for (int i = 0; i < 3; ++i)
            if (!clipSlab(o[i], v[i], -h[i], h[i], tNear, tFar))
                return false;
        t = tNear;
        return true;
    }

    /// solid cylinder: centre c, unit axis u, half length h, radius r
    inline bool cylinder(const Eigen::Vector3d &a, const Eigen::Vector3d &d, const Eigen::Vector3d &c,
                         const Eigen::Vector3d &u, double h, double r, double tMax, double &t) noexcept
    {
        const Eigen::Vector3d m = a - c;
        const double ms = m.dot(u), vs = d.dot(u);
        double tNear = 0.0, tFar = tMax;
        if (!clipSlab(ms, vs, -h, h, tNear, tFar))
            return false;
        const Eigen::Vector3d mp = m - ms * u, vp = d - vs * u;
        const double A = vp.squaredNorm(), B = mp.dot(vp), C = mp.squaredNorm() - r * r;
        if (A == 0.0)  // parallel to the axis
        {
            if (C > 0.0)
                return false;
        }
        else
        {
            double lo = 0.0, hi = 0.0;
            if (!quadraticRoots(A, B, C, lo, hi))
                return false;
            tNear = std::max(tNear, lo);
            tFar = std::min(tFar, hi);
            if (tNear > tFar)
                return false;
        }
        t = tNear;
        return true;
    }

    /// solid capsule: the union of the end spheres and the cylinder between them (the first contact with a
    /// union of convex solids is the earliest of their first contacts)
    inline bool capsule(const Eigen::Vector3d &a, const Eigen::Vector3d &d, const CapsuleObstacle &o, double tMax,
                        double &t) noexcept
    {
        const Eigen::Vector3d p0(o.ax, o.ay, o.az), axis(o.dx, o.dy, o.dz);
        const double r = o.radius;
        bool any = sphere(a, d, p0, r, tMax, t);
        if (o.invLengthSq == 0.0f)  // degenerate: one sphere
            return any;
        double best = any ? t : tMax, ti = 0.0;
        if (sphere(a, d, p0 + axis, r, best, ti))
        {
            best = ti;
            any = true;
        }
        const double length = axis.norm();
        if (cylinder(a, d, p0 + 0.5 * axis, axis / length, 0.5 * length, r, best, ti))
        {
            best = ti;
            any = true;
        }
        t = best;
        return any;
    }

    /** \brief A segment as its midpoint and half vector (float), for the separating-axis cull against
        ObstacleAabb boxes (the box's three axes and the three cross products with the segment's direction). */
    struct FloatSegment
    {
        float mx, my, mz, hx, hy, hz, ahx, ahy, ahz;

        void set(const Eigen::Vector3d &a, const Eigen::Vector3d &d, double tMax) noexcept
        {
            const Eigen::Vector3d half = 0.5 * tMax * d, mid = a + half;
            mx = static_cast<float>(mid.x());
            my = static_cast<float>(mid.y());
            mz = static_cast<float>(mid.z());
            hx = static_cast<float>(half.x());
            hy = static_cast<float>(half.y());
            hz = static_cast<float>(half.z());
            // a little slack on the cross-product axes so that near-parallel segments are never culled wrongly
            constexpr float EPS = 1e-6f;
            ahx = std::abs(hx) + EPS;
            ahy = std::abs(hy) + EPS;
            ahz = std::abs(hz) + EPS;
        }

        /// false only when the segment surely misses the box
        bool overlaps(const ObstacleAabb &b) const noexcept
        {
            const float cx = mx - b.cx, cy = my - b.cy, cz = mz - b.cz;
            if (std::abs(cx) > b.ex + ahx || std::abs(cy) > b.ey + ahy || std::abs(cz) > b.ez + ahz)
                return false;
            if (std::abs(cy * hz - cz * hy) > b.ey * ahz + b.ez * ahy)
                return false;
            if (std::abs(cz * hx - cx * hz) > b.ex * ahz + b.ez * ahx)
                return false;
            return std::abs(cx * hy - cy * hx) <= b.ex * ahy + b.ey * ahx;
        }
    };
}  // namespace ropras::ompl_ext::segment

#endif
