#include "ropras/pomdp/OmplPathPlanner.h"

#include <ompl/base/PlannerTerminationCondition.h>
#include <ompl/base/ScopedState.h>
#include <ompl/geometric/PathGeometric.h>
#include <ompl/util/Console.h>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <exception>

#include "ropras/core/Error.h"

namespace ropras::pomdp
{
    namespace
    {
        double *values(ompl::base::State *state)
        {
            return state->as<ompl::base::RealVectorStateSpace::StateType>()->values;
        }
    }  // namespace

    void OmplPathPlannerSettings::readParameters(const ParameterMap &params)
    {
        timeLimit = params.get("plan_time", timeLimit);
        maxIterations = params.getCount("plan_iterations", maxIterations);
        shortcut = params.getCount("shortcut", shortcut ? 1 : 0) != 0;
        const std::string prefix = PLANNER_PREFIX;
        for (const auto &entry : params.values())
        {
            if (entry.first.compare(0, prefix.size(), prefix) != 0)
                continue;
            const std::string name = entry.first.substr(prefix.size());
            if (name.empty())
                throw Error("OmplPathPlanner: parameter \"" + entry.first + "\" names no planner parameter");
            double value = params.get(entry.first, 0.0);  // marks it used
            if (value == 0.0)
                value = 0.0;  // -0 would be written "-0", which no bool parser takes
            // every digit of a whole number (OMPL's integer parsers stop at an exponent; the planner registry refuses
            // what does not fit the parameter's type), 17 significant digits otherwise
            char text[400];
            std::snprintf(text, sizeof text, value == std::floor(value) ? "%.0f" : "%.17g", value);
            plannerParams[name] = text;
        }
        validate();
    }

    void OmplPathPlannerSettings::validate() const
    {
        if (planner.empty())
            throw Error("OmplPathPlanner: empty planner name");
        if (!(timeLimit > 0.0) || !std::isfinite(timeLimit))
            throw Error("OmplPathPlanner: per-plan time limit (plan_time) " + std::to_string(timeLimit) +
                        " s must be finite and > 0");
        if (!(resolution > 0.0) || !std::isfinite(resolution))
            throw Error("OmplPathPlanner: motion-check resolution " + std::to_string(resolution) +
                        " must be finite and > 0");
    }

    const char *pathPlanStatusName(PathPlanStatus status) noexcept
    {
        switch (status)
        {
            case PathPlanStatus::Solved:
                return "solved";
            case PathPlanStatus::InvalidStart:
                return "invalid start";
            case PathPlanStatus::InvalidTarget:
                return "invalid target";
            case PathPlanStatus::NotFound:
                return "not found";
            case PathPlanStatus::PlannerError:
                return "planner error";
        }
        return "unknown";
    }

    OmplPathPlanner::OmplPathPlanner(std::shared_ptr<const ompl_ext::RobotModel> robot,
                                     std::shared_ptr<const ompl_ext::Environment> environment,
                                     const OmplPathPlannerSettings &settings)
        : settings_(settings), environment_(environment)
    {
        settings_.validate();
        if (!robot)
            throw Error("OmplPathPlanner: null RobotModel");
        if (!environment)
            throw Error("OmplPathPlanner: null Environment");
        ompl_ext::PlanningContextOptions options;
        options.resolution = settings_.resolution;
        options.backend = settings_.backend;
        options.planner = settings_.planner;
        options.plannerParams = settings_.plannerParams;
        options.checker = settings_.checker;
        context_ = ompl_ext::makePlanningContext(robot, std::move(environment), options);
        dof_ = robot->dof();
        scratch_.resize(2 * dof_);
        // Set the planner up once now so that configuration errors surface here, not as failed plans.
        try
        {
            const auto &space = context_.setup->getStateSpace();
            ompl::base::ScopedState<> s(space);
            const auto &bounds = space->as<ompl::base::RealVectorStateSpace>()->getBounds();
            for (std::size_t i = 0; i < dof_; ++i)
                values(s.get())[i] = 0.5 * (bounds.low[i] + bounds.high[i]);
            context_.setup->setStartAndGoalStates(s, s);
            context_.setup->setup();
            context_.setup->clear();
        }
        catch (const std::exception &e)
        {
            throw Error("OmplPathPlanner: planner \"" + settings_.planner + "\" failed to set up for robot '" +
                        robot->name() + "': " + e.what());
        }
    }

