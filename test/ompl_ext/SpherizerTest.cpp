#include <gtest/gtest.h>

#include "ExpectError.h"
#include "MeshSurfaceSampling.h"

#include <cmath>
#include <filesystem>
#include <functional>
#include <iostream>
#include <random>

#include "ropras/core/Error.h"
#include "ropras/ompl_ext/model/MeshLoader.h"
#include "ropras/ompl_ext/model/RobotModel.h"
#include "ropras/ompl_ext/model/Spherizer.h"

namespace
{
    namespace fs = std::filesystem;
    using ropras::Error;
    using ropras::ompl_ext::RobotModel;
    using ropras::ompl_ext::Sphere;
    using ropras::ompl_ext::SphereCover;
    using ropras::ompl_ext::SpherizerOptions;
    using ropras::ompl_ext::TriangleMesh;
    namespace spherizer = ropras::ompl_ext::spherizer;
    using ropras::test::sampleMeshSurface;
    using ropras::test::uncovered;

    const std::string SHARED = ROPRAS_SHARED_DIR;
    constexpr double PI = 3.14159265358979323846;

    /// Fibonacci points on a sphere's surface
    std::vector<Eigen::Vector3d> sphereSurface(const Sphere &s, int n)
    {
        std::vector<Eigen::Vector3d> out;
        const double golden = PI * (3.0 - std::sqrt(5.0));
        for (int i = 0; i < n; ++i)
        {
            const double z = 1.0 - 2.0 * (i + 0.5) / n;
            const double r = std::sqrt(1.0 - z * z);
            out.push_back(s.center + s.radius * Eigen::Vector3d(r * std::cos(golden * i), r * std::sin(golden * i), z));
        }
        return out;
    }

    double maxProtrusion(const std::vector<Sphere> &spheres, const std::function<double(const Eigen::Vector3d &)> &dist)
    {
        double worst = 0.0;
        for (const Sphere &s : spheres)
        {
            for (const Eigen::Vector3d &p : sphereSurface(s, 400))
            {
                worst = std::max(worst, dist(p));
            }
        }
        return worst;
    }

    // ---- exact geometry used to check the covers ----

    Eigen::Vector3d closestOnTriangle(const Eigen::Vector3d &p, const Eigen::Vector3d &a, const Eigen::Vector3d &b,
                                      const Eigen::Vector3d &c)
    {
        // Ericson, Real-Time Collision Detection, 5.1.5
        const Eigen::Vector3d ab = b - a, ac = c - a, ap = p - a;
        const double d1 = ab.dot(ap), d2 = ac.dot(ap);
        if (d1 <= 0 && d2 <= 0)
            return a;
        const Eigen::Vector3d bp = p - b;
        const double d3 = ab.dot(bp), d4 = ac.dot(bp);
        if (d3 >= 0 && d4 <= d3)
            return b;
        const double vc = d1 * d4 - d3 * d2;
        if (vc <= 0 && d1 >= 0 && d3 <= 0)
            return a + d1 / (d1 - d3) * ab;
        const Eigen::Vector3d cp = p - c;
        const double d5 = ab.dot(cp), d6 = ac.dot(cp);
        if (d6 >= 0 && d5 <= d6)
            return c;
        const double vb = d5 * d2 - d1 * d6;
        if (vb <= 0 && d2 >= 0 && d6 <= 0)
            return a + d2 / (d2 - d6) * ac;
        const double va = d3 * d6 - d5 * d4;
        if (va <= 0 && (d4 - d3) >= 0 && (d5 - d6) >= 0)
            return b + (d4 - d3) / ((d4 - d3) + (d5 - d6)) * (c - b);
        const double denom = 1.0 / (va + vb + vc);
        return a + ab * (vb * denom) + ac * (vc * denom);
    }

    /// distance from p to the solid a closed mesh bounds (0 inside; winding number decides inside)
    double meshSolidDistance(const TriangleMesh &m, const Eigen::Vector3d &p)
    {
        double winding = 0.0, best = std::numeric_limits<double>::infinity();
        for (const auto &t : m.triangles)
        {
            const Eigen::Vector3d a = m.vertices[t[0]] - p, b = m.vertices[t[1]] - p, c = m.vertices[t[2]] - p;
            const double la = a.norm(), lb = b.norm(), lc = c.norm();
            winding +=
                2.0 * std::atan2(a.dot(b.cross(c)), la * lb * lc + a.dot(b) * lc + b.dot(c) * la + c.dot(a) * lb);
            best =
                std::min(best, (closestOnTriangle(p, m.vertices[t[0]], m.vertices[t[1]], m.vertices[t[2]]) - p).norm());
        }
        return std::abs(winding) / (4.0 * PI) > 0.5 ? 0.0 : best;
    }

