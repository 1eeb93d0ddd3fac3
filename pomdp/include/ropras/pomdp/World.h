#ifndef ROPRAS_POMDP_WORLD_H
#define ROPRAS_POMDP_WORLD_H

#include <memory>
#include <utility>

#include "ropras/core/Error.h"
#include "ropras/pomdp/Model.h"

namespace ropras::pomdp
{
    /** \brief What really happens when an action executes: the hidden true state and its evolution.

        The planner only ever sees the model M (its fast generative model); the world may differ from it
        (e.g. a physics engine's collision detection instead of the planner's sphere model). The world
        returns the same StepResult as the model so the episode loop can feed the observation to the
        particle filter and book the reward. One world object runs one episode at a time (not thread-safe). */
    template <class M>
    class World
    {
    public:
        using State = typename M::State;
        using Action = typename M::Action;
        using Observation = typename M::Observation;

        virtual ~World() = default;

        /** \brief Starts an episode in the true state \a initial. */
        virtual void reset(const State &initial) = 0;

        /** \brief The current true state. */
        virtual const State &state() const = 0;

        /** \brief Executes \a action: the new true state, the observation the agent receives, the reward and
            whether the episode ended. */
        virtual StepResult<State, Observation> step(const Action &action, Rng &rng) = 0;
    };

    /** \brief The model used as its own world (a pure simulation). */
    template <class M>
    class SimulatedWorld final : public World<M>
    {
    public:
        using typename World<M>::State;
        using typename World<M>::Action;
        using typename World<M>::Observation;

        explicit SimulatedWorld(std::shared_ptr<const M> model) : model_(std::move(model))
        {
            if (!model_)
            {
                throw Error("SimulatedWorld: null model");
            }
        }

        void reset(const State &initial) override { state_ = initial; }
        const State &state() const override { return state_; }
        StepResult<State, Observation> step(const Action &action, Rng &rng) override
        {
            auto result = model_->step(state_, action, rng);
            state_ = result.next;
            return result;
        }

    private:
        std::shared_ptr<const M> model_;
        State state_{};
    };
}  // namespace ropras::pomdp

#endif
