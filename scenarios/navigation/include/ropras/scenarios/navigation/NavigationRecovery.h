#ifndef ROPRAS_SCENARIOS_NAVIGATION_RECOVERY_H
#define ROPRAS_SCENARIOS_NAVIGATION_RECOVERY_H

#include <string>
#include <vector>

#include "ropras/pomdp/ParticleFilter.h"
#include "ropras/scenarios/navigation/NavigationModel.h"

namespace ropras::scenarios
{
    /** \brief Depletion recovery of the navigation scenarios (`depletion_recovery` "observation"): when no
        particle explains a step, the belief is rebuilt from what the robot observed instead of ignoring it.

        - A position was observed (the robot is in an observation zone): every particle is redrawn from the
          observation alone, s = o + N(0, observation_sigma) per axis, kept only where the model could have
          produced that observation and gone on (inside an observation zone, not blocked, not in a danger zone
          or the goal; at most 100 draws per particle). That is the posterior of a flat prior over the states
          that explain o; the old particles, all contradicted, carry nothing.
        - None was observed (or every particle would have ended the episode): every particle moves by the first
          of up to 100 Gaussian jitters that makes it explain the step (outside every observation zone, not
          blocked, not in a danger zone or the goal); their s.d. is observation_sigma for the first 20 draws and
          doubles every 20, so the move is as small as the draws allow.

        A particle with no such draw keeps its place and weight 0 (all zero: the filter makes them uniform).
        Allocation-free, noexcept in its loops; the model must outlive it. */
    class NavigationRecovery final : public pomdp::DepletionRecovery<NavigationModel>
    {
    public:
        void recover(const NavigationModel &model, const NavigationModel::Action &a,
                     const NavigationModel::Observation &o, std::vector<NavState> &particles,
                     std::vector<double> &weights, pomdp::Rng &rng) override;
        std::string name() const override { return "observation"; }
    };
}  // namespace ropras::scenarios

#endif
