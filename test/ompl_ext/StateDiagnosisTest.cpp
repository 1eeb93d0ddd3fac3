// explainInvalidState: the checker's verdict with its cause — which joint is outside its limits (or not finite),
// which link touches which obstacle, which two links touch — cross-checked against the double-precision FCL
// reference on random configurations of the shipped arm.
#include "ropras/ompl_ext/collision/StateDiagnosis.h"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <random>
#include <string>
#include <vector>

#include "ropras/ompl_ext/collision/CrossCheck.h"
#include "ropras/ompl_ext/collision/FclReferenceChecker.h"

using namespace ropras::ompl_ext;

namespace
{
    std::shared_ptr<const RobotModel> shippedArm()
    {
        const std::string dir = std::string(ROPRAS_SOURCE_DIR) + "/robots/ropras_arm/";
        return RobotModel::fromUrdfFile(dir + "ropras_arm.urdf", dir + "ropras_arm.srdf");
    }

    bool contains(const std::string &text, const std::string &part)
    {
        return text.find(part) != std::string::npos;
    }
}  // namespace

TEST(StateDiagnosis, NamesTheJointOutsideItsLimits)
{
    const auto robot = shippedArm();
    const CollisionChecker checker(robot);
    const Environment empty;
    std::vector<double> q(robot->dof(), 0.0);
    EXPECT_EQ(explainInvalidState(checker, empty, q.data()), "");
    const PlanningJoint &elbow = robot->joints()[2];
    q[2] = elbow.upper + 0.5;
    const std::string why = explainInvalidState(checker, empty, q.data());
    EXPECT_EQ(why.rfind("outside the joint limits: joint '" + elbow.name + "' = ", 0), 0u) << why;
    EXPECT_TRUE(contains(why, "is outside its limits [-2.5, 2.5]")) << why;
    q[0] = std::numeric_limits<double>::quiet_NaN();
    const std::string both = explainInvalidState(checker, empty, q.data());
    EXPECT_TRUE(contains(both, "joint '" + robot->joints()[0].name + "' = nan is not a finite number")) << both;
    EXPECT_TRUE(contains(both, "joint '" + elbow.name + "'")) << both;
}

TEST(StateDiagnosis, NamesThePairInCollisionAsTheReferenceDoes)
{
    const auto robot = shippedArm();
    const CollisionChecker checker(robot);
    const FclSphereChecker reference(robot);
    Environment env;
    Eigen::Isometry3d pose = Eigen::Isometry3d::Identity();
    pose.translation() = Eigen::Vector3d(0.45, 0.0, 0.3);
    env.addBox("crate", pose, Eigen::Vector3d(0.3, 0.3, 0.3));
    const Environment empty;
    std::mt19937_64 rng(7);
    std::vector<double> q(robot->dof());
    std::size_t obstacle = 0, self = 0, valid = 0;
    for (int k = 0; k < 400; ++k)
    {
        sampleConfiguration(*robot, rng, q.data());
        for (const Environment *e : {static_cast<const Environment *>(&env), &empty})
        {
            const std::string why = explainInvalidState(checker, *e, q.data());
            if (checker.isValid(*e, q.data()))
            {
                EXPECT_EQ(why, "");
                ++valid;
                continue;
            }
            ASSERT_FALSE(why.empty());
            const std::string contact = reference.describeCollision(*e, q.data());
            if (contact.empty())  // float rounding at contact: the explanation says so, with the distance
            {
                EXPECT_TRUE(contains(why, "within rounding of contact")) << why;
                continue;
            }
            EXPECT_EQ(why, "in collision: " + contact);
            if (contains(why, "self-collision: "))
                ++self;
            else
            {
                EXPECT_TRUE(contains(why, "touches object 'crate'")) << why;
                ++obstacle;
            }
        }
    }
    EXPECT_GT(obstacle, 10u);
    EXPECT_GT(self, 0u);
    EXPECT_GT(valid, 100u);
}
