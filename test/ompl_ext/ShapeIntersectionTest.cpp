// shapesIntersect (FCL's narrow phase) cross-checked on random pairs: spheres against the closed form, every other
// pair of sphere, box, cylinder and capsule against Bullet's contactPairTest; pairs within 1 mm of contact (as
// Bullet measures them) are left out, the two libraries may call those either way. Plus the argument errors.
#include <btBulletCollisionCommon.h>
#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <memory>
#include <random>

#include "ExpectError.h"
#include "ropras/ompl_ext/scene/ShapeIntersection.h"

namespace ropras::ompl_ext
{
    namespace
    {
        constexpr double NEAR = 1e-3;  ///< pairs closer than this to contact are not compared

        struct Random
        {
            std::mt19937_64 rng;
            explicit Random(std::uint64_t seed) : rng(seed) {}
            double uniform(double lo, double hi) { return std::uniform_real_distribution<double>(lo, hi)(rng); }
            Eigen::Isometry3d pose(double half)
            {
                Eigen::Isometry3d p = Eigen::Isometry3d::Identity();
                p.translation() = Eigen::Vector3d(uniform(-half, half), uniform(-half, half), uniform(-half, half));
                Eigen::Quaterniond q(uniform(-1, 1), uniform(-1, 1), uniform(-1, 1), uniform(-1, 1));
                p.linear() = q.normalized().toRotationMatrix();
                return p;
            }
            Shape shape(int type)
            {
                switch (type)
                {
                    case 0:
                        return Shape::sphere(uniform(0.05, 0.3));
                    case 1:
                        return Shape::box(Eigen::Vector3d(uniform(0.05, 0.6), uniform(0.05, 0.6), uniform(0.05, 0.6)));
                    case 2:
                        return Shape::cylinder(uniform(0.05, 0.3), uniform(0.1, 0.6));
                    default:
                        return Shape::capsule(uniform(0.05, 0.3), uniform(0.1, 0.6));
                }
            }
        };

        /// Bullet's shape for \a s (no collision margin beyond the shape), owned by the caller
        std::unique_ptr<btCollisionShape> bulletShape(const Shape &s)
        {
            std::unique_ptr<btCollisionShape> out;
            switch (s.type)
            {
                case ShapeType::Sphere:
                    out = std::make_unique<btSphereShape>(s.radius);
                    break;
                case ShapeType::Box:
                    out = std::make_unique<btBoxShape>(btVector3(s.extents.x(), s.extents.y(), s.extents.z()) * 0.5);
                    break;
                case ShapeType::Cylinder:  // along local z, as ropras and FCL
                    out = std::make_unique<btCylinderShapeZ>(btVector3(s.radius, s.radius, 0.5 * s.length));
                    break;
                default:
                    out = std::make_unique<btCapsuleShapeZ>(s.radius, s.length);
                    break;
            }
            // Bullet rounds the edges of a convex shape by its collision margin (4 cm by default): none here, so that
            // its boxes and cylinders have the sharp edges of ropras' and FCL's
            if (s.type == ShapeType::Box || s.type == ShapeType::Cylinder)
                out->setMargin(0);
            return out;
        }

        btTransform bulletPose(const Eigen::Isometry3d &p)
        {
            const Eigen::Matrix3d &r = p.linear();
            const btMatrix3x3 basis(r(0, 0), r(0, 1), r(0, 2), r(1, 0), r(1, 1), r(1, 2), r(2, 0), r(2, 1), r(2, 2));
            return btTransform(basis, btVector3(p.translation().x(), p.translation().y(), p.translation().z()));
        }

        /// Bullet's verdict: 1 overlapping, 0 apart, -1 within NEAR of contact (not compared)
        int bulletVerdict(btCollisionWorld &world, const Shape &a, const Eigen::Isometry3d &pa, const Shape &b,
                          const Eigen::Isometry3d &pb)
        {
            auto sa = bulletShape(a), sb = bulletShape(b);
            btCollisionObject oa, ob;
            oa.setCollisionShape(sa.get());
            ob.setCollisionShape(sb.get());
            oa.setWorldTransform(bulletPose(pa));
            ob.setWorldTransform(bulletPose(pb));
            struct Closest : btCollisionWorld::ContactResultCallback
            {
                double distance = std::numeric_limits<double>::infinity();
                btScalar addSingleResult(btManifoldPoint &cp, const btCollisionObjectWrapper *, int, int,
                                         const btCollisionObjectWrapper *, int, int) override
                {
                    distance = std::min(distance, static_cast<double>(cp.getDistance()));
                    return 0;
                }
            } closest;
            closest.m_closestDistanceThreshold = static_cast<btScalar>(NEAR);
            world.contactPairTest(&oa, &ob, closest);
            if (std::abs(closest.distance) < NEAR)
                return -1;
            return closest.distance < 0.0 ? 1 : 0;
        }
    }  // namespace

