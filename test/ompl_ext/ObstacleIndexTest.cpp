// ObstacleIndex (the broad phase): the tree's structure (every primitive once, boxes nested), and the indexed
// checker against the same scene scanned without an index (a chain of small overlays, each below the index's
// threshold) and against FCL with the same spheres, on random configurations in large random scenes: single,
// batch, all-valid and motion checks, both SIMD backends, after objects move (refits, then a rebuild), in copies,
// after objects are added, under a per-particle overlay and from two threads.
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <random>
#include <string>
#include <thread>
#include <vector>

#include "ropras/ompl_ext/collision/CollisionChecker.h"
#include "ropras/ompl_ext/collision/FclReferenceChecker.h"
#include "ropras/ompl_ext/model/RobotModel.h"
#include "ropras/ompl_ext/scene/Environment.h"
#include "ropras/ompl_ext/scene/PointCloud.h"

using namespace ropras::ompl_ext;

namespace
{
    const std::string SOURCE = ROPRAS_SOURCE_DIR;

    std::shared_ptr<const RobotModel> panda()
    {
        static const auto robot =
            RobotModel::fromUrdfFile(SOURCE + "/robots/panda/panda.urdf", SOURCE + "/robots/panda/panda.srdf");
        return robot;
    }

    std::vector<SimdBackend> backends()
    {
        std::vector<SimdBackend> b{SimdBackend::Scalar};
        if (simdBackendAvailable(SimdBackend::Avx2))
            b.push_back(SimdBackend::Avx2);
        return b;
    }

    Eigen::Isometry3d randomPose(std::mt19937_64 &rng, double half, double zLo, double zHi)
    {
        std::uniform_real_distribution<double> u(-half, half), z(zLo, zHi);
        std::normal_distribution<double> n;
        Eigen::Isometry3d p = Eigen::Isometry3d::Identity();
        p.linear() = Eigen::Quaterniond(n(rng), n(rng), n(rng), n(rng)).normalized().toRotationMatrix();
        p.translation() = Eigen::Vector3d(u(rng), u(rng), z(rng));
        return p;
    }

    /// one random object: one to three primitives of every kind (now and then a small point cloud)
    std::vector<Shape> randomShapes(std::mt19937_64 &rng)
    {
        std::uniform_real_distribution<double> size(0.02, 0.12), offset(-0.1, 0.1);
        std::vector<Shape> shapes;
        const int n = 1 + static_cast<int>(rng() % 3);
        for (int k = 0; k < n; ++k)
        {
            Eigen::Isometry3d at = Eigen::Isometry3d::Identity();
            at.translation() = Eigen::Vector3d(offset(rng), offset(rng), offset(rng));
            switch (rng() % 17)
            {
                case 0:
                case 1:
                case 2:
                case 3:
                    shapes.push_back(Shape::sphere(size(rng), at));
                    break;
                case 4:
                case 5:
                case 6:
                case 7:
                case 8:
                    shapes.push_back(Shape::box({size(rng), size(rng), size(rng)}, at));
                    break;
                case 9:
                case 10:
                case 11:
                    shapes.push_back(Shape::cylinder(size(rng), 2.0 * size(rng), at));
                    break;
                case 12:
                case 13:
                case 14:
                case 15:
                    shapes.push_back(Shape::capsule(size(rng), 2.0 * size(rng), at));
                    break;
                default:
                {
                    std::vector<Eigen::Vector3f> points;
                    for (int i = 0; i < 30; ++i)
                        points.emplace_back(
                            (at.translation() + Eigen::Vector3d(offset(rng), offset(rng), offset(rng))).cast<float>());
                    shapes.push_back(Shape::pointCloud(PointCloud::build(points, 0.01f)));
                }
            }
        }
        return shapes;
    }

    /// \a count random objects over a 12 m x 12 m x 5 m room around the robot: about a dozen within its reach
    Environment randomScene(std::size_t count, std::uint64_t seed)
    {
        std::mt19937_64 rng(seed);
        Environment env;
        for (std::size_t i = 0; i < count; ++i)
            env.addObject("object" + std::to_string(i), randomShapes(rng), randomPose(rng, 6.0, -1.0, 4.0));
        return env;
    }

    /** \brief The objects of \a env (not its base) over \a base, in a chain of overlays of 8 objects each (at most
        24 primitives: below ObstacleIndex::MIN_PRIMITIVES, so every one of them is scanned without an index). */
    std::shared_ptr<const Environment> unindexed(const Environment &env, std::shared_ptr<const Environment> base)
    {
        std::shared_ptr<const Environment> chain = std::move(base);
        for (std::size_t first = 0; first < env.objectCount(); first += 8)
        {
            auto next = std::make_shared<Environment>(chain);
            for (std::size_t id = first; id < std::min(first + 8, env.objectCount()); ++id)
            {
                const int i = static_cast<int>(id);
                next->addObject(env.objectName(i), env.objectShapes(i), env.objectPose(i));
            }
            EXPECT_EQ(next->obstacleTree(), nullptr);
            chain = std::move(next);
        }
        return chain;
    }

