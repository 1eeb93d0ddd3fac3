#ifndef ROPRAS_SCENARIOS_MULTI_DRONE_WORLD_H
#define ROPRAS_SCENARIOS_MULTI_DRONE_WORLD_H

#include <memory>

#include "ropras/pomdp/World.h"
#include "ropras/scenarios/BulletCollisionWorld.h"
#include "ropras/scenarios/multi-drone/MultiDroneModel.h"

namespace ropras::scenarios
{
    /** \brief What really happens in Multi-Drone Tag: the same rules as MultiDroneModel, except that whether
        two drones touch is decided by a Bullet collision world holding the four drone spheres (agents),
        not by the model's analytic centre-distance test. The box bounds, the target's flight, capture,
        reward and observation are the model's shared functions (proposeMove, finishStep), evaluated at the
        true next state. One instance per episode (not thread-safe). */
    class MultiDroneWorld final : public pomdp::World<MultiDroneModel>
    {
    public:
        /** \brief Throws ropras::Error for a null model. */
        explicit MultiDroneWorld(std::shared_ptr<const MultiDroneModel> model);

        void reset(const State &initial) override;
        const State &state() const override { return state_; }
        pomdp::StepResult<State, Observation> step(const Action &action, pomdp::Rng &rng) override;

        /** \brief Whether drone \a d of the current state moved to \a p would touch another drone (Bullet). */
        bool blocked(std::size_t d, const double *p) const;

    private:
        std::shared_ptr<const MultiDroneModel> model_;
        BulletCollisionWorld bullet_;
        State state_{};
    };
}  // namespace ropras::scenarios

#endif
