#ifndef ROPRAS_POMDP_OMPL_REFERENCE_POLICY_H
#define ROPRAS_POMDP_OMPL_REFERENCE_POLICY_H

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstddef>
#include <memory>
#include <string>
#include <vector>

#include "ropras/core/Error.h"
#include "ropras/ompl_ext/motion/JointSteps.h"
#include "ropras/pomdp/OmplPathPlanner.h"
#include "ropras/pomdp/PathCache.h"
#include "ropras/pomdp/ReferencePolicy.h"
#include "ropras/pomdp/SamplingHeuristic.h"

namespace ropras::pomdp
{
    /** \brief What a model provides so that an OMPL planner can produce its macro-actions: the robot
        configuration inside a state, the configuration of a target, optionally the obstacles a particle
        believes in, and PathToMacroAction.

        All functions are called once per reference plan (not per simulated step), must not throw and must
        not keep references to their arguments. */
    template <class State, class Action, class Target>
    class OmplPlanningAdapter
    {
    public:
        virtual ~OmplPlanningAdapter() = default;

        /** \brief Required: writes the robot's planning-joint values (RobotModel::dof() of them, planning-
            joint order) in \a state to \a q. */
        virtual void configuration(const State &state, double *q) const = 0;

        /** \brief Required: the configuration to plan to for \a target (from the sampling heuristic), seen
            from the particle \a start; false when the target has no configuration (a counted failure). */
        virtual bool targetConfiguration(const State &start, const Target &target, double *q) const = 0;

        /** \brief Required, PathToMacroAction: converts the planned joint-space path into primitive actions
            appended to \a out. \a waypoints is row-major, \a count x dof, first = configuration(start),
            last = the target configuration, every straight segment collision-free (at the planner's
            motion-check resolution) in the particle's environment. The model discretizes it (typically with
            discretizeJointPath: points at most one primitive step apart) and may truncate the macro to a
            maximum length (a partial path toward the target is a valid macro). Returns false, or appends
            nothing, when it cannot convert (a counted failure). */
        virtual bool pathToMacroAction(const State &start, const double *waypoints, std::size_t count,
                                       std::vector<Action> &out) const = 0;

        /** \brief Optional, obstacles carried by the particle, first form: a whole Environment for
            \a particle (e.g. one of a few scene hypotheses the model keeps), installed in O(1). Return null
            (the default) to use the second form. */
        virtual std::shared_ptr<const ompl_ext::Environment> environment(const State &particle) const
        {
            (void)particle;
            return nullptr;
        }

        /** \brief Optional, the planning margin's fallback, first form: the obstacles of \a particle without
            the margin its planning environment is grown by. A particle whose configuration is invalid in its
            planning environment but valid in this one (noise pushed it inside the margin, as after a grasp
            deep in a shelf) is planned for here instead of failing every plan as an invalid start. Return
            null (the default) to use the policy's true environment (OmplReferencePolicy::setTrueEnvironment,
            posed by poseObstacles), or no fallback when it has none. Called only for such starts. */
        virtual std::shared_ptr<const ompl_ext::Environment> trueEnvironment(const State &particle) const
        {
            (void)particle;
            return nullptr;
        }

        /** \brief Optional, second form: move the objects whose poses \a particle carries in \a working (the
            policy's private copy of its base Environment, Environment::setObjectPose, O(moved primitives))
            and return true; return false (the default) when the particle carries no obstacle poses, then
            the base Environment is used unchanged. */
        virtual bool poseObstacles(const State &particle, ompl_ext::Environment &working) const
        {
            (void)particle;
            (void)working;
            return false;
        }
    };

    /// the joint-path discretizer models use in pathToMacroAction (ompl_ext/motion/JointSteps.h: L2 norm, equal
    /// pieces of at most one step, every waypoint kept, optional truncation; throws Error on a bad step or path)
    using ompl_ext::discretizeJointPath;

