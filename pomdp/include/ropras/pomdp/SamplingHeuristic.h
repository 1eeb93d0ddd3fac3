#ifndef ROPRAS_POMDP_SAMPLING_HEURISTIC_H
#define ROPRAS_POMDP_SAMPLING_HEURISTIC_H

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <memory>
#include <string>
#include <vector>

#include "ropras/core/Error.h"
#include "ropras/pomdp/BeliefView.h"
#include "ropras/pomdp/TargetSpace.h"

namespace ropras::pomdp
{
    /** \brief The sampling heuristic J(. | b) of SampleMacroActionSBMP: picks a target for a new macro from
        the belief. Model-agnostic: everything model-specific comes from a TargetSpace. Returns false when
        it cannot produce a target (counted as a failed reference plan by the caller). */
    template <class State, class Target>
    class SamplingHeuristic
    {
    public:
        virtual ~SamplingHeuristic() = default;
        virtual bool sample(const State &agent, BeliefView<State> belief, Rng &rng, Target &out) = 0;
        virtual std::string name() const = 0;
    };

    /** \brief Normalised entropy in [0, 1] of the histogram of \a bins (log base: \a numBins, or the number
        of entries when numBins is 0). \a bins is sorted in place. */
    inline double normalizedEntropy(std::vector<std::uint64_t> &bins, std::size_t numBins) noexcept
    {
        const std::size_t n = bins.size();
        const std::size_t base = numBins > 0 ? numBins : n;
        if (n <= 1 || base <= 1)
        {
            return 0.0;
        }
        std::sort(bins.begin(), bins.end());
        double h = 0.0;
        std::size_t run = 1;
        for (std::size_t i = 1; i <= n; ++i)
        {
            if (i < n && bins[i] == bins[i - 1])
            {
                ++run;
                continue;
            }
            const double p = static_cast<double>(run) / static_cast<double>(n);
            h -= p * std::log(p);
            run = 1;
        }
        return std::min(1.0, std::max(0.0, h / std::log(static_cast<double>(base))));
    }

    /** \brief The paper's Uniform heuristic: the goal (of a particle drawn from the belief) with probability
        goalProbability (0.5), otherwise an informative target chosen uniformly. */
    template <class State, class Target>
    class UniformHeuristic final : public SamplingHeuristic<State, Target>
    {
    public:
        explicit UniformHeuristic(std::shared_ptr<const TargetSpace<State, Target>> space, double goalProbability = 0.5)
            : space_(std::move(space)), goalProbability_(goalProbability)
        {
            if (!space_)
            {
                throw Error("UniformHeuristic: no target space");
            }
            if (!(goalProbability >= 0.0 && goalProbability <= 1.0))
            {
                throw Error("UniformHeuristic: goal probability " + std::to_string(goalProbability) +
                            " is not in [0, 1]");
            }
        }

        bool sample(const State &agent, BeliefView<State> belief, Rng &rng, Target &out) override
        {
            const State &particle = belief.empty() ? agent : belief[rng.uniformIndex(belief.size)];
            const std::size_t n = space_->numInformative(particle);
            if (n == 0 || rng.bernoulli(goalProbability_))
            {
                out = space_->goal(particle);
                return true;
            }
            out = space_->informative(particle, static_cast<std::size_t>(rng.uniformIndex(n)));
            return true;
        }

        std::string name() const override { return "uniform"; }

    private:
        std::shared_ptr<const TargetSpace<State, Target>> space_;
        double goalProbability_;
    };

    /** \brief The paper's Dynamic heuristic: the goal with probability 1 - H(b) (H = normalised belief
        entropy over TargetSpace::entropyBin), otherwise an informative target with probability inversely
        proportional to its distance from the agent (distance + minDistance, minDistance > 0). */
    template <class State, class Target>
    class DynamicHeuristic final : public SamplingHeuristic<State, Target>
    {
    public:
        explicit DynamicHeuristic(std::shared_ptr<const TargetSpace<State, Target>> space, double minDistance = 1e-6)
            : space_(std::move(space)), minDistance_(minDistance)
        {
            if (!space_)
            {
                throw Error("DynamicHeuristic: no target space");
            }
            if (!(minDistance > 0.0) || !std::isfinite(minDistance))
            {
                throw Error("DynamicHeuristic: minDistance " + std::to_string(minDistance) + " must be > 0");
            }
        }

