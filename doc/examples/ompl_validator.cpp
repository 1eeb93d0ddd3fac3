// Tutorial example (doc/ompl-plugin.md): ropras' vectorized validators inside a plain OMPL program.
//   example_ompl_validator [URDF [SCENE.yaml [SRDF]]]
// Defaults: the arm and the tabletop scene that ship with ropras. Any robot works: the start is the middle of every
// joint's range (all zeros is outside the Panda's joint 4 limits), the goal a step from it, within the limits.
#include <ompl/base/spaces/RealVectorStateSpace.h>
#include <ompl/geometric/SimpleSetup.h>
#include <ompl/geometric/planners/rrt/RRTConnect.h>
#include <ompl/util/Console.h>
#include <algorithm>
#include <iostream>

#include <ropras/ompl_ext/collision/CollisionChecker.h>
#include <ropras/ompl_ext/collision/StateDiagnosis.h>
#include <ropras/ompl_ext/ompl/MotionValidator.h>
#include <ropras/ompl_ext/ompl/PlanningContext.h>
#include <ropras/ompl_ext/ompl/StateValidityChecker.h>
#include <ropras/ompl_ext/scene/SceneYaml.h>

namespace ob = ompl::base;
namespace og = ompl::geometric;
namespace rx = ropras::ompl_ext;

int main(int argc, char **argv)
try
{
    const std::string urdf = argc > 1 ? argv[1] : ROPRAS_DEFAULT_ROBOTS_DIR "/ropras_arm/ropras_arm.urdf";
    const std::string scene = argc > 2 ? argv[2] : ROPRAS_DEFAULT_SCENES_DIR "/tabletop.yaml";
    const std::string srdf = argc > 3 ? argv[3] : "";  // disabled self-collision pairs (MoveIt's SRDF)
    ompl::msg::setLogLevel(ompl::msg::LOG_WARN);

    // 1. The robot (any URDF, loaded at run time; its SRDF disables the link pairs that touch by design) and the
    //    obstacles.
    auto robot = rx::RobotModel::fromUrdfFile(urdf, srdf);
    auto environment = std::make_shared<const rx::Environment>(rx::loadPlanningScene(scene));

    // 2. An ordinary OMPL setup over the planning joints, bounds from the joint limits.
    og::SimpleSetup ss(rx::createStateSpace(*robot));
    const ob::SpaceInformationPtr &si = ss.getSpaceInformation();

    // 3. Install the ropras validators: one shared CollisionChecker (thread-safe), the environment shared by both.
    auto checker = std::make_shared<const rx::CollisionChecker>(robot);
    ss.setStateValidityChecker(std::make_shared<rx::StateValidityChecker>(si, checker, environment));
    si->setMotionValidator(std::make_shared<rx::MotionValidator>(si, checker, environment, 1.0 / 32.0));

    // 4. Start and goal within the joint limits; explainInvalidState says which joint or which pair is wrong.
    ob::ScopedState<> start(ss.getStateSpace()), goal(ss.getStateSpace());
    for (std::size_t i = 0; i < robot->dof(); ++i)
    {
        const rx::PlanningJoint &joint = robot->joints()[i];
        start[i] = 0.5 * (joint.lower + joint.upper);
        goal[i] = std::clamp(start[i] + (i % 2 == 0 ? 0.6 : -0.4), joint.lower, joint.upper);
    }
    for (const auto &[name, state] : {std::pair{"start", &start}, std::pair{"goal", &goal}})
    {
        const std::string why = rx::explainInvalidState(*checker, *environment, state->reals().data());
        if (!why.empty())
        {
            std::cerr << "the " << name << " is invalid for this robot and scene: " << why
                      << "\npick other joint values\n";
            return 1;
        }
    }

    // 5. Plan as usual with any OMPL planner.
    ss.setStartAndGoalStates(start, goal);
    ss.setPlanner(std::make_shared<og::RRTConnect>(si));
    const ob::PlannerStatus status = ss.solve(ob::timedPlannerTerminationCondition(1.0));
    std::cout << "status: " << status.asString() << ", plan time " << ss.getLastPlanComputationTime() * 1e6 << " us\n";
    if (status != ob::PlannerStatus::EXACT_SOLUTION)
        return 1;
    ss.simplifySolution();
    std::cout << "path: " << ss.getSolutionPath().getStateCount() << " states, length " << ss.getSolutionPath().length()
              << " rad, valid " << ss.getSolutionPath().check() << '\n';
    return 0;
}
catch (const std::exception &e)
{
    std::cerr << "error: " << e.what() << '\n';
    return 2;
}
