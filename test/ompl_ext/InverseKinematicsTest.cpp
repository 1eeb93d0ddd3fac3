// Inverse kinematics: reachable targets of the three kinds on the Panda and the shipped arm (residual checked
// with the reference FK, joint limits), unreachable targets as status values, seeds, the validity predicate
// (collision-free in a scene), and the errors of bad targets and options.
#include <gtest/gtest.h>

#define ROPRAS_ALLOCATION_COUNTER_ONLY  // the counting operator new is defined in VectorizedRRTConnectAllocationTest
#include "../AllocationCounter.h"
#include "ExpectError.h"
#include "KinematicsTestRobots.h"
#include "ropras/ompl_ext/collision/CollisionChecker.h"
#include "ropras/ompl_ext/kinematics/CollisionFreePredicate.h"
#include "ropras/ompl_ext/kinematics/InverseKinematics.h"
#include "ropras/ompl_ext/scene/SceneYaml.h"

namespace
{
    using namespace ropras;
    using namespace ropras::ompl_ext;
    using ropras::test::randomConfiguration;
    using ropras::test::rotationAngle;

    IkTarget targetOf(IkTargetKind kind, const Eigen::Isometry3d &t, const Eigen::Vector3d &toolAxis)
    {
        switch (kind)
        {
            case IkTargetKind::Position:
                return IkTarget::position(t.translation());
            case IkTargetKind::PositionAxis:
                return IkTarget::positionAxis(t.translation(), t.linear() * toolAxis, toolAxis);
            case IkTargetKind::Pose:
                break;
        }
        return IkTarget::pose(t);
    }

    /// reachable targets (FK of random configurations) of every kind: solved, in limits, residual by the reference
    void expectSolvesReachable(const std::shared_ptr<const RobotModel> &robot, const std::string &tip, int targets)
    {
        const InverseKinematics ik(robot, tip);
        const int tipLink = robot->linkIndex(tip);
        IkOptions options;
        options.restarts = 2000;  // enough that every reachable target is found
        const Eigen::Vector3d toolAxis = Eigen::Vector3d(0.3, -0.2, 1.0).normalized();
        core::Rng goals(21);
        for (IkTargetKind kind : {IkTargetKind::Position, IkTargetKind::PositionAxis, IkTargetKind::Pose})
        {
            int solved = 0;
            for (int k = 0; k < targets; ++k)
            {
                const std::vector<double> goal = randomConfiguration(*robot, goals);
                const Eigen::Isometry3d t = robot->linkTransformsReference(goal.data())[tipLink];
                const IkTarget target = targetOf(kind, t, toolAxis);
                core::Rng rng(static_cast<std::uint64_t>(k));
                std::vector<double> q;
                const IkResult r = ik.solve(target, robot->defaultConfiguration(), rng, q, options);
                ASSERT_EQ(q.size(), robot->dof());
                EXPECT_TRUE(robot->withinBounds(q.data()));
                if (r.status != IkStatus::Solved)
                    continue;
                ++solved;
                const Eigen::Isometry3d got = robot->linkTransformsReference(q.data())[tipLink];
                EXPECT_LE((got.translation() - t.translation()).norm(), options.positionTolerance * (1 + 1e-9));
                EXPECT_NEAR(r.positionError, (got.translation() - t.translation()).norm(), 1e-9);
                if (kind == IkTargetKind::Pose)
                {
                    EXPECT_LE(rotationAngle(got.linear(), t.linear()), options.orientationTolerance * (1 + 1e-6));
                }
                if (kind == IkTargetKind::PositionAxis)
                {
                    const double angle =
                        std::acos(std::clamp((got.linear() * toolAxis).dot(t.linear() * toolAxis), -1.0, 1.0));
                    EXPECT_LE(angle, 2 * options.orientationTolerance);  // acos loses digits near 1
                }
            }
            // FK of an in-limit configuration is reachable: every target must be solved
            EXPECT_EQ(solved, targets) << robot->name() << " target kind " << static_cast<int>(kind);
        }
    }
}  // namespace

