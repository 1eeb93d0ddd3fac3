// Joint-space macro-actions: cutting a path into primitive steps (norms, waypoints, truncation) and executing a
// noisy step as a motion that is valid or blocked at the last valid configuration (checked against a
// brute-force fine interpolation with isValid), reproducible with a seed.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <random>
#include <vector>

#include "ExpectError.h"
#include "PointRobotUrdf.h"
#include "ropras/ompl_ext/motion/JointSteps.h"

namespace ropras::ompl_ext
{
    namespace
    {
        double norm(const double *v, std::size_t dof, StepNorm n)
        {
            double s = 0.0;
            for (std::size_t k = 0; k < dof; ++k)
                s = n == StepNorm::L2 ? s + v[k] * v[k] : std::max(s, std::abs(v[k]));
            return n == StepNorm::L2 ? std::sqrt(s) : s;
        }

        std::shared_ptr<const RobotModel> pointRobot()
        {
            return RobotModel::fromUrdfFile(test::writePointRobotUrdf("ropras_point_robot_joint_steps_test.urdf"));
        }

        std::shared_ptr<const RobotModel> arm()
        {
            const std::string dir = std::string(ROPRAS_SOURCE_DIR) + "/robots/ropras_arm/";
            return RobotModel::fromUrdfFile(dir + "ropras_arm.urdf", dir + "ropras_arm.srdf");
        }

        Eigen::Isometry3d at(const Eigen::Vector3d &t)
        {
            Eigen::Isometry3d p = Eigen::Isometry3d::Identity();
            p.translation() = t;
            return p;
        }

        /// the first invalid configuration's fraction on q0 -> q1 sampled at \a samples + 1 points, or 2 if none
        double bruteFirstInvalid(const CollisionChecker &checker, const Environment &env, const double *q0,
                                 const double *q1, int samples)
        {
            const std::size_t dof = checker.robot().dof();
            std::vector<double> q(dof);
            for (int k = 1; k <= samples; ++k)
            {
                const double t = double(k) / samples;
                for (std::size_t j = 0; j < dof; ++j)
                    q[j] = q0[j] + t * (q1[j] - q0[j]);
                if (!checker.isValid(env, q.data()))
                    return t;
            }
            return 2.0;
        }
    }  // namespace

    TEST(JointSteps, EqualPiecesAtMostOneStepAndEveryCorner)
    {
        const std::vector<double> path{0.0, 0.0, 0.3, 0.0, 0.3, 0.4, 0.3, 0.4};  // 0.3, 0.4, then zero length
        std::vector<double> points;
        ASSERT_EQ(discretizeJointPath(path.data(), 4, 2, 0.1, 0, points), 7u);
        const std::vector<double> expected{0.1, 0.0, 0.2, 0.0, 0.3, 0.0, 0.3, 0.1, 0.3, 0.2, 0.3, 0.3, 0.3, 0.4};
        ASSERT_EQ(points.size(), expected.size());
        for (std::size_t i = 0; i < expected.size(); ++i)
            EXPECT_NEAR(points[i], expected[i], 1e-12) << i;
        // step 0.25: 0.3 -> 2 pieces of 0.15, 0.4 -> 2 pieces of 0.2; the corner (0.3, 0) is kept
        points.clear();
        ASSERT_EQ(discretizeJointPath(path.data(), 4, 2, 0.25, 0, points), 4u);
        const std::vector<double> coarse{0.15, 0.0, 0.3, 0.0, 0.3, 0.2, 0.3, 0.4};
        for (std::size_t i = 0; i < coarse.size(); ++i)
            EXPECT_NEAR(points[i], coarse[i], 1e-12) << i;
        points.clear();
        EXPECT_EQ(discretizeJointPath(path.data(), 4, 2, 0.1, 4, points), 4u);
        EXPECT_EQ(points.size(), 8u);
        EXPECT_NEAR(points[6], 0.3, 1e-12);
        EXPECT_NEAR(points[7], 0.1, 1e-12);
        // exact pieces of 0.25: 0.25 then the 0.05 remainder to the corner, 0.25 then 0.15
        points.clear();
        JointStepOptions exact;
        exact.step = 0.25;
        ASSERT_EQ(discretizeJointPath(path.data(), 4, 2, exact, points), 4u);
        const std::vector<double> exactPoints{0.25, 0.0, 0.3, 0.0, 0.3, 0.25, 0.3, 0.4};
        for (std::size_t i = 0; i < exactPoints.size(); ++i)
            EXPECT_NEAR(points[i], exactPoints[i], 1e-12) << i;
    }

