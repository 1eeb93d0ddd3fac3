#include "ropras/scenarios/manipulation/ShelfMoveRecovery.h"

#include <algorithm>
#include <cmath>

namespace ropras::scenarios
{
    bool ShelfMoveRecovery::repair(const ShelfMoveModel &model, const ShelfMoveModel::Action &a,
                                   const ShelfMoveModel::Observation &o, ShelfMoveModel::State &s, pomdp::Rng &rng,
                                   double *likelihood) noexcept
    {
        const double w = model.config().canObservationNoise;
        bool haveValid = false;
        ShelfMoveModel::State firstValid;
        // the particle's own joints first (their mismatch only lowers the likelihood), then the observed ones
        for (int joints = 0; joints < 2; ++joints)
        {
            ShelfMoveModel::State base = s;
            if (joints == 1)
            {
                std::copy(o.q, o.q + ARM_DOF, base.q);
                model.arm().clamp(base.q);
            }
            base.held = o.held >= 0 && o.held < static_cast<int>(SHELF_CANS) ? o.held : -1;
            model.followHand(base);
            // the detected cans at fresh draws inside the observation's box (a draw may overlap a can or the
            // hand), then where the particle has them
            for (int attempt = 0; attempt <= DETECTION_DRAWS; ++attempt)
            {
                ShelfMoveModel::State r = base;
                for (std::size_t k = 0; attempt < DETECTION_DRAWS && k < SHELF_CANS; ++k)
                {
                    if (static_cast<int>(k) == r.held || !((o.detected >> k) & 1u))
                    {
                        continue;
                    }
                    for (int axis = 0; axis < 2; ++axis)
                    {
                        r.can[k][axis] = o.can[k][axis] + rng.uniform(-w, w);
                    }
                }
                if (!model.validState(r))
                {
                    continue;
                }
                const double z = model.observationProbability(o, r, a);
                if (z > 0.0)
                {
                    s = r;
                    if (likelihood)
                        *likelihood = z;
                    return true;
                }
                if (!haveValid)
                {
                    firstValid = r;
                    haveValid = true;
                }
            }
        }
        if (haveValid)
        {
            s = firstValid;
            if (likelihood)
                *likelihood = 0.0;  // no valid candidate explains the observation
        }
        return haveValid;
    }

    void ShelfMoveRecovery::recover(const ShelfMoveModel &model, const ShelfMoveModel::Action &a,
                                    const ShelfMoveModel::Observation &o, std::vector<ShelfMoveModel::State> &particles,
                                    std::vector<double> &weights, pomdp::Rng &rng)
    {
        weights.resize(particles.size());
        for (std::size_t i = 0; i < particles.size(); ++i)
        {
            double z = 0.0;
            if (!repair(model, a, o, particles[i], rng, &z))
            {
                z = model.observationProbability(o, particles[i], a);  // kept as it was
            }
            weights[i] = std::isfinite(z) && z > 0.0 ? z : 0.0;
        }
    }
}  // namespace ropras::scenarios
