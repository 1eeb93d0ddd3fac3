// Environment queries (firstHit, objectDistances, nearestObject, objectsWithin) cross-checked on random scenes
// of each shape type: segments against Bullet's btCollisionWorld::rayTest and against sphere tracing of the
// double-precision Environment::signedDistance; distances against fcl::distance (and a brute force over the
// points for clouds). Plus the edge cases and the argument errors.
#include <BulletCollision/NarrowPhaseCollision/btRaycastCallback.h>
#include <btBulletCollisionCommon.h>
#include <gtest/gtest.h>

#include <fcl/narrowphase/distance.h>
#include <algorithm>
#include <cmath>
#include <cstring>
#include <iostream>
#include <limits>
#include <memory>
#include <random>
#include <vector>

#include "ExpectError.h"
#include "ropras/ompl_ext/scene/EnvironmentQueries.h"

namespace ropras::ompl_ext
{
    namespace
    {
        Eigen::Isometry3d pose(const Eigen::Vector3d &t, const Eigen::Quaterniond &q = Eigen::Quaterniond::Identity())
        {
            Eigen::Isometry3d p = Eigen::Isometry3d::Identity();
            p.linear() = q.toRotationMatrix();
            p.translation() = t;
            return p;
        }

        struct Random
        {
            std::mt19937_64 rng;
            explicit Random(std::uint64_t seed) : rng(seed) {}
            double uniform(double lo, double hi) { return std::uniform_real_distribution<double>(lo, hi)(rng); }
            Eigen::Vector3d point(double half)
            {
                return {uniform(-half, half), uniform(-half, half), uniform(-half, half)};
            }
            Eigen::Quaterniond turn()
            {
                std::normal_distribution<double> n(0.0, 1.0);
                return Eigen::Quaterniond(n(rng), n(rng), n(rng), n(rng)).normalized();
            }
        };

        /// \a count random objects of \a type in [-1, 1]^3 (a cloud: 300 points in a 0.3 m cube, radius 0.02)
        Environment randomScene(ShapeType type, int count, std::uint64_t seed)
        {
            Random r(seed);
            Environment env;
            for (int i = 0; i < count; ++i)
            {
                const std::string name = "object" + std::to_string(i);
                const Eigen::Isometry3d p = pose(r.point(1.0), r.turn());
                switch (type)
                {
                    case ShapeType::Sphere:
                        env.addSphere(name, p.translation(), r.uniform(0.03, 0.3));
                        break;
                    case ShapeType::Box:
                        env.addBox(name, p, {r.uniform(0.05, 0.5), r.uniform(0.05, 0.5), r.uniform(0.05, 0.5)});
                        break;
                    case ShapeType::Cylinder:
                        env.addCylinder(name, p, r.uniform(0.03, 0.25), r.uniform(0.05, 0.5));
                        break;
                    case ShapeType::Capsule:
                        env.addCapsule(name, p, r.uniform(0.03, 0.25), i % 5 == 0 ? 0.0 : r.uniform(0.05, 0.5));
                        break;
                    case ShapeType::PointCloud:
                    {
                        std::vector<Eigen::Vector3f> points;
                        for (int k = 0; k < 300; ++k)
                            points.push_back(r.point(0.15).cast<float>());
                        env.addPointCloud(name, PointCloud::build(points, 0.02f), p);
                        break;
                    }
                }
            }
            return env;
        }

