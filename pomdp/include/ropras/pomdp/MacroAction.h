#ifndef ROPRAS_POMDP_MACRO_ACTION_H
#define ROPRAS_POMDP_MACRO_ACTION_H

#include <cstddef>
#include <cstdint>
#include <vector>

#include "ropras/pomdp/Model.h"

namespace ropras::pomdp
{
    /** \brief An owning macro-action: primitive actions executed one after the other. */
    template <class Action>
    using MacroAction = std::vector<Action>;

    /** \brief A non-owning view of a macro-action (solvers keep macros in flat pools). */
    template <class Action>
    struct MacroView
    {
        const Action *data{nullptr};
        std::size_t length{0};

        const Action *begin() const noexcept { return data; }
        const Action *end() const noexcept { return data + length; }
    };

    /** \brief Outcome of executing a macro-action with the generative model.

        The macro observation is the whole sequence of primitive observations, folded into one 64-bit
        order-sensitive bin key (observationKeyOf() of each step combined by a hash mix): two executions
        fall into the same observation branch iff every primitive observation fell into the same bin (up to
        64-bit hash collisions). The last primitive observation is kept too. */
    template <class State, class Observation>
    struct MacroStepResult
    {
        State next{};
        Observation lastObservation{};
        std::uint64_t observationKey{0};
        /** \brief The key of the last non-empty primitive observation alone (empty = the key of a
            default-constructed Observation, e.g. None); the empty key when every observation was empty. */
        std::uint64_t lastObservationKey{0};
        /** \brief Discounted sum of the rewards inside the macro: sum_k gamma^k r_k. */
        double reward{0.0};
        /** \brief Number of primitive steps executed (< length when the macro terminated early). */
        unsigned steps{0};
        /** \brief gamma^steps: the factor applied to the value after the macro. */
        double discount{1.0};
        bool terminal{false};
    };

    /** \brief Folds one more primitive observation key into a macro observation key. */
    inline std::uint64_t combineObservationKey(std::uint64_t key, std::uint64_t stepKey) noexcept
    {
        std::uint64_t z = key ^ (stepKey + 0x9e3779b97f4a7c15ULL + (key << 6) + (key >> 2));
        z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9ULL;
        z = (z ^ (z >> 27)) * 0x94d049bb133111ebULL;
        return z ^ (z >> 31);
    }

    /** \brief Executes \a macro from \a s step by step; a terminal step (goal, collision) ends it early.
        An empty macro leaves the state unchanged with zero reward and discount 1. */
    template <class M>
    inline MacroStepResult<typename M::State, typename M::Observation> executeMacro(const M &model,
                                                                                    const typename M::State &s,
                                                                                    MacroView<typename M::Action> macro,
                                                                                    Rng &rng) noexcept
    {
        MacroStepResult<typename M::State, typename M::Observation> out;
        const double gamma = model.discount();
        out.next = s;
        std::uint64_t key = 0x243f6a8885a308d3ULL;
        const std::uint64_t emptyKey = observationKeyOf(model, typename M::Observation{});
        out.lastObservationKey = emptyKey;
        for (const auto &a : macro)
        {
            auto step = model.step(out.next, a, rng);
            out.reward += out.discount * step.reward;
            out.discount *= gamma;
            ++out.steps;
            const std::uint64_t stepKey = observationKeyOf(model, step.observation);
            key = combineObservationKey(key, stepKey);
            if (stepKey != emptyKey)
            {
                out.lastObservationKey = stepKey;
            }
            out.next = std::move(step.next);
            out.lastObservation = std::move(step.observation);
            if (step.terminal)
            {
                out.terminal = true;
                break;
            }
        }
        out.observationKey = key;
        return out;
    }
}  // namespace ropras::pomdp

#endif
