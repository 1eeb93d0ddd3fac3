// CollisionChecker on hand-written robots (every joint type, a branching two-arm robot) and batch rows at limits
// and bad values, against the reference FK and single checks.
#include <gtest/gtest.h>

#include <atomic>
#include <filesystem>
#include <thread>

#include "CollisionCheckerTestUtil.h"
#include "ropras/core/Error.h"

using namespace ropras::test;

namespace
{
    /// largest distance of the batch and single sphere centres of 8 rows \a qs from the reference FK
    double worstCentreError(const RobotModel &robot, const CollisionChecker &checker, const std::vector<double> &qs)
    {
        const std::size_t ns = robot.spheres().size(), dof = robot.dof();
        std::vector<float> single(4 * ns), batch(4 * ns * 8);
        checker.sphereCentersBatch(qs.data(), batch.data());
        double worst = 0.0;
        for (std::size_t i = 0; i < 8; ++i)
        {
            const auto ref = robot.sphereCentersReference(qs.data() + dof * i);
            checker.sphereCenters(qs.data() + dof * i, single.data());
            for (std::size_t s = 0; s < ns; ++s)
            {
                const Eigen::Vector3d fromSingle(single[4 * s], single[4 * s + 1], single[4 * s + 2]);
                const Eigen::Vector3d fromBatch(batch[(4 * s) * 8 + i], batch[(4 * s + 1) * 8 + i],
                                                batch[(4 * s + 2) * 8 + i]);
                worst = std::max({worst, (fromSingle - ref[s]).norm(), (fromBatch - ref[s]).norm()});
            }
        }
        return worst;
    }
}  // namespace

TEST(CollisionCheckerTest, EveryJointTypeMatchesReferenceFk)
{
    const auto robot = RobotModel::fromUrdfString(ALL_JOINTS_URDF, ".", "all_joints.urdf");
    ASSERT_EQ(robot->dof(), 3u);
    std::mt19937_64 rng(900);
    std::uniform_real_distribution<double> u(0.0, 1.0);
    for (SimdBackend backend : backends())
    {
        CollisionChecker checker(robot, backend);
        std::vector<double> qs(3 * 8);
        double worst = 0.0;
        for (int k = 0; k < 2000; ++k)
        {
            for (int i = 0; i < 8; ++i)
            {
                qs[3 * i] = -2.5 + 5.0 * u(rng);
                qs[3 * i + 1] = -0.2 + 0.6 * u(rng);
                // continuous: any finite value, also far from zero (range reduction in double)
                qs[3 * i + 2] = (k % 4 == 0 ? 1000.0 : 10.0) * (2.0 * u(rng) - 1.0);
            }
            worst = std::max(worst, worstCentreError(*robot, checker, qs));
        }
        EXPECT_LT(worst, 1e-5) << simdBackendName(backend);
        // the continuous joint accepts any finite value; the prismatic one is bounded
        std::vector<double> q{0.1, 0.1, 1e4};
        EXPECT_TRUE(checker.isValid(Environment(), q.data()));
        q[1] = 0.41;
        EXPECT_FALSE(checker.isValid(Environment(), q.data()));
    }
}