TEST(InverseKinematics, ShippedArmSolvesEveryTargetKind)
{
    expectSolvesReachable(RobotModel::fromUrdfFile(test::shippedArmUrdf()), "tcp", 40);
}

TEST(InverseKinematics, PandaSolvesEveryTargetKind)
{
    if (!test::haveSharedRobots())
        GTEST_SKIP() << "../shared not found: " << ROPRAS_SHARED_DIR << " (needs robots/panda)";
    expectSolvesReachable(RobotModel::fromUrdfFile(test::sharedRobot("panda/panda_spherized.urdf")), "panda_hand", 40);
}

TEST(InverseKinematics, EveryJointTypeArm)
{
    // prismatic, continuous, skew axes, a held joint and a base pose; joints off the chain keep their seed values
    const auto robot = test::everyJointTypeArm();
    const InverseKinematics ik(robot, "tip");
    core::Rng goals(4);
    int solved = 0;
    for (int k = 0; k < 30; ++k)
    {
        const std::vector<double> goal = randomConfiguration(*robot, goals);
        const Eigen::Isometry3d t = robot->linkTransformsReference(goal.data())[robot->linkIndex("tip")];
        std::vector<double> seed = robot->defaultConfiguration(), q;
        seed[0] = 0.7;  // side_joint: not on the chain
        core::Rng rng(1);
        const IkResult r = ik.solve(IkTarget::position(t.translation()), seed, rng, q);
        EXPECT_EQ(q[0], 0.7);
        solved += r.status == IkStatus::Solved ? 1 : 0;
        EXPECT_TRUE(robot->withinBounds(q.data()));
    }
    EXPECT_EQ(solved, 30);
}

TEST(InverseKinematics, UnreachableTargetIsAStatus)
{
    const auto robot = RobotModel::fromUrdfFile(test::shippedArmUrdf());
    const InverseKinematics ik(robot, "tcp");
    IkOptions options;
    options.restarts = 20;
    core::Rng rng(1);
    std::vector<double> q;
    const IkResult r =
        ik.solve(IkTarget::position(Eigen::Vector3d(5.0, 0.0, 0.5)), robot->defaultConfiguration(), rng, q, options);
    EXPECT_EQ(r.status, IkStatus::NotConverged);
    EXPECT_EQ(r.attempts, 21u);
    EXPECT_GT(r.positionError, 3.0);
    EXPECT_TRUE(robot->withinBounds(q.data()));
    // the best configuration returned points at the target: no other reaches closer than it by much
    double closest = 1e9;
    core::Rng samples(2);
    for (int s = 0; s < 2000; ++s)
    {
        const std::vector<double> c = randomConfiguration(*robot, samples);
        closest = std::min(closest, (robot->linkTransformsReference(c.data())[robot->linkIndex("tcp")].translation() -
                                     Eigen::Vector3d(5.0, 0.0, 0.5))
                                        .norm());
    }
    EXPECT_LE(r.positionError, closest + 1e-6);
    // with a time limit the solve stops: timed out (or out of restarts first), never an exception
    options.restarts = 100000000;
    options.timeLimit = 0.02;
    const IkResult timed =
        ik.solve(IkTarget::position(Eigen::Vector3d(5.0, 0.0, 0.5)), robot->defaultConfiguration(), rng, q, options);
    EXPECT_EQ(timed.status, IkStatus::TimedOut);
    EXPECT_LT(timed.attempts, 100000000u);
}

