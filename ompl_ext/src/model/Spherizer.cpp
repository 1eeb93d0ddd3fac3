#include "ropras/ompl_ext/model/Spherizer.h"

#include <algorithm>
#include <cmath>
#include <sstream>

#include "model/SurfaceCover.h"
#include "ropras/core/Error.h"

// The public shapes become closed triangle surfaces; model/SurfaceCover.cpp covers them (doc/spherizer.md).

namespace ropras::ompl_ext
{
    namespace
    {
        constexpr double PI = 3.14159265358979323846;

        std::string fmt(double v)
        {
            std::ostringstream ss;
            ss.precision(10);
            ss << v;
            return ss.str();
        }

        void checkOptions(const SpherizerOptions &options, const std::string &what)
        {
            if (!std::isfinite(options.tolerance) || options.tolerance <= 0.0)
            {
                throw Error("spherizer (" + what + "): tolerance " + fmt(options.tolerance) +
                            " must be positive and finite");
            }
            if (options.maxSpheresPerGeometry < 1)
            {
                throw Error("spherizer (" + what + "): maxSpheresPerGeometry " +
                            std::to_string(options.maxSpheresPerGeometry) + " must be at least 1");
            }
        }
    }  // namespace

    namespace spherizer
    {
        SphereCover coverBoxDetailed(const Eigen::Vector3d &fullExtents, const SpherizerOptions &options)
        {
            const std::string what =
                "box (" + fmt(fullExtents.x()) + ", " + fmt(fullExtents.y()) + ", " + fmt(fullExtents.z()) + ")";
            checkOptions(options, what);
            if (!fullExtents.allFinite() || (fullExtents.array() <= 0.0).any())
            {
                throw Error("spherizer: " + what + " must have positive finite extents");
            }
            const Eigen::Vector3d h = 0.5 * fullExtents;
            std::vector<Eigen::Vector3d> v;
            for (int i = 0; i < 8; ++i)
            {
                v.emplace_back((i & 1) ? h.x() : -h.x(), (i & 2) ? h.y() : -h.y(), (i & 4) ? h.z() : -h.z());
            }
            const std::vector<Eigen::Vector3i> t = {{0, 2, 1}, {1, 2, 3}, {4, 5, 6}, {5, 7, 6}, {0, 1, 4}, {1, 5, 4},
                                                    {2, 6, 3}, {3, 6, 7}, {0, 4, 2}, {2, 4, 6}, {1, 3, 5}, {3, 7, 5}};
            return coverTriangles(v, t, options, 0.0);
        }

        SphereCover coverCylinderDetailed(double radius, double length, const SpherizerOptions &options)
        {
            const std::string what = "cylinder radius " + fmt(radius) + " length " + fmt(length);
            checkOptions(options, what);
            if (!std::isfinite(radius) || !std::isfinite(length) || radius <= 0.0 || length <= 0.0)
            {
                throw Error("spherizer: " + what + " must have positive finite radius and length");
            }
            // Inscribed polygonal prism; every true surface point is within the sagitta of the polygon surface, so
            // the spheres grow by the sagitta ("slack") to stay conservative for the round cylinder.
            const double wantedSagitta = 0.02 * std::min(options.tolerance, radius);
            int m = static_cast<int>(std::ceil(PI / std::acos(std::max(-1.0, 1.0 - wantedSagitta / radius))));
            m = std::clamp(m, 16, 256);
            const double sagitta = radius * (1.0 - std::cos(PI / m));
            const double hz = 0.5 * length;
            std::vector<Eigen::Vector3d> v;
            for (int i = 0; i < m; ++i)
            {
                const double a = 2.0 * PI * i / m;
                v.emplace_back(radius * std::cos(a), radius * std::sin(a), -hz);
                v.emplace_back(radius * std::cos(a), radius * std::sin(a), hz);
            }
            const int bottom = static_cast<int>(v.size());
            v.emplace_back(0.0, 0.0, -hz);
            const int top = static_cast<int>(v.size());
            v.emplace_back(0.0, 0.0, hz);
            std::vector<Eigen::Vector3i> t;
            for (int i = 0; i < m; ++i)
            {
                const int j = (i + 1) % m;
                t.emplace_back(2 * i, 2 * j, 2 * i + 1);
                t.emplace_back(2 * j, 2 * j + 1, 2 * i + 1);
                t.emplace_back(bottom, 2 * j, 2 * i);
                t.emplace_back(top, 2 * i + 1, 2 * j + 1);
            }
            SphereCover c = coverTriangles(v, t, options, sagitta);
            return c;
        }

        SphereCover coverMeshDetailed(const std::vector<Eigen::Vector3d> &vertices,
                                      const std::vector<Eigen::Vector3i> &triangles, const SpherizerOptions &options)
        {
            const std::string what = "mesh of " + std::to_string(vertices.size()) + " vertices and " +
                                     std::to_string(triangles.size()) + " triangles";
            checkOptions(options, what);
            if (triangles.empty())
            {
                throw Error("spherizer: " + what + " has no triangles");
            }
            for (const Eigen::Vector3i &t : triangles)
            {
                for (int k = 0; k < 3; ++k)
                {
                    if (t[k] < 0 || t[k] >= static_cast<int>(vertices.size()))
                    {
                        throw Error("spherizer: " + what + ": triangle index " + std::to_string(t[k]) +
                                    " out of range");
                    }
                    if (!vertices[t[k]].allFinite())
                    {
                        throw Error("spherizer: " + what + ": vertex " + std::to_string(t[k]) + " is not finite");
                    }
                }
            }
            return coverTriangles(vertices, triangles, options, 0.0);
        }

        std::vector<Sphere> coverBox(const Eigen::Vector3d &fullExtents, const SpherizerOptions &options)
        {
            return coverBoxDetailed(fullExtents, options).spheres;
        }

        std::vector<Sphere> coverCylinder(double radius, double length, const SpherizerOptions &options)
        {
            return coverCylinderDetailed(radius, length, options).spheres;
        }

        std::vector<Sphere> coverMesh(const std::vector<Eigen::Vector3d> &vertices,
                                      const std::vector<Eigen::Vector3i> &triangles, const SpherizerOptions &options)
        {
            return coverMeshDetailed(vertices, triangles, options).spheres;
        }
    }  // namespace spherizer
}  // namespace ropras::ompl_ext