namespace
{
    /** \brief Two arms on one base (a tree, not a chain): the second arm's first frame does not follow its parent
        in the frame order, so both FK paths must reload the parent's frame. The arms reach each other
        (self-collision pairs across the branches). */
    const char *const TWO_ARMS_URDF = R"(<?xml version="1.0"?>
<robot name="two_arms">
  <link name="base"><collision><geometry><sphere radius="0.06"/></geometry></collision></link>
  <link name="l1"><collision><origin xyz="0 0 0.1"/><geometry><sphere radius="0.04"/></geometry></collision>
                  <collision><origin xyz="0 0 0.2"/><geometry><sphere radius="0.04"/></geometry></collision></link>
  <link name="l2"><collision><origin xyz="0.1 0 0"/><geometry><sphere radius="0.035"/></geometry></collision>
                  <collision><origin xyz="0.2 0 0"/><geometry><sphere radius="0.03"/></geometry></collision></link>
  <link name="l3"><collision><origin xyz="0.08 0.02 0"/><geometry><sphere radius="0.03"/></geometry></collision></link>
  <link name="r1"><collision><origin xyz="0 0 0.1"/><geometry><sphere radius="0.04"/></geometry></collision>
                  <collision><origin xyz="0 0 0.2"/><geometry><sphere radius="0.04"/></geometry></collision></link>
  <link name="r2"><collision><origin xyz="-0.1 0 0"/><geometry><sphere radius="0.035"/></geometry></collision>
                  <collision><origin xyz="-0.2 0 0"/><geometry><sphere radius="0.03"/></geometry></collision></link>
  <link name="r3"><collision><origin xyz="0 0 0.05"/><geometry><sphere radius="0.03"/></geometry></collision></link>
  <joint name="left_1" type="revolute"><parent link="base"/><child link="l1"/>
    <origin xyz="0 0.15 0.05" rpy="0 0 0"/><axis xyz="0 0 1"/><limit lower="-3" upper="3" effort="1" velocity="1"/></joint>
  <joint name="left_2" type="revolute"><parent link="l1"/><child link="l2"/>
    <origin xyz="0 0 0.25" rpy="1.5707963267948966 0 0"/><axis xyz="0 0 1"/><limit lower="-2" upper="2" effort="1" velocity="1"/></joint>
  <joint name="left_3" type="revolute"><parent link="l2"/><child link="l3"/>
    <origin xyz="0.25 0 0" rpy="0.2 -0.3 0.4"/><axis xyz="0.3 0.8 0.1"/><limit lower="-2.5" upper="2.5" effort="1" velocity="1"/></joint>
  <joint name="right_1" type="revolute"><parent link="base"/><child link="r1"/>
    <origin xyz="0 -0.15 0.05" rpy="0 0 3.141592653589793"/><axis xyz="0 0 1"/><limit lower="-3" upper="3" effort="1" velocity="1"/></joint>
  <joint name="right_2" type="revolute"><parent link="r1"/><child link="r2"/>
    <origin xyz="0 0 0.25" rpy="-1.5707963267948966 0 0"/><axis xyz="0 0 1"/><limit lower="-2" upper="2" effort="1" velocity="1"/></joint>
  <joint name="right_3" type="prismatic"><parent link="r2"/><child link="r3"/>
    <origin xyz="-0.25 0 0" rpy="0 0.5 0"/><axis xyz="0 1 0"/><limit lower="-0.1" upper="0.15" effort="1" velocity="1"/></joint>
</robot>)";
}  // namespace

TEST(CollisionCheckerTest, BranchingRobotMatchesReferenceFkAndBruteForce)
{
    const auto robot = RobotModel::fromUrdfString(TWO_ARMS_URDF, ".", "two_arms.urdf");
    ASSERT_EQ(robot->dof(), 6u);
    // sphere centres of both paths against the reference FK, over the whole joint range
    std::mt19937_64 rng(950);
    for (SimdBackend backend : backends())
    {
        CollisionChecker checker(robot, backend);
        std::vector<double> qs;
        double worst = 0.0;
        for (int k = 0; k < 500; ++k)
        {
            qs.clear();
            for (int i = 0; i < 8; ++i)
            {
                const auto q = randomConfig(*robot, rng);
                qs.insert(qs.end(), q.begin(), q.end());
            }
            worst = std::max(worst, worstCentreError(*robot, checker, qs));
        }
        EXPECT_LT(worst, 1e-5) << simdBackendName(backend);
    }
    // verdicts of every path against the brute force: the arms against each other, then with obstacles
    const VerdictStats self = checkVerdicts(robot, Environment(), 3000, 951);
    EXPECT_GT(self.invalid, 100) << "random configurations must include arm-against-arm contacts";
    EXPECT_GT(self.valid, 1000);
    EXPECT_LT(self.nearContact, 15);
    Environment env;
    env.addSphere("ball", {0.25, 0.0, 0.35}, 0.08);
    env.addBox("plate", pose({0.0, 0.0, 0.55}), {0.4, 0.3, 0.02});
    const VerdictStats world = checkVerdicts(robot, env, 3000, 952);
    EXPECT_GT(world.invalid, self.invalid);
    EXPECT_GT(world.valid, 500);
    EXPECT_LT(world.nearContact, 15);
}

