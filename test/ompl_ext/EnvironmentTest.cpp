// Environment: authoring form -> query form, copy and setObjectPose semantics, exact signed distances, errors.
#include <gtest/gtest.h>

#include <cmath>
#include <cstring>
#include <limits>
#include <random>

#include "ropras/core/Error.h"
#include "ropras/ompl_ext/scene/Environment.h"
#include "ropras/ompl_ext/scene/PointCloud.h"

using ropras::Error;
using ropras::ompl_ext::Environment;
using ropras::ompl_ext::PointCloud;
using ropras::ompl_ext::Shape;

namespace
{
    Eigen::Isometry3d pose(const Eigen::Vector3d &t, const Eigen::Quaterniond &q = Eigen::Quaterniond::Identity())
    {
        Eigen::Isometry3d p = Eigen::Isometry3d::Identity();
        p.linear() = q.normalized().toRotationMatrix();
        p.translation() = t;
        return p;
    }

    Eigen::Quaterniond randomRotation(std::mt19937 &rng)
    {
        std::normal_distribution<double> n(0.0, 1.0);
        return Eigen::Quaterniond(n(rng), n(rng), n(rng), n(rng)).normalized();
    }

    /// message of the Error thrown by f, or "" when none
    template <class F>
    std::string errorOf(F &&f)
    {
        try
        {
            f();
        }
        catch (const Error &e)
        {
            return e.what();
        }
        return "";
    }

    /// brute-force signed distance of a point to a primitive in its own frame, by dense surface sampling
    /// (outside: distance to the nearest surface sample; used only for points well outside)
    double sampledBoxDistance(const Eigen::Vector3d &p, const Eigen::Vector3d &h)
    {
        const Eigen::Vector3d clamped = p.cwiseMax(-h).cwiseMin(h);
        return (p - clamped).norm();
    }
}  // namespace

TEST(EnvironmentTest, BuildsQueryFormForEveryPrimitive)
{
    Environment env;
    EXPECT_EQ(env.addSphere("ball", {1, 2, 3}, 0.5), 0);
    const Eigen::Quaterniond q(Eigen::AngleAxisd(0.3, Eigen::Vector3d(1, 2, 3).normalized()));
    EXPECT_EQ(env.addBox("crate", pose({0.1, 0.2, 0.3}, q), {0.4, 0.6, 0.8}), 1);
    EXPECT_EQ(env.addCylinder("can", pose({-1, 0, 0.5}, q), 0.1, 0.3), 2);
    EXPECT_EQ(env.addCapsule("pill", pose({0, -1, 0}), 0.05, 0.4), 3);
    EXPECT_EQ(env.objectCount(), 4u);

    ASSERT_EQ(env.spheres().size(), 1u);
    EXPECT_FLOAT_EQ(env.spheres()[0].x, 1.0f);
    EXPECT_FLOAT_EQ(env.spheres()[0].r, 0.5f);

    ASSERT_EQ(env.boxes().size(), 1u);
    const auto &b = env.boxes()[0];
    const Eigen::Matrix3d r = q.toRotationMatrix();
    for (int i = 0; i < 3; ++i)
        for (int j = 0; j < 3; ++j)
            EXPECT_NEAR(b.rot[3 * i + j], r(i, j), 1e-7);
    EXPECT_FLOAT_EQ(b.hx, 0.2f);
    EXPECT_FLOAT_EQ(b.hy, 0.3f);
    EXPECT_FLOAT_EQ(b.hz, 0.4f);
    EXPECT_NEAR(b.boundRadius, 0.5 * std::sqrt(0.16 + 0.36 + 0.64), 1e-6);

    ASSERT_EQ(env.cylinders().size(), 1u);
    const auto &c = env.cylinders()[0];
    EXPECT_NEAR(c.ax, r(0, 2), 1e-7);
    EXPECT_NEAR(c.ay, r(1, 2), 1e-7);
    EXPECT_NEAR(c.az, r(2, 2), 1e-7);
    EXPECT_FLOAT_EQ(c.halfLength, 0.15f);
    EXPECT_FLOAT_EQ(c.radius, 0.1f);

    ASSERT_EQ(env.capsules().size(), 1u);
    const auto &p = env.capsules()[0];
    EXPECT_FLOAT_EQ(p.az, -0.2f);
    EXPECT_FLOAT_EQ(p.dz, 0.4f);
    EXPECT_FLOAT_EQ(p.ay, -1.0f);
    EXPECT_NEAR(p.invLengthSq, 1.0 / 0.16, 1e-4);
}

