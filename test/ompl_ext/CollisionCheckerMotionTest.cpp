// CollisionChecker motions: verdicts against dense reference sampling, the lastValid contract, every sample checked.
#include <gtest/gtest.h>

#include <atomic>
#include <filesystem>
#include <thread>

#include "CollisionCheckerTestUtil.h"
#include "ropras/core/Error.h"

using namespace ropras::test;

namespace
{
    struct MotionStats
    {
        int valid{0}, invalid{0}, skipped{0};
    };

    /// motions q0 -> q1 vs dense sampling of the reference at the same samples (k / n, k = 1..n)
    MotionStats checkMotions(const std::shared_ptr<const RobotModel> &robot, const Environment &env, int motions,
                             double maxDelta, double resolution, std::uint64_t seed)
    {
        MotionStats stats;
        std::mt19937_64 rng(seed);
        std::uniform_real_distribution<double> u(-maxDelta, maxDelta);
        const std::size_t dof = robot->dof();
        std::vector<std::unique_ptr<CollisionChecker>> checkers;
        for (SimdBackend b : backends())
            checkers.push_back(std::make_unique<CollisionChecker>(robot, b));
        for (int attempt = 0; attempt < 100 * motions && stats.valid + stats.invalid + stats.skipped < motions;
             ++attempt)
        {
            const auto q0 = randomConfig(*robot, rng);
            if (referenceMargin(*robot, env, q0.data()) < 1e-4)
                continue;  // the start must be valid
            std::vector<double> q1(dof);
            for (std::size_t j = 0; j < dof; ++j)
                q1[j] = std::clamp(q0[j] + u(rng), robot->joints()[j].lower, robot->joints()[j].upper);
            double step = 0.0;
            for (std::size_t j = 0; j < dof; ++j)
                step = std::max(step, std::abs(q1[j] - q0[j]));
            const long n = std::max(1L, static_cast<long>(std::ceil(step / resolution)));
            long firstBad = -1;
            bool near = false;
            std::vector<double> q(dof);
            for (long k = 1; k <= n; ++k)
            {
                const double t = static_cast<double>(k) / static_cast<double>(n);
                for (std::size_t j = 0; j < dof; ++j)
                    q[j] = q0[j] + t * (q1[j] - q0[j]);
                const double m = referenceMargin(*robot, env, q.data());
                if (std::abs(m) < 1e-4)
                    near = true;
                if (m <= 0.0 && firstBad < 0)
                    firstBad = k;
                if (near)
                    break;
            }
            if (near)
            {
                ++stats.skipped;
                continue;
            }
            const bool truth = firstBad < 0;
            (truth ? stats.valid : stats.invalid) += 1;
            const double expectedLast = truth ? 1.0 : static_cast<double>(firstBad - 1) / static_cast<double>(n);
            for (const auto &checker : checkers)
            {
                double last = -1.0;
                EXPECT_EQ(checker->isMotionValid(env, q0.data(), q1.data(), resolution, &last), truth)
                    << simdBackendName(checker->backend());
                if (!truth)
                {
                    EXPECT_NEAR(last, expectedLast, 1e-12)
                        << simdBackendName(checker->backend()) << " n " << n << " first invalid sample " << firstBad;
                }
                EXPECT_EQ(checker->isMotionValid(env, q0.data(), q1.data(), resolution), truth);
            }
        }
        return stats;
    }
}  // namespace

TEST(CollisionCheckerTest, PandaMotionsMatchDenseReferenceSampling)
{
    REQUIRE_SHARED();
    const auto robot = loadRobot("panda");
    const MotionStats s = checkMotions(robot, clutter(600), 250, 0.8, 1.0 / 32.0, 601);
    EXPECT_GT(s.valid, 30);
    EXPECT_GT(s.invalid, 30);
    EXPECT_LT(s.skipped, 25);
    // a coarse resolution (fewer samples than lanes) and a fine one
    const MotionStats coarse = checkMotions(robot, clutter(602), 100, 0.8, 0.2, 603);
    EXPECT_GT(coarse.invalid, 5);
    const MotionStats fine = checkMotions(robot, clutter(604), 40, 0.5, 0.005, 605);
    EXPECT_GT(fine.invalid + fine.valid, 20);
}

TEST(CollisionCheckerTest, Ur5MotionsMatchDenseReferenceSampling)
{
    REQUIRE_SHARED();
    const auto robot = loadRobot("ur5");
    const MotionStats s = checkMotions(robot, clutter(610), 150, 0.8, 1.0 / 32.0, 611);
    EXPECT_GT(s.valid, 10);
    EXPECT_GT(s.invalid, 10);
}

