#ifndef ROPRAS_POMDP_OMPL_PATH_PLANNER_H
#define ROPRAS_POMDP_OMPL_PATH_PLANNER_H

#include <cstddef>
#include <cstdint>
#include <map>
#include <memory>
#include <string>
#include <vector>

#include "ropras/ompl_ext/collision/CollisionChecker.h"
#include "ropras/ompl_ext/model/RobotModel.h"
#include "ropras/ompl_ext/ompl/MotionValidator.h"
#include "ropras/ompl_ext/ompl/PlanningContext.h"
#include "ropras/ompl_ext/scene/Environment.h"
#include "ropras/pomdp/ParameterMap.h"

namespace ropras::pomdp
{
    /** \brief Settings of OmplPathPlanner (and so of OmplReferencePolicy). */
    struct OmplPathPlannerSettings
    {
        /// any name of ompl_ext::PlannerRegistry (every OMPL geometric planner, VectorizedRRTConnect, ...)
        std::string planner{"VectorizedRRTConnect"};
        /// planner parameters by name (planner->params()), e.g. {"range", "0.3"}, {"seed", "7"}
        std::map<std::string, std::string> plannerParams;
        /// wall-clock limit per plan in seconds (ompl::base::timedPlannerTerminationCondition); > 0
        double timeLimit{0.05};
        /// 0: none; else the plan also stops after this many evaluations of the termination condition
        /// (one per planner iteration for OMPL's single-threaded planners): deterministic, unlike time
        std::uint64_t maxIterations{0};
        /// greedy deterministic shortcutting of the found path (farthest directly reachable waypoint)
        bool shortcut{true};
        double resolution{ompl_ext::MotionValidator::DEFAULT_RESOLUTION};  ///< motion-check step (rad or m)
        ompl_ext::SimdBackend backend{ompl_ext::SimdBackend::Best};
        /// null: the planner builds its own CollisionChecker; else it shares this one (same RobotModel), as a
        /// scenario that already has one should: building a checker costs far more than a reference plan
        std::shared_ptr<const ompl_ext::CollisionChecker> checker;

        /// the prefix of the parameters that go to the planner itself: `planner.range=2` sets plannerParams["range"]
        static constexpr const char *PLANNER_PREFIX = "planner.";

        /** \brief Reads `plan_time` (s), `plan_iterations`, `shortcut` (0/1) and every `planner.NAME` (into
            plannerParams[NAME]: whole numbers in digits, others with 17 significant digits; the planner registry
            refuses a name the planner lacks, or a value its type cannot hold, when it is created) from \a params
            (other fields keep their values); throws ropras::Error on a non-positive time or an empty NAME. */
        void readParameters(const ParameterMap &params);
        /// throws ropras::Error naming the bad field
        void validate() const;
    };

    /** \brief Outcome of one OmplPathPlanner::plan() call. */
    enum class PathPlanStatus
    {
        Solved,
        InvalidStart,   ///< the start configuration is out of bounds, not finite or in collision
        InvalidTarget,  ///< the target configuration is out of bounds, not finite or in collision
        NotFound,       ///< no exact solution within the time / iteration limit
        PlannerError    ///< the planner threw (an exception from OMPL); counted, never propagated
    };

    const char *pathPlanStatusName(PathPlanStatus status) noexcept;

    /** \brief Counters of an OmplPathPlanner (and of the reference policy around it). */
    struct PathPlannerStatistics
    {
        std::size_t requested{0};  ///< plan() calls
        std::size_t solved{0};
        std::size_t invalidStart{0};
        std::size_t invalidTarget{0};
        std::size_t notFound{0};
        std::size_t plannerErrors{0};
        double planSeconds{0.0};  ///< wall-clock time inside plan() (validation, planning, shortcutting)

        std::size_t failed() const { return requested - solved; }
    };

    /** \brief One robot, one OMPL planner chosen by name, many joint-space queries: the motion-planning
        half of the OMPL reference policy.

        Keeps ONE PlanningContext (SimpleSetup with ropras' validity checker and motion validator) and calls
        `clear()` between plans; the obstacles are swapped per query in O(1) with setEnvironment(). A query
        first checks start and target with the CollisionChecker (no OMPL call, no OMPL log message for
        invalid endpoints), then runs the planner under the per-plan time limit (plus the optional iteration
        bound), keeps only exact solutions and shortcuts them greedily. plan() never throws: every failure
        is a status and a counter. Not thread-safe (one instance per solver thread). */
    class OmplPathPlanner
    {
    public:
        /** \brief Throws ropras::Error for a null robot/environment, an unknown planner name or parameter,
            bad settings, or a planner whose setup() fails. */
        OmplPathPlanner(std::shared_ptr<const ompl_ext::RobotModel> robot,
                        std::shared_ptr<const ompl_ext::Environment> environment,
                        const OmplPathPlannerSettings &settings = OmplPathPlannerSettings());
        ~OmplPathPlanner();
        OmplPathPlanner(const OmplPathPlanner &) = delete;
        OmplPathPlanner &operator=(const OmplPathPlanner &) = delete;

        std::size_t dof() const { return dof_; }
        const ompl_ext::CollisionChecker &checker() const { return *context_.checker; }
        const ompl_ext::PlanningContext &context() const { return context_; }
        const OmplPathPlannerSettings &settings() const { return settings_; }
        const std::shared_ptr<const ompl_ext::Environment> &environment() const { return environment_; }

        /// the obstacles of the next queries (O(1); null is ignored and keeps the current ones)
        void setEnvironment(std::shared_ptr<const ompl_ext::Environment> environment);

        /** \brief Plans from \a start to \a target (dof() values each). On Solved, path() holds the
            waypoints (row-major, waypointCount() x dof(), first = start, last = target), every straight
            segment valid per the CollisionChecker at the settings' resolution. */
        PathPlanStatus plan(const double *start, const double *target) noexcept;

        const std::vector<double> &path() const { return path_; }
        std::size_t waypointCount() const { return dof_ == 0 ? 0 : path_.size() / dof_; }

        const PathPlannerStatistics &statistics() const { return statistics_; }
        void resetStatistics() { statistics_ = PathPlannerStatistics(); }

    private:
        PathPlanStatus solve(const double *start, const double *target);
        void shortcut();

        OmplPathPlannerSettings settings_;
        ompl_ext::PlanningContext context_;
        std::shared_ptr<const ompl_ext::Environment> environment_;
        std::size_t dof_{0};
        std::vector<double> path_, scratch_;
        PathPlannerStatistics statistics_;
    };
}  // namespace ropras::pomdp

#endif