TEST(InverseKinematics, SameSeedSameResult)
{
    const auto robot = RobotModel::fromUrdfFile(test::shippedArmUrdf());
    const InverseKinematics ik(robot, "tcp");
    core::Rng goals(9);
    std::vector<double> goal = randomConfiguration(*robot, goals);
    const Eigen::Isometry3d t = robot->linkTransformsReference(goal.data())[robot->linkIndex("tcp")];
    // a predicate that rejects the first three solutions forces restarts, so the RNG decides the result
    std::vector<std::vector<double>> results;
    std::vector<std::size_t> attempts;
    for (std::uint64_t seed : {5u, 5u, 6u})
    {
        int calls = 0;
        const ConfigurationPredicate fourthOnward = [&calls](const double *) { return ++calls > 3; };
        core::Rng rng(seed);
        std::vector<double> q;
        const IkResult r = ik.solve(IkTarget::position(t.translation()), robot->defaultConfiguration(), rng, q,
                                    IkOptions(), fourthOnward);
        EXPECT_EQ(r.status, IkStatus::Solved);
        EXPECT_GE(r.attempts, 4u);
        results.push_back(q);
        attempts.push_back(r.attempts);
    }
    EXPECT_EQ(results[0], results[1]);
    EXPECT_EQ(attempts[0], attempts[1]);
    EXPECT_NE(results[0], results[2]);
}

TEST(InverseKinematics, CollisionFreeOptionGivesValidConfigurations)
{
    const auto robot = RobotModel::fromUrdfFile(test::shippedArmUrdf(),
                                                std::string(ROPRAS_SOURCE_DIR) + "/robots/ropras_arm/ropras_arm.srdf");
    const CollisionChecker checker(robot);
    const Environment env = loadPlanningScene(std::string(ROPRAS_SOURCE_DIR) + "/scenes/tabletop.yaml");
    const InverseKinematics ik(robot, "tcp");
    const ConfigurationPredicate valid = collisionFreePredicate(checker, env);
    core::Rng goals(13);
    int targets = 0, solved = 0, invalidWithout = 0;
    while (targets < 30)
    {
        const std::vector<double> goal = randomConfiguration(*robot, goals);
        if (!checker.isValid(env, goal.data()))
            continue;  // a target some valid configuration reaches
        ++targets;
        const Eigen::Vector3d p = robot->linkTransformsReference(goal.data())[robot->linkIndex("tcp")].translation();
        std::vector<double> q;
        core::Rng rng(static_cast<std::uint64_t>(targets));
        const IkResult r = ik.solve(IkTarget::position(p), robot->defaultConfiguration(), rng, q, IkOptions(), valid);
        if (r.status == IkStatus::Solved)
        {
            ++solved;
            EXPECT_TRUE(checker.isValid(env, q.data()));
        }
        core::Rng again(static_cast<std::uint64_t>(targets));
        const IkResult free = ik.solve(IkTarget::position(p), robot->defaultConfiguration(), again, q);
        EXPECT_EQ(free.status, IkStatus::Solved);
        invalidWithout += checker.isValid(env, q.data()) ? 0 : 1;
    }
    EXPECT_GE(solved, 28);
    EXPECT_GT(invalidWithout, 0) << "the scene never made a difference: the test would not catch a predicate ignored";

    // a predicate that rejects everything: the target is reached but no solution is valid
    const ConfigurationPredicate never = [](const double *) { return false; };
    core::Rng rng(1);
    std::vector<double> q;
    IkOptions options;
    options.restarts = 5;
    const Eigen::Vector3d p =
        robot->linkTransformsReference(robot->defaultConfiguration().data())[robot->linkIndex("tcp")].translation();
    EXPECT_EQ(ik.solve(IkTarget::position(p), robot->defaultConfiguration(), rng, q, options, never).status,
              IkStatus::NoValidSolution);
}