        /// the Environment rebuilt as a Bullet collision world (zero margins on boxes and cylinders, so that
        /// their corners are sharp); each collision object's user index is the Environment object id
        class BulletScene
        {
        public:
            explicit BulletScene(const Environment &env)
                : dispatcher_(&configuration_), world_(&dispatcher_, &broadphase_, &configuration_)
            {
                for (std::size_t id = 0; id < env.objectCount(); ++id)
                {
                    const auto &shapes = env.objectShapes(static_cast<int>(id));
                    for (std::size_t k = 0; k < shapes.size(); ++k)
                    {
                        const Shape &s = shapes[k];
                        const Eigen::Isometry3d world = env.shapeWorldPose(static_cast<int>(id), k);
                        switch (s.type)
                        {
                            case ShapeType::Sphere:
                                add(std::make_unique<btSphereShape>(btScalar(s.radius)), world, id);
                                break;
                            case ShapeType::Box:
                                add(std::make_unique<btBoxShape>(vec(0.5 * s.extents)), world, id, true);
                                break;
                            case ShapeType::Cylinder:
                                add(std::make_unique<btCylinderShapeZ>(vec({s.radius, s.radius, 0.5 * s.length})),
                                    world, id, true);
                                break;
                            case ShapeType::Capsule:
                                add(std::make_unique<btCapsuleShapeZ>(btScalar(s.radius), btScalar(s.length)), world,
                                    id);
                                break;
                            case ShapeType::PointCloud:
                                for (const Eigen::Vector3f &p : s.cloud->points())
                                    add(std::make_unique<btSphereShape>(btScalar(s.cloud->pointRadius())),
                                        pose(world * p.cast<double>()), id);
                                break;
                        }
                    }
                }
                world_.updateAabbs();
            }
            BulletScene(const BulletScene &) = delete;
            BulletScene &operator=(const BulletScene &) = delete;
            ~BulletScene()
            {
                for (auto &object : objects_)
                    world_.removeCollisionObject(object.get());
            }

            struct Ray
            {
                bool hit{false};
                double fraction{1.0};
                int object{-1};
            };
            Ray ray(const Eigen::Vector3d &a, const Eigen::Vector3d &b) const
            {
                btCollisionWorld::ClosestRayResultCallback callback(vec(a), vec(b));
                // GJK ray cast: Bullet's default (sub-simplex) cast is approximate, off by millimetres
                callback.m_flags |= btTriangleRaycastCallback::kF_UseGjkConvexCastRaytest;
                world_.rayTest(vec(a), vec(b), callback);
                Ray r;
                if (callback.hasHit())
                {
                    r.hit = true;
                    r.fraction = callback.m_closestHitFraction;
                    r.object = callback.m_collisionObject->getUserIndex();
                }
                return r;
            }

        private:
            static btVector3 vec(const Eigen::Vector3d &v)
            {
                return {btScalar(v.x()), btScalar(v.y()), btScalar(v.z())};
            }
            void add(std::unique_ptr<btCollisionShape> shape, const Eigen::Isometry3d &world, std::size_t id,
                     bool sharp = false)
            {
                if (sharp)
                    shape->setMargin(btScalar(1e-3));
                auto object = std::make_unique<btCollisionObject>();
                const Eigen::Matrix3d r = world.linear();
                btTransform t;
                t.setBasis(btMatrix3x3(btScalar(r(0, 0)), btScalar(r(0, 1)), btScalar(r(0, 2)), btScalar(r(1, 0)),
                                       btScalar(r(1, 1)), btScalar(r(1, 2)), btScalar(r(2, 0)), btScalar(r(2, 1)),
                                       btScalar(r(2, 2))));
                t.setOrigin(vec(world.translation()));
                object->setWorldTransform(t);
                object->setCollisionShape(shape.get());
                object->setUserIndex(static_cast<int>(id));
                world_.addCollisionObject(object.get());
                shapes_.push_back(std::move(shape));
                objects_.push_back(std::move(object));
            }

            btDefaultCollisionConfiguration configuration_;
            btCollisionDispatcher dispatcher_;
            btDbvtBroadphase broadphase_;
            mutable btCollisionWorld world_;
            std::vector<std::unique_ptr<btCollisionShape>> shapes_;
            std::vector<std::unique_ptr<btCollisionObject>> objects_;
        };

        /// sphere tracing of Environment::signedDistance (double, authoring form): the first point of a -> b
        /// within \a eps of an obstacle (fraction), or -1; \a closest gets the smallest distance seen
        double traceFirst(const Environment &env, const Eigen::Vector3d &a, const Eigen::Vector3d &b, double eps,
                          double &closest)
        {
            const double length = (b - a).norm();
            closest = std::numeric_limits<double>::infinity();
            for (double s = 0.0;;)
            {
                const double sd = env.signedDistance(a + (s / length) * (b - a), 0.0);
                closest = std::min(closest, sd);
                if (sd <= eps)
                    return s / length;
                if (s >= length)
                    return -1.0;
                s = std::min(length, s + std::max(sd, eps));
            }
        }

