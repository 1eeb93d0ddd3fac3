#include "model/TriangleGeometry.h"

#include <cmath>

namespace ropras::ompl_ext
{
    void clipPlane(std::vector<Eigen::Vector3d> &poly, int axis, double value, double side,
                   std::vector<Eigen::Vector3d> &scratch)
    {
        scratch.clear();
        const std::size_t n = poly.size();
        for (std::size_t i = 0; i < n; ++i)
        {
            const Eigen::Vector3d &a = poly[i];
            const Eigen::Vector3d &b = poly[(i + 1) % n];
            const double da = (a[axis] - value) * side;
            const double db = (b[axis] - value) * side;
            if (da <= 0.0)
            {
                scratch.push_back(a);
            }
            if ((da < 0.0 && db > 0.0) || (da > 0.0 && db < 0.0))
            {
                const double t = da / (da - db);
                Eigen::Vector3d p = a + t * (b - a);
                p[axis] = value;  // exactly on the plane
                scratch.push_back(p);
            }
        }
        poly.swap(scratch);
    }

    Eigen::Vector3d closestOnTriangle(const Eigen::Vector3d &p, const Eigen::Vector3d &a, const Eigen::Vector3d &b,
                                      const Eigen::Vector3d &c)
    {
        const Eigen::Vector3d ab = b - a, ac = c - a, ap = p - a;
        const double d1 = ab.dot(ap), d2 = ac.dot(ap);
        if (d1 <= 0.0 && d2 <= 0.0)
        {
            return a;
        }
        const Eigen::Vector3d bp = p - b;
        const double d3 = ab.dot(bp), d4 = ac.dot(bp);
        if (d3 >= 0.0 && d4 <= d3)
        {
            return b;
        }
        const double vc = d1 * d4 - d3 * d2;
        if (vc <= 0.0 && d1 >= 0.0 && d3 <= 0.0)
        {
            return a + d1 / (d1 - d3) * ab;
        }
        const Eigen::Vector3d cp = p - c;
        const double d5 = ab.dot(cp), d6 = ac.dot(cp);
        if (d6 >= 0.0 && d5 <= d6)
        {
            return c;
        }
        const double vb = d5 * d2 - d1 * d6;
        if (vb <= 0.0 && d2 >= 0.0 && d6 <= 0.0)
        {
            return a + d2 / (d2 - d6) * ac;
        }
        const double va = d3 * d6 - d5 * d4;
        if (va <= 0.0 && (d4 - d3) >= 0.0 && (d5 - d6) >= 0.0)
        {
            return b + (d4 - d3) / ((d4 - d3) + (d5 - d6)) * (c - b);
        }
        const double denom = 1.0 / (va + vb + vc);
        if (!std::isfinite(denom))
        {
            return a;  // degenerate triangle: its vertices are checked through the edges above
        }
        return a + ab * (vb * denom) + ac * (vc * denom);
    }
}  // namespace ropras::ompl_ext