TEST(EnvironmentTest, ObjectsComposeObjectAndShapePoses)
{
    Environment env;
    const Eigen::Isometry3d objectPose =
        pose({1, 0, 0}, Eigen::Quaterniond(Eigen::AngleAxisd(M_PI / 2, Eigen::Vector3d::UnitZ())));
    const int id = env.addObject(
        "shelf", {Shape::box({0.2, 0.2, 0.2}, pose({0.5, 0, 0})), Shape::sphere(0.1, pose({0, 0, 1}))}, objectPose);
    // the box centre is the object pose applied to (0.5, 0, 0): (1, 0.5, 0)
    EXPECT_NEAR(env.boxes()[0].cx, 1.0, 1e-6);
    EXPECT_NEAR(env.boxes()[0].cy, 0.5, 1e-6);
    EXPECT_NEAR(env.spheres()[0].z, 1.0, 1e-6);
    EXPECT_TRUE(env.shapeWorldPose(id, 0).isApprox(objectPose * pose({0.5, 0, 0})));
    EXPECT_EQ(env.objectShapes(id).size(), 2u);
    EXPECT_EQ(env.objectName(id), "shelf");
    EXPECT_EQ(env.objectId("shelf"), id);
    EXPECT_TRUE(env.hasObject("shelf"));
    EXPECT_FALSE(env.hasObject("table"));
}

TEST(EnvironmentTest, CopiesAreIndependentAndSetObjectPoseMovesOneObject)
{
    Environment env;
    env.addBox("a", pose({0, 0, 0}), {1, 1, 1});
    env.addBox("b", pose({2, 0, 0}), {1, 1, 1});
    env.addCylinder("c", pose({0, 2, 0}), 0.2, 1.0);
    const Environment original = env;

    Environment moved = env;
    const Eigen::Isometry3d newPose =
        pose({5, 5, 5}, Eigen::Quaterniond(Eigen::AngleAxisd(0.7, Eigen::Vector3d::UnitX())));
    moved.setObjectPose("b", newPose);

    // the copy moved, the source did not
    EXPECT_NEAR(moved.boxes()[1].cx, 5.0, 1e-6);
    EXPECT_NEAR(env.boxes()[1].cx, 2.0, 1e-6);
    EXPECT_TRUE(moved.objectPose(1).isApprox(newPose));
    // only b's entries were rewritten
    EXPECT_EQ(std::memcmp(&moved.boxes()[0], &original.boxes()[0], sizeof(moved.boxes()[0])), 0);
    EXPECT_EQ(std::memcmp(&moved.cylinders()[0], &original.cylinders()[0], sizeof(moved.cylinders()[0])), 0);

    // same query form as an environment built at that pose directly
    Environment direct;
    direct.addBox("a", pose({0, 0, 0}), {1, 1, 1});
    direct.addBox("b", newPose, {1, 1, 1});
    direct.addCylinder("c", pose({0, 2, 0}), 0.2, 1.0);
    EXPECT_EQ(std::memcmp(&moved.boxes()[1], &direct.boxes()[1], sizeof(direct.boxes()[1])), 0);

    // and the same distances everywhere
    std::mt19937 rng(3);
    std::uniform_real_distribution<double> u(-3.0, 8.0);
    for (int k = 0; k < 200; ++k)
    {
        const Eigen::Vector3d x(u(rng), u(rng), u(rng));
        EXPECT_DOUBLE_EQ(moved.signedDistance(x, 0.1), direct.signedDistance(x, 0.1));
    }

    // moving back restores the original query form exactly
    moved.setObjectPose(1, pose({2, 0, 0}));
    EXPECT_EQ(std::memcmp(&moved.boxes()[1], &original.boxes()[1], sizeof(original.boxes()[1])), 0);
}

