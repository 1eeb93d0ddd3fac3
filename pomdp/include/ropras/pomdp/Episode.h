#ifndef ROPRAS_POMDP_EPISODE_H
#define ROPRAS_POMDP_EPISODE_H

#include <cstddef>
#include <cstdint>
#include <limits>
#include <string>
#include <type_traits>
#include <utility>
#include <vector>

#include "ropras/core/Error.h"
#include "ropras/core/MemoryLimit.h"
#include "ropras/pomdp/Budget.h"
#include "ropras/pomdp/ParticleFilter.h"
#include "ropras/pomdp/SearchStatistics.h"
#include "ropras/pomdp/Solver.h"
#include "ropras/pomdp/World.h"

namespace ropras::pomdp
{
    /** \brief Settings of one closed-loop episode. */
    struct EpisodeSettings
    {
        /** \brief Maximum primitive steps (the horizon H). */
        std::size_t maxSteps{100};
        /** \brief Budget of every planning call. */
        Budget budget{Budget::ofSimulations(1000)};
        /** \brief Particles handed to the solver per plan (resampled from the filter; 0 = filter size). */
        std::size_t planningParticles{0};
        /** \brief false (default): execute the whole planned macro-action, then replan. true: execute only its
            first primitive action, then replan (closed loop at every step). */
        bool replanEveryStep{false};
    };

    /** \brief Outcome of one episode (a value: failures are counted, not thrown). */
    struct EpisodeResult
    {
        double discountedReturn{0.0};
        double undiscountedReturn{0.0};
        std::size_t steps{0};
        bool terminal{false};
        /** \brief The episode ended in a goal state (the model's optional reachedGoal(); false without it). */
        bool success{false};
        std::size_t plans{0};
        /** \brief Plans that returned no action (the model's rollout action for a particle of the belief was executed
            instead). */
        std::size_t invalidPlans{0};
        std::size_t depletions{0};
        /** \brief Sum over the planning calls (simulations, reference requests and failures, seconds, ...). */
        SearchStatistics search;
    };

    /** \brief Watches an episode (recording for pictures, logging). Every hook has an empty default. */
    template <class M>
    class EpisodeObserver
    {
    public:
        using State = typename M::State;
        using Action = typename M::Action;
        using Observation = typename M::Observation;

        virtual ~EpisodeObserver() = default;
        /** \brief Before the first plan: the true initial state and the initial particle belief. */
        virtual void onStart(const State &trueState, const std::vector<State> &particles)
        {
            (void)trueState;
            (void)particles;
        }
        /** \brief After a planning call: the macro-action about to be executed. */
        virtual void onPlan(std::size_t step, const std::vector<Action> &macro, const SearchStatistics &statistics)
        {
            (void)step;
            (void)macro;
            (void)statistics;
        }
        /** \brief Whether to receive the search tree of planning call \a plan (0-based) through onTree(). */
        virtual bool wantsTree(std::size_t plan) const
        {
            (void)plan;
            return false;
        }
        /** \brief The search tree of planning call \a plan (made at primitive step \a step), when wantsTree(plan)
            and the solver has a tree. */
        virtual void onTree(std::size_t plan, std::size_t step, const TreeSnapshot &tree)
        {
            (void)plan;
            (void)step;
            (void)tree;
        }
        /** \brief After primitive step \a step (1-based) and the filter update: the world's result and the
            belief (unchanged when the step was terminal). */
        virtual void onStep(std::size_t step, const Action &action, const StepResult<State, Observation> &result,
                            const std::vector<State> &particles)
        {
            (void)step;
            (void)action;
            (void)result;
            (void)particles;
        }
    };

    namespace detail
    {
        template <class M, class = void>
        struct HasReachedGoal : std::false_type
        {
        };
        template <class M>
        struct HasReachedGoal<
            M, std::void_t<decltype(std::declval<const M &>().reachedGoal(std::declval<const typename M::State &>()))>>
            : std::true_type
        {
        };
    }  // namespace detail

    /** \brief Whether \a s is a goal state: the model's optional `bool reachedGoal(const State &) const`, or
        false when the model has none. */
    template <class M>
    inline bool reachedGoalOf(const M &model, const typename M::State &s) noexcept
    {
        if constexpr (detail::HasReachedGoal<M>::value)
        {
            return model.reachedGoal(s);
        }
        else
        {
            (void)model;
            (void)s;
            return false;
        }
    }