    std::vector<double> randomConfigs(const RobotModel &robot, std::size_t count, std::mt19937_64 &rng)
    {
        std::vector<double> qs(count * robot.dof());
        for (std::size_t k = 0; k < count; ++k)
            for (std::size_t j = 0; j < robot.dof(); ++j)
                qs[k * robot.dof() + j] =
                    std::uniform_real_distribution<double>(robot.joints()[j].lower, robot.joints()[j].upper)(rng);
        return qs;
    }

    /// every path of \a checker gives the same verdicts on \a indexed and \a scanned (the same obstacles)
    void expectSameVerdicts(const CollisionChecker &checker, const Environment &indexed, const Environment &scanned,
                            std::uint64_t seed, std::size_t configs = 400)
    {
        const RobotModel &robot = checker.robot();
        const std::size_t dof = robot.dof();
        std::mt19937_64 rng(seed);
        const std::vector<double> qs = randomConfigs(robot, configs, rng);
        std::size_t valid = 0;
        for (std::size_t k = 0; k < configs; ++k)
        {
            const bool v = checker.isValid(scanned, qs.data() + k * dof);
            ASSERT_EQ(checker.isValid(indexed, qs.data() + k * dof), v) << "configuration " << k;
            valid += v ? 1 : 0;
        }
        // the scene must decide both ways, or the comparison proves little
        EXPECT_GT(valid, configs / 20);
        EXPECT_LT(valid, configs - configs / 20);
        std::vector<char> a(configs), b(configs);
        bool *va = reinterpret_cast<bool *>(a.data()), *vb = reinterpret_cast<bool *>(b.data());
        EXPECT_EQ(checker.isValidBatch(indexed, qs.data(), configs, va),
                  checker.isValidBatch(scanned, qs.data(), configs, vb));
        EXPECT_EQ(a, b);
        const auto w = static_cast<std::size_t>(checker.width());
        for (std::size_t k = 0; k + w <= configs; k += w)
            ASSERT_EQ(checker.allValid(indexed, qs.data() + k * dof, w),
                      checker.allValid(scanned, qs.data() + k * dof, w))
                << "block " << k / w;
        // motions between consecutive valid configurations (lastValid fractions too)
        std::size_t motions = 0, validMotions = 0;
        for (std::size_t k = 0; k + 1 < configs && motions < 60; ++k)
        {
            const double *q0 = qs.data() + k * dof, *q1 = qs.data() + (k + 1) * dof;
            if (!checker.isValid(scanned, q0))
                continue;
            double fa = -1.0, fb = -1.0;
            const bool m = checker.isMotionValid(scanned, q0, q1, 0.05, &fb);
            ASSERT_EQ(checker.isMotionValid(indexed, q0, q1, 0.05, &fa), m) << "motion " << k;
            EXPECT_EQ(fa, fb) << "motion " << k;
            ++motions;
            validMotions += m ? 1 : 0;
        }
        EXPECT_GT(motions, 10u);
        EXPECT_LT(validMotions, motions);
    }

    /// the tree's invariants: each primitive in exactly one leaf lane with its box; every lane holds its child
    void expectTreeHolds(const Environment &env)
    {
        const ObstacleTree *tree = env.obstacleTree();
        ASSERT_NE(tree, nullptr);
        const std::size_t n = env.primitiveCount();
        std::vector<int> seen(n, 0);
        const auto lane = [](const ObstacleIndexNode &node, int i)
        { return std::array<float, 6>{node.lox[i], node.loy[i], node.loz[i], node.hix[i], node.hiy[i], node.hiz[i]}; };
        for (std::size_t ni = 0; ni < tree->nodes.size(); ++ni)
        {
            const ObstacleIndexNode &node = tree->nodes[ni];
            for (int i = 0; i < OBSTACLE_INDEX_FANOUT; ++i)
            {
                const std::int32_t child = node.child[i];
                if (child < 0)
                {
                    EXPECT_GT(lane(node, i)[0], lane(node, i)[3]) << "an empty lane overlaps boxes";
                    continue;
                }
                const auto box = lane(node, i);
                if (tree->isLeaf(static_cast<std::int32_t>(ni)))
                {
                    ASSERT_LT(static_cast<std::size_t>(child), n);
                    ++seen[static_cast<std::size_t>(child)];
                    const ObstacleAabb &b = env.primitiveBox(static_cast<std::size_t>(child));
                    EXPECT_EQ(box[0], b.cx - b.ex);
                    EXPECT_EQ(box[3], b.cx + b.ex);
                    EXPECT_EQ(box[2], b.cz - b.ez);
                    EXPECT_EQ(box[5], b.cz + b.ez);
                    continue;
                }
                ASSERT_LT(static_cast<std::size_t>(child), ni);
                const ObstacleIndexNode &sub = tree->nodes[static_cast<std::size_t>(child)];
                for (int j = 0; j < OBSTACLE_INDEX_FANOUT; ++j)
                {
                    if (sub.child[j] < 0)
                        continue;
                    const auto inner = lane(sub, j);
                    for (int a = 0; a < 3; ++a)
                    {
                        EXPECT_LE(box[a], inner[a]) << "node " << ni << " lane " << i;
                        EXPECT_GE(box[3 + a], inner[3 + a]) << "node " << ni << " lane " << i;
                    }
                }
            }
        }
        for (std::size_t k = 0; k < n; ++k)
            ASSERT_EQ(seen[k], 1) << "primitive " << k;
    }

