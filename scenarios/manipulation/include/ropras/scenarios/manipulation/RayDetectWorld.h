#ifndef ROPRAS_SCENARIOS_MANIPULATION_RAY_DETECT_WORLD_H
#define ROPRAS_SCENARIOS_MANIPULATION_RAY_DETECT_WORLD_H

#include <memory>

#include "ropras/pomdp/World.h"
#include "ropras/scenarios/manipulation/ArmBulletWorld.h"
#include "ropras/scenarios/manipulation/RayDetectModel.h"

namespace ropras::scenarios
{
    /** \brief What really happens in Ray-Detect: the model's noise draw and its goal / reward / observation-noise
        rules (RayDetectModel::proposeMotion, finishStep), but whether the motion collides and what the detector
        sees are decided by an ArmBulletWorld built from the true state's scene: the table and the can (static,
        not detectable), the 4 obstacle boxes at the true poses (btBoxShape, detectable), the arm as its
        collision spheres; the detector is btCollisionWorld::rayTest against the 4 obstacles. */
    class RayDetectWorld final : public pomdp::World<RayDetectModel>
    {
    public:
        explicit RayDetectWorld(std::shared_ptr<const RayDetectModel> model);

        /// rebuilds the Bullet world with the obstacles of \a initial
        void reset(const State &initial) override;
        const State &state() const override { return state_; }
        pomdp::StepResult<State, Observation> step(const Action &action, pomdp::Rng &rng) override;

        /// the Bullet detector in \a s's configuration (the world's obstacles: those of the last reset)
        RayDetectModel::Detection detect(const double *q) const;
        ArmBulletWorld &bullet() { return *bullet_; }

    private:
        std::shared_ptr<const RayDetectModel> model_;
        std::unique_ptr<ArmBulletWorld> bullet_;
        State state_{};
    };
}  // namespace ropras::scenarios

#endif
