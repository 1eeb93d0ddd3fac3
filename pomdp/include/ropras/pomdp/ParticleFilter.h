#ifndef ROPRAS_POMDP_PARTICLE_FILTER_H
#define ROPRAS_POMDP_PARTICLE_FILTER_H

#include <cmath>
#include <functional>
#include <memory>
#include <string>
#include <vector>

#include "ropras/core/Error.h"
#include "ropras/core/MemoryLimit.h"
#include "ropras/pomdp/BeliefView.h"
#include "ropras/pomdp/Model.h"
#include "ropras/pomdp/ParameterMap.h"

namespace ropras::pomdp
{
    /** \brief What a particle filter does when every particle has zero likelihood (depletion).

        recover() gets the propagated particles (already stepped with \a a) and must leave a non-empty set
        with non-negative weights (the filter normalises; all-zero weights become uniform). Must not throw. */
    template <class M>
    class DepletionRecovery
    {
    public:
        using State = typename M::State;
        virtual ~DepletionRecovery() = default;
        virtual void recover(const M &model, const typename M::Action &a, const typename M::Observation &o,
                             std::vector<State> &particles, std::vector<double> &weights, Rng &rng) = 0;
        virtual std::string name() const = 0;
    };

    /** \brief Recovery: keep the propagated particles with uniform weights (the observation is ignored). */
    template <class M>
    class IgnoreObservationRecovery final : public DepletionRecovery<M>
    {
    public:
        void recover(const M &, const typename M::Action &, const typename M::Observation &,
                     std::vector<typename M::State> &particles, std::vector<double> &weights, Rng &) override
        {
            weights.assign(particles.size(), 1.0);
        }
        std::string name() const override { return "ignore-observation"; }
    };

    /** \brief Recovery: draw fresh particles from the initial belief, step them with \a a and weight them by
        Z(o | s', a); if they are all zero too, the fresh propagated particles get uniform weights. */
    template <class M>
    class PriorRecovery final : public DepletionRecovery<M>
    {
    public:
        void recover(const M &model, const typename M::Action &a, const typename M::Observation &o,
                     std::vector<typename M::State> &particles, std::vector<double> &weights, Rng &rng) override
        {
            double total = 0.0;
            for (std::size_t i = 0; i < particles.size(); ++i)
            {
                particles[i] = model.step(model.sampleInitialState(rng), a, rng).next;
                const double w = model.observationProbability(o, particles[i], a);
                weights[i] = std::isfinite(w) && w > 0.0 ? w : 0.0;
                total += weights[i];
            }
            if (!(total > 0.0))
            {
                weights.assign(particles.size(), 1.0);
            }
        }
        std::string name() const override { return "prior"; }
    };

    /** \brief Parameters of the execution-time particle filter. */
    struct ParticleFilterSettings
    {
        std::size_t numParticles{1000};
        /** \brief Resample when ESS < threshold * N (1 = after every update). */
        double resampleThreshold{1.0};
        /** \brief Apply the model's reinvigorate() to every particle after resampling (needs the model's
            optional reinvigorate()). */
        bool reinvigorate{false};
        /** \brief Condition on continuation: update() follows a step that did not end the episode (a terminal
            step ends it before any update), so a particle whose own step is terminal (it would have entered
            the goal or a danger zone) gets weight 0, whatever the observation says. */
        bool continuation{false};

        static ParticleFilterSettings fromParameters(const ParameterMap &p)
        {
            ParticleFilterSettings s;
            s.numParticles = p.getCount("particles", s.numParticles);
            s.resampleThreshold = p.get("resample_threshold", s.resampleThreshold);
            s.reinvigorate = p.getCount("reinvigorate", 0) != 0;
            s.continuation = p.getCount("continuation", s.continuation ? 1 : 0, 1) != 0;
            if (s.numParticles == 0)
            {
                throw Error("particle filter: particles must be >= 1");
            }
            if (!(s.resampleThreshold >= 0.0 && s.resampleThreshold <= 1.0))
            {
                throw Error("particle filter: resample_threshold = " + std::to_string(s.resampleThreshold) +
                            " is not in [0, 1]");
            }
            return s;
        }
    };

    /** \brief Bootstrap particle filter for execution: propagate with the generative model, weight by
        Z(o | s', a), systematic (low-variance) resampling when the effective sample size is low, then
        optional reinvigoration (model-provided noise injection). Depletion (all weights 0, or NaN/inf
        likelihoods) never crashes: the pluggable DepletionRecovery repairs the belief and the event is
        counted and reported to the logger. */
    template <class M>
    class ParticleFilter
    {
    public:
        using State = typename M::State;
        using Action = typename M::Action;
        using Observation = typename M::Observation;
        using Logger = std::function<void(const std::string &)>;