    TEST(JointSteps, SegmentPiecesCountsWhatDiscretizeCuts)
    {
        EXPECT_EQ(segmentPieces(0.05, 0.1), 1u);
        EXPECT_EQ(segmentPieces(0.1, 0.1), 1u);
        EXPECT_EQ(segmentPieces(3 * 0.1, 0.1), 3u);  // 3 * 0.1 / 0.1 = 3.0000000000000004: rounding, no 4th piece
        EXPECT_EQ(segmentPieces(0.30001, 0.1), 4u);
        std::mt19937 gen(17);
        std::uniform_real_distribution<double> length(1e-6, 3.0);
        for (int trial = 0; trial < 200; ++trial)
        {
            const double l = length(gen);
            const std::vector<double> path{0.0, 0.0, l, 0.0};
            std::vector<double> points;
            EXPECT_EQ(discretizeJointPath(path.data(), 2, 2, 0.1, 0, points), segmentPieces(l, 0.1)) << l;
        }
    }

    TEST(JointSteps, BadPathsThrowNamingTheValue)
    {
        const std::vector<double> path{0.0, 0.0, 0.3, 0.0};
        std::vector<double> points;
        ropras::test::expectErrorMentions([&] { discretizeJointPath(path.data(), 2, 2, std::nan(""), 0, points); },
                                          {"step", "nan"});
        ropras::test::expectErrorMentions([&] { discretizeJointPath(path.data(), 2, 2, 0.0, 0, points); },
                                          {"step", "0"});
        ropras::test::expectErrorMentions([&] { discretizeJointPath(path.data(), 1, 2, 0.1, 0, points); },
                                          {"two waypoints", "1"});
        const std::vector<double> bad{0.0, 0.0, 0.1, 0.0, std::nan(""), 0.0};
        ropras::test::expectErrorMentions([&] { discretizeJointPath(bad.data(), 3, 2, 0.1, 0, points); },
                                          {"waypoint 2", "joint 0", "nan"});
        EXPECT_TRUE(points.empty());  // nothing appended before the error
    }

    TEST(JointSteps, RandomPathsNormsWaypointsAndTruncation)
    {
        std::mt19937_64 rng(5);
        std::uniform_real_distribution<double> u(-1.0, 1.0);
        const std::size_t dof = 7;
        for (int trial = 0; trial < 200; ++trial)
        {
            const std::size_t count = 2 + std::size_t(trial % 5);
            std::vector<double> path(count * dof);
            for (double &v : path)
                v = 2.0 * u(rng);
            for (StepNorm n : {StepNorm::L2, StepNorm::Linf})
                for (StepSplit split : {StepSplit::Exact, StepSplit::Equal})
                {
                    JointStepOptions o;
                    o.step = 0.05 + 0.3 * std::abs(u(rng));
                    o.norm = n;
                    o.split = split;
                    std::vector<double> points, steps;
                    const std::size_t total = discretizeJointPath(path.data(), count, dof, o, points);
                    ASSERT_EQ(jointSteps(path.data(), count, dof, o, steps), total);
                    ASSERT_EQ(steps.size(), total * dof);
                    // walk the steps: the sum reproduces every point, each waypoint is reached in order, and a
                    // step shorter than the norm only ends on a waypoint
                    std::vector<double> q(path.begin(), path.begin() + long(dof));
                    std::size_t nextWaypoint = 1;
                    for (std::size_t i = 0; i < total; ++i)
                    {
                        const double *dq = steps.data() + i * dof;
                        for (std::size_t k = 0; k < dof; ++k)
                        {
                            q[k] += dq[k];
                            ASSERT_NEAR(q[k], points[i * dof + k], 1e-12);
                        }
                        const double size = norm(dq, dof, n);
                        EXPECT_LE(size, o.step * (1.0 + 1e-9));
                        bool onWaypoint = true;
                        for (std::size_t k = 0; k < dof; ++k)
                            onWaypoint = onWaypoint && points[i * dof + k] == path[nextWaypoint * dof + k];
                        if (onWaypoint)
                        {
                            ++nextWaypoint;
                        }
                        else if (split == StepSplit::Exact)
                        {
                            EXPECT_NEAR(size, o.step, 1e-12 * o.step) << "step " << i << " is not a whole step";
                        }
                    }
                    EXPECT_EQ(nextWaypoint, count) << "every waypoint is a point";
                    // truncation gives the first points of the whole cut
                    JointStepOptions cut = o;
                    cut.maxSteps = 1 + std::size_t(trial) % (total + 2);
                    std::vector<double> truncated;
                    const std::size_t kept = discretizeJointPath(path.data(), count, dof, cut, truncated);
                    ASSERT_EQ(kept, std::min(cut.maxSteps, total));
                    for (std::size_t i = 0; i < kept * dof; ++i)
                        ASSERT_EQ(truncated[i], points[i]);
                }
        }
    }

