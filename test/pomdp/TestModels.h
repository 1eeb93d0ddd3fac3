// Small models shared by the pomdp tests.
#ifndef ROPRAS_TEST_POMDP_TEST_MODELS_H
#define ROPRAS_TEST_POMDP_TEST_MODELS_H

#include <cmath>
#include <cstdint>
#include <limits>

#include "ropras/pomdp/Model.h"

namespace ropras::pomdp::test
{
    /** \brief One-step bandit: action i pays rewards[i] deterministically and ends the episode. */
    struct BanditModel
    {
        using State = int;
        using Action = int;
        using Observation = int;
        double rewards[3]{1.0, 2.0, 3.0};

        StepResult<State, Observation> step(State s, Action a, Rng &) const noexcept
        {
            return {s, 0, rewards[a], true};
        }
        double observationProbability(Observation, State, Action) const noexcept { return 1.0; }
        State sampleInitialState(Rng &) const noexcept { return 0; }
        double discount() const noexcept { return 0.9; }
        std::size_t numActions() const noexcept { return 3; }
        Action action(std::size_t i) const noexcept { return static_cast<Action>(i); }
    };

    /** \brief 1-D linear Gaussian model: x' = x + u + N(0, q), o = x' + N(0, r), x0 ~ N(m0, p0). With
        \c bounded, the observation noise is treated as supported on |o - x'| <= 1 (for depletion tests). */
    struct LinearGaussianModel
    {
        using State = double;
        using Action = double;
        using Observation = double;
        double q{0.5};
        double r{0.3};
        double m0{1.0};
        double p0{2.0};
        bool bounded{false};
        double reinvigorationStd{0.0};

        StepResult<State, Observation> step(State x, Action u, Rng &rng) const noexcept
        {
            StepResult<State, Observation> out;
            out.next = x + u + rng.normal(0.0, std::sqrt(q));
            out.observation = out.next + rng.normal(0.0, std::sqrt(r));
            out.reward = -std::abs(out.next);
            return out;
        }
        double observationProbability(Observation o, State x, Action) const noexcept
        {
            const double d = o - x;
            if (std::isnan(o))
            {
                return std::numeric_limits<double>::quiet_NaN();
            }
            if (bounded && std::abs(d) > 1.0)
            {
                return 0.0;
            }
            return std::exp(-0.5 * d * d / r) / std::sqrt(2.0 * 3.141592653589793 * r);
        }
        State sampleInitialState(Rng &rng) const noexcept { return rng.normal(m0, std::sqrt(p0)); }
        double discount() const noexcept { return 0.95; }
        std::uint64_t observationKey(Observation o) const noexcept
        {
            return static_cast<std::uint64_t>(static_cast<std::int64_t>(std::floor(o * 10.0)));
        }
        void reinvigorate(State &x, Rng &rng) const noexcept { x += rng.normal(0.0, reinvigorationStd); }
    };

    /** \brief Counts steps and terminates at step \c terminalAt (for macro tests). */
    struct CounterModel
    {
        using State = int;
        using Action = int;
        using Observation = int;
        int terminalAt{2};

        StepResult<State, Observation> step(State s, Action a, Rng &) const noexcept
        {
            return {s + 1, a, 1.0, s + 1 >= terminalAt};
        }
        double observationProbability(Observation, State, Action) const noexcept { return 1.0; }
        State sampleInitialState(Rng &) const noexcept { return 0; }
        double discount() const noexcept { return 0.5; }
        std::size_t numActions() const noexcept { return 2; }
        Action action(std::size_t i) const noexcept { return static_cast<Action>(i); }
    };
}  // namespace ropras::pomdp::test

#endif
