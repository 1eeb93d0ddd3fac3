// `ropras plan`: one motion plan for a MoveIt problem (PlanningScene + MotionPlanRequest) with any OMPL planner.
#include <ompl/base/PlannerTerminationCondition.h>
#include <ompl/util/Console.h>
#include <ompl/util/RandomNumbers.h>
#include <algorithm>
#include <chrono>
#include <fstream>
#include <iomanip>
#include <iostream>

#include "ArgumentChecks.h"
#include "CommandRegistry.h"
#include "OutputChecks.h"
#include "RobotSelection.h"
#include "ropras/core/Error.h"
#include "ropras/ompl_ext/collision/StateDiagnosis.h"
#include "ropras/ompl_ext/ompl/PlannerRegistry.h"
#include "ropras/ompl_ext/ompl/PlanningContext.h"
#include "ropras/ompl_ext/scene/SceneYaml.h"

namespace
{
    using namespace ropras;
    using namespace ropras::ompl_ext;

    struct PlanArgs
    {
        std::string urdf, srdf, scene, request, planner{"RRTConnect"}, out;
        std::vector<std::string> params;
        ropras::bin::RobotSelection selection;
        double time{1.0};
        double resolution{MotionValidator::DEFAULT_RESOLUTION};
        bool simplify{false};
        unsigned seed{1};
    };

    double pathLength(const ompl::geometric::PathGeometric &path)
    {
        return path.length();
    }

    int run(const PlanArgs &a)
    {
        ropras::bin::refuseOverwritingInputs("--out", a.out, {a.urdf, a.srdf, a.scene, a.request});
        ompl::msg::setLogLevel(ompl::msg::LOG_WARN);
        ompl::RNG::setSeed(a.seed);
        // the request first (its group and start state choose the planned and held joints), then the robot: the
        // scene may attach objects to its links (robot_state.attached_collision_objects)
        const MotionPlanRequest request = loadMotionPlanRequest(a.request);
        const auto robotModel = RobotModel::fromUrdfFile(a.urdf, a.srdf, a.selection.options(&request));
        ropras::bin::Warnings warnings("plan");
        warnings.add(robotModel->warnings());
        auto environment = std::make_shared<Environment>(loadPlanningScene(a.scene, robotModel));
        PlanningContextOptions options;
        options.planner = a.planner;
        options.plannerParams = ropras::bin::keyValueOptions(a.params, "--param");
        options.resolution = a.resolution;
        PlanningContext context = makePlanningContext(robotModel, environment, options);
        const RobotModel &robot = *context.robot;
        auto &ss = *context.setup;

        ompl::base::ScopedState<> start(ss.getStateSpace()), goal(ss.getStateSpace());
        std::vector<std::string> valueWarnings;
        context.setState(start.get(), request.start, a.request + ": start state", &valueWarnings);
        context.setState(goal.get(), request.goal, a.request + ": goal", &valueWarnings);
        warnings.add(valueWarnings);
        warnings.print();
        for (const auto &[what, state] : {std::pair{"start state", start.get()}, std::pair{"goal", goal.get()}})
        {
            const double *q = state->as<ompl::base::RealVectorStateSpace::StateType>()->values;
            const std::string why = explainInvalidState(*context.checker, *environment, q);
            if (!why.empty())
                throw Error(a.request + ": the " + what + " is invalid: " + why);
        }
        ss.setStartAndGoalStates(start, goal);
        ss.setup();

        const auto t0 = std::chrono::steady_clock::now();
        const ompl::base::PlannerStatus status = ss.solve(ompl::base::timedPlannerTerminationCondition(a.time));
        const double planUs = std::chrono::duration<double, std::micro>(std::chrono::steady_clock::now() - t0).count();
        const bool solved = status == ompl::base::PlannerStatus::EXACT_SOLUTION;
        std::cout << "robot " << robot.name() << " (" << robot.dof() << " joints"
                  << (robot.group().empty() ? "" : ", group " + robot.group()) << ", " << robot.spheres().size()
                  << " spheres), scene " << a.scene << " (" << environment->objectCount() << " objects)\n"
                  << "planner " << ss.getPlanner()->getName() << ": " << status.asString() << " in " << std::fixed
                  << std::setprecision(1) << planUs << " us\n";
        if (!solved)
            return 1;
        auto &path = ss.getSolutionPath();
        std::cout << "path: " << path.getStateCount() << " states, length " << std::setprecision(4) << pathLength(path)
                  << " rad\n";
        if (a.simplify)
        {
            const auto s0 = std::chrono::steady_clock::now();
            ss.simplifySolution();
            const double simpUs =
                std::chrono::duration<double, std::micro>(std::chrono::steady_clock::now() - s0).count();
            std::cout << "simplified in " << std::setprecision(1) << simpUs << " us: " << path.getStateCount()
                      << " states, length " << std::setprecision(4) << pathLength(path) << " rad\n";
        }
        const bool valid = path.check();
        std::cout << "path check: " << (valid ? "valid" : "INVALID") << '\n';
        if (!a.out.empty())
        {
            std::ofstream out(a.out);
            if (!out)
                throw Error("cannot write " + a.out);
            for (std::size_t i = 0; i < robot.dof(); ++i)
                out << (i ? "," : "") << robot.joints()[i].name;
            out << '\n' << std::setprecision(10);
            for (std::size_t k = 0; k < path.getStateCount(); ++k)
            {
                const auto *q = path.getState(k)->as<ompl::base::RealVectorStateSpace::StateType>()->values;
                for (std::size_t i = 0; i < robot.dof(); ++i)
                    out << (i ? "," : "") << q[i];
                out << '\n';
            }
            std::cout << "wrote " << a.out << '\n';
        }
        return valid ? 0 : 1;
    }