    TriangleMesh torus(double big, double small, int nu, int nv)
    {
        TriangleMesh m;
        for (int i = 0; i < nu; ++i)
        {
            for (int j = 0; j < nv; ++j)
            {
                const double u = 2 * PI * i / nu, v = 2 * PI * j / nv;
                m.vertices.emplace_back((big + small * std::cos(v)) * std::cos(u),
                                        (big + small * std::cos(v)) * std::sin(u), small * std::sin(v));
            }
        }
        for (int i = 0; i < nu; ++i)
        {
            for (int j = 0; j < nv; ++j)
            {
                const int a = i * nv + j, b = ((i + 1) % nu) * nv + j, c = ((i + 1) % nu) * nv + (j + 1) % nv,
                          d = i * nv + (j + 1) % nv;
                m.triangles.emplace_back(a, b, c);
                m.triangles.emplace_back(a, c, d);
            }
        }
        return m;
    }

    void expectConservative(const std::vector<Sphere> &spheres, const std::vector<Eigen::Vector3d> &points,
                            const std::string &what)
    {
        double worst = -1.0;
        for (const Eigen::Vector3d &p : points)
        {
            worst = std::max(worst, uncovered(spheres, p));
        }
        EXPECT_LE(worst, 1e-12) << what << ": a surface point lies " << worst << " m outside every sphere";
    }

    using ropras::test::expectErrorMentions;
}  // namespace

TEST(Spherizer, BoxCoverIsConservativeAndTight)
{
    std::mt19937 rng(42);
    std::uniform_real_distribution<double> u(-1.0, 1.0);
    for (const Eigen::Vector3d &ext :
         {Eigen::Vector3d(0.1, 0.1, 0.1), Eigen::Vector3d(0.3, 0.05, 0.12), Eigen::Vector3d(0.6, 0.02, 0.4)})
    {
        for (const double tol : {0.005, 0.02, 0.05})
        {
            SpherizerOptions o;
            o.tolerance = tol;
            o.maxSpheresPerGeometry = 48;
            const SphereCover c = spherizer::coverBoxDetailed(ext, o);
            const std::string what = "box " + std::to_string(ext.x()) + "x" + std::to_string(ext.y()) + "x" +
                                     std::to_string(ext.z()) + " tol " + std::to_string(tol);
            ASSERT_FALSE(c.spheres.empty());
            EXPECT_LE(static_cast<int>(c.spheres.size()), o.maxSpheresPerGeometry);
            // surface samples: a random face point per sample, plus the corners
            const Eigen::Vector3d h = 0.5 * ext;
            std::vector<Eigen::Vector3d> pts;
            for (int i = 0; i < 20000; ++i)
            {
                Eigen::Vector3d p(u(rng) * h.x(), u(rng) * h.y(), u(rng) * h.z());
                const int axis = i % 3;
                p[axis] = (i / 3) % 2 ? h[axis] : -h[axis];
                pts.push_back(p);
            }
            for (int k = 0; k < 8; ++k)
            {
                pts.emplace_back((k & 1) ? h.x() : -h.x(), (k & 2) ? h.y() : -h.y(), (k & 4) ? h.z() : -h.z());
            }
            expectConservative(c.spheres, pts, what);
            const double measured = maxProtrusion(
                c.spheres, [&](const Eigen::Vector3d &p) { return (p.cwiseAbs() - h).cwiseMax(0.0).norm(); });
            EXPECT_LE(measured, c.protrusion + 1e-9) << what;
            if (c.toleranceMet)
            {
                EXPECT_LE(measured, tol + 1e-9) << what;
            }
            std::cout << "[ spherizer ] " << what << ": " << c.spheres.size() << " spheres, protrusion bound "
                      << c.protrusion << ", measured " << measured << (c.toleranceMet ? "" : " (relaxed)") << '\n';
        }
    }
}