TEST(EnvironmentTest, PointCloudsAreSharedBetweenCopies)
{
    const auto cloud = PointCloud::build({{0, 0, 0}, {1, 0, 0}, {0, 1, 0}}, 0.01f);
    Environment env;
    env.addPointCloud("scan", cloud, pose({0, 0, 1}));
    const Environment copy = env;
    ASSERT_EQ(copy.clouds().size(), 1u);
    EXPECT_EQ(copy.clouds()[0].cloud.get(), cloud.get());
    // the bounding sphere holds every inflated point
    const auto &c = env.clouds()[0];
    for (const Eigen::Vector3f &p : cloud->points())
    {
        const Eigen::Vector3f w = p + Eigen::Vector3f(0, 0, 1);
        EXPECT_LE((w - Eigen::Vector3f(c.cx, c.cy, c.cz)).norm() + cloud->pointRadius(), c.boundRadius);
    }
    // the world -> cloud transform undoes the pose
    const Eigen::Vector3f back = c.worldToCloud * Eigen::Vector3f(1, 0, 1);
    EXPECT_NEAR((back - Eigen::Vector3f(1, 0, 0)).norm(), 0.0, 1e-6);
    // distance: point (1, 0, 1) in the world is a cloud point, inflated by 0.01
    EXPECT_NEAR(env.signedDistance({1, 0, 1.5}, 0.1), 0.5 - 0.01 - 0.1, 1e-6);
}

TEST(EnvironmentTest, SignedDistanceExactForEachPrimitive)
{
    {
        Environment env;
        EXPECT_EQ(env.signedDistance({0, 0, 0}, 0.1), std::numeric_limits<double>::infinity());
        env.addSphere("s", {1, 0, 0}, 0.5);
        EXPECT_NEAR(env.signedDistance({3, 0, 0}, 0.25), 2.0 - 0.5 - 0.25, 1e-12);
        EXPECT_NEAR(env.signedDistance({1, 0, 0.2}, 0.1), -0.5 + 0.2 - 0.1, 1e-12);
    }
    {
        Environment env;
        env.addBox("b", pose({0, 0, 0}), {2, 4, 6});
        EXPECT_NEAR(env.signedDistance({3, 0, 0}, 0.0), 2.0, 1e-12);                   // face
        EXPECT_NEAR(env.signedDistance({2, 3, 0}, 0.0), std::sqrt(2.0), 1e-12);        // edge
        EXPECT_NEAR(env.signedDistance({2, 3, 4}, 0.1), std::sqrt(3.0) - 0.1, 1e-12);  // corner
        EXPECT_NEAR(env.signedDistance({0.5, 0, 0}, 0.0), -0.5, 1e-12);                // inside: nearest face x = 1
        EXPECT_NEAR(env.signedDistance({0, 0, 0}, 0.2), -1.0 - 0.2, 1e-12);
    }
    {
        Environment env;
        env.addCylinder("c", pose({0, 0, 0}), 1.0, 2.0);                         // radius 1, z in [-1, 1]
        EXPECT_NEAR(env.signedDistance({3, 0, 0}, 0.0), 2.0, 1e-12);             // side
        EXPECT_NEAR(env.signedDistance({0.5, 0, 3}, 0.0), 2.0, 1e-12);           // cap
        EXPECT_NEAR(env.signedDistance({2, 0, 2}, 0.0), std::sqrt(2.0), 1e-12);  // rim: exact, not a capsule
        EXPECT_NEAR(env.signedDistance({0, 0, 0.5}, 0.0), -0.5, 1e-12);          // inside, nearer the cap
        EXPECT_NEAR(env.signedDistance({0.9, 0, 0}, 0.0), -0.1, 1e-12);          // inside, nearer the side
    }
    {
        Environment env;
        env.addCapsule("p", pose({0, 0, 0}), 0.5, 2.0);  // segment z in [-1, 1]
        EXPECT_NEAR(env.signedDistance({2, 0, 0.3}, 0.0), 1.5, 1e-12);
        EXPECT_NEAR(env.signedDistance({0, 0, 3}, 0.0), 1.5, 1e-12);
        EXPECT_NEAR(env.signedDistance({0, 0, 0}, 0.0), -0.5, 1e-12);
    }
}