    TEST(JointStepExecutor, BlockedMotionStopsAtTheLastValidConfiguration)
    {
        // the point robot (disc of radius 0.04 on x, y in [0, 1]) and a wall at x in [0.45, 0.55]
        const auto checker = std::make_shared<const CollisionChecker>(pointRobot());
        Environment env;
        env.addBox("wall", at({0.5, 0.5, 0.0}), {0.1, 0.6, 0.2});
        const double resolution = 0.01;
        const JointStepExecutor executor(checker, resolution);
        core::Rng rng(1);
        const double q[2] = {0.2, 0.5}, dq[2] = {0.5, 0.0};
        double out[2];
        const StepOutcome o = executor.execute(env, q, dq, rng, out);
        ASSERT_TRUE(o.blocked);
        // the disc touches the wall when x + 0.04 >= 0.45: at most one resolution short of x = 0.41
        EXPECT_LE(out[0], 0.41);
        EXPECT_GE(out[0], 0.41 - resolution - 1e-9);
        EXPECT_EQ(out[1], 0.5);
        EXPECT_TRUE(checker->isValid(env, out));
        // a free step ends at its target; from inside the limits to beyond them: clamped
        const double free[2] = {0.0, 0.2};
        EXPECT_FALSE(executor.execute(env, q, free, rng, out).blocked);
        EXPECT_DOUBLE_EQ(out[0], 0.2);
        EXPECT_DOUBLE_EQ(out[1], 0.7);
        const double beyond[2] = {-0.5, 0.9};
        const StepOutcome clamped = executor.execute(env, q, beyond, rng, out);
        EXPECT_FALSE(clamped.blocked);
        EXPECT_EQ(out[0], 0.0);
        EXPECT_EQ(out[1], 1.0);
    }

    TEST(JointStepExecutor, ArmMatchesBruteForceInterpolation)
    {
        const auto robot = arm();
        const auto checker = std::make_shared<const CollisionChecker>(robot);
        const std::size_t dof = robot->dof();
        Environment env;
        std::mt19937_64 gen(3);
        std::uniform_real_distribution<double> u(-1.0, 1.0);
        for (int i = 0; i < 6; ++i)
            env.addSphere("ball" + std::to_string(i), {0.6 * u(gen), 0.6 * u(gen), 0.3 + 0.4 * u(gen)}, 0.12);
        env.addBox("floor", at({0, 0, -0.1}), {2.0, 2.0, 0.1});
        const double resolution = 0.02;
        const JointStepExecutor executor(checker, resolution, std::vector<double>(dof, 0.02));
        core::Rng rng(9);
        std::vector<double> q(dof), dq(dof), out(dof), target(dof);
        int blocked = 0, free = 0, between = 0;
        for (int trial = 0; trial < 3000 && blocked < 200; ++trial)
        {
            for (std::size_t j = 0; j < dof; ++j)
                q[j] = robot->joints()[j].lower +
                       (robot->joints()[j].upper - robot->joints()[j].lower) * 0.5 * (1.0 + u(gen));
            if (!checker->isValid(env, q.data()))
                continue;
            for (std::size_t j = 0; j < dof; ++j)
                dq[j] = 0.4 * u(gen);
            // the same noise as the executor draws: a copy of its generator
            core::Rng copy = rng;
            for (std::size_t j = 0; j < dof; ++j)
                target[j] =
                    std::clamp(q[j] + dq[j] + 0.02 * copy.normal(), robot->joints()[j].lower, robot->joints()[j].upper);
            const StepOutcome o = executor.execute(env, q.data(), dq.data(), rng, out.data());
            double largest = 0.0;
            for (std::size_t j = 0; j < dof; ++j)
                largest = std::max(largest, std::abs(target[j] - q[j]));
            if (!o.blocked)
            {
                ++free;
                for (std::size_t j = 0; j < dof; ++j)
                    ASSERT_NEAR(out[j], target[j], 1e-12);  // the same sum, perhaps fused differently
                EXPECT_TRUE(checker->isValid(env, out.data()));
                continue;
            }
            ++blocked;
            // isMotionValid samples the motion every `resolution` of the largest joint change: the same samples
            // checked one by one with isValid put the first invalid one right after the reached fraction
            const int coarse = std::max(1, int(std::ceil(largest / resolution)));
            const double first = bruteFirstInvalid(*checker, env, q.data(), target.data(), coarse);
            ASSERT_LE(first, 1.0) << "blocked, but every sampled configuration is valid";
            EXPECT_NEAR(o.fraction, first - 1.0 / coarse, 1e-12);
            // a 16 times finer sampling holds those samples: its first invalid configuration is at most one
            // coarse step past the reached fraction (before it when the motion passed a thin contact between
            // two samples: counted)
            const double fine = bruteFirstInvalid(*checker, env, q.data(), target.data(), 16 * coarse);
            EXPECT_LE(fine, o.fraction + 1.0 / coarse + 1e-12);
            if (fine < o.fraction)
                ++between;
            for (std::size_t j = 0; j < dof; ++j)
                EXPECT_NEAR(out[j], q[j] + o.fraction * (target[j] - q[j]), 1e-12);
            EXPECT_TRUE(checker->isValid(env, out.data()));
        }
        std::cout << "arm: " << blocked << " blocked and " << free << " free noisy steps checked; " << between
                  << " blocked ones passed a contact between two samples\n";
        EXPECT_GE(blocked, 50);
        EXPECT_GE(free, 50);
    }