    /// \a moves random objects to random poses, the first \a inReach of them into the robot's reach
    void moveRandomObjects(Environment &env, std::size_t moves, std::mt19937_64 &rng, std::size_t inReach)
    {
        for (std::size_t m = 0; m < moves; ++m)
        {
            const int id = static_cast<int>(rng() % env.objectCount());
            env.setObjectPose(id, m < inReach ? randomPose(rng, 0.9, 0.0, 1.2) : randomPose(rng, 6.0, -1.0, 4.0));
        }
    }
}  // namespace

TEST(ObstacleIndex, OnlyLargeEnvironmentsHaveATree)
{
    EXPECT_EQ(randomScene(ObstacleIndex::MIN_PRIMITIVES / 3, 1).obstacleTree(), nullptr);  // <= MIN - 1 primitives
    Environment env = randomScene(400, 2);
    ASSERT_GE(env.primitiveCount(), ObstacleIndex::MIN_PRIMITIVES);
    expectTreeHolds(env);
    env.clear();
    EXPECT_EQ(env.obstacleTree(), nullptr);
}

TEST(ObstacleIndex, AgreesWithTheScanOnLargeRandomScenes)
{
    for (SimdBackend backend : backends())
    {
        const CollisionChecker checker(panda(), backend);
        for (std::uint64_t seed : {11u, 12u})
        {
            SCOPED_TRACE(std::string(simdBackendName(backend)) + ", scene seed " + std::to_string(seed));
            const Environment env = randomScene(2000, seed);
            ASSERT_NE(env.obstacleTree(), nullptr);
            expectSameVerdicts(checker, env, *unindexed(env, nullptr), seed + 100);
        }
    }
}

TEST(ObstacleIndex, MovedObjectsAreRefittedThenRebuilt)
{
    const CollisionChecker checker(panda());
    Environment env = randomScene(1500, 21);
    std::mt19937_64 rng(22);
    for (int round = 0; round < 3; ++round)
    {
        SCOPED_TRACE("round " + std::to_string(round));
        moveRandomObjects(env, 100, rng, 3);  // refits of the built tree
        expectTreeHolds(env);
        expectSameVerdicts(checker, env, *unindexed(env, nullptr), 30 + static_cast<std::uint64_t>(round), 200);
    }
    // past ObstacleIndex::REFITS_PER_PRIMITIVE moves per primitive the tree is rebuilt by the next check
    moveRandomObjects(env, ObstacleIndex::REFITS_PER_PRIMITIVE * env.primitiveCount() + 10, rng, 0);
    expectTreeHolds(env);
    expectSameVerdicts(checker, env, *unindexed(env, nullptr), 40, 200);
}

TEST(ObstacleIndex, CopiesAndAddedObjectsKeepTheirOwnTree)
{
    const CollisionChecker checker(panda());
    Environment env = randomScene(1200, 51);
    const auto scanned = unindexed(env, nullptr);
    ASSERT_NE(env.obstacleTree(), nullptr);  // built, then shared with the copy
    Environment copy = env;
    std::mt19937_64 rng(52);
    moveRandomObjects(copy, 300, rng, 15);  // the copy's own tree; env's stays as it was
    for (int i = 0; i < 40; ++i)
        copy.addObject("added" + std::to_string(i), randomShapes(rng),
                       i % 10 == 0 ? randomPose(rng, 1.0, 0.0, 1.2) : randomPose(rng, 6.0, -1.0, 4.0));
    expectTreeHolds(env);
    expectTreeHolds(copy);
    expectSameVerdicts(checker, env, *scanned, 53, 200);
    expectSameVerdicts(checker, copy, *unindexed(copy, nullptr), 54, 200);
}

