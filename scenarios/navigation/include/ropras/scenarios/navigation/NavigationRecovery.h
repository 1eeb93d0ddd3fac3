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

        - A position o was seen: every particle is redrawn from the observation alone, s = o + N(0,
          observation_sigma) per axis, kept only where the model could have produced o and gone on (in an
          observation zone, NavigationModel::continuesAt, a non-zero likelihood; at most 100 draws). That is
          the posterior of a flat prior over the states that explain o; the old particles, all contradicted,
          carry nothing.
        - None was seen: every particle moves to where the step's None is explained (outside every observation
          zone, continuesAt). It takes 20 Gaussian jitters of s.d. observation_sigma and keeps the shortest one
          that explains the step and whose straight move touches no wall or obstacle; if none does, 20 more
          at twice the s.d., and so on up to 16 observation_sigma. (A depletion after a step that every particle
          ended, with continuation on, takes the branch of what was seen.)

        A particle with no such draw keeps its place and weight 0 (all zero: the filter makes them uniform).
        Stateless: one instance may serve any number of filters. */
    class NavigationRecovery final : public pomdp::DepletionRecovery<NavigationModel>
    {
    public:
        void recover(const NavigationModel &model, const NavigationModel::Action &a,
                     const NavigationModel::Observation &o, std::vector<NavState> &particles,
                     std::vector<double> &weights, pomdp::Rng &rng) noexcept override;
        std::string name() const override { return "observation"; }
    };
}  // namespace ropras::scenarios

#endif