TEST(InverseKinematics, BadInputIsAnErrorNamingTheValue)
{
    const double nan = std::nan("");
    test::expectErrorMentions([&] { IkTarget::position(Eigen::Vector3d(0.1, nan, 0.2)); }, {"position", "nan"});
    test::expectErrorMentions([&] { IkTarget::positionAxis(Eigen::Vector3d(0.1, 0, 0.2), Eigen::Vector3d::Zero()); },
                              {"approach axis", "zero"});
    test::expectErrorMentions(
        [&]
        { IkTarget::positionAxis(Eigen::Vector3d(0.1, 0, 0.2), Eigen::Vector3d::UnitX(), Eigen::Vector3d::Zero()); },
        {"tool axis"});
    test::expectErrorMentions([&]
                              { IkTarget::pose(Eigen::Vector3d(0.1, 0, 0.2), Eigen::Quaterniond(2.0, 0.0, 0.0, 0.0)); },
                              {"quaternion", "(2, 0, 0, 0)", "unit"});
    test::expectErrorMentions(
        [&] { IkTarget::pose(Eigen::Vector3d(0.1, 0, 0.2), Eigen::Quaterniond(nan, 0.0, 0.0, 1.0)); }, {"quaternion"});
    Eigen::Isometry3d skew = Eigen::Isometry3d::Identity();
    skew.linear()(0, 1) = 0.5;
    test::expectErrorMentions([&] { IkTarget::pose(skew); }, {"orthonormal"});

    const auto robot = RobotModel::fromUrdfFile(test::shippedArmUrdf());
    test::expectErrorMentions([&] { InverseKinematics(robot, "no_such_tip"); }, {"no_such_tip"});
    const InverseKinematics ik(robot, "tcp");
    core::Rng rng(1);
    std::vector<double> q;
    const IkTarget target = IkTarget::position(Eigen::Vector3d(0.3, 0.1, 0.4));
    test::expectErrorMentions([&] { ik.solve(target, std::vector<double>(3, 0.0), rng, q); }, {"3 values", "6"});
    std::vector<double> seed = robot->defaultConfiguration();
    seed[2] = nan;
    test::expectErrorMentions([&] { ik.solve(target, seed, rng, q); }, {"elbow_joint", "nan"});
    IkOptions options;
    options.positionTolerance = -1.0;
    test::expectErrorMentions([&] { ik.solve(target, robot->defaultConfiguration(), rng, q, options); },
                              {"positionTolerance"});
    options = IkOptions();
    options.timeLimit = nan;
    test::expectErrorMentions([&] { ik.solve(target, robot->defaultConfiguration(), rng, q, options); }, {"timeLimit"});
    options = IkOptions();
    options.maxIterations = 0;
    test::expectErrorMentions([&] { ik.solve(target, robot->defaultConfiguration(), rng, q, options); },
                              {"maxIterations"});
}

TEST(InverseKinematics, SolveAndChainDoNotAllocate)
{
    const auto robot = RobotModel::fromUrdfFile(test::shippedArmUrdf());
    const InverseKinematics ik(robot, "tcp");
    const KinematicChain &chain = ik.chain();
    IkWorkspace ws = ik.makeWorkspace();
    ChainWorkspace cws = chain.makeWorkspace();
    IkOptions options;
    options.timeLimit = 1.0;
    core::Rng goals(3), rng(4);
    std::vector<std::vector<double>> goalConfigurations;
    for (int k = 0; k < 20; ++k)
        goalConfigurations.push_back(randomConfiguration(*robot, goals));
    const std::vector<double> seed = robot->defaultConfiguration();
    std::vector<double> q(robot->dof()), batch(12 * 5), qs;
    for (int k = 0; k < 5; ++k)
        qs.insert(qs.end(), goalConfigurations[k].begin(), goalConfigurations[k].end());
    const ConfigurationPredicate pickFirstJointPositive = [](const double *c) { return c[0] > 0.0; };
    int solved = 0;
    const std::size_t before = test::allocationCount.load();
    for (const std::vector<double> &goal : goalConfigurations)
    {
        const Eigen::Isometry3d t = chain.tipPose(goal.data());
        chain.jacobian(goal.data(), cws);
        chain.tipPosesBatch(qs.data(), 5, batch.data());
        for (const IkTarget &target : {IkTarget::position(t.translation()),
                                       IkTarget::positionAxis(t.translation(), t.linear().col(2)), IkTarget::pose(t)})
        {
            const IkResult r = ik.solve(target, seed.data(), rng, ws, q.data(), options, &pickFirstJointPositive);
            solved += r.status == IkStatus::Solved ? 1 : 0;
        }
    }
    EXPECT_EQ(test::allocationCount.load(), before);
    EXPECT_GT(solved, 50);  // the calls did real work (the predicate rejects about half the solutions)
}
