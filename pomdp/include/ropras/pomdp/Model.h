#ifndef ROPRAS_POMDP_MODEL_H
#define ROPRAS_POMDP_MODEL_H

#include <cstdint>
#include <cstring>
#include <type_traits>
#include <utility>

#include "ropras/pomdp/Rng.h"

namespace ropras::pomdp
{
    /** \brief Result of one generative step G(s, a) of a model. */
    template <class State, class Observation>
    struct StepResult
    {
        State next{};
        Observation observation{};
        double reward{0.0};
        /** \brief The episode ended in \c next (goal reached, collision, ...): no value follows. */
        bool terminal{false};
    };

    /** \page pomdp_model The Model concept

        Solvers are templates over a model type \c M (no virtual call per step). A model is a const
        description that may be shared by threads; every random choice takes an explicit Rng.

        Required:
        - `using State = ...; using Action = ...; using Observation = ...;` value types chosen by the model
          (small trivially copyable types are fastest; no heap allocation per step is needed then).
        - `StepResult<State, Observation> step(const State &s, const Action &a, Rng &rng) const noexcept`
          the generative model: next state, observation, reward, terminal flag.
        - `double observationProbability(const Observation &o, const State &next, const Action &a) const`
          Z(o | s', a): a probability (discrete observations) or density (continuous), >= 0.
        - `State sampleInitialState(Rng &rng) const` a sample of the initial belief b0.
        - `double discount() const` gamma in (0, 1).

        Required by the solvers over primitive actions (POMCP, random reference macro-actions, default
        rollouts):
        - `std::size_t numActions() const` and `Action action(std::size_t i) const` a finite action set.

        Optional (detected at compile time; the default is used when absent):
        - `std::uint64_t observationKey(const Observation &o) const` the bin of an observation for the
          tree's observation binning. Default: the value itself for integral and enum observations (any
          other observation type requires this function).
        - `Action rolloutAction(const State &s, Rng &rng) const` rollout policy. Default: a uniformly
          chosen action among numActions().
        - `double heuristicValue(const State &s) const` value estimate added at the end of a rollout.
          Default: 0.
        - `void reinvigorate(State &s, Rng &rng) const` noise injected into a particle after a particle
          filter update (particle reinvigoration). Default: none.
    */

    namespace detail
    {
        template <class M, class = void>
        struct HasObservationKey : std::false_type
        {
        };
        template <class M>
        struct HasObservationKey<M, std::void_t<decltype(std::declval<const M &>().observationKey(
                                        std::declval<const typename M::Observation &>()))>> : std::true_type
        {
        };

        template <class M, class = void>
        struct HasRolloutAction : std::false_type
        {
        };
        template <class M>
        struct HasRolloutAction<M, std::void_t<decltype(std::declval<const M &>().rolloutAction(
                                       std::declval<const typename M::State &>(), std::declval<Rng &>()))>>
            : std::true_type
        {
        };

        template <class M, class = void>
        struct HasHeuristicValue : std::false_type
        {
        };
        template <class M>
        struct HasHeuristicValue<M, std::void_t<decltype(std::declval<const M &>().heuristicValue(
                                        std::declval<const typename M::State &>()))>> : std::true_type
        {
        };

        template <class M, class = void>
        struct HasReinvigorate : std::false_type
        {
        };
        template <class M>
        struct HasReinvigorate<M, std::void_t<decltype(std::declval<const M &>().reinvigorate(
                                      std::declval<typename M::State &>(), std::declval<Rng &>()))>> : std::true_type
        {
        };

        template <class M, class = void>
        struct HasActionSet : std::false_type
        {
        };
        template <class M>
        struct HasActionSet<M, std::void_t<decltype(std::declval<const M &>().numActions()),
                                           decltype(std::declval<const M &>().action(std::size_t{0}))>> : std::true_type
        {
        };
    }  // namespace detail

    /** \brief Whether the model has the optional reinvigorate(). */
    template <class M>
    inline constexpr bool hasReinvigorate = detail::HasReinvigorate<M>::value;

    /** \brief Whether the model has a finite action set (numActions(), action(i)). */
    template <class M>
    inline constexpr bool hasActionSet = detail::HasActionSet<M>::value;

    /** \brief Observation bin key: the model's observationKey() or the integral/enum value itself. */
    template <class M>
    inline std::uint64_t observationKeyOf(const M &model, const typename M::Observation &o) noexcept
    {
        if constexpr (detail::HasObservationKey<M>::value)
        {
            return static_cast<std::uint64_t>(model.observationKey(o));
        }
        else
        {
            using O = typename M::Observation;
            static_assert(std::is_integral_v<O> || std::is_enum_v<O>,
                          "Model::Observation is not integral or enum: the model must provide observationKey()");
            (void)model;
            return static_cast<std::uint64_t>(o);
        }
    }

    /** \brief Rollout action: the model's rolloutAction() or a uniformly chosen primitive action. */
    template <class M>
    inline typename M::Action rolloutActionOf(const M &model, const typename M::State &s, Rng &rng) noexcept
    {
        if constexpr (detail::HasRolloutAction<M>::value)
        {
            return model.rolloutAction(s, rng);
        }
        else
        {
            static_assert(hasActionSet<M>, "rollouts need Model::rolloutAction() or numActions()/action(i)");
            (void)s;
            return model.action(static_cast<std::size_t>(rng.uniformIndex(model.numActions())));
        }
    }

    /** \brief Heuristic value at the end of a rollout: the model's heuristicValue() or 0. */
    template <class M>
    inline double heuristicValueOf(const M &model, const typename M::State &s) noexcept
    {
        if constexpr (detail::HasHeuristicValue<M>::value)
        {
            return model.heuristicValue(s);
        }
        else
        {
            (void)model;
            (void)s;
            return 0.0;
        }
    }

    /** \brief Discounted random rollout from \a s for at most \a steps primitive steps, plus the heuristic
        value of the last state unless it is terminal or \a withHeuristic is false. */
    template <class M>
    inline double rolloutValue(const M &model, typename M::State s, unsigned steps, Rng &rng,
                               bool withHeuristic = true) noexcept
    {
        const double gamma = model.discount();
        double value = 0.0;
        double weight = 1.0;
        for (unsigned i = 0; i < steps; ++i)
        {
            const auto a = rolloutActionOf(model, s, rng);
            auto result = model.step(s, a, rng);
            value += weight * result.reward;
            weight *= gamma;
            if (result.terminal)
            {
                return value;
            }
            s = std::move(result.next);
        }
        return withHeuristic ? value + weight * heuristicValueOf(model, s) : value;
    }
}  // namespace ropras::pomdp

#endif