TEST(Spherizer, CylinderCoverIsConservative)
{
    std::mt19937 rng(7);
    std::uniform_real_distribution<double> u(0.0, 1.0);
    for (const auto &[radius, length] : {std::pair{0.05, 0.3}, std::pair{0.2, 0.04}, std::pair{0.06, 0.06}})
    {
        SpherizerOptions o;
        o.tolerance = 0.02;
        o.maxSpheresPerGeometry = 40;
        const SphereCover c = spherizer::coverCylinderDetailed(radius, length, o);
        const std::string what = "cylinder r " + std::to_string(radius) + " l " + std::to_string(length);
        EXPECT_LE(static_cast<int>(c.spheres.size()), o.maxSpheresPerGeometry);
        std::vector<Eigen::Vector3d> pts;
        for (int i = 0; i < 20000; ++i)
        {
            const double a = 2 * PI * u(rng);
            if (i % 2 == 0)
            {  // lateral surface of the true (round) cylinder
                pts.emplace_back(radius * std::cos(a), radius * std::sin(a), (u(rng) - 0.5) * length);
            }
            else
            {  // caps, including their rims
                const double r = radius * (i % 10 == 1 ? 1.0 : std::sqrt(u(rng)));
                pts.emplace_back(r * std::cos(a), r * std::sin(a), (i % 4 == 1 ? 0.5 : -0.5) * length);
            }
        }
        expectConservative(c.spheres, pts, what);
        const double measured = maxProtrusion(c.spheres,
                                              [&](const Eigen::Vector3d &p)
                                              {
                                                  const double dr = std::max(0.0, p.head<2>().norm() - radius);
                                                  const double dz = std::max(0.0, std::abs(p.z()) - 0.5 * length);
                                                  return std::hypot(dr, dz);
                                              });
        EXPECT_LE(measured, c.protrusion + 1e-9) << what;
        if (c.toleranceMet)
        {
            EXPECT_LE(measured, o.tolerance + 1e-9) << what;
        }
        std::cout << "[ spherizer ] " << what << ": " << c.spheres.size() << " spheres, protrusion bound "
                  << c.protrusion << ", measured " << measured << (c.toleranceMet ? "" : " (relaxed)") << '\n';
    }
}

TEST(Spherizer, NonConvexMeshCover)
{
    const TriangleMesh m = torus(0.12, 0.035, 32, 12);
    SpherizerOptions o;
    o.tolerance = 0.02;
    o.maxSpheresPerGeometry = 40;
    const SphereCover c = spherizer::coverMeshDetailed(m.vertices, m.triangles, o);
    EXPECT_LE(static_cast<int>(c.spheres.size()), o.maxSpheresPerGeometry);
    expectConservative(c.spheres, sampleMeshSurface(m, 20000, 3), "torus");
    const double measured = maxProtrusion(c.spheres, [&](const Eigen::Vector3d &p) { return meshSolidDistance(m, p); });
    EXPECT_LE(measured, c.protrusion + 1e-9);
    // the hole of the torus (radius 0.085) must stay mostly free: no sphere swallows the centre
    EXPECT_GT(uncovered(c.spheres, Eigen::Vector3d::Zero()), 0.0);
    std::cout << "[ spherizer ] torus: " << c.spheres.size() << " spheres, protrusion bound " << c.protrusion
              << ", measured " << measured << (c.toleranceMet ? "" : " (relaxed)") << '\n';
}

TEST(Spherizer, ToleranceRelaxedWithinBudget)
{
    SpherizerOptions o;
    o.tolerance = 0.001;
    o.maxSpheresPerGeometry = 6;
    const Eigen::Vector3d ext(0.4, 0.3, 0.2);
    const SphereCover c = spherizer::coverBoxDetailed(ext, o);
    EXPECT_FALSE(c.toleranceMet);
    EXPECT_LE(c.spheres.size(), 6u);
    EXPECT_GT(c.protrusion, o.tolerance);
    std::vector<Eigen::Vector3d> corners;
    for (int k = 0; k < 8; ++k)
    {
        corners.emplace_back((k & 1) ? 0.2 : -0.2, (k & 2) ? 0.15 : -0.15, (k & 4) ? 0.1 : -0.1);
    }
    expectConservative(c.spheres, corners, "relaxed box");
    // one sphere is always possible
    o.maxSpheresPerGeometry = 1;
    const auto one = spherizer::coverBox(ext, o);
    ASSERT_EQ(one.size(), 1u);
    expectConservative(one, corners, "single-sphere box");
    // the vector API returns the same spheres as the detailed one
    EXPECT_EQ(spherizer::coverBox(ext, o).size(), spherizer::coverBoxDetailed(ext, o).spheres.size());
}

