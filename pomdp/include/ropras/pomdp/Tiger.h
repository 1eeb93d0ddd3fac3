#ifndef ROPRAS_POMDP_TIGER_H
#define ROPRAS_POMDP_TIGER_H

#include <cstddef>
#include <cstdint>

#include "ropras/pomdp/Model.h"
#include "ropras/pomdp/SolverFactory.h"
#include "ropras/pomdp/TargetSpace.h"

namespace ropras::pomdp
{
    class ModelRegistry;

    /** \brief The classic Tiger POMDP (Kaelbling, Littman & Cassandra 1998), infinite-horizon version:
        listening costs 1 and reports the tiger's side correctly with probability 0.85; opening the door
        without the tiger pays +10, with the tiger -100; after opening, the problem resets (tiger placed
        uniformly, uninformative observation). gamma = 0.95; the optimal value from the uniform belief is
        about 19.37. */
    struct TigerModel
    {
        using State = std::uint8_t;        ///< 0: tiger behind the left door, 1: behind the right door.
        using Action = std::uint8_t;       ///< LISTEN, OPEN_LEFT, OPEN_RIGHT.
        using Observation = std::uint8_t;  ///< 0: hear left, 1: hear right.

        static constexpr Action LISTEN = 0;
        static constexpr Action OPEN_LEFT = 1;
        static constexpr Action OPEN_RIGHT = 2;

        double listenAccuracy{0.85};
        double listenReward{-1.0};
        double correctReward{10.0};
        double wrongReward{-100.0};
        double gamma{0.95};

        StepResult<State, Observation> step(State s, Action a, Rng &rng) const noexcept
        {
            StepResult<State, Observation> out;
            if (a == LISTEN)
            {
                out.next = s;
                out.reward = listenReward;
                out.observation = rng.bernoulli(listenAccuracy) ? s : static_cast<Observation>(1 - s);
                return out;
            }
            const State opened = a == OPEN_LEFT ? 0 : 1;
            out.reward = opened == s ? wrongReward : correctReward;
            out.next = static_cast<State>(rng.uniformIndex(2));
            out.observation = static_cast<Observation>(rng.uniformIndex(2));
            return out;
        }

        double observationProbability(Observation o, State next, Action a) const noexcept
        {
            if (a != LISTEN)
            {
                return 0.5;
            }
            return o == next ? listenAccuracy : 1.0 - listenAccuracy;
        }

        State sampleInitialState(Rng &rng) const noexcept { return static_cast<State>(rng.uniformIndex(2)); }

        double discount() const noexcept { return gamma; }

        std::size_t numActions() const noexcept { return 3; }

        Action action(std::size_t i) const noexcept { return static_cast<Action>(i); }
    };

    /** \brief Tiger's target space for the sampling heuristics: the goal of a particle is opening the door
        without the tiger, the single informative target is listening; a target is the primitive action that
        reaches it (the connector turns it into a one-step macro). Entropy bins: the tiger's side. */
    class TigerTargetSpace final : public TargetSpace<TigerModel::State, TigerModel::Action>
    {
    public:
        TigerModel::Action goal(const TigerModel::State &particle) const override
        {
            return particle == 0 ? TigerModel::OPEN_RIGHT : TigerModel::OPEN_LEFT;
        }
        std::size_t numInformative(const TigerModel::State &) const override { return 1; }
        TigerModel::Action informative(const TigerModel::State &, std::size_t) const override
        {
            return TigerModel::LISTEN;
        }
        double distance(const TigerModel::State &, const TigerModel::Action &) const override { return 1.0; }
        std::uint64_t entropyBin(const TigerModel::State &particle) const override { return particle; }
        std::size_t numEntropyBins() const override { return 2; }
        bool sampleFree(Rng &rng, TigerModel::Action &out) const override
        {
            out = static_cast<TigerModel::Action>(rng.uniformIndex(3));
            return true;
        }
    };

    /** \brief Tiger's components for makeSolver(): informed reference policy = sampling heuristic over
        TigerTargetSpace (parameter heuristic: 0 uniform, 1 dynamic (default); epsilon: epsilon-greedy
        mixture weight, default 0) with a one-step connector; defaults ucb_c = 30, rollout_steps = 0. */
    ModelComponents<TigerModel> tigerComponents(const TigerModel &model = TigerModel{});

    /** \brief Registers "tiger" in \a registry. */
    void registerTiger(ModelRegistry &registry);
}  // namespace ropras::pomdp

#endif