        const ShapeType ALL_TYPES[] = {ShapeType::Sphere, ShapeType::Box, ShapeType::Cylinder, ShapeType::Capsule,
                                       ShapeType::PointCloud};
    }  // namespace

    double percentile(std::vector<double> v, double p)
    {
        if (v.empty())
            return 0.0;
        std::sort(v.begin(), v.end());
        return v[std::min(v.size() - 1, std::size_t(p * double(v.size())))];
    }

    // Tolerances, stated. Against sphere tracing of the double-precision signed distance: 1e-5 m along the
    // segment (float primitives; the trace stops within 1e-7), and no hit/miss disagreement unless the segment
    // grazes a surface within 1e-5. Against Bullet (float; its GJK ray cast stops within 1e-3 m of a
    // surface, so its hit point may sit up to 1e-3 m before the surface and a segment passing within 1e-3 m
    // may count as a hit; along a slanted segment that is several millimetres): Bullet's hit point lies within
    // 1.5e-3 m of the surface, at least 90 % of the hits agree within 2e-3 m along the segment, and a hit/miss
    // disagreement only for a segment passing within 2e-3 m of a surface. Bullet's cylinder cast is coarser
    // (its hit point up to 6 cm inside the cylinder): 1e-1 m, 60 % and 1e-2 m for cylinders.
    TEST(EnvironmentQueries, SegmentsAgreeWithSphereTracingAndBullet)
    {
        constexpr int SEGMENTS = 2000;
        for (ShapeType type : ALL_TYPES)
        {
            const bool cylinder = type == ShapeType::Cylinder;
            const Environment env = randomScene(type, 16, 100 + static_cast<int>(type));
            const BulletScene bullet(env);
            Random r(7 + static_cast<int>(type));
            int hits = 0, traceGrazing = 0, bulletGrazing = 0, compared = 0;
            double worstTrace = 0.0, worstOff = 0.0;
            std::vector<double> bulletErrors;
            for (int i = 0; i < SEGMENTS; ++i)
            {
                Eigen::Vector3d a = r.point(1.5), b = r.point(1.5);
                if (i % 4 == 0)  // short segments too
                    b = a + 0.2 * r.point(1.0);
                if (env.signedDistance(a, 0.0) < 1e-3)  // Bullet reports nothing from inside: separate test
                    continue;
                ++compared;
                const SegmentHit hit = firstHit(env, a, b);
                const double length = (b - a).norm();
                double closest = 0.0;
                const double traced = traceFirst(env, a, b, 1e-7, closest);
                if (hit.hit != (traced >= 0.0))
                {
                    EXPECT_LT(std::abs(closest), 1e-5) << shapeTypeName(type) << " segment " << i << ": ours "
                                                       << hit.hit << ", trace closest approach " << closest;
                    ++traceGrazing;
                }
                else if (hit.hit)
                {
                    ++hits;
                    const double error = std::abs(hit.fraction - traced) * length;
                    worstTrace = std::max(worstTrace, error);
                    EXPECT_LT(error, 1e-5) << shapeTypeName(type) << " segment " << i;
                    EXPECT_EQ(hit.name, env.objectName(hit.object));
                    EXPECT_NEAR((hit.point - (a + hit.fraction * (b - a))).norm(), 0.0, 1e-12);
                    EXPECT_NEAR(hit.distance, hit.fraction * length, 1e-12);
                    // the reported object is the one touched there
                    EXPECT_LT(std::abs(env.objectSignedDistance(hit.object, hit.point, 0.0)), 1e-5);
                }
                const BulletScene::Ray ray = bullet.ray(a, b);
                if (ray.hit != hit.hit)
                {
                    EXPECT_LT(std::abs(closest), cylinder ? 1e-2 : 2e-3)
                        << shapeTypeName(type) << " segment " << i << ": ours " << hit.hit << ", Bullet " << ray.hit;
                    ++bulletGrazing;
                }
                else if (hit.hit)
                {
                    bulletErrors.push_back(std::abs(hit.fraction - ray.fraction) * length);
                    const double off = env.signedDistance(a + ray.fraction * (b - a), 0.0);
                    worstOff = std::max(worstOff, std::abs(off));
                    EXPECT_LT(std::abs(off), cylinder ? 0.1 : 1.5e-3) << shapeTypeName(type) << " segment " << i;
                }
            }
            const auto within =
                std::count_if(bulletErrors.begin(), bulletErrors.end(), [](double e) { return e < 2e-3; });
            std::cout << shapeTypeName(type) << ": " << compared << " segments, " << hits
                      << " hits; worst |ours - trace| " << worstTrace << " m; |ours - Bullet| median "
                      << percentile(bulletErrors, 0.5) << " m, 95 % " << percentile(bulletErrors, 0.95) << " m, "
                      << within << " of " << bulletErrors.size() << " within 2e-3 m, Bullet's hit point at most "
                      << worstOff << " m off the surface; hit/miss disagreements " << traceGrazing << " (trace), "
                      << bulletGrazing << " (Bullet, grazing)\n";
            EXPECT_GT(hits, compared / 20) << shapeTypeName(type) << ": too few hits to test anything";
            EXPECT_EQ(traceGrazing, 0) << shapeTypeName(type);
            EXPECT_LE(bulletGrazing, compared / 100) << shapeTypeName(type);
            EXPECT_GE(double(within), (cylinder ? 0.6 : 0.9) * double(bulletErrors.size())) << shapeTypeName(type);
        }
    }