    std::function<int()> setup(CLI::App &app)
    {
        auto args = std::make_shared<PlanArgs>();
        app.add_option("--urdf", args->urdf, "robot URDF")->required()->check(CLI::ExistingFile);
        app.add_option("--srdf", args->srdf, "SRDF (disabled self-collision pairs)")->check(CLI::ExistingFile);
        app.add_option("--scene", args->scene, "MoveIt PlanningScene YAML")->required()->check(CLI::ExistingFile);
        app.add_option("--request", args->request, "MoveIt MotionPlanRequest YAML")
            ->required()
            ->check(CLI::ExistingFile);
        app.add_option("--planner", args->planner, "planner name (see `ropras planners`)")->capture_default_str();
        app.add_option("--param", args->params, "planner parameter key=value (repeatable)");
        app.add_option("--time", args->time, "planning time limit (s, at most 86400)")
            ->capture_default_str()
            ->check(ropras::bin::PLAN_SECONDS);
        app.add_option("--resolution", args->resolution, "motion-check joint step (rad)")
            ->capture_default_str()
            ->check(ropras::bin::POSITIVE_NUMBER);
        app.add_flag("--simplify", args->simplify, "simplify the path (OMPL's simplifySolution)");
        app.add_option("--out", args->out, "write the joint-space path as CSV");
        app.add_option("--seed", args->seed, "OMPL random seed")->capture_default_str()->check(ropras::bin::SEED32);
        args->selection.addOptions(app, true);
        return [args] { return run(*args); };
    }

    int listPlanners()
    {
        for (const std::string &name : PlannerRegistry::instance().names())
            std::cout << name << '\n';
        return 0;
    }

    const ropras::bin::CommandRegistrar planCommand{
        {"plan", "plan one MoveIt problem with any OMPL planner using the ropras validators", setup}};
    const ropras::bin::CommandRegistrar plannersCommand{{"planners", "list the planners available by name",
                                                         [](CLI::App &)
                                                         { return std::function<int()>(listPlanners); }}};
}  // namespace