TEST(CollisionCheckerTest, LastValidFractionContract)
{
    REQUIRE_SHARED();
    const auto robot = loadRobot("panda");
    // joint 1 sweeps the arm through a wall: the first invalid sample decides lastValid exactly
    std::vector<double> q0{-1.2, 0.3, 0.0, -1.5, 0.0, 1.8, 0.8}, q1{1.2, 0.3, 0.0, -1.5, 0.0, 1.8, 0.8};
    Environment env;
    env.addBox("wall", pose({0.5, 0.0, 0.5}), {0.3, 0.05, 1.0});
    const double res = 1.0 / 32.0;
    const long n = static_cast<long>(std::ceil(2.4 / res));
    long firstBad = -1;
    for (long k = 1; k <= n && firstBad < 0; ++k)
    {
        std::vector<double> q(q0);
        q[0] = q0[0] + (q1[0] - q0[0]) * static_cast<double>(k) / static_cast<double>(n);
        if (referenceMargin(*robot, env, q.data()) <= 0.0)
            firstBad = k;
    }
    ASSERT_GT(firstBad, 1);
    ASSERT_LT(firstBad, n);
    for (SimdBackend b : backends())
    {
        CollisionChecker checker(robot, b);
        double last = -1.0;
        EXPECT_FALSE(checker.isMotionValid(env, q0.data(), q1.data(), res, &last));
        EXPECT_DOUBLE_EQ(last, static_cast<double>(firstBad - 1) / static_cast<double>(n));
        // every sample up to lastValid is valid, the next one is not
        std::vector<double> q(q0);
        q[0] = q0[0] + (q1[0] - q0[0]) * last;
        EXPECT_TRUE(checker.isValid(env, q.data()));
        q[0] = q0[0] + (q1[0] - q0[0]) * (last + 1.0 / static_cast<double>(n));
        EXPECT_FALSE(checker.isValid(env, q.data()));
        // the reverse motion stops on the other side of the wall
        double lastBack = -1.0;
        EXPECT_FALSE(checker.isMotionValid(env, q1.data(), q0.data(), res, &lastBack));
        EXPECT_GT(lastBack, 0.0);
        EXPECT_LT(lastBack + last, 1.0);
        // an invalid start: assumed valid unless checkStart
        std::vector<double> inWall(q0);
        inWall[0] = q0[0] + (q1[0] - q0[0]) * static_cast<double>(firstBad) / static_cast<double>(n);
        double lastFromWall = -1.0;
        EXPECT_FALSE(checker.isMotionValid(env, inWall.data(), q0.data(), res, &lastFromWall, true));
        EXPECT_EQ(lastFromWall, 0.0);
        // a valid motion reports 1 (the whole motion), both for many samples and for a single one
        const std::vector<double> beside{-1.2, 0.0, 0.0, -1.5, 0.0, 1.8, 0.8};
        double whole = -1.0;
        ASSERT_TRUE(checker.isMotionValid(env, q0.data(), beside.data(), res, &whole));
        EXPECT_EQ(whole, 1.0);
        whole = -1.0;
        EXPECT_TRUE(checker.isMotionValid(env, q0.data(), q0.data(), res, &whole));
        EXPECT_EQ(whole, 1.0);
        // a zero-length motion checks q1 only
        EXPECT_TRUE(checker.isMotionValid(env, q0.data(), q0.data(), res));
        EXPECT_FALSE(checker.isMotionValid(env, inWall.data(), inWall.data(), res, &lastFromWall));
        EXPECT_EQ(lastFromWall, 0.0);
    }
}

TEST(CollisionCheckerTest, EverySampleOfAMotionIsChecked)
{
    // one joint swings a 3 mm tip sphere on a circle of radius 0.5 m; a 3 mm obstacle on the circle touches the tip
    // at exactly one sample of a motion at 1/32 rad (its neighbours are 2 * 0.5 * sin(1/64) = 15.6 mm away): for
    // every motion length of 1-70 samples and every sample, the motion is invalid and lastValid stops just before it
    const std::string urdf =
        "<robot name=\"swing\"><link name=\"base\"/><link name=\"arm\"><collision><origin xyz=\"0.5 0 0\"/>"
        "<geometry><sphere radius=\"0.003\"/></geometry></collision></link>"
        "<joint name=\"j\" type=\"revolute\"><parent link=\"base\"/><child link=\"arm\"/><axis xyz=\"0 0 1\"/>"
        "<limit lower=\"-3\" upper=\"3\" effort=\"1\" velocity=\"1\"/></joint></robot>";
    const auto robot = RobotModel::fromUrdfString(urdf, ".", "swing.urdf");
    const double res = 1.0 / 32.0, q0 = -1.0;
    std::size_t motions = 0;
    for (SimdBackend b : backends())
    {
        const CollisionChecker checker(robot, b);
        for (long n = 1; n <= 70; ++n)
        {
            const double q1 = q0 + static_cast<double>(n) * res;  // exactly n steps
            for (long k = 1; k <= n; ++k)
            {
                const double at = q0 + (q1 - q0) * static_cast<double>(k) / static_cast<double>(n);
                Environment env;
                env.addSphere("dot", {0.5 * std::cos(at), 0.5 * std::sin(at), 0.0}, 0.003);
                double last = -1.0;
                ASSERT_FALSE(checker.isMotionValid(env, &q0, &q1, res, &last))
                    << simdBackendName(b) << ": " << n << " samples, the one in contact: " << k;
                ASSERT_DOUBLE_EQ(last, static_cast<double>(k - 1) / static_cast<double>(n))
                    << simdBackendName(b) << ": " << n << " samples, the one in contact: " << k;
                ++motions;
            }
            // the obstacle halfway between two samples is missed at this resolution (the contract: samples only)
            Environment between;
            const double mid = q0 + res * 0.5;
            between.addSphere("dot", {0.5 * std::cos(mid), 0.5 * std::sin(mid), 0.0}, 0.003);
            EXPECT_TRUE(checker.isMotionValid(between, &q0, &q1, res)) << n;
        }
    }
    EXPECT_EQ(motions, backends().size() * (70u * 71u / 2u));
}