TEST(EnvironmentTest, RotatedBoxDistanceMatchesLocalFrameComputation)
{
    std::mt19937 rng(5);
    std::uniform_real_distribution<double> u(-2.0, 2.0);
    for (int trial = 0; trial < 20; ++trial)
    {
        const Eigen::Isometry3d p = pose({u(rng), u(rng), u(rng)}, randomRotation(rng));
        const Eigen::Vector3d extents(0.3 + std::abs(u(rng)), 0.3 + std::abs(u(rng)), 0.3 + std::abs(u(rng)));
        Environment env;
        env.addBox("b", p, extents);
        for (int k = 0; k < 50; ++k)
        {
            const Eigen::Vector3d x(3 * u(rng), 3 * u(rng), 3 * u(rng));
            const Eigen::Vector3d local = p.inverse() * x;
            const Eigen::Vector3d h = 0.5 * extents;
            if ((local.cwiseAbs() - h).maxCoeff() <= 0.0)
                continue;  // inside: covered by the exact tests above
            EXPECT_NEAR(env.signedDistance(x, 0.05), sampledBoxDistance(local, h) - 0.05, 1e-9);
        }
    }
}

TEST(EnvironmentTest, NearestObjectWins)
{
    Environment env;
    env.addSphere("far", {10, 0, 0}, 1.0);
    env.addBox("near", pose({0, 2, 0}), {1, 1, 1});
    EXPECT_NEAR(env.signedDistance({0, 0, 0}, 0.0), 1.5, 1e-12);
    env.clear();
    EXPECT_EQ(env.objectCount(), 0u);
    EXPECT_TRUE(env.boxes().empty());
    EXPECT_TRUE(env.spheres().empty());
    EXPECT_EQ(env.signedDistance({0, 0, 0}, 0.0), std::numeric_limits<double>::infinity());
    // names are free again after clear()
    EXPECT_EQ(env.addSphere("far", {0, 0, 0}, 1.0), 0);
}

TEST(EnvironmentTest, InvalidShapesThrowNamingTheObject)
{
    Environment env;
    const double nan = std::numeric_limits<double>::quiet_NaN();
    const double inf = std::numeric_limits<double>::infinity();
    EXPECT_NE(errorOf(
                  [&] {
                      env.addSphere("negative_ball", {0, 0, 0}, -1.0);
                  })
                  .find("negative_ball"),
              std::string::npos);
    EXPECT_NE(errorOf([&] { env.addSphere("zero_ball", {0, 0, 0}, 0.0); }).find("zero_ball"), std::string::npos);
    EXPECT_NE(errorOf([&] { env.addSphere("nan_ball", {0, 0, 0}, nan); }).find("nan_ball"), std::string::npos);
    EXPECT_NE(errorOf([&] { env.addSphere("nan_centre", {nan, 0, 0}, 1.0); }).find("nan_centre"), std::string::npos);
    EXPECT_NE(errorOf([&] { env.addBox("flat_box", pose({0, 0, 0}), {1, 0, 1}); }).find("flat_box"), std::string::npos);
    EXPECT_NE(errorOf([&] { env.addBox("inf_box", pose({0, 0, 0}), {1, inf, 1}); }).find("inf_box"), std::string::npos);
    EXPECT_NE(errorOf(
                  [&] {
                      env.addCylinder("thin_can", pose({0, 0, 0}), 0.0, 1.0);
                  })
                  .find("thin_can"),
              std::string::npos);
    EXPECT_NE(errorOf(
                  [&] {
                      env.addCylinder("short_can", pose({0, 0, 0}), 1.0, 0.0);
                  })
                  .find("short_can"),
              std::string::npos);
    EXPECT_NE(errorOf(
                  [&] {
                      env.addCapsule("bad_pill", pose({0, 0, 0}), 0.1, -1.0);
                  })
                  .find("bad_pill"),
              std::string::npos);
    EXPECT_NE(errorOf([&] { env.addPointCloud("no_cloud", nullptr); }).find("no_cloud"), std::string::npos);
    Eigen::Isometry3d scaled = Eigen::Isometry3d::Identity();
    scaled.linear() *= 2.0;
    EXPECT_NE(errorOf([&] { env.addBox("scaled_box", scaled, {1, 1, 1}); }).find("scaled_box"), std::string::npos);
    EXPECT_NE(errorOf([&] { env.addObject("empty_object", {}); }).find("empty_object"), std::string::npos);
    EXPECT_NE(errorOf([&] { env.addObject("", {Shape::sphere(1.0)}); }), "");
    // a degenerate capsule (length 0) is a sphere and is accepted
    EXPECT_NO_THROW(env.addCapsule("round_pill", pose({0, 0, 0}), 0.1, 0.0));
    EXPECT_EQ(env.capsules()[0].invLengthSq, 0.0f);
    EXPECT_NEAR(env.signedDistance({1, 0, 0}, 0.0), 0.9, 1e-12);
    // nothing half-added by the failures
    EXPECT_EQ(env.objectCount(), 1u);
    EXPECT_TRUE(env.boxes().empty());
}

