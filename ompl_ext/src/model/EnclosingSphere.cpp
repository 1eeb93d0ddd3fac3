#include "model/EnclosingSphere.h"

#include <algorithm>
#include <cmath>

namespace ropras::ompl_ext
{
    namespace
    {
        double coverRadius(const std::vector<Sphere> &spheres, const Eigen::Vector3d &c, std::size_t *farthest)
        {
            double best = 0.0;
            std::size_t arg = 0;
            for (std::size_t i = 0; i < spheres.size(); ++i)
            {
                const double r = (spheres[i].center - c).norm() + spheres[i].radius;
                if (r > best)
                {
                    best = r;
                    arg = i;
                }
            }
            if (farthest != nullptr)
            {
                *farthest = arg;
            }
            return best;
        }
    }  // namespace

    Sphere enclosingSphere(const std::vector<Sphere> &spheres, int refineIterations)
    {
        Sphere out;
        if (spheres.empty())
        {
            return out;
        }
        // one or two spheres: the minimal ball in closed form (the refinement below costs 2000 passes per call,
        // and CollisionChecker asks for two such balls per self-collision pair: a 1000-link chain has 497 503)
        if (spheres.size() <= 2)
        {
            out = spheres[0];
            if (spheres.size() == 2)
            {
                const Sphere &a = spheres[0], &b = spheres[1];
                const Eigen::Vector3d d = b.center - a.center;
                const double dist = d.norm();
                if (dist + a.radius <= b.radius)
                {
                    out = b;
                }
                else if (dist + b.radius > a.radius && dist > 0.0)
                {
                    const double r = 0.5 * (dist + a.radius + b.radius);
                    out.center = a.center + d * ((r - a.radius) / dist);
                    out.radius = coverRadius(spheres, out.center, nullptr);  // exact enclosure, as below
                }
            }
            out.radius += 1e-12 + 1e-12 * out.radius;
            return out;
        }
        // Ritter: start from the first sphere and grow minimally to swallow each sphere outside (two passes).
        Eigen::Vector3d c = spheres[0].center;
        double r = spheres[0].radius;
        for (int pass = 0; pass < 2; ++pass)
        {
            for (const Sphere &s : spheres)
            {
                const Eigen::Vector3d d = s.center - c;
                const double dist = d.norm();
                if (dist + s.radius <= r)
                {
                    continue;
                }
                if (dist + r <= s.radius || dist == 0.0)
                {
                    c = s.center;
                    r = s.radius;
                    continue;
                }
                const double newR = 0.5 * (r + dist + s.radius);
                c += d * ((newR - r) / dist);
                r = newR;
            }
        }
        Sphere best{c, coverRadius(spheres, c, nullptr)};
        // a lower bound on the minimal radius: half the widest span between the sphere farthest from the first and
        // any other. When Ritter's ball is already that small (a line of spheres), refining cannot improve it: skip
        // the 2 x refineIterations passes (a link of 100 000 spheres on a line spent seconds there)
        std::size_t outer = 0;
        coverRadius(spheres, spheres[0].center, &outer);
        const Sphere &o = spheres[outer];
        double lower = 0.0;
        for (const Sphere &s : spheres)
            lower = std::max(lower, 0.5 * ((s.center - o.center).norm() + s.radius + o.radius));
        if (best.radius <= lower * (1.0 + 1e-12))
        {
            best.radius += 1e-12 + 1e-12 * best.radius;
            return best;
        }

        // Badoiu-Clarkson: step toward the far side of the farthest sphere with a shrinking step; the centre
        // converges to the minimal enclosing ball's centre.
        Eigen::Vector3d x = spheres[0].center;
        for (int k = 1; k <= refineIterations; ++k)
        {
            std::size_t far = 0;
            coverRadius(spheres, x, &far);
            const Eigen::Vector3d d = spheres[far].center - x;
            const double n = d.norm();
            const Eigen::Vector3d p = n > 0.0 ? Eigen::Vector3d(spheres[far].center + d / n * spheres[far].radius)
                                              : Eigen::Vector3d(spheres[far].center);
            x += (p - x) / static_cast<double>(k + 1);
            if (k % 25 == 0)
            {
                const double rx = coverRadius(spheres, x, nullptr);
                if (rx < best.radius)
                {
                    best = Sphere{x, rx};
                }
            }
        }
        const double rx = coverRadius(spheres, x, nullptr);
        if (rx < best.radius)
        {
            best = Sphere{x, rx};
        }
        // Guard the enclosure against rounding in the callers' float arithmetic.
        best.radius += 1e-12 + 1e-12 * best.radius;
        return best;
    }
}  // namespace ropras::ompl_ext
