// Link poses (single and batch) against the reference FK and Orocos KDL; the chain's Jacobian against finite
// differences of its FK.
#include <gtest/gtest.h>
#include <kdl/chainfksolverpos_recursive.hpp>
#include <kdl/tree.hpp>
#include <kdl_parser/kdl_parser.hpp>

#include "ExpectError.h"
#include "KinematicsTestRobots.h"
#include "ropras/ompl_ext/kinematics/KinematicChain.h"
#include "ropras/ompl_ext/kinematics/LinkPoses.h"

namespace
{
    using namespace ropras;
    using namespace ropras::ompl_ext;
    using ropras::test::randomConfiguration;
    using ropras::test::rotationAngle;

    /// every link of \a robot at \a samples random configurations: LinkPoses vs the reference FK
    void expectLinkPosesMatchReference(const std::shared_ptr<const RobotModel> &robot, int samples)
    {
        const LinkPoses poses(robot);
        core::Rng rng(7);
        double worstPosition = 0.0, worstAngle = 0.0;
        for (int s = 0; s < samples; ++s)
        {
            const std::vector<double> q = randomConfiguration(*robot, rng);
            const std::vector<Eigen::Isometry3d> reference = robot->linkTransformsReference(q.data());
            for (std::size_t l = 0; l < robot->links().size(); ++l)
            {
                const Eigen::Isometry3d t = poses.linkPose(q.data(), static_cast<int>(l));
                worstPosition = std::max(worstPosition, (t.translation() - reference[l].translation()).norm());
                worstAngle = std::max(worstAngle, rotationAngle(t.linear(), reference[l].linear()));
                EXPECT_TRUE(t.matrix().row(3).isApprox(Eigen::RowVector4d(0, 0, 0, 1)));
            }
        }
        EXPECT_LT(worstPosition, 1e-6) << robot->name();
        EXPECT_LT(worstAngle, 1e-6) << robot->name();
    }

    /// batch of every size 1..9 (the 4-wide blocks and their tails) against the single path, for every link
    void expectBatchMatchesSingle(const std::shared_ptr<const RobotModel> &robot)
    {
        const LinkPoses poses(robot);
        core::Rng rng(11);
        const std::size_t dof = robot->dof();
        for (std::size_t count = 1; count <= 9; ++count)
        {
            std::vector<double> qs;
            for (std::size_t k = 0; k < count; ++k)
            {
                const std::vector<double> q = randomConfiguration(*robot, rng);
                qs.insert(qs.end(), q.begin(), q.end());
            }
            for (std::size_t l = 0; l < robot->links().size(); ++l)
            {
                std::vector<double> out(12 * count + 12, -7.0);  // one extra pose must stay untouched
                poses.linkPosesBatch(qs.data(), count, static_cast<int>(l), out.data());
                for (std::size_t k = 0; k < count; ++k)
                {
                    const Eigen::Isometry3d t = poses.linkPose(qs.data() + k * dof, static_cast<int>(l));
                    const Eigen::Map<const Eigen::Matrix3d> r(out.data() + 12 * k);
                    const Eigen::Map<const Eigen::Vector3d> p(out.data() + 12 * k + 9);
                    EXPECT_LT((r - t.linear()).cwiseAbs().maxCoeff(), 1e-12) << "link " << l << " of " << count;
                    EXPECT_LT((p - t.translation()).cwiseAbs().maxCoeff(), 1e-12) << "link " << l << " of " << count;
                }
                for (std::size_t i = 12 * count; i < out.size(); ++i)
                    EXPECT_EQ(out[i], -7.0);
            }
        }
    }
}  // namespace

TEST(LinkPoses, EveryJointTypeMatchesReference)
{
    const auto robot = test::everyJointTypeArm();
    expectLinkPosesMatchReference(robot, 200);
    expectBatchMatchesSingle(robot);
    // the chain to the tip: the planning joints on the path in root -> tip order, the held one folded away
    const KinematicChain chain(robot, "tip");
    ASSERT_EQ(chain.size(), 5u);
    const std::vector<std::string> names{"a", "slide", "b", "c", "d"};
    for (std::size_t i = 0; i < names.size(); ++i)
        EXPECT_EQ(chain.joints()[i].name, names[i]);
    EXPECT_TRUE(chain.joints()[1].prismatic);
    EXPECT_TRUE(chain.joints()[3].continuous);
    // the root link's pose is the base pose; a link with no planning joint above it does not move
    const LinkPoses poses(robot);
    const std::vector<double> q = robot->defaultConfiguration();
    EXPECT_TRUE(poses.linkPose(q.data(), "base").isApprox(robot->basePose(), 1e-14));
    EXPECT_EQ(poses.chain("base").size(), 0u);
}