TEST(EnvironmentTest, NamesAndIdsAreChecked)
{
    Environment env;
    env.addSphere("table", {0, 0, 0}, 1.0);
    env.addSphere("chair", {0, 0, 3}, 1.0);
    EXPECT_NE(errorOf([&] { env.addSphere("table", {5, 0, 0}, 1.0); }).find("table"), std::string::npos);
    const std::string unknown = errorOf([&] { env.objectId("lamp"); });
    EXPECT_NE(unknown.find("lamp"), std::string::npos);
    EXPECT_NE(unknown.find("chair"), std::string::npos);  // lists what exists
    EXPECT_NE(errorOf([&] { env.setObjectPose(7, Eigen::Isometry3d::Identity()); }).find("7"), std::string::npos);
    EXPECT_NE(errorOf([&] { env.setObjectPose(-1, Eigen::Isometry3d::Identity()); }), "");
    EXPECT_NE(errorOf([&] { env.objectPose(2); }), "");
    EXPECT_NE(errorOf([&] { env.objectName(2); }), "");
    EXPECT_NE(errorOf([&] { env.shapeWorldPose(0, 1); }).find("table"), std::string::npos);
    Eigen::Isometry3d bad = Eigen::Isometry3d::Identity();
    bad.translation().x() = std::numeric_limits<double>::quiet_NaN();
    EXPECT_NE(errorOf([&] { env.setObjectPose("chair", bad); }).find("chair"), std::string::npos);
    // the failed move left the object where it was
    EXPECT_NEAR(env.spheres()[1].z, 3.0f, 1e-6);
    EXPECT_TRUE(env.objectPose(1).translation().isApprox(Eigen::Vector3d(0, 0, 3)));
}

