#ifndef ROPRAS_SCENARIOS_CROSSING_WORLD_H
#define ROPRAS_SCENARIOS_CROSSING_WORLD_H

#include <memory>

#include "ropras/pomdp/World.h"
#include "ropras/scenarios/BulletCollisionWorld.h"
#include "ropras/scenarios/crossing/CrossingModel.h"

namespace ropras::scenarios
{
    /** \brief What really happens in stretch-crossing: a Bullet collision world holds the lab walls and the
        tables (boxes), the pedestrian (a sphere agent) and the robot (a rigid agent: the compound of its
        collision spheres); after every substep Bullet decides whether the robot touches the pedestrian or a
        table / wall. The pedestrian's step is scaled per action by 1 + U(-n, n), n =
        world_pedestrian_speed_noise (a roughly constant speed; the model assumes exactly constant). The drive,
        the goal test, the clearance penalty, rewards and observations are the model's shared functions
        (CrossingModel::simulate). One instance per episode (not thread-safe). */
    class CrossingWorld final : public pomdp::World<CrossingModel>
    {
    public:
        /** \brief Throws ropras::Error for a null model. */
        explicit CrossingWorld(std::shared_ptr<const CrossingModel> model);

        void reset(const State &initial) override;
        const State &state() const override { return state_; }
        pomdp::StepResult<State, Observation> step(const Action &action, pomdp::Rng &rng) override;

        /** \brief Bullet's verdict on the robot and the pedestrian as they are in \a s. */
        CrossingEvent contact(const State &s);

    private:
        std::shared_ptr<const CrossingModel> model_;
        BulletCollisionWorld bullet_;
        std::size_t robot_{0}, pedestrian_{0};
        State state_{};
    };
}  // namespace ropras::scenarios

#endif