    /** \brief The OMPL-backed reference policy (Algorithm 1, SampleMacroActionSBMP): for a particle
        \a start, target <- SamplingHeuristic(b) (Uniform / Dynamic / epsilon-greedy), a joint-space plan
        from configuration(start) to targetConfiguration(target) with ANY OMPL planner by name under a
        per-plan time limit (OmplPathPlanner: one SimpleSetup, cleared between plans), in the obstacles of
        that particle (OmplPlanningAdapter::environment / poseObstacles), converted by the model's
        pathToMacroAction. Every failure (no target, invalid start or target, no path in time, planner
        exception, failed conversion) returns false and is counted; sample() never throws. ROP-RAS3,
        R-POMCP, B-plan and RBSS use it unchanged (ModelComponents::referencePolicy). */
    template <class M, class Target>
    class OmplReferencePolicy final : public ReferencePolicy<M>
    {
    public:
        using typename ReferencePolicy<M>::State;
        using typename ReferencePolicy<M>::Action;
        using Adapter = OmplPlanningAdapter<State, Action, Target>;

        /** \brief Statistics beyond the planner's: targets the heuristic could not produce, targets without
            a configuration, failed conversions, and the time in sample(). */
        struct Statistics
        {
            std::size_t requested{0};         ///< sample() calls
            std::size_t succeeded{0};         ///< macros returned
            std::size_t noTarget{0};          ///< the heuristic or targetConfiguration() failed
            std::size_t conversionFailed{0};  ///< pathToMacroAction() failed or produced nothing
            std::size_t reused{0};            ///< macros cut from a kept path (PathCache), no plan run
            std::size_t marginStarts{0};      ///< starts inside the planning margin, planned in the true obstacles
            double seconds{0.0};              ///< wall-clock time in sample()
            std::size_t failed() const { return requested - succeeded; }
        };

        /** \brief Throws ropras::Error for missing parts, an unknown planner name or parameter, or bad
            settings (see OmplPathPlanner). */
        OmplReferencePolicy(std::shared_ptr<const Adapter> adapter,
                            std::unique_ptr<SamplingHeuristic<State, Target>> heuristic,
                            std::shared_ptr<const ompl_ext::RobotModel> robot,
                            std::shared_ptr<const ompl_ext::Environment> environment,
                            const OmplPathPlannerSettings &settings = OmplPathPlannerSettings())
            : adapter_(std::move(adapter)), heuristic_(std::move(heuristic))
        {
            if (!adapter_ || !heuristic_)
                throw Error("OmplReferencePolicy: missing adapter or sampling heuristic");
            if (!environment)
                throw Error("OmplReferencePolicy: null Environment");
            base_ = environment;
            working_ = std::make_shared<ompl_ext::Environment>(*environment);
            planner_ = std::make_unique<OmplPathPlanner>(std::move(robot), std::move(environment), settings);
            start_.resize(planner_->dof());
            target_.resize(planner_->dof());
        }

        bool sample(const State &start, BeliefView<State> belief, Rng &rng, std::vector<Action> &out) override
        {
            const auto begin = std::chrono::steady_clock::now();
            const bool ok = sampleImpl(start, belief, rng, out);
            statistics_.seconds += std::chrono::duration<double>(std::chrono::steady_clock::now() - begin).count();
            return ok;
        }

        std::string name() const override { return heuristic_->name() + "+ompl(" + planner_->settings().planner + ")"; }

        const Statistics &statistics() const { return statistics_; }

        /** \brief The planning margin's fallback, second form: \a environment is the policy's base Environment
            without the margin (the same objects, so that poseObstacles poses a private copy of it as it poses
            the base). A start the planner rejects (PathPlanStatus::InvalidStart) in its planning environment
            but valid in its true one (the adapter's trueEnvironment, else this one posed) is planned for again
            in the true one; the plan then keeps no
            margin from the obstacles near the start (its start is already inside the margin), which beats
            failing every plan as an invalid start. Null (the default) switches the second form off. */
        void setTrueEnvironment(std::shared_ptr<const ompl_ext::Environment> environment)
        {
            trueBase_ = environment;
            trueWorking_ = environment ? std::make_shared<ompl_ext::Environment>(*environment) : nullptr;
        }