TEST(EnvironmentTest, CopiesShareNamesAndShapesUntilOneAddsAnObject)
{
    Environment env;
    env.addBox("a", pose({0, 0, 0}), {1, 1, 1});
    env.addSphere("b", {2, 0, 0}, 0.5);
    env.addCylinder("c", pose({0, 2, 0}), 0.2, 1.0);
    Environment copy = env;
    copy.addCapsule("d", pose({0, 0, 3}), 0.1, 0.5);
    copy.setObjectPose("a", pose({1, 1, 1}));
    // the source keeps its three objects, names and poses
    EXPECT_EQ(env.objectCount(), 3u);
    EXPECT_FALSE(env.hasObject("d"));
    EXPECT_FALSE(env.nameInUse("d"));
    EXPECT_NE(errorOf([&] { env.objectId("d"); }).find("unknown object 'd'"), std::string::npos);
    EXPECT_TRUE(env.capsules().empty());
    EXPECT_TRUE(env.primitiveObjects(ropras::ompl_ext::ShapeType::Capsule).empty());
    EXPECT_EQ(env.primitiveCount(), 3u);
    EXPECT_TRUE(env.objectPose(0).isApprox(pose({0, 0, 0})));
    // the copy has four
    ASSERT_EQ(copy.objectCount(), 4u);
    EXPECT_EQ(copy.objectId("d"), 3);
    EXPECT_EQ(copy.objectName(3), "d");
    EXPECT_EQ(copy.primitiveObjects(ropras::ompl_ext::ShapeType::Capsule), std::vector<int>{3});
    EXPECT_EQ(copy.primitiveCount(), 4u);
    // a copy of the copy adds its own object: neither of the others sees it
    Environment third = copy;
    third.addSphere("e", {0, 0, -2}, 0.1);
    EXPECT_FALSE(copy.hasObject("e"));
    EXPECT_EQ(third.objectId("e"), 4);
    EXPECT_EQ(third.primitiveObjects(ropras::ompl_ext::ShapeType::Sphere), (std::vector<int>{1, 4}));
    EXPECT_EQ(copy.primitiveObjects(ropras::ompl_ext::ShapeType::Sphere), std::vector<int>{1});
    // clearing a copy leaves the others whole, and the cleared one can be refilled with the same names
    third.clear();
    EXPECT_EQ(third.objectCount(), 0u);
    EXPECT_EQ(third.primitiveCount(), 0u);
    EXPECT_TRUE(third.obstacleBoxChunks().empty());
    EXPECT_EQ(copy.objectId("d"), 3);
    EXPECT_EQ(third.addSphere("a", {0, 0, 0}, 0.1), 0);
    EXPECT_EQ(env.objectName(0), "a");
    EXPECT_EQ(env.objectShapes(0)[0].type, ropras::ompl_ext::ShapeType::Box);
    // the sole owner of its names adds in place; an Environment built the same way answers the same
    Environment direct;
    direct.addBox("a", pose({1, 1, 1}), {1, 1, 1});
    direct.addSphere("b", {2, 0, 0}, 0.5);
    direct.addCylinder("c", pose({0, 2, 0}), 0.2, 1.0);
    direct.addCapsule("d", pose({0, 0, 3}), 0.1, 0.5);
    std::mt19937 rng(8);
    std::uniform_real_distribution<double> u(-3.0, 4.0);
    for (int k = 0; k < 200; ++k)
    {
        const Eigen::Vector3d x(u(rng), u(rng), u(rng));
        EXPECT_DOUBLE_EQ(copy.signedDistance(x, 0.05), direct.signedDistance(x, 0.05));
    }
}

namespace
{
    /// every primitive's lane of Environment::obstacleBoxChunks() holds its box, lanes past the last are empty
    void expectBoxLanes(const Environment &e, const std::string &what)
    {
        using ropras::ompl_ext::OBSTACLE_BOX_LANES;
        using ropras::ompl_ext::ObstacleAabb;
        using ropras::ompl_ext::ShapeType;
        const std::size_t n = e.primitiveCount();
        if (n < static_cast<std::size_t>(OBSTACLE_BOX_LANES))
        {
            EXPECT_TRUE(e.obstacleBoxChunks().empty()) << what;
            return;
        }
        ASSERT_EQ(e.obstacleBoxChunks().size(), (n + OBSTACLE_BOX_LANES - 1) / OBSTACLE_BOX_LANES) << what;
        std::size_t perType[5] = {0, 0, 0, 0, 0};
        for (std::size_t k = 0; k < n; ++k)
        {
            const ropras::ompl_ext::PrimitiveRef &r = e.primitiveRef(k);
            // primitives are numbered in the order they were added, their slots per type likewise
            EXPECT_EQ(static_cast<std::size_t>(r.slot), perType[static_cast<std::size_t>(r.type)]++) << what << k;
            const auto i = static_cast<std::size_t>(r.slot);
            const ObstacleAabb &b = r.type == ShapeType::Sphere     ? e.spheres()[i].aabb
                                    : r.type == ShapeType::Box      ? e.boxes()[i].aabb
                                    : r.type == ShapeType::Cylinder ? e.cylinders()[i].aabb
                                    : r.type == ShapeType::Capsule  ? e.capsules()[i].aabb
                                                                    : e.clouds()[i].aabb;
            const auto &c = e.obstacleBoxChunks()[k / OBSTACLE_BOX_LANES];
            const std::size_t l = k % OBSTACLE_BOX_LANES;
            EXPECT_EQ(c.cx[l], b.cx) << what << k;
            EXPECT_EQ(c.cy[l], b.cy) << what << k;
            EXPECT_EQ(c.cz[l], b.cz) << what << k;
            EXPECT_EQ(c.ex[l], b.ex) << what << k;
            EXPECT_EQ(c.ey[l], b.ey) << what << k;
            EXPECT_EQ(c.ez[l], b.ez) << what << k;
        }
        for (std::size_t k = n; k % OBSTACLE_BOX_LANES != 0; ++k)
        {
            const auto &c = e.obstacleBoxChunks().back();
            const std::size_t l = k % OBSTACLE_BOX_LANES;
            EXPECT_EQ(c.ex[l], -std::numeric_limits<float>::infinity()) << what << k;
            EXPECT_EQ(c.ey[l], -std::numeric_limits<float>::infinity()) << what << k;
            EXPECT_EQ(c.ez[l], -std::numeric_limits<float>::infinity()) << what << k;
        }
    }
}  // namespace

