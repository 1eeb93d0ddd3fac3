// The synthetic benchmark robots of test/data/robots (scripts/make-test-robots.py): a Panda on a prismatic torso
// (8 joints) and two Pandas on one torso (14 joints, SRDF group "both_arms"). Their SIMD FK (single and batch, every
// backend; the batch takes the row-by-row path past 8 joints) against the reference FK in double, their verdicts
// against brute force in an empty world (self-collision), and a plan with each registry RRT-Connect.
#include <gtest/gtest.h>
#include <ompl/geometric/SimpleSetup.h>

#include <algorithm>
#include <cmath>
#include <map>
#include <memory>
#include <random>
#include <string>
#include <tuple>
#include <vector>

#include "CollisionCheckerTestUtil.h"
#include "ropras/ompl_ext/collision/CollisionChecker.h"
#include "ropras/ompl_ext/model/RobotModel.h"
#include "ropras/ompl_ext/ompl/MotionValidator.h"
#include "ropras/ompl_ext/ompl/PlannerRegistry.h"
#include "ropras/ompl_ext/ompl/PlanningContext.h"
#include "ropras/ompl_ext/ompl/StateValidityChecker.h"
#include "ropras/ompl_ext/planners/VectorizedRRTConnect.h"
#include "ropras/ompl_ext/scene/Environment.h"

using namespace ropras::ompl_ext;
using ropras::test::randomConfig;
using ropras::test::referenceMargin;

namespace
{
    std::shared_ptr<const RobotModel> testRobot(const std::string &name, const std::string &group = "")
    {
        const std::string dir = std::string(ROPRAS_SOURCE_DIR) + "/test/data/robots/" + name + "/";
        RobotModel::Options options;
        options.group = group;
        return RobotModel::fromUrdfFile(dir + name + ".urdf", dir + name + ".srdf", options);
    }

    /// brute force in an empty world: some enabled self pair of spheres overlaps (reference FK, double)
    bool referenceSelfCollision(const RobotModel &robot, const double *q)
    {
        return referenceMargin(robot, Environment(), q) < 0.0;
    }

    void checkFkAndVerdicts(const std::shared_ptr<const RobotModel> &robot)
    {
        const std::size_t dof = robot->dof(), ns = robot->spheres().size();
        std::vector<SimdBackend> backends{SimdBackend::Scalar};
        if (simdBackendAvailable(SimdBackend::Avx2))
            backends.push_back(SimdBackend::Avx2);
        const Environment empty;
        for (SimdBackend backend : backends)
        {
            CollisionChecker checker(robot, backend);
            const auto w = static_cast<std::size_t>(checker.width());
            std::mt19937_64 rng(3);
            std::vector<float> single(4 * ns), batch(4 * ns * w);
            std::vector<double> qs(dof * w);
            double worst = 0.0;
            int invalid = 0, disagreements = 0, nearContact = 0;
            for (int k = 0; k < 1200; k += static_cast<int>(w))
            {
                for (std::size_t i = 0; i < w; ++i)
                {
                    const auto q = randomConfig(*robot, rng);
                    std::copy(q.begin(), q.end(), qs.begin() + static_cast<std::ptrdiff_t>(i * dof));
                }
                checker.sphereCentersBatch(qs.data(), batch.data());
                bool verdicts[64];
                checker.isValidBatch(empty, qs.data(), w, verdicts);
                for (std::size_t i = 0; i < w; ++i)
                {
                    const double *q = qs.data() + i * dof;
                    const auto ref = robot->sphereCentersReference(q);
                    checker.sphereCenters(q, single.data());
                    for (std::size_t s = 0; s < ns; ++s)
                    {
                        const Eigen::Vector3d a(single[4 * s], single[4 * s + 1], single[4 * s + 2]);
                        const Eigen::Vector3d b(batch[(4 * s) * w + i], batch[(4 * s + 1) * w + i],
                                                batch[(4 * s + 2) * w + i]);
                        worst = std::max({worst, (a - ref[s]).norm(), (b - ref[s]).norm()});
                    }
                    const bool expected = !referenceSelfCollision(*robot, q);
                    const bool got = checker.isValid(empty, q);
                    invalid += expected ? 0 : 1;
                    if (got != expected || verdicts[i] != expected)
                    {
                        // float FK may decide contacts within its rounding either way: count those apart
                        std::vector<double> probe(q, q + dof);
                        bool near = false;
                        for (double d : {-1e-4, 1e-4})
                            for (std::size_t j = 0; j < dof && !near; ++j)
                            {
                                probe = std::vector<double>(q, q + dof);
                                probe[j] = std::clamp(probe[j] + d, robot->joints()[j].lower, robot->joints()[j].upper);
                                near = referenceSelfCollision(*robot, probe.data()) == expected;
                            }
                        (near ? nearContact : disagreements) += 1;
                    }
                }
            }
            EXPECT_LT(worst, 2e-5) << robot->name() << " " << simdBackendName(backend);
            EXPECT_GT(worst, 0.0);  // float results were compared
            EXPECT_EQ(disagreements, 0) << robot->name() << " " << simdBackendName(backend);
            EXPECT_LE(nearContact, 3);
            EXPECT_GT(invalid, 20) << "the self-collision test is exercised";
            EXPECT_LT(invalid, 1100) << "most random configurations are valid";
        }
    }
}  // namespace

