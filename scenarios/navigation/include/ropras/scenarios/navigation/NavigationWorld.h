#ifndef ROPRAS_SCENARIOS_NAVIGATION_WORLD_H
#define ROPRAS_SCENARIOS_NAVIGATION_WORLD_H

#include <memory>

#include "ropras/pomdp/World.h"
#include "ropras/scenarios/BulletCollisionWorld.h"
#include "ropras/scenarios/navigation/NavigationModel.h"

namespace ropras::scenarios
{
    /** \brief What really happens in a navigation scenario: the model's rules (slip, rewards, terminal
        flags, observations: NavigationModel::executedAction / arrive), but whether a move is blocked is
        decided by a Bullet collision world built from the same walls and obstacles (the robot is a Bullet
        sphere of radius robot_radius), not by the model's grid. Leaving the bounds is blocked as in the
        model. One instance per episode. */
    class NavigationWorld final : public pomdp::World<NavigationModel>
    {
    public:
        explicit NavigationWorld(std::shared_ptr<const NavigationModel> model);

        void reset(const State &initial) override;
        const State &state() const override { return state_; }
        pomdp::StepResult<State, Observation> step(const Action &action, pomdp::Rng &rng) override;

        /** \brief Whether Bullet says the robot at \a p touches a wall or obstacle, or \a p is out of bounds. */
        bool blocked(const double *p) const;

    private:
        std::shared_ptr<const NavigationModel> model_;
        std::unique_ptr<BulletCollisionWorld> bullet_;
        std::size_t agent_{0};
        State state_{};
    };
}  // namespace ropras::scenarios

#endif