TEST(EnvironmentTest, ObstacleBoxChunksHoldEveryPrimitiveBoxInOrder)
{
    using ropras::ompl_ext::ShapeType;
    std::mt19937 rng(12);
    std::uniform_real_distribution<double> u(-2.0, 2.0), s(0.05, 0.5);
    Environment env;
    // 19 primitives of every type (three chunks, the last partly empty), one object with several shapes
    for (int i = 0; i < 4; ++i)
    {
        env.addSphere("s" + std::to_string(i), {u(rng), u(rng), u(rng)}, s(rng));
        env.addBox("b" + std::to_string(i), pose({u(rng), u(rng), u(rng)}, randomRotation(rng)),
                   {s(rng), s(rng), s(rng)});
        env.addCylinder("y" + std::to_string(i), pose({u(rng), u(rng), u(rng)}, randomRotation(rng)), s(rng), s(rng));
        env.addCapsule("p" + std::to_string(i), pose({u(rng), u(rng), u(rng)}, randomRotation(rng)), s(rng), s(rng));
        expectBoxLanes(env, "while adding, primitive ");
    }
    env.addPointCloud("scan", PointCloud::build({{0, 0, 0}, {0.3f, 0.1f, 0}}, 0.02f), pose({1, 0, 0}));
    Shape offset = Shape::box({0.1, 0.2, 0.3});
    offset.pose = pose({0.5, 0, 0}, randomRotation(rng));
    env.addObject("pair", {Shape::sphere(0.1), offset}, pose({0, 1, 0}, randomRotation(rng)));
    env.setObjectPose("b2", pose({0.3, -0.2, 0.1}, randomRotation(rng)));
    env.setObjectPose("pair", pose({0.3, 0.2, 0.1}, randomRotation(rng)));
    ASSERT_EQ(env.primitiveCount(), 19u);
    expectBoxLanes(env, "mixed, primitive ");
    const Environment copy = env;
    expectBoxLanes(copy, "copy, primitive ");
    EXPECT_EQ(env.primitiveRef(16).type, ShapeType::PointCloud);
    EXPECT_EQ(env.primitiveRef(17).type, ShapeType::Sphere);
    EXPECT_EQ(env.primitiveRef(18).type, ShapeType::Box);
    // objects whose shapes straddle the first chunk (7 -> 10 primitives) and a later one (15 -> 18)
    for (int before : {7, 15})
    {
        Environment e;
        for (int i = 0; i < before; ++i)
            e.addSphere("s" + std::to_string(i), {u(rng), u(rng), u(rng)}, s(rng));
        expectBoxLanes(e, "spheres only, primitive ");
        e.addObject("three", {Shape::sphere(0.1), offset, Shape::capsule(0.1, 0.2)}, pose({0, 0, 1}));
        expectBoxLanes(e, "straddling " + std::to_string(before) + ", primitive ");
        e.setObjectPose("three", pose({1, 0, 1}, randomRotation(rng)));
        expectBoxLanes(e, "moved, straddling " + std::to_string(before) + ", primitive ");
    }
}