        /** \brief H(b) of \a belief (uses a scratch buffer; not thread-safe, one heuristic per solver). */
        double entropy(BeliefView<State> belief)
        {
            if (belief.size <= 1)
            {
                return 0.0;
            }
            const double own = space_->beliefEntropy(belief);
            if (own >= 0.0)
            {
                return std::min(1.0, own);
            }
            bins_.clear();
            for (const auto &particle : belief)
            {
                bins_.push_back(space_->entropyBin(particle));
            }
            return normalizedEntropy(bins_, space_->numEntropyBins());
        }

        bool sample(const State &agent, BeliefView<State> belief, Rng &rng, Target &out) override
        {
            const State &particle =
                belief.size <= 1 ? (belief.empty() ? agent : belief[0]) : belief[rng.uniformIndex(belief.size)];
            const double h = entropy(belief);
            if (h <= 0.0)
            {
                out = space_->goal(particle);
                return true;
            }
            const std::size_t n = space_->numInformative(particle);
            if (n == 0 || !rng.bernoulli(h))
            {
                out = space_->goal(particle);
                return true;
            }
            weights_.resize(n);
            double total = 0.0;
            for (std::size_t i = 0; i < n; ++i)
            {
                const double d = space_->distance(agent, space_->informative(particle, i));
                weights_[i] = 1.0 / (std::max(0.0, std::isfinite(d) ? d : 1e300) + minDistance_);
                total += weights_[i];
            }
            double u = rng.uniform01() * total;
            std::size_t chosen = n - 1;
            for (std::size_t i = 0; i < n; ++i)
            {
                u -= weights_[i];
                if (u < 0.0)
                {
                    chosen = i;
                    break;
                }
            }
            out = space_->informative(particle, chosen);
            return true;
        }

        std::string name() const override { return "dynamic"; }

    private:
        std::shared_ptr<const TargetSpace<State, Target>> space_;
        double minDistance_;
        std::vector<std::uint64_t> bins_;
        std::vector<double> weights_;
    };

    /** \brief Epsilon-greedy mixture: with probability epsilon a uniform free-space target
        (TargetSpace::sampleFree), otherwise the inner heuristic. */
    template <class State, class Target>
    class EpsilonGreedyHeuristic final : public SamplingHeuristic<State, Target>
    {
    public:
        EpsilonGreedyHeuristic(std::shared_ptr<const TargetSpace<State, Target>> space,
                               std::unique_ptr<SamplingHeuristic<State, Target>> inner, double epsilon)
            : space_(std::move(space)), inner_(std::move(inner)), epsilon_(epsilon)
        {
            if (!space_ || !inner_)
            {
                throw Error("EpsilonGreedyHeuristic: missing target space or inner heuristic");
            }
            if (!(epsilon >= 0.0 && epsilon <= 1.0))
            {
                throw Error("EpsilonGreedyHeuristic: epsilon " + std::to_string(epsilon) + " is not in [0, 1]");
            }
        }

        bool sample(const State &agent, BeliefView<State> belief, Rng &rng, Target &out) override
        {
            if (rng.bernoulli(epsilon_))
            {
                return space_->sampleFree(rng, out);
            }
            return inner_->sample(agent, belief, rng, out);
        }

        std::string name() const override { return "epsilon-greedy(" + inner_->name() + ")"; }

    private:
        std::shared_ptr<const TargetSpace<State, Target>> space_;
        std::unique_ptr<SamplingHeuristic<State, Target>> inner_;
        double epsilon_;
    };
}  // namespace ropras::pomdp

#endif