TEST(ObstacleIndex, ParticleOverlayOverAnIndexedBase)
{
    // a large static base (indexed) and a particle's few movable objects (scanned): the same as all scanned
    const CollisionChecker checker(panda());
    const auto base = std::make_shared<const Environment>(randomScene(1500, 61));
    const auto scannedBase = unindexed(*base, nullptr);
    std::mt19937_64 rng(62);
    Environment movable(base), movableScanned(scannedBase);
    for (int i = 0; i < 4; ++i)
    {
        const auto shapes = randomShapes(rng);
        const Eigen::Isometry3d at = randomPose(rng, 0.8, 0.0, 1.0);
        movable.addObject("movable" + std::to_string(i), shapes, at);
        movableScanned.addObject("movable" + std::to_string(i), shapes, at);
    }
    for (int round = 0; round < 3; ++round)
    {
        for (int i = 0; i < 4; ++i)
        {
            const Eigen::Isometry3d at = randomPose(rng, 0.8, 0.0, 1.0);
            movable.setObjectPose(i, at);
            movableScanned.setObjectPose(i, at);
        }
        expectSameVerdicts(checker, movable, movableScanned, 63 + static_cast<std::uint64_t>(round), 200);
    }
}

TEST(ObstacleIndex, AgreesWithFclOnALargeScene)
{
    const auto robot = panda();
    const CollisionChecker checker(robot);
    const FclSphereChecker fcl(robot);
    Environment env = randomScene(1500, 71);
    std::mt19937_64 rng(72);
    moveRandomObjects(env, 200, rng, 10);
    const std::vector<double> qs = randomConfigs(*robot, 150, rng);
    std::size_t compared = 0, valid = 0;
    for (std::size_t k = 0; k < 150; ++k)
    {
        const double *q = qs.data() + k * robot->dof();
        if (std::abs(fcl.distance(env, q)) < 1e-4)
            continue;  // float contact tolerance: FCL is exact in double
        const bool v = fcl.isValid(env, q);
        ASSERT_EQ(checker.isValid(env, q), v) << "configuration " << k;
        ++compared;
        valid += v ? 1 : 0;
    }
    EXPECT_GT(compared, 140u);
    EXPECT_GT(valid, 5u);
    EXPECT_LT(valid, compared - 5);
}

TEST(ObstacleIndex, TwoThreadsShareTheFirstBuild)
{
    // the tree is built by the first check after the scene was made: two threads race for it
    const CollisionChecker checker(panda());
    const Environment env = randomScene(3000, 81);
    const auto scanned = unindexed(env, nullptr);
    std::mt19937_64 rng(82);
    const std::vector<double> qs = randomConfigs(checker.robot(), 300, rng);
    std::vector<char> expected(300);
    for (std::size_t k = 0; k < 300; ++k)
        expected[k] = checker.isValid(*scanned, qs.data() + k * checker.robot().dof()) ? 1 : 0;
    std::vector<char> got[2] = {std::vector<char>(300), std::vector<char>(300)};
    std::thread threads[2];
    for (int t = 0; t < 2; ++t)
        threads[t] = std::thread(
            [&, t]
            {
                for (std::size_t k = 0; k < 300; ++k)
                    got[t][k] = checker.isValid(env, qs.data() + k * checker.robot().dof()) ? 1 : 0;
            });
    for (std::thread &t : threads)
        t.join();
    EXPECT_EQ(got[0], expected);
    EXPECT_EQ(got[1], expected);
}

TEST(ObstacleIndex, HeldBodiesOverAnIndexedBase)
{
    // a can in the hand (single and batch paths of the attached kernels) over a large indexed base
    const auto robot = panda();
    const auto base = std::make_shared<const Environment>(randomScene(1500, 91));
    const auto scannedBase = unindexed(*base, nullptr);
    AttachedBody can;
    can.name = "can";
    can.link = "panda_hand";
    can.pose.translation() = Eigen::Vector3d(0.0, 0.0, 0.105);
    can.pose.linear() = Eigen::Quaterniond(0.7071068, 0.0, 0.7071068, 0.0).normalized().toRotationMatrix();
    can.shapes = {Shape::cylinder(0.03, 0.12)};
    can.touchLinks = {"panda_leftfinger", "panda_rightfinger"};
    Environment held(base), heldScanned(scannedBase);
    held.attach(robot, can);
    heldScanned.attach(robot, can);
    for (SimdBackend backend : backends())
    {
        SCOPED_TRACE(simdBackendName(backend));
        expectSameVerdicts(CollisionChecker(robot, backend), held, heldScanned, 92, 300);
    }
}