    TEST(JointStepExecutor, NoiseIsReproducibleWithASeed)
    {
        const auto checker = std::make_shared<const CollisionChecker>(pointRobot());
        const Environment empty;
        const JointStepExecutor noisy(checker, 0.01, {0.01, 0.02});
        const double q[2] = {0.5, 0.5}, dq[2] = {0.05, -0.05};
        double a[2], b[2];
        core::Rng r1(42), r2(42), r3(43);
        double sum[2] = {0, 0}, sumSq[2] = {0, 0};
        const int n = 4000;
        bool differs = false;
        for (int i = 0; i < n; ++i)
        {
            noisy.execute(empty, q, dq, r1, a);
            noisy.execute(empty, q, dq, r2, b);
            ASSERT_EQ(a[0], b[0]);
            ASSERT_EQ(a[1], b[1]);
            noisy.execute(empty, q, dq, r3, b);
            differs = differs || b[0] != a[0];
            for (int j = 0; j < 2; ++j)
            {
                const double e = a[j] - (q[j] + dq[j]);
                sum[j] += e;
                sumSq[j] += e * e;
            }
        }
        EXPECT_TRUE(differs);
        // the noise has the stated deviations (4000 samples: the mean within 4 standard errors)
        EXPECT_NEAR(sum[0] / n, 0.0, 4 * 0.01 / std::sqrt(n));
        EXPECT_NEAR(sum[1] / n, 0.0, 4 * 0.02 / std::sqrt(n));
        EXPECT_NEAR(std::sqrt(sumSq[0] / n), 0.01, 0.001);
        EXPECT_NEAR(std::sqrt(sumSq[1] / n), 0.02, 0.002);
        // without noise the step is exact and the generator is not touched
        const JointStepExecutor exact(checker, 0.01);
        core::Rng r4(1), untouched(1);
        exact.execute(empty, q, dq, r4, a);
        EXPECT_EQ(a[0], q[0] + dq[0]);
        EXPECT_EQ(a[1], q[1] + dq[1]);
        EXPECT_EQ(r4(), untouched());
    }

    TEST(JointStepExecutor, BadArgumentsThrow)
    {
        const auto checker = std::make_shared<const CollisionChecker>(pointRobot());
        ropras::test::expectErrorMentions([&] { JointStepExecutor(nullptr, 0.01); }, {"null"});
        ropras::test::expectErrorMentions([&] { JointStepExecutor(checker, 0.0); }, {"resolution", "0"});
        ropras::test::expectErrorMentions([&] { JointStepExecutor(checker, std::nan("")); }, {"resolution", "nan"});
        ropras::test::expectErrorMentions([&] { JointStepExecutor(checker, 0.01, {0.1}); }, {"1 noise", "2 joints"});
        ropras::test::expectErrorMentions([&] { JointStepExecutor(checker, 0.01, {0.1, -1.0}); }, {"joint 1", "-1"});
        const JointStepExecutor executor(checker, 0.01);
        const Environment empty;
        core::Rng rng(1);
        double out[2];
        const double inside[2] = {0.5, 0.5}, outside[2] = {1.5, 0.5}, nanStep[2] = {0.1, std::nan("")};
        ropras::test::expectErrorMentions([&] { executor.execute(empty, outside, inside, rng, out); },
                                          {"joint x", "outside its limits"});
        ropras::test::expectErrorMentions([&] { executor.execute(empty, inside, nanStep, rng, out); },
                                          {"joint y", "nan"});
        const double huge[2] = {1e300, 0.0};
        ropras::test::expectErrorMentions(
            [&] { JointStepExecutor(checker, 1e-300).execute(empty, inside, huge, rng, out); }, {"1e8 resolutions"});
    }
}  // namespace ropras::ompl_ext