    TEST(EnvironmentQueries, MixedSceneMatchesTheNearestPerTypeHit)
    {
        Environment env;
        for (ShapeType type : ALL_TYPES)
        {
            const Environment part = randomScene(type, 5, 300 + static_cast<int>(type));
            for (std::size_t id = 0; id < part.objectCount(); ++id)
                env.addObject(std::string(shapeTypeName(type)) + std::to_string(id), part.objectShapes(int(id)),
                              part.objectPose(int(id)));
        }
        const BulletScene bullet(env);
        Random r(11);
        int agree = 0, compared = 0;
        for (int i = 0; i < 2000; ++i)
        {
            const Eigen::Vector3d a = r.point(1.5), b = r.point(1.5);
            if (env.signedDistance(a, 0.0) < 1e-3)
                continue;
            ++compared;
            const SegmentHit hit = firstHit(env, a, b);
            const BulletScene::Ray ray = bullet.ray(a, b);
            if (hit.hit == ray.hit && (!hit.hit || hit.object == ray.object))
                ++agree;
            if (hit.hit)
            {
                EXPECT_EQ(env.objectName(hit.object).substr(0, std::strlen(shapeTypeName(hit.type))),
                          shapeTypeName(hit.type));
            }
        }
        std::cout << "mixed scene: " << agree << " of " << compared << " segments agree with Bullet on the object\n";
        EXPECT_GE(agree, compared * 99 / 100);
    }

    TEST(EnvironmentQueries, SegmentStartingInsideHitsAtZero)
    {
        for (ShapeType type : ALL_TYPES)
        {
            const Environment env = randomScene(type, 12, 500 + static_cast<int>(type));
            Random r(3);
            int inside = 0;
            for (int i = 0; i < 4000 && inside < 100; ++i)
            {
                const Eigen::Vector3d a = r.point(1.2), b = r.point(1.5);
                if (env.signedDistance(a, 0.0) > -1e-4)
                    continue;
                ++inside;
                const SegmentHit hit = firstHit(env, a, b);
                ASSERT_TRUE(hit.hit) << shapeTypeName(type);
                EXPECT_EQ(hit.fraction, 0.0);
                EXPECT_EQ(hit.distance, 0.0);
                EXPECT_EQ(hit.point, a);
                EXPECT_LT(env.objectSignedDistance(hit.object, a, 0.0), 0.0) << shapeTypeName(type);
            }
            EXPECT_GE(inside, 20) << shapeTypeName(type);
        }
    }