    /** \brief Runs one episode in \a world: the true state is drawn from the model's initial belief, then
        repeatedly: plan a macro from the filter's belief, execute it primitive by primitive in the world
        (updating the filter after each step; only its first action when replanEveryStep), until a terminal
        step or maxSteps. The filter must be initialised. \a observer (optional) sees every plan and step. */
    template <class M>
    EpisodeResult runEpisode(const M &model, Solver<M> &solver, ParticleFilter<M> &filter, World<M> &world,
                             const EpisodeSettings &settings, Rng &rng, EpisodeObserver<M> *observer = nullptr)
    {
        settings.budget.validate();
        if (filter.particles().empty())
        {
            throw Error("runEpisode: the particle filter is not initialised");
        }
        Rng worldRng(rng.split());
        world.reset(model.sampleInitialState(worldRng));
        const double gamma = model.discount();
        double weight = 1.0;
        EpisodeResult result;
        const std::size_t depletionsBefore = filter.depletions();
        if (settings.planningParticles > 0)
        {
            // the belief handed to the solver and the solver's copy of it (32-bit particle indices)
            const std::string what =
                "planning particles (--planning-particles) " + std::to_string(settings.planningParticles);
            checkedBytes(settings.planningParticles, 2 * sizeof(typename M::State), what);
            if (settings.planningParticles > std::numeric_limits<std::uint32_t>::max())
            {
                throw Error(what + " exceed the solvers' 32-bit particle indices (at most 4294967295)");
            }
        }
        if (observer)
        {
            observer->onStart(world.state(), filter.particles());
        }
        while (result.steps < settings.maxSteps && !result.terminal)
        {
            const std::size_t n =
                settings.planningParticles > 0 ? settings.planningParticles : filter.particles().size();
            const auto belief = filter.sampleUnweighted(n, rng);
            auto plan = solver.plan(BeliefView<typename M::State>{belief.data(), belief.size()}, settings.budget, rng);
            if (observer && observer->wantsTree(result.plans))
            {
                TreeSnapshot tree;
                if (solver.treeSnapshot(tree))
                {
                    observer->onTree(result.plans, result.steps, tree);
                }
            }
            ++result.plans;
            result.search.accumulate(plan.statistics);
            if (!plan.valid || plan.action.empty())
            {
                ++result.invalidPlans;
                // the agent does not know the world's state: the rollout action of a particle of its belief
                plan.action.assign(1, rolloutActionOf(model, belief[rng.uniformIndex(belief.size())], rng));
            }
            if (settings.replanEveryStep)
            {
                plan.action.resize(1);
            }
            if (observer)
            {
                observer->onPlan(result.steps, plan.action, plan.statistics);
            }
            for (const auto &a : plan.action)
            {
                auto step = world.step(a, worldRng);
                result.discountedReturn += weight * step.reward;
                result.undiscountedReturn += step.reward;
                weight *= gamma;
                ++result.steps;
                if (step.terminal)
                {
                    result.terminal = true;
                }
                else
                {
                    filter.update(a, step.observation, rng);
                }
                if (observer)
                {
                    observer->onStep(result.steps, a, step, filter.particles());
                }
                if (result.terminal || result.steps >= settings.maxSteps)
                {
                    break;
                }
            }
        }
        result.success = reachedGoalOf(model, world.state());
        result.depletions = filter.depletions() - depletionsBefore;
        return result;
    }

    /** \brief runEpisode() with the model as its own world (SimulatedWorld). */
    template <class M>
    EpisodeResult runEpisode(const M &model, Solver<M> &solver, ParticleFilter<M> &filter,
                             const EpisodeSettings &settings, Rng &rng)
    {
        struct Borrowed final : World<M>
        {
            explicit Borrowed(const M &m) : model_(m) {}
            void reset(const typename M::State &initial) override { state_ = initial; }
            const typename M::State &state() const override { return state_; }
            StepResult<typename M::State, typename M::Observation> step(const typename M::Action &a, Rng &r) override
            {
                auto out = model_.step(state_, a, r);
                state_ = out.next;
                return out;
            }
            const M &model_;
            typename M::State state_{};
        };
        Borrowed world(model);
        return runEpisode(model, solver, filter, world, settings, rng);
    }
}  // namespace ropras::pomdp

#endif