    OmplPathPlanner::~OmplPathPlanner() = default;

    void OmplPathPlanner::setEnvironment(std::shared_ptr<const ompl_ext::Environment> environment)
    {
        if (!environment || environment == environment_)
            return;
        environment_ = environment;
        context_.setEnvironment(std::move(environment));
    }

    PathPlanStatus OmplPathPlanner::plan(const double *start, const double *target) noexcept
    {
        const auto begin = std::chrono::steady_clock::now();
        ++statistics_.requested;
        PathPlanStatus status;
        try
        {
            status = solve(start, target);
        }
        catch (...)
        {
            status = PathPlanStatus::PlannerError;
        }
        switch (status)
        {
            case PathPlanStatus::Solved:
                ++statistics_.solved;
                break;
            case PathPlanStatus::InvalidStart:
                ++statistics_.invalidStart;
                break;
            case PathPlanStatus::InvalidTarget:
                ++statistics_.invalidTarget;
                break;
            case PathPlanStatus::NotFound:
                ++statistics_.notFound;
                break;
            case PathPlanStatus::PlannerError:
                ++statistics_.plannerErrors;
                break;
        }
        if (status != PathPlanStatus::Solved)
            path_.clear();
        statistics_.planSeconds += std::chrono::duration<double>(std::chrono::steady_clock::now() - begin).count();
        return status;
    }

    PathPlanStatus OmplPathPlanner::solve(const double *start, const double *target)
    {
        path_.clear();
        const ompl_ext::RobotModel &robot = context_.checker->robot();
        if (!robot.withinBounds(start) || !context_.checker->isValid(*environment_, start))
            return PathPlanStatus::InvalidStart;
        if (!robot.withinBounds(target) || !context_.checker->isValid(*environment_, target))
            return PathPlanStatus::InvalidTarget;

        auto &setup = *context_.setup;
        setup.clear();
        const auto &space = setup.getStateSpace();
        ompl::base::ScopedState<> s(space), g(space);
        std::copy(start, start + dof_, values(s.get()));
        std::copy(target, target + dof_, values(g.get()));
        setup.setStartAndGoalStates(s, g);

        ompl::base::PlannerTerminationCondition ptc = ompl::base::timedPlannerTerminationCondition(settings_.timeLimit);
        if (settings_.maxIterations > 0)
        {
            auto count = std::make_shared<std::uint64_t>(0);
            const std::uint64_t limit = settings_.maxIterations;
            ptc = ompl::base::plannerOrTerminationCondition(
                ptc, ompl::base::PlannerTerminationCondition([count, limit] { return ++*count > limit; }));
        }
        const ompl::base::PlannerStatus result = setup.solve(ptc);
        if (result != ompl::base::PlannerStatus::EXACT_SOLUTION || !setup.haveExactSolutionPath())
            return PathPlanStatus::NotFound;

        const auto &solution = setup.getSolutionPath();
        const std::size_t n = solution.getStateCount();
        if (n == 0)
            return PathPlanStatus::NotFound;
        path_.reserve((n + 1) * dof_);
        for (std::size_t i = 0; i < n; ++i)
        {
            const double *q = values(const_cast<ompl::base::State *>(solution.getState(i)));
            path_.insert(path_.end(), q, q + dof_);
        }
        if (n == 1)  // start == target: a one-state path; make it a (zero-length) segment
            path_.insert(path_.end(), target, target + dof_);
        if (settings_.shortcut)
            shortcut();
        return PathPlanStatus::Solved;
    }

    void OmplPathPlanner::shortcut()
    {
        // Greedy and deterministic: from waypoint i, jump to the farthest waypoint j reachable by a straight
        // valid motion (j = i + 1 is valid by construction of the planner's path).
        const std::size_t n = waypointCount();
        if (n <= 2)
            return;
        scratch_.clear();
        std::size_t i = 0;
        scratch_.insert(scratch_.end(), path_.begin(), path_.begin() + dof_);
        while (i + 1 < n)
        {
            std::size_t j = n - 1;
            while (j > i + 1 && !context_.checker->isMotionValid(*environment_, &path_[i * dof_], &path_[j * dof_],
                                                                 settings_.resolution))
                --j;
            scratch_.insert(scratch_.end(), path_.begin() + j * dof_, path_.begin() + (j + 1) * dof_);
            i = j;
        }
        path_.swap(scratch_);
    }
}  // namespace ropras::pomdp