TEST(Spherizer, BadInputs)
{
    SpherizerOptions o;
    expectErrorMentions([&] { spherizer::coverBox(Eigen::Vector3d(0.1, -0.1, 0.1), o); }, {"box", "-0.1"});
    expectErrorMentions([&] { spherizer::coverCylinder(std::nan(""), 0.1, o); }, {"cylinder", "nan"});
    expectErrorMentions([&] { spherizer::coverCylinder(0.1, 0.0, o); }, {"cylinder"});
    expectErrorMentions([&] { spherizer::coverMesh({Eigen::Vector3d::Zero()}, {Eigen::Vector3i(0, 0, 1)}, o); },
                        {"mesh", "index 1"});
    expectErrorMentions([&] { spherizer::coverMesh({}, {}, o); }, {"mesh", "no triangles"});
    expectErrorMentions(
        [&]
        {
            spherizer::coverMesh(
                {Eigen::Vector3d::Zero(), Eigen::Vector3d::UnitX(), Eigen::Vector3d(0, std::nan(""), 0)},
                {Eigen::Vector3i(0, 1, 2)}, o);
        },
        {"mesh", "not finite"});
    SpherizerOptions badTol;
    badTol.tolerance = 0.0;
    expectErrorMentions([&] { spherizer::coverBox(Eigen::Vector3d::Ones(), badTol); }, {"tolerance"});
    SpherizerOptions badMax;
    badMax.maxSpheresPerGeometry = 0;
    expectErrorMentions([&] { spherizer::coverBox(Eigen::Vector3d::Ones(), badMax); }, {"maxSpheresPerGeometry"});
}

TEST(Spherizer, SharedMeshRobotsAreCovered)
{
    if (!fs::is_directory(SHARED + "/robots"))
    {
        GTEST_SKIP() << "../shared not found: " << SHARED;
    }
    struct Robot
    {
        std::string urdf, srdf;
        std::size_t dof;
    };
    for (const Robot &r : {Robot{"robots/panda/panda.urdf", "robots/panda/panda.srdf", 7},
                           Robot{"robots/ur5/ur5.urdf", "robots/ur5/ur5.srdf", 6}})
    {
        auto m = RobotModel::fromUrdfFile(SHARED + "/" + r.urdf, SHARED + "/" + r.srdf);
        EXPECT_EQ(m->dof(), r.dof);
        EXPECT_FALSE(m->spheres().empty());
        double worstBound = 0.0;
        int meshes = 0;
        // every mesh surface point (in the link frame) is inside one of its link's spheres
        std::map<int, std::vector<Sphere>> linkSpheres;
        for (const auto &cl : m->collisionLinks())
        {
            for (int i = cl.firstSphere; i < cl.firstSphere + cl.sphereCount; ++i)
            {
                linkSpheres[cl.link].push_back(Sphere{m->spheres()[i].centerInLink, m->spheres()[i].radius});
            }
        }
        for (const auto &g : m->collisionGeometries())
        {
            if (g.type != ropras::ompl_ext::CollisionGeometry::Type::Mesh)
            {
                continue;
            }
            ++meshes;
            worstBound = std::max(worstBound, g.coverProtrusion);
            const TriangleMesh mesh = ropras::ompl_ext::loadMesh(g.meshPath, g.scale);
            std::vector<Eigen::Vector3d> pts = sampleMeshSurface(mesh, 2000, 5);
            for (auto &p : pts)
            {
                p = g.origin * p;
            }
            expectConservative(linkSpheres[g.link], pts, g.meshPath);
        }
        EXPECT_GT(meshes, 0);
        std::cout << "[ spherizer ] " << r.urdf << ": " << m->collisionGeometries().size() << " collision elements, "
                  << m->spheres().size() << " spheres, " << m->selfCollisionPairs().size()
                  << " self pairs, worst protrusion bound " << worstBound << " m\n";
    }
}

TEST(Spherizer, FlatAndDegenerateMeshes)
{
    SpherizerOptions o;
    // an open, flat square (two triangles): covered, and the spheres hug the plane
    const std::vector<Eigen::Vector3d> v = {{0, 0, 0}, {0.3, 0, 0}, {0.3, 0.2, 0}, {0, 0.2, 0}};
    const std::vector<Eigen::Vector3i> t = {{0, 1, 2}, {0, 2, 3}};
    const SphereCover c = spherizer::coverMeshDetailed(v, t, o);
    EXPECT_LE(static_cast<int>(c.spheres.size()), o.maxSpheresPerGeometry);
    TriangleMesh square{v, t};
    expectConservative(c.spheres, sampleMeshSurface(square, 5000, 9), "flat square");
    // a single zero-area triangle (all three vertices equal) and a sliver
    const std::vector<Eigen::Vector3d> p = {{0.1, 0.2, 0.3}, {0.1, 0.2, 0.3}, {0.1, 0.2, 0.3}, {0.5, 0.2, 0.3}};
    const auto point = spherizer::coverMesh(p, {Eigen::Vector3i(0, 1, 2)}, o);
    ASSERT_FALSE(point.empty());
    expectConservative(point, {p[0]}, "point");
    const auto sliver = spherizer::coverMesh(p, {Eigen::Vector3i(0, 1, 3)}, o);
    std::vector<Eigen::Vector3d> segment;
    for (int i = 0; i <= 100; ++i)
    {
        segment.push_back(p[0] + (p[3] - p[0]) * (i / 100.0));
    }
    expectConservative(sliver, segment, "sliver");
}