    TEST(EnvironmentQueries, TangentRotatedDegenerateAndEmpty)
    {
        Environment env;
        env.addSphere("ball", {0, 0, 0}, 1.0);
        // tangent: touches (0, 1, 0) half way
        SegmentHit hit = firstHit(env, {-2, 1, 0}, {2, 1, 0});
        ASSERT_TRUE(hit.hit);
        EXPECT_DOUBLE_EQ(hit.fraction, 0.5);
        EXPECT_EQ(hit.object, 0);
        EXPECT_EQ(hit.name, "ball");
        EXPECT_EQ(hit.type, ShapeType::Sphere);
        EXPECT_FALSE(firstHit(env, {-2, 1.0001, 0}, {2, 1.0001, 0}).hit);
        // stops short / ends exactly on the surface
        EXPECT_FALSE(firstHit(env, {-3, 0, 0}, {-1.001, 0, 0}).hit);
        hit = firstHit(env, {-3, 0, 0}, {-1, 0, 0});
        ASSERT_TRUE(hit.hit);
        EXPECT_DOUBLE_EQ(hit.fraction, 1.0);

        // a box turned 45 degrees about z: its edge is at x = -h sqrt(2)
        Environment turned;
        turned.addBox("diamond",
                      pose({0, 0, 0}, Eigen::Quaterniond(Eigen::AngleAxisd(M_PI / 4, Eigen::Vector3d::UnitZ()))),
                      {1.0, 1.0, 1.0});
        hit = firstHit(turned, {-2, 0, 0}, {2, 0, 0});
        ASSERT_TRUE(hit.hit);
        EXPECT_NEAR(hit.point.x(), -std::sqrt(0.5), 1e-6);
        // grazing the top face (z = 0.5) counts: the box is closed
        hit = firstHit(turned, {-2, 0, 0.5}, {2, 0, 0.5});
        ASSERT_TRUE(hit.hit);
        EXPECT_NEAR(hit.point.x(), -std::sqrt(0.5), 1e-6);
        EXPECT_FALSE(firstHit(turned, {-2, 0, 0.5001}, {2, 0, 0.5001}).hit);

        // a zero-length capsule is a sphere; a capsule along z is hit on its cap, its side, or not at all
        Environment capsules;
        capsules.addCapsule("dot", pose({0, 0, 0}), 0.5, 0.0);
        capsules.addCapsule("rod", pose({3, 0, 0}), 0.25, 1.0);
        hit = firstHit(capsules, {0, 0, 2}, {0, 0, -2});
        ASSERT_TRUE(hit.hit);
        EXPECT_EQ(hit.name, "dot");
        EXPECT_NEAR(hit.point.z(), 0.5, 1e-7);
        hit = firstHit(capsules, {3, 0, 2}, {3, 0, -2});
        ASSERT_TRUE(hit.hit);
        EXPECT_EQ(hit.name, "rod");
        EXPECT_NEAR(hit.point.z(), 0.75, 1e-7);
        hit = firstHit(capsules, {2, 0, 0.3}, {4, 0, 0.3});
        ASSERT_TRUE(hit.hit);
        EXPECT_NEAR(hit.point.x(), 2.75, 1e-7);
        EXPECT_FALSE(firstHit(capsules, {2, 0, 0.8}, {4, 0, 0.8}).hit);  // beside the cap sphere: 0.3^2+... miss

        // a segment along a cylinder's axis enters through the end disc
        Environment can;
        can.addCylinder("can", pose({0, 0, 0}), 0.2, 1.0);
        hit = firstHit(can, {0.1, 0, 3}, {0.1, 0, -3});
        ASSERT_TRUE(hit.hit);
        EXPECT_NEAR(hit.point.z(), 0.5, 1e-7);
        EXPECT_FALSE(firstHit(can, {0.21, 0, 3}, {0.21, 0, -3}).hit);

        // one object of two primitives: the hit names the object
        Environment table;
        table.addSphere("ball", {5, 5, 5}, 0.1);
        table.addObject("table",
                        {Shape::box({1, 1, 0.05}, pose({0, 0, 0.5})), Shape::cylinder(0.05, 0.5, pose({0, 0, 0.25}))});
        hit = firstHit(table, {0, 0, 2}, {0, 0, -1});
        ASSERT_TRUE(hit.hit);
        EXPECT_EQ(hit.object, 1);
        EXPECT_EQ(hit.name, "table");
        EXPECT_EQ(hit.type, ShapeType::Box);
        EXPECT_NEAR(hit.point.z(), 0.525, 1e-6);
        hit = firstHit(table, {0, 0, 0.4}, {0, 0, -1});
        ASSERT_TRUE(hit.hit);
        EXPECT_EQ(hit.type, ShapeType::Cylinder);
        EXPECT_EQ(hit.name, "table");

        const Environment empty;
        EXPECT_FALSE(firstHit(empty, {0, 0, 0}, {1, 1, 1}).hit);
        EXPECT_EQ(firstHit(empty, {0, 0, 0}, {1, 1, 1}).object, -1);
        Environment emptyCloud;
        emptyCloud.addPointCloud("nothing", PointCloud::build({}, 0.1f));
        EXPECT_FALSE(firstHit(emptyCloud, {0, 0, 0}, {1, 1, 1}).hit);
        EXPECT_EQ(nearestObject(empty, {0, 0, 0}).object, -1);
        EXPECT_TRUE(std::isinf(nearestObject(empty, {0, 0, 0}).distance));
    }

