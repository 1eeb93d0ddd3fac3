#ifndef ROPRAS_TEST_MESH_SURFACE_SAMPLING_H
#define ROPRAS_TEST_MESH_SURFACE_SAMPLING_H

#include <Eigen/Core>
#include <limits>
#include <random>
#include <vector>

#include "ropras/ompl_ext/model/MeshLoader.h"
#include "ropras/ompl_ext/model/Spherizer.h"

namespace ropras::test
{
    /// how far \a p lies outside every sphere (<= 0: covered)
    inline double uncovered(const std::vector<ompl_ext::Sphere> &spheres, const Eigen::Vector3d &p)
    {
        double best = std::numeric_limits<double>::infinity();
        for (const ompl_ext::Sphere &s : spheres)
        {
            best = std::min(best, (p - s.center).norm() - s.radius);
        }
        return best;
    }

    /// \a n points uniform over the mesh surface (triangles picked by area, fixed \a seed), then every vertex
    /// (corners are the hardest points to cover)
    inline std::vector<Eigen::Vector3d> sampleMeshSurface(const ompl_ext::TriangleMesh &m, int n, unsigned seed)
    {
        std::vector<double> area;
        for (const auto &t : m.triangles)
        {
            area.push_back(
                0.5 * (m.vertices[t[1]] - m.vertices[t[0]]).cross(m.vertices[t[2]] - m.vertices[t[0]]).norm() + 1e-15);
        }
        std::mt19937 rng(seed);
        std::discrete_distribution<int> pick(area.begin(), area.end());
        std::uniform_real_distribution<double> u(0.0, 1.0);
        std::vector<Eigen::Vector3d> out;
        for (int i = 0; i < n; ++i)
        {
            const auto &t = m.triangles[pick(rng)];
            double a = u(rng), b = u(rng);
            if (a + b > 1.0)
            {
                a = 1.0 - a;
                b = 1.0 - b;
            }
            out.push_back(m.vertices[t[0]] + a * (m.vertices[t[1]] - m.vertices[t[0]]) +
                          b * (m.vertices[t[2]] - m.vertices[t[0]]));
        }
        for (const auto &v : m.vertices)
        {
            out.push_back(v);
        }
        return out;
    }
}  // namespace ropras::test

#endif