TEST(TestRobots, PandaOnAPrismaticTorsoMatchesReferenceFk)
{
    const auto robot = testRobot("panda_torso", "arm_with_torso");
    ASSERT_EQ(robot->dof(), 8u);
    EXPECT_EQ(robot->joints()[0].name, "torso_lift_joint");
    EXPECT_DOUBLE_EQ(robot->joints()[0].upper, 0.4);
    // the lift moves every arm sphere by its value along z
    std::vector<double> q(8, 0.0);
    q[3] = -1.5;
    const auto low = robot->sphereCentersReference(q.data());
    q[0] = 0.3;
    const auto high = robot->sphereCentersReference(q.data());
    const auto &links = robot->collisionLinks();
    int moved = 0;
    for (std::size_t s = 0; s < low.size(); ++s)
    {
        const bool onBase = links[static_cast<std::size_t>(robot->spheres()[s].collisionLink)].name == "base_link";
        EXPECT_NEAR((high[s] - low[s]).z(), onBase ? 0.0 : 0.3, 1e-12);
        moved += onBase ? 0 : 1;
    }
    EXPECT_GT(moved, 300);
    checkFkAndVerdicts(robot);
}

TEST(TestRobots, TwoArmsMatchReferenceFk)
{
    const auto robot = testRobot("dual_panda", "both_arms");
    ASSERT_EQ(robot->dof(), 14u);
    EXPECT_EQ(robot->joints().front().name, "left_panda_joint1");
    EXPECT_EQ(robot->joints().back().name, "right_panda_joint7");
    checkFkAndVerdicts(robot);
}

TEST(TestRobots, BothRrtConnectsPlanForTheTwoArms)
{
    // one arm's joint 1 turned by 2 rad, the other's by -2, in an empty world: every plan is valid end to end
    const auto robot = testRobot("dual_panda", "both_arms");
    auto checker = std::make_shared<const CollisionChecker>(robot);
    auto env = std::make_shared<const Environment>();
    for (const std::string planner : {"VectorizedRRTConnect", "RRTConnect"})
    {
        ompl::geometric::SimpleSetup ss(createStateSpace(*robot));
        const auto &si = ss.getSpaceInformation();
        si->setStateValidityChecker(std::make_shared<StateValidityChecker>(si, checker, env));
        si->setMotionValidator(std::make_shared<MotionValidator>(si, checker, env));
        si->setup();
        ompl::base::ScopedState<> start(ss.getStateSpace()), goal(ss.getStateSpace());
        const double ready[7] = {0.0, -0.785, 0.0, -2.356, 0.0, 1.571, 0.785};
        for (int k = 0; k < 14; ++k)
        {
            start[k] = ready[k % 7];
            goal[k] = ready[k % 7];
        }
        goal[0] = 2.0;
        goal[7] = -2.0;
        goal[10] = -1.0;
        ASSERT_TRUE(si->isValid(start.get()));
        ASSERT_TRUE(si->isValid(goal.get()));
        ss.setStartAndGoalStates(start, goal);
        ss.setPlanner(PlannerRegistry::instance().create(planner, si, {{"range", "1.0"}}));
        ASSERT_EQ(ss.solve(10.0), ompl::base::PlannerStatus::EXACT_SOLUTION) << planner;
        const auto &path = ss.getSolutionPath();
        for (std::size_t i = 0; i + 1 < path.getStateCount(); ++i)
            EXPECT_TRUE(checker->isMotionValid(
                *env, path.getState(i)->as<ompl::base::RealVectorStateSpace::StateType>()->values,
                path.getState(i + 1)->as<ompl::base::RealVectorStateSpace::StateType>()->values,
                MotionValidator::DEFAULT_RESOLUTION))
                << planner << " segment " << i;
    }
}

TEST(TestRobots, DynamicDomainIsOnUpToEightJointsUnlessSet)
{
    // VectorizedRRTConnect's default: the dynamic domain for the 8-joint torso arm, none for the 14-joint pair of arms;
    // an explicit dynamic_domain is kept either way
    for (const auto &[name, group, expected] :
         {std::tuple{"panda_torso", "arm_with_torso", true}, std::tuple{"dual_panda", "both_arms", false}})
    {
        const auto robot = testRobot(name, group);
        ompl::geometric::SimpleSetup ss(createStateSpace(*robot));
        const auto &si = ss.getSpaceInformation();
        for (const char *set : {"", "0", "1"})
        {
            std::map<std::string, std::string> params;
            if (*set != '\0')
                params["dynamic_domain"] = set;
            auto planner = std::dynamic_pointer_cast<VectorizedRRTConnect>(
                PlannerRegistry::instance().create("VectorizedRRTConnect", si, params));
            ASSERT_TRUE(planner);
            planner->setup();
            EXPECT_EQ(planner->getDynamicDomain(), *set == '\0' ? expected : *set == '1') << name << " '" << set << "'";
        }
    }
}