namespace
{
    /** \brief Rows of a batch in every form the batch loader distinguishes: in range, exactly at a limit (valid),
        one ulp past it, NaN, infinite, and continuous angles far from zero (reduced in double). Every verdict of
        isValidBatch must equal isValid on the same row, for both backends and any row count. */
    void checkBatchRows(const std::shared_ptr<const RobotModel> &robot, const Environment &env, std::uint64_t seed)
    {
        const std::size_t dof = robot->dof();
        const double nan = std::numeric_limits<double>::quiet_NaN();
        const double inf = std::numeric_limits<double>::infinity();
        std::mt19937_64 rng(seed);
        std::uniform_real_distribution<double> u(0.0, 1.0);
        std::vector<double> qs;
        const std::size_t count = 8 * 300 + 5;  // full batches, then a tail
        for (std::size_t k = 0; k < count; ++k)
        {
            std::vector<double> q(dof);
            for (std::size_t j = 0; j < dof; ++j)
            {
                const PlanningJoint &joint = robot->joints()[j];
                const bool continuous = joint.type == JointType::Continuous;
                const double lo = continuous ? -3.0 : joint.lower, hi = continuous ? 3.0 : joint.upper;
                q[j] = lo + (hi - lo) * u(rng);
                // one row in four of the batches gets a special value in one joint
                if (k % 4 != 1 || j != (k / 4) % dof)
                    continue;
                switch ((k / 4 / dof) % 6)
                {
                    case 0:
                        q[j] = continuous ? 200.0 * (u(rng) - 0.5) : lo;  // at the limit: valid
                        break;
                    case 1:
                        q[j] = continuous ? 1e4 * (u(rng) - 0.5) : hi;
                        break;
                    case 2:
                        q[j] = continuous ? 1e6 : std::nextafter(hi, inf);  // one ulp past the limit
                        break;
                    case 3:
                        q[j] = continuous ? -1e6 : std::nextafter(lo, -inf);
                        break;
                    case 4:
                        q[j] = nan;
                        break;
                    default:
                        q[j] = (k % 8 < 4) ? inf : -inf;
                        break;
                }
            }
            qs.insert(qs.end(), q.begin(), q.end());
        }
        for (SimdBackend b : backends())
        {
            const CollisionChecker checker(robot, b);
            for (const std::size_t n : {count, std::size_t{8}, std::size_t{13}})
            {
                std::unique_ptr<bool[]> v(new bool[n]);
                const std::size_t nValid = checker.isValidBatch(env, qs.data(), n, v.get());
                std::size_t valid = 0, invalid = 0;
                for (std::size_t k = 0; k < n; ++k)
                {
                    const bool single = checker.isValid(env, qs.data() + k * dof);
                    EXPECT_EQ(v[k], single) << robot->name() << " " << simdBackendName(b) << " row " << k;
                    (single ? valid : invalid) += 1;
                }
                EXPECT_EQ(nValid, valid);
                if (n == count)
                {
                    EXPECT_GT(valid, count / 20) << robot->name();
                    EXPECT_GT(invalid, count / 20) << robot->name();
                }
            }
            // allValid over windows of every length 0..20 at many offsets: true exactly when every row of the
            // window is valid by isValid (windows with and without bad rows, short and full blocks)
            std::vector<char> single(count);
            for (std::size_t k = 0; k < count; ++k)
                single[k] = checker.isValid(env, qs.data() + k * dof) ? 1 : 0;
            std::size_t allTrue = 0, allFalse = 0;
            for (std::size_t start = 0; start + 20 <= count; start += 7)
                for (std::size_t len = 0; len <= 20; ++len)
                {
                    const bool expected = std::all_of(single.begin() + static_cast<std::ptrdiff_t>(start),
                                                      single.begin() + static_cast<std::ptrdiff_t>(start + len),
                                                      [](char c) { return c != 0; });
                    ASSERT_EQ(checker.allValid(env, qs.data() + start * dof, len), expected)
                        << robot->name() << " " << simdBackendName(b) << " rows " << start << " + " << len;
                    (expected ? allTrue : allFalse) += 1;
                }
            EXPECT_GT(allTrue, 300u) << robot->name();  // enough windows of each answer
            EXPECT_GT(allFalse, 300u) << robot->name();
        }
    }
}  // namespace

TEST(CollisionCheckerTest, BatchRowsMatchSingleChecksAtLimitsAndBadValues)
{
    // three joints (the AVX2 loader's short-row path), a continuous one among them
    const auto small = RobotModel::fromUrdfString(ALL_JOINTS_URDF, ".", "all_joints.urdf");
    Environment env;
    env.addSphere("ball", {0.25, 0.2, 0.25}, 0.12);
    checkBatchRows(small, env, 1001);
    if (!std::filesystem::exists(SHARED + "/robots"))
        GTEST_SKIP() << "../shared not found: " << SHARED << " (the Panda part is skipped)";
    checkBatchRows(loadRobot("panda"), clutter(1002), 1003);
    // more obstacles than a call keeps boxes for on the stack: the boxes are computed per batch instead
    Environment crowded = clutter(1004);
    std::mt19937_64 rng(1005);
    std::uniform_real_distribution<double> u(-0.8, 0.8);
    for (int k = 0; k < 80; ++k)
        crowded.addSphere("ball" + std::to_string(k), {u(rng), u(rng), 0.4 + 0.5 * u(rng)}, 0.03);
    checkBatchRows(loadRobot("panda"), crowded, 1006);
}