    TEST(ShapeIntersection, SpheresMatchTheClosedForm)
    {
        Random random(11);
        int compared = 0, overlapping = 0;
        for (int i = 0; i < 2000; ++i)
        {
            const Shape a = random.shape(0), b = random.shape(0);
            const Eigen::Isometry3d pa = random.pose(0.4), pb = random.pose(0.4);
            const double gap = (pa.translation() - pb.translation()).norm() - a.radius - b.radius;
            if (std::abs(gap) < 1e-9)
                continue;
            ++compared;
            overlapping += gap < 0.0;
            EXPECT_EQ(shapesIntersect(a, pa, b, pb), gap < 0.0) << "pair " << i << ", gap " << gap;
        }
        EXPECT_GT(compared, 1900);
        EXPECT_GT(overlapping, 200);  // both verdicts are exercised
        EXPECT_LT(overlapping, compared - 200);
    }

    TEST(ShapeIntersection, EveryPrimitivePairAgreesWithBullet)
    {
        btDefaultCollisionConfiguration configuration;
        btCollisionDispatcher dispatcher(&configuration);
        btDbvtBroadphase broadphase;
        btCollisionWorld world(&dispatcher, &broadphase, &configuration);
        Random random(23);
        for (int ta = 0; ta < 4; ++ta)
            for (int tb = ta; tb < 4; ++tb)
            {
                int compared = 0, overlapping = 0;
                for (int i = 0; i < 400; ++i)
                {
                    const Shape a = random.shape(ta), b = random.shape(tb);
                    const Eigen::Isometry3d pa = random.pose(0.5), pb = random.pose(0.5);
                    const int bullet = bulletVerdict(world, a, pa, b, pb);
                    if (bullet < 0)
                        continue;
                    ++compared;
                    overlapping += bullet;
                    EXPECT_EQ(shapesIntersect(a, pa, b, pb), bullet == 1)
                        << shapeTypeName(a.type) << " / " << shapeTypeName(b.type) << ", pair " << i;
                }
                EXPECT_GT(compared, 350) << ta << " / " << tb;
                EXPECT_GT(overlapping, 40) << ta << " / " << tb;
                EXPECT_LT(overlapping, compared - 40) << ta << " / " << tb;
            }
    }

    TEST(ShapeIntersection, ShapePosesComposeWithThePlacement)
    {
        // a box offset 1 m along x in its own frame, placed at the origin: it overlaps a sphere at x = 1 only
        const Shape box = Shape::box(Eigen::Vector3d(0.2, 0.2, 0.2), Eigen::Isometry3d(Eigen::Translation3d(1, 0, 0)));
        const Shape sphere = Shape::sphere(0.05);
        const Eigen::Isometry3d origin = Eigen::Isometry3d::Identity();
        EXPECT_TRUE(shapesIntersect(box, origin, sphere, Eigen::Isometry3d(Eigen::Translation3d(1, 0, 0))));
        EXPECT_FALSE(shapesIntersect(box, origin, sphere, origin));
    }

    TEST(ShapeIntersection, BadArgumentsNameTheProblem)
    {
        const Shape box = Shape::box(Eigen::Vector3d(0.1, 0.1, 0.1));
        const Eigen::Isometry3d origin = Eigen::Isometry3d::Identity();
        Shape negative = Shape::sphere(0.1);
        negative.radius = -1.0;
        ropras::test::expectErrorMentions([&] { shapesIntersect(negative, origin, box, origin); },
                                          {"shapesIntersect", "shape a (sphere): a size is negative", "radius -1"});
        Shape nanBox = box;
        nanBox.extents.x() = std::nan("");
        ropras::test::expectErrorMentions([&] { shapesIntersect(box, origin, nanBox, origin); },
                                          {"shapesIntersect", "shape b (box): a size is negative or not finite"});
        Eigen::Isometry3d bad = origin;
        bad.translation().x() = std::numeric_limits<double>::infinity();
        ropras::test::expectErrorMentions([&] { shapesIntersect(box, bad, box, origin); },
                                          {"shapesIntersect", "shape a (box): the pose is not finite"});
        const Shape cloud = Shape::pointCloud(nullptr);
        ropras::test::expectErrorMentions([&] { shapesIntersect(box, origin, cloud, origin); },
                                          {"shapesIntersect", "shape b (point cloud): point clouds are not supported"});
    }
}  // namespace ropras::ompl_ext
