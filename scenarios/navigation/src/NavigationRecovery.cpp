#include "ropras/scenarios/navigation/NavigationRecovery.h"

namespace ropras::scenarios
{
    namespace
    {
        constexpr int DRAWS = 100;

        /// a state from which the episode went on with observation "seen" (true: a position, false: None)
        bool explains(const NavigationModel &model, const NavState &s, const NavigationModel::Observation &o,
                      const NavigationModel::Action &a) noexcept
        {
            const auto &c = model.config();
            return model.observable(s.p) == o.seen && !model.blocked(s.p) && !model.inDanger(s.p) &&
                   !c.goal.contains(s.p) && model.observationProbability(o, s, a) > 0.0;
        }
    }  // namespace

    void NavigationRecovery::recover(const NavigationModel &model, const NavigationModel::Action &a,
                                     const NavigationModel::Observation &o, std::vector<NavState> &particles,
                                     std::vector<double> &weights, pomdp::Rng &rng)
    {
        const int dims = model.dims();
        const double sigma = model.config().observationSigma;
        weights.assign(particles.size(), 0.0);
        for (std::size_t i = 0; i < particles.size(); ++i)
        {
            NavState &s = particles[i];
            for (int draw = 0; draw < DRAWS; ++draw)
            {
                NavState t = s;
                // from the observation itself, or jittered around the particle with a growing spread
                const double spread = o.seen ? sigma : sigma * static_cast<double>(1 << (draw / 20));
                for (int k = 0; k < dims; ++k)
                {
                    t.p[k] = (o.seen ? o.p[k] : s.p[k]) + rng.normal(0.0, spread);
                }
                if (explains(model, t, o, a))
                {
                    s = t;
                    weights[i] = 1.0;
                    break;
                }
            }
        }
    }
}  // namespace ropras::scenarios
