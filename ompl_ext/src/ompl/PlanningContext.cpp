#include "ropras/ompl_ext/ompl/PlanningContext.h"

#include "ropras/core/Error.h"
#include "ropras/ompl_ext/ompl/JointStateSpace.h"
#include "ropras/ompl_ext/ompl/PlannerRegistry.h"

namespace ropras::ompl_ext
{
    std::shared_ptr<ompl::base::RealVectorStateSpace> createStateSpace(const RobotModel &robot)
    {
        if (robot.dof() == 0)
            throw Error("robot '" + robot.name() + "' (" + robot.source() + ") has no planning joints");
        auto space = std::make_shared<JointStateSpace>(robot.dof());
        ompl::base::RealVectorBounds bounds(robot.dof());
        for (std::size_t i = 0; i < robot.dof(); ++i)
        {
            const PlanningJoint &joint = robot.joints()[i];
            bounds.setLow(i, joint.lower);
            bounds.setHigh(i, joint.upper);
            space->setDimensionName(i, joint.name);
        }
        space->setBounds(bounds);
        space->setName(robot.name());
        return space;
    }

    void PlanningContext::setEnvironment(std::shared_ptr<const Environment> environment)
    {
        validityChecker->setEnvironment(environment);
        motionValidator->setEnvironment(std::move(environment));
    }

    void PlanningContext::setState(ompl::base::State *state, const std::map<std::string, double> &jointValues,
                                   const std::string &context, std::vector<std::string> *warnings) const
    {
        const std::vector<double> q = robot->planningValues(jointValues, context, warnings);
        std::copy(q.begin(), q.end(), state->as<ompl::base::RealVectorStateSpace::StateType>()->values);
    }

    PlanningContext makePlanningContext(std::shared_ptr<const RobotModel> robot,
                                        std::shared_ptr<const Environment> environment,
                                        const PlanningContextOptions &options)
    {
        if (!robot)
            throw Error("makePlanningContext: null RobotModel");
        if (!environment)
            throw Error("makePlanningContext: null Environment");
        PlanningContext context;
        context.robot = robot;
        if (options.checker && &options.checker->robot() != robot.get())
            throw Error("makePlanningContext: the shared CollisionChecker is for robot '" +
                        options.checker->robot().name() + "', not for the context's robot object '" + robot->name() +
                        "'");
        context.checker =
            options.checker ? options.checker : std::make_shared<CollisionChecker>(robot, options.backend);
        context.setup = std::make_shared<ompl::geometric::SimpleSetup>(createStateSpace(*robot));
        const auto &si = context.setup->getSpaceInformation();
        context.validityChecker = std::make_shared<StateValidityChecker>(si, context.checker, environment);
        context.motionValidator =
            std::make_shared<MotionValidator>(si, context.checker, environment, options.resolution);
        context.setup->setStateValidityChecker(context.validityChecker);
        si->setMotionValidator(context.motionValidator);
        if (!options.planner.empty())
            context.setup->setPlanner(PlannerRegistry::instance().create(options.planner, si, options.plannerParams));
        else if (!options.plannerParams.empty())
            throw Error("makePlanningContext: planner parameters given without a planner name");
        si->setup();  // SimpleSetup::setup() also needs start and goal; it runs again in solve()
        return context;
    }

    PlanningContext makePlanningContext(const std::string &urdfPath, const std::string &srdfPath,
                                        std::shared_ptr<const Environment> environment,
                                        const RobotModel::Options &robotOptions, const PlanningContextOptions &options)
    {
        return makePlanningContext(RobotModel::fromUrdfFile(urdfPath, srdfPath, robotOptions), std::move(environment),
                                   options);
    }
}  // namespace ropras::ompl_ext