TEST(LinkPoses, ShippedArmAndPandaMatchReference)
{
    expectLinkPosesMatchReference(RobotModel::fromUrdfFile(test::shippedArmUrdf()), 300);
    expectBatchMatchesSingle(RobotModel::fromUrdfFile(test::shippedArmUrdf()));
    if (!test::haveSharedRobots())
        GTEST_SKIP() << "../shared not found: " << ROPRAS_SHARED_DIR << " (the Panda part needs robots/panda)";
    const auto panda = RobotModel::fromUrdfFile(test::sharedRobot("panda/panda_spherized.urdf"));
    expectLinkPosesMatchReference(panda, 300);
    expectBatchMatchesSingle(panda);
}

TEST(LinkPoses, UnknownLinkIsAnError)
{
    const auto robot = RobotModel::fromUrdfFile(test::shippedArmUrdf());
    const LinkPoses poses(robot);
    const std::vector<double> q = robot->defaultConfiguration();
    test::expectErrorMentions([&] { poses.linkPose(q.data(), "no_such_link"); }, {"no_such_link", "ropras_arm"});
    test::expectErrorMentions([&] { KinematicChain(robot, "tool_lnk"); }, {"tool_lnk"});
    std::vector<double> out(12);
    test::expectErrorMentions([&] { poses.linkPosesBatch(q.data(), 1, "wrist", out.data()); }, {"wrist"});
}

TEST(KinematicChain, JacobianMatchesFiniteDifferences)
{
    for (const auto &[robot, tip] : {std::pair(test::everyJointTypeArm(), std::string("tip")),
                                     std::pair(RobotModel::fromUrdfFile(test::shippedArmUrdf()), std::string("tcp"))})
    {
        const KinematicChain chain(robot, tip);
        ChainWorkspace ws = chain.makeWorkspace();
        core::Rng rng(3);
        const double h = 1e-6;
        for (int s = 0; s < 50; ++s)
        {
            std::vector<double> q = randomConfiguration(*robot, rng);
            chain.jacobian(q.data(), ws);
            EXPECT_TRUE(ws.tip.isApprox(chain.tipPose(q.data()), 1e-14));
            for (std::size_t i = 0; i < chain.size(); ++i)
            {
                const auto v = static_cast<std::size_t>(chain.joints()[i].variable);
                std::vector<double> plus = q, minus = q;
                plus[v] += h;
                minus[v] -= h;
                const Eigen::Isometry3d tp = chain.tipPose(plus.data()), tm = chain.tipPose(minus.data());
                const Eigen::Vector3d linear = (tp.translation() - tm.translation()) / (2 * h);
                const Eigen::AngleAxisd d(tp.linear() * tm.linear().transpose());
                const Eigen::Vector3d angular = d.axis() * d.angle() / (2 * h);
                const auto col = static_cast<Eigen::Index>(i);
                EXPECT_LT((ws.jacobian().block<3, 1>(0, col) - linear).norm(), 1e-6) << tip << " joint " << i;
                EXPECT_LT((ws.jacobian().block<3, 1>(3, col) - angular).norm(), 1e-6) << tip << " joint " << i;
            }
        }
    }
}

TEST(KinematicChain, AgreesWithKdlForwardKinematics)
{
    std::vector<std::pair<std::string, std::string>> robots{{test::shippedArmUrdf(), "tcp"}};
    if (test::haveSharedRobots())
        robots.emplace_back(test::sharedRobot("panda/panda_spherized.urdf"), "panda_hand");
    else
        std::cout << "../shared not found: the Panda part is skipped\n";
    for (const auto &[urdf, tip] : robots)
    {
        const auto robot = RobotModel::fromUrdfFile(urdf);
        const KinematicChain chain(robot, tip);
        KDL::Tree tree;
        ASSERT_TRUE(kdl_parser::treeFromFile(urdf, tree)) << urdf;
        KDL::Chain kdl;
        ASSERT_TRUE(tree.getChain(robot->links().front().name, tip, kdl));
        ASSERT_EQ(kdl.getNrOfJoints(), chain.size());
        KDL::ChainFkSolverPos_recursive fk(kdl);
        core::Rng rng(5);
        for (int s = 0; s < 200; ++s)
        {
            const std::vector<double> q = randomConfiguration(*robot, rng);
            KDL::JntArray jq(kdl.getNrOfJoints());
            for (std::size_t i = 0; i < chain.size(); ++i)
                jq(static_cast<unsigned>(i)) = q[static_cast<std::size_t>(chain.joints()[i].variable)];
            KDL::Frame f;
            ASSERT_GE(fk.JntToCart(jq, f), 0);
            const Eigen::Isometry3d t = chain.tipPose(q.data());
            Eigen::Matrix3d r;
            for (int a = 0; a < 3; ++a)
            {
                EXPECT_NEAR(t.translation()[a], f.p(a), 1e-9) << urdf;
                for (int b = 0; b < 3; ++b)
                    r(a, b) = f.M(a, b);
            }
            EXPECT_LT(rotationAngle(t.linear(), r), 1e-9) << urdf;
        }
    }
}
