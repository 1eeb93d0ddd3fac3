#ifndef ROPRAS_POMDP_EPISODE_H
#define ROPRAS_POMDP_EPISODE_H

#include <cstddef>

#include "ropras/core/Error.h"
#include "ropras/pomdp/Budget.h"
#include "ropras/pomdp/ParticleFilter.h"
#include "ropras/pomdp/SearchStatistics.h"
#include "ropras/pomdp/Solver.h"

namespace ropras::pomdp
{
    /** \brief Settings of one closed-loop episode. */
    struct EpisodeSettings
    {
        /** \brief Maximum primitive steps. */
        std::size_t maxSteps{100};
        /** \brief Budget of every planning call. */
        Budget budget{Budget::ofSimulations(1000)};
        /** \brief Particles handed to the solver per plan (resampled from the filter; 0 = filter size). */
        std::size_t planningParticles{0};
    };

    /** \brief Outcome of one episode (a value: failures are counted, not thrown). */
    struct EpisodeResult
    {
        double discountedReturn{0.0};
        double undiscountedReturn{0.0};
        std::size_t steps{0};
        bool terminal{false};
        std::size_t plans{0};
        /** \brief Plans that returned no action (the model's rollout action was executed instead). */
        std::size_t invalidPlans{0};
        std::size_t depletions{0};
        SearchStatistics search;
    };

    /** \brief Runs one episode: the world is the model itself (a simulator) with a hidden true state drawn
        from the initial belief. Plan a macro from the filter's belief, execute it primitive by primitive in
        the world (updating the filter after each step), stop at a terminal step or maxSteps. The filter must
        be initialised. */
    template <class M>
    EpisodeResult runEpisode(const M &model, Solver<M> &solver, ParticleFilter<M> &filter,
                             const EpisodeSettings &settings, Rng &rng)
    {
        settings.budget.validate();
        if (filter.particles().empty())
        {
            throw Error("runEpisode: the particle filter is not initialised");
        }
        Rng world(rng.split());
        auto state = model.sampleInitialState(world);
        const double gamma = model.discount();
        double weight = 1.0;
        EpisodeResult result;
        const std::size_t depletionsBefore = filter.depletions();
        while (result.steps < settings.maxSteps && !result.terminal)
        {
            const std::size_t n =
                settings.planningParticles > 0 ? settings.planningParticles : filter.particles().size();
            const auto belief = filter.sampleUnweighted(n, rng);
            auto plan = solver.plan(BeliefView<typename M::State>{belief.data(), belief.size()}, settings.budget, rng);
            ++result.plans;
            result.search.accumulate(plan.statistics);
            if (!plan.valid || plan.action.empty())
            {
                ++result.invalidPlans;
                plan.action.assign(1, rolloutActionOf(model, state, rng));
            }
            for (const auto &a : plan.action)
            {
                auto step = model.step(state, a, world);
                result.discountedReturn += weight * step.reward;
                result.undiscountedReturn += step.reward;
                weight *= gamma;
                ++result.steps;
                state = std::move(step.next);
                if (step.terminal)
                {
                    result.terminal = true;
                    break;
                }
                filter.update(a, step.observation, rng);
                if (result.steps >= settings.maxSteps)
                {
                    break;
                }
            }
        }
        result.depletions = filter.depletions() - depletionsBefore;
        return result;
    }
}  // namespace ropras::pomdp

#endif