        /** \brief Opt-in experience reuse (PathCache: "plan once, cut many macro-actions"): before planning,
            a kept path toward the same target configuration that passes within \a settings.radius of the
            start is continued (re-checked in the particle's environment); every new plan is kept. A radius
            of 0 switches it off (the default). Throws ropras::Error for bad settings. */
        void setPathCache(const PathCache::Settings &settings)
        {
            settings.validate();
            cache_ = settings.radius > 0.0 ? std::make_unique<PathCache>(planner_->dof(), settings) : nullptr;
        }
        /// the experience cache, or null when off
        const PathCache *pathCache() const { return cache_.get(); }
        const PathPlannerStatistics &plannerStatistics() const { return planner_->statistics(); }
        const OmplPathPlanner &planner() const { return *planner_; }
        /// the status of the last plan (Solved also when the failure was in the heuristic or conversion)
        PathPlanStatus lastStatus() const { return lastStatus_; }

    private:
        bool sampleImpl(const State &start, BeliefView<State> belief, Rng &rng, std::vector<Action> &out) noexcept
        {
            ++statistics_.requested;
            lastStatus_ = PathPlanStatus::Solved;
            try
            {
                if (!heuristic_->sample(start, belief, rng, targetValue_) ||
                    !adapter_->targetConfiguration(start, targetValue_, target_.data()))
                {
                    ++statistics_.noTarget;
                    return false;
                }
                if (auto own = adapter_->environment(start))
                    planner_->setEnvironment(std::move(own));
                else if (adapter_->poseObstacles(start, *working_))
                    planner_->setEnvironment(working_);
                else
                    planner_->setEnvironment(base_);
                adapter_->configuration(start, start_.data());
                const double *path = nullptr;
                std::size_t count = 0;
                if (cache_ &&
                    cache_->find(planner_->checker(), *planner_->environment(), planner_->settings().resolution,
                                 start_.data(), target_.data(), rng, cached_))
                {
                    ++statistics_.reused;
                    path = cached_.data();
                    count = cached_.size() / planner_->dof();
                }
                else
                {
                    lastStatus_ = planner_->plan(start_.data(), target_.data());
                    // the planner rejects a start inside the planning margin: plan again in the true obstacles
                    if (lastStatus_ == PathPlanStatus::InvalidStart && useTrueEnvironment(start))
                        lastStatus_ = planner_->plan(start_.data(), target_.data());
                    if (lastStatus_ != PathPlanStatus::Solved)
                        return false;
                    path = planner_->path().data();
                    count = planner_->waypointCount();
                    if (cache_)
                        cache_->store(target_.data(), path, count);
                }
                const std::size_t before = out.size();
                if (!adapter_->pathToMacroAction(start, path, count, out) || out.size() == before)
                {
                    out.resize(before);
                    ++statistics_.conversionFailed;
                    return false;
                }
                ++statistics_.succeeded;
                return true;
            }
            catch (...)
            {
                ++statistics_.conversionFailed;
                return false;
            }
        }

        /// a start the planning obstacles reject: install its true obstacles when the start is valid there
        bool useTrueEnvironment(const State &start)
        {
            std::shared_ptr<const ompl_ext::Environment> truth = adapter_->trueEnvironment(start);
            if (!truth && trueBase_)
            {
                if (adapter_->poseObstacles(start, *trueWorking_))
                    truth = trueWorking_;
                else
                    truth = trueBase_;
            }
            if (!truth || !planner_->checker().isValid(*truth, start_.data()))
                return false;
            planner_->setEnvironment(std::move(truth));
            ++statistics_.marginStarts;
            return true;
        }

        std::shared_ptr<const Adapter> adapter_;
        std::unique_ptr<SamplingHeuristic<State, Target>> heuristic_;
        std::shared_ptr<const ompl_ext::Environment> base_;
        std::shared_ptr<ompl_ext::Environment> working_;
        std::shared_ptr<const ompl_ext::Environment> trueBase_;
        std::shared_ptr<ompl_ext::Environment> trueWorking_;
        std::unique_ptr<OmplPathPlanner> planner_;
        std::vector<double> start_, target_, cached_;
        std::unique_ptr<PathCache> cache_;
        Target targetValue_{};
        Statistics statistics_;
        PathPlanStatus lastStatus_{PathPlanStatus::Solved};
    };
}  // namespace ropras::pomdp

#endif