    TEST(EnvironmentQueries, BadArgumentsNameTheValue)
    {
        Environment env;
        env.addSphere("ball", {0, 0, 0}, 1.0);
        const double nan = std::numeric_limits<double>::quiet_NaN();
        ropras::test::expectErrorMentions([&] { firstHit(env, {1, 2, 3}, {1, 2, 3}); }, {"firstHit", "length 0"});
        ropras::test::expectErrorMentions(
            [&] {
                firstHit(env, {nan, 0, 0}, {1, 2, 3});
            },
            {"firstHit", "non-finite", "nan"});
        ropras::test::expectErrorMentions([&] { firstHit(env, {0, 0, 0}, {1, HUGE_VAL, 3}); }, {"firstHit", "inf"});
        std::vector<ObjectDistance> distances;
        ropras::test::expectErrorMentions(
            [&] {
                objectDistances(env, {0, nan, 0}, 0.0, distances);
            },
            {"objectDistances", "nan"});
        ropras::test::expectErrorMentions(
            [&] {
                objectDistances(env, {0, 0, 0}, -0.5, distances);
            },
            {"objectDistances", "radius", "-0.5"});
        std::vector<int> ids;
        ropras::test::expectErrorMentions(
            [&] {
                objectsWithin(env, {0, 0, 0}, 0.0, -1.0, ids);
            },
            {"objectsWithin", "distance", "-1"});
        ropras::test::expectErrorMentions(
            [&] {
                objectsWithin(env, {0, 0, 0}, 0.0, nan, ids);
            },
            {"objectsWithin", "nan"});
        ropras::test::expectErrorMentions([&] { nearestObject(env, {0, 0, nan}, 0.1); }, {"nearestObject", "nan"});
    }

