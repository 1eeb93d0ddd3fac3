#ifndef ROPRAS_SCENARIOS_MANIPULATION_SPHERE_SEARCH_WORLD_H
#define ROPRAS_SCENARIOS_MANIPULATION_SPHERE_SEARCH_WORLD_H

#include <memory>

#include "ropras/pomdp/World.h"
#include "ropras/scenarios/manipulation/ArmBulletWorld.h"
#include "ropras/scenarios/manipulation/SphereSearchModel.h"

namespace ropras::scenarios
{
    /** \brief What really happens in Sphere-Search: the model's noise draw and its light / goal / reward rules
        (SphereSearchModel::proposeMotion, finishStep), but whether the motion collides is decided by an
        ArmBulletWorld built from the same obstacle spheres, with the arm as its collision spheres. */
    class SphereSearchWorld final : public pomdp::World<SphereSearchModel>
    {
    public:
        explicit SphereSearchWorld(std::shared_ptr<const SphereSearchModel> model);

        void reset(const State &initial) override { state_ = initial; }
        const State &state() const override { return state_; }
        pomdp::StepResult<State, Observation> step(const Action &action, pomdp::Rng &rng) override;

        ArmBulletWorld &bullet() { return bullet_; }

    private:
        std::shared_ptr<const SphereSearchModel> model_;
        ArmBulletWorld bullet_;
        State state_{};
    };
}  // namespace ropras::scenarios

#endif
