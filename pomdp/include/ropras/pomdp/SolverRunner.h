#ifndef ROPRAS_POMDP_SOLVER_RUNNER_H
#define ROPRAS_POMDP_SOLVER_RUNNER_H

#include <cstdint>
#include <memory>
#include <set>
#include <string>
#include <vector>

#include "ropras/core/Error.h"
#include "ropras/pomdp/Episode.h"
#include "ropras/pomdp/ParticleFilter.h"
#include "ropras/pomdp/SearchStatistics.h"
#include "ropras/pomdp/SolverFactory.h"

namespace ropras::pomdp
{
    /** \brief A solver bound to a model, with the model's types erased: what the CLI and benchmarks drive
        (the search inside stays a template over the model). */
    class SolverRunner
    {
    public:
        virtual ~SolverRunner() = default;
        virtual std::string modelName() const = 0;
        virtual std::string solverName() const = 0;
        /** \brief One planning call from the initial belief (particles drawn with \a seed). */
        virtual SearchStatistics planFromInitialBelief(const Budget &budget, std::uint64_t seed) = 0;
        /** \brief One closed-loop episode (world, filter and solver seeded from \a seed). */
        virtual EpisodeResult runEpisode(const EpisodeSettings &settings, std::uint64_t seed) = 0;
    };

    /** \brief SolverRunner for model type M. Parameters: the solver's, the particle filter's (particles,
        resample_threshold, reinvigorate) and the model components' defaults; any other name throws. */
    template <class M>
    class ModelSolverRunner final : public SolverRunner
    {
    public:
        ModelSolverRunner(std::string modelName, ModelComponents<M> components, const std::string &solverName,
                          const ParameterMap &params)
            : modelName_(std::move(modelName)), components_(std::move(components))
        {
            const ParameterMap merged = withDefaults(components_, params, solverName);
            solver_ = makeSolver(solverName, components_, merged);
            filterSettings_ = ParticleFilterSettings::fromParameters(merged);
            if (filterSettings_.reinvigorate && !hasReinvigorate<M>)
            {
                throw Error("parameter reinvigorate = 1, but model " + modelName_ + " has no reinvigorate()");
            }
            merged.requireAllUsed("solver " + solverName + " on model " + modelName_,
                                  unreadDefaultsAllowed(components_, params, solverName));
        }

        std::string modelName() const override { return modelName_; }
        std::string solverName() const override { return solver_->name(); }

        SearchStatistics planFromInitialBelief(const Budget &budget, std::uint64_t seed) override
        {
            Rng rng(seed);
            particles_.resize(filterSettings_.numParticles);
            for (auto &p : particles_)
            {
                p = components_.model->sampleInitialState(rng);
            }
            return solver_->plan(BeliefView<typename M::State>{particles_.data(), particles_.size()}, budget, rng)
                .statistics;
        }

        EpisodeResult runEpisode(const EpisodeSettings &settings, std::uint64_t seed) override
        {
            Rng rng(seed);
            ParticleFilter<M> filter(components_.model, filterSettings_);
            filter.initialize(rng);
            return pomdp::runEpisode(*components_.model, *solver_, filter, settings, rng);
        }

    private:
        std::string modelName_;
        ModelComponents<M> components_;
        std::unique_ptr<Solver<M>> solver_;
        ParticleFilterSettings filterSettings_;
        std::vector<typename M::State> particles_;
    };
}  // namespace ropras::pomdp

#endif