    // Tolerance 1e-5 m against FCL (float primitives; FCL's analytic sphere-primitive distances in double).
    TEST(EnvironmentQueries, DistancesAgreeWithFclAndBruteForce)
    {
        for (ShapeType type : ALL_TYPES)
        {
            const Environment env = randomScene(type, 10, 700 + static_cast<int>(type));
            // FCL objects per primitive, labelled by object id
            std::vector<std::pair<std::unique_ptr<fcl::CollisionObjectd>, int>> fclObjects;
            for (std::size_t id = 0; id < env.objectCount(); ++id)
            {
                const auto &shapes = env.objectShapes(int(id));
                for (std::size_t k = 0; k < shapes.size(); ++k)
                {
                    const Shape &s = shapes[k];
                    std::shared_ptr<fcl::CollisionGeometryd> g;
                    if (s.type == ShapeType::Sphere)
                        g = std::make_shared<fcl::Sphered>(s.radius);
                    else if (s.type == ShapeType::Box)
                        g = std::make_shared<fcl::Boxd>(s.extents);
                    else if (s.type == ShapeType::Cylinder)
                        g = std::make_shared<fcl::Cylinderd>(s.radius, s.length);
                    else if (s.type == ShapeType::Capsule)
                        g = std::make_shared<fcl::Capsuled>(s.radius, s.length);
                    if (g)
                        fclObjects.emplace_back(
                            std::make_unique<fcl::CollisionObjectd>(g, env.shapeWorldPose(int(id), k)), int(id));
                }
            }
            Random r(9);
            std::vector<ObjectDistance> distances;
            std::vector<int> within;
            double worst = 0.0;
            int compared = 0;
            for (int i = 0; i < 1000; ++i)
            {
                const Eigen::Vector3d c = r.point(1.5);
                const double radius = i % 3 == 0 ? 0.0 : r.uniform(0.01, 0.3);
                objectDistances(env, c, radius, distances);
                ASSERT_EQ(distances.size(), env.objectCount());
                std::vector<double> reference(env.objectCount(), std::numeric_limits<double>::infinity());
                if (type == ShapeType::PointCloud)
                {
                    for (std::size_t id = 0; id < env.objectCount(); ++id)
                    {
                        const Shape &s = env.objectShapes(int(id))[0];
                        const Eigen::Isometry3d world = env.shapeWorldPose(int(id), 0);
                        for (const Eigen::Vector3f &p : s.cloud->points())
                            reference[id] = std::min(reference[id], (world * p.cast<double>() - c).norm() -
                                                                        double(s.cloud->pointRadius()) - radius);
                    }
                }
                else
                {
                    const auto query = std::make_shared<fcl::Sphered>(std::max(radius, 1e-9));
                    const fcl::CollisionObjectd sphere(query, pose(c));
                    for (const auto &[object, id] : fclObjects)
                    {
                        fcl::DistanceRequestd request;
                        fcl::DistanceResultd result;
                        const double d = fcl::distance(&sphere, object.get(), request, result);
                        if (d > 0.0)  // FCL reports -1 when overlapping: only separated pairs are compared
                            reference[std::size_t(id)] =
                                std::min(reference[std::size_t(id)], d - (radius == 0.0 ? 1e-9 : 0.0));
                        else
                            reference[std::size_t(id)] = std::nan("");
                    }
                }
                for (std::size_t id = 0; id < env.objectCount(); ++id)
                {
                    EXPECT_EQ(distances[id].object, int(id));
                    EXPECT_EQ(distances[id].name, env.objectName(int(id)));
                    if (std::isnan(reference[id]))
                    {
                        EXPECT_LT(distances[id].distance, 1e-5) << shapeTypeName(type);
                        continue;
                    }
                    ++compared;
                    const double error = std::abs(distances[id].distance - reference[id]);
                    worst = std::max(worst, error);
                    EXPECT_LT(error, 1e-5) << shapeTypeName(type) << " query " << i << " object " << id;
                }
                // nearestObject is the minimum; objectsWithin is the filter
                const auto best =
                    std::min_element(distances.begin(), distances.end(),
                                     [](const auto &x, const auto &y) { return x.distance < y.distance; });
                const ObjectDistance nearest = nearestObject(env, c, radius);
                EXPECT_EQ(nearest.object, best->object);
                EXPECT_EQ(nearest.distance, best->distance);
                const double limit = r.uniform(0.0, 0.5);
                objectsWithin(env, c, radius, limit, within);
                std::vector<int> expected;
                for (const ObjectDistance &d : distances)
                    if (d.distance <= limit)
                        expected.push_back(d.object);
                EXPECT_EQ(within, expected) << shapeTypeName(type) << " query " << i;
            }
            std::cout << shapeTypeName(type) << ": " << compared << " separated sphere-object pairs, worst |ours - "
                      << (type == ShapeType::PointCloud ? "brute force" : "FCL") << "| " << worst << " m\n";
            EXPECT_GT(compared, 5000);
        }
    }

    TEST(EnvironmentQueries, PenetrationIsNegative)
    {
        Environment env;
        env.addSphere("ball", {1, 0, 0}, 0.5);
        env.addBox("crate", pose({-1, 0, 0}), {1, 1, 1});
        std::vector<ObjectDistance> d;
        objectDistances(env, {1.2, 0, 0}, 0.1, d);
        EXPECT_NEAR(d[0].distance, -0.4, 1e-12);  // 0.2 from the centre: 0.3 inside, plus the radius
        EXPECT_NEAR(d[1].distance, 1.6, 1e-12);
        std::vector<int> ids;
        objectsWithin(env, {1.2, 0, 0}, 0.1, 0.0, ids);
        EXPECT_EQ(ids, std::vector<int>{0});
        objectsWithin(env, {0, 0, 0}, 0.0, 0.5, ids);
        EXPECT_EQ(ids, (std::vector<int>{0, 1}));
    }
}  // namespace ropras::ompl_ext