        ParticleFilter(std::shared_ptr<const M> model, const ParticleFilterSettings &settings,
                       std::unique_ptr<DepletionRecovery<M>> recovery = nullptr, Logger logger = nullptr)
            : model_(std::move(model)), settings_(settings), recovery_(std::move(recovery)), logger_(std::move(logger))
        {
            if (!model_)
            {
                throw Error("ParticleFilter: missing model");
            }
            if (settings_.numParticles == 0)
            {
                throw Error("ParticleFilter: numParticles must be >= 1");
            }
            // the particles, the resampling scratch, the weights, and the belief a solver gets and copies
            checkedBytes(settings_.numParticles, 4 * sizeof(State) + sizeof(double),
                         "parameter particles = " + std::to_string(settings_.numParticles) + " (particle filter)");
            if (settings_.reinvigorate && !hasReinvigorate<M>)
            {
                throw Error("ParticleFilter: reinvigoration requested but the model has no reinvigorate()");
            }
            if (!recovery_)
            {
                recovery_ = std::make_unique<IgnoreObservationRecovery<M>>();
            }
        }

        /** \brief Fills the belief from the model's initial-belief sampler. */
        void initialize(Rng &rng)
        {
            particles_.resize(settings_.numParticles);
            for (auto &p : particles_)
            {
                p = model_->sampleInitialState(rng);
            }
            weights_.assign(particles_.size(), 1.0 / static_cast<double>(particles_.size()));
        }

        /** \brief Sets the belief explicitly (equal weights); throws ropras::Error if empty. */
        void setParticles(std::vector<State> particles)
        {
            if (particles.empty())
            {
                throw Error("ParticleFilter::setParticles: empty particle set");
            }
            particles_ = std::move(particles);
            weights_.assign(particles_.size(), 1.0 / static_cast<double>(particles_.size()));
        }

        /** \brief Belief update for one primitive step (a, o). Returns false when depletion occurred (and was
            recovered). */
        bool update(const Action &a, const Observation &o, Rng &rng)
        {
            const M &model = *model_;
            double total = 0.0;
            for (std::size_t i = 0; i < particles_.size(); ++i)
            {
                auto step = model.step(particles_[i], a, rng);
                particles_[i] = std::move(step.next);
                const double z =
                    settings_.continuation && step.terminal ? 0.0 : model.observationProbability(o, particles_[i], a);
                weights_[i] *= std::isfinite(z) && z > 0.0 ? z : 0.0;
                total += weights_[i];
            }
            bool ok = true;
            if (!(total > 0.0) || !std::isfinite(total))
            {
                ok = false;
                ++depletions_;
                recovery_->recover(model, a, o, particles_, weights_, rng);
                if (logger_)
                {
                    logger_("particle filter: all " + std::to_string(particles_.size()) +
                            " particles have zero likelihood; recovered with '" + recovery_->name() + "'");
                }
                total = 0.0;
                for (double &w : weights_)
                {
                    w = std::isfinite(w) && w > 0.0 ? w : 0.0;
                    total += w;
                }
                if (!(total > 0.0))
                {
                    weights_.assign(particles_.size(), 1.0);
                    total = static_cast<double>(particles_.size());
                }
            }
            double sumSquares = 0.0;
            for (double &w : weights_)
            {
                w /= total;
                sumSquares += w * w;
            }
            const double ess = 1.0 / sumSquares;
            if (ess < settings_.resampleThreshold * static_cast<double>(particles_.size()) ||
                settings_.resampleThreshold >= 1.0)
            {
                resample(rng);
                if constexpr (hasReinvigorate<M>)
                {
                    if (settings_.reinvigorate)
                    {
                        for (auto &p : particles_)
                        {
                            model.reinvigorate(p, rng);
                        }
                    }
                }
            }
            return ok;
        }

        /** \brief Systematic (low-variance) resampling to equal weights. */
        void resample(Rng &rng)
        {
            const std::size_t n = particles_.size();
            scratch_.resize(n);
            const double step = 1.0 / static_cast<double>(n);
            double u = rng.uniform01() * step;
            double cumulative = weights_[0];
            std::size_t i = 0;
            for (std::size_t k = 0; k < n; ++k)
            {
                while (u > cumulative && i + 1 < n)
                {
                    cumulative += weights_[++i];
                }
                scratch_[k] = particles_[i];
                u += step;
            }
            particles_.swap(scratch_);
            weights_.assign(n, step);
        }

        /** \brief \a n particles drawn by systematic resampling (the unweighted belief handed to a solver). */
        std::vector<State> sampleUnweighted(std::size_t n, Rng &rng) const
        {
            std::vector<State> out(n);
            const double step = 1.0 / static_cast<double>(n);
            double u = rng.uniform01() * step;
            double cumulative = weights_[0];
            std::size_t i = 0;
            for (std::size_t k = 0; k < n; ++k)
            {
                while (u > cumulative && i + 1 < particles_.size())
                {
                    cumulative += weights_[++i];
                }
                out[k] = particles_[i];
                u += step;
            }
            return out;
        }

        const std::vector<State> &particles() const { return particles_; }
        const std::vector<double> &weights() const { return weights_; }
        std::size_t depletions() const { return depletions_; }

    private:
        std::shared_ptr<const M> model_;
        ParticleFilterSettings settings_;
        std::unique_ptr<DepletionRecovery<M>> recovery_;
        Logger logger_;
        std::vector<State> particles_;
        std::vector<State> scratch_;
        std::vector<double> weights_;
        std::size_t depletions_{0};
    };
}  // namespace ropras::pomdp

#endif
