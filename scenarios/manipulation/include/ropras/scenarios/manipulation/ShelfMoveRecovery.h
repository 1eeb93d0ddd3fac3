#ifndef ROPRAS_SCENARIOS_MANIPULATION_SHELF_MOVE_RECOVERY_H
#define ROPRAS_SCENARIOS_MANIPULATION_SHELF_MOVE_RECOVERY_H

#include <string>
#include <vector>

#include "ropras/pomdp/ParticleFilter.h"
#include "ropras/scenarios/manipulation/ShelfMoveModel.h"

namespace ropras::scenarios
{
    /** \brief Shelf-Move's depletion recovery: repairs every particle from the observation that none of them
        explains, instead of ignoring it. Depletion happens when the world and the model part ways (a grasp the
        world refused, a step the world blocked, a can seen where no particle has it); ignoring the observation
        then keeps a belief that never meets the world again (every later observation has zero likelihood too).

        Per particle: what it holds becomes what the gripper reports (a can it believed held but is not stays
        where the hand left it; a can reported held follows the hand); every can the observation detects is
        moved to the detection + U(-w, w) in x and y (w = can_observation_noise; its height kept; up to
        DETECTION_DRAWS draws, then where the particle has it). This is tried with the particle's own joints
        first (a joint mismatch only lowers the likelihood), then with the observed ones (clamped). The first
        candidate that is physically valid (validState: no floating or interpenetrating can, the arm clear)
        and explains the observation (likelihood > 0) is taken, else the first valid one; with none the
        particle keeps its propagated state. The weights are the likelihoods of the repaired particles (the
        filter makes them uniform when all are zero). */
    class ShelfMoveRecovery final : public pomdp::DepletionRecovery<ShelfMoveModel>
    {
    public:
        void recover(const ShelfMoveModel &model, const ShelfMoveModel::Action &a, const ShelfMoveModel::Observation &o,
                     std::vector<ShelfMoveModel::State> &particles, std::vector<double> &weights,
                     pomdp::Rng &rng) override;
        std::string name() const override { return "shelf-move-observation-repair"; }

        /// draws of the detected cans' positions tried before the repair keeps them where they are
        static constexpr int DETECTION_DRAWS = 8;

        /// the repair of one particle (true when a valid candidate was applied to \a s); \a likelihood (if
        /// non-null) gets Z(o | repaired s), 0 when no valid candidate explains \a o (left unset otherwise)
        static bool repair(const ShelfMoveModel &model, const ShelfMoveModel::Action &a,
                           const ShelfMoveModel::Observation &o, ShelfMoveModel::State &s, pomdp::Rng &rng,
                           double *likelihood = nullptr) noexcept;
    };
}  // namespace ropras::scenarios

#endif
