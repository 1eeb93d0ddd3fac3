#include "ropras/scenarios/navigation/NavigationRecovery.h"

#include <algorithm>
#include <cmath>

namespace ropras::scenarios
{
    namespace
    {
        constexpr int SEEN_DRAWS = 100;       ///< draws from the observation per particle
        constexpr int SPREAD_LEVELS = 5;      ///< None: jitter s.d. sigma, 2 sigma, ... 16 sigma
        constexpr int DRAWS_PER_SPREAD = 20;  ///< None: draws at each s.d.

        /// a state from which the episode went on with observation \a o (the likelihood is 0 where a seen
        /// position is unobservable, None observable, or beyond the cutoff)
        bool explains(const NavigationModel &model, const NavState &s, const NavigationModel::Observation &o,
                      const NavigationModel::Action &a) noexcept
        {
            return model.continuesAt(s.p) && model.observationProbability(o, s, a) > 0.0;
        }

        /// the straight move from \a s to \a t never touches a wall or obstacle (checked every quarter step)
        bool freeMove(const NavigationModel &model, const NavState &s, const NavState &t, double length) noexcept
        {
            const int pieces = static_cast<int>(std::ceil(length / (0.25 * model.config().stepLength)));
            for (int i = 1; i < pieces; ++i)
            {
                const double f = static_cast<double>(i) / pieces;
                NavState m;
                for (int k = 0; k < 3; ++k)
                {
                    m.p[k] = s.p[k] + f * (t.p[k] - s.p[k]);
                }
                if (model.blocked(m.p))
                {
                    return false;
                }
            }
            return true;
        }

        double distance(const NavState &s, const NavState &t) noexcept
        {
            double d2 = 0.0;
            for (int k = 0; k < 3; ++k)
            {
                d2 += (t.p[k] - s.p[k]) * (t.p[k] - s.p[k]);
            }
            return std::sqrt(d2);
        }
    }  // namespace

    void NavigationRecovery::recover(const NavigationModel &model, const NavigationModel::Action &a,
                                     const NavigationModel::Observation &o, std::vector<NavState> &particles,
                                     std::vector<double> &weights, pomdp::Rng &rng) noexcept
    {
        const int dims = model.dims();
        const double sigma = model.config().observationSigma;
        weights.assign(particles.size(), 0.0);
        for (std::size_t i = 0; i < particles.size(); ++i)
        {
            NavState &s = particles[i];
            if (o.seen)  // redrawn from the observation alone
            {
                for (int draw = 0; draw < SEEN_DRAWS && weights[i] == 0.0; ++draw)
                {
                    NavState t = s;
                    for (int k = 0; k < dims; ++k)
                    {
                        t.p[k] = o.p[k] + rng.normal(0.0, sigma);
                    }
                    if (explains(model, t, o, a))
                    {
                        s = t;
                        weights[i] = 1.0;
                    }
                }
                continue;
            }
            // None: the shortest free move among the draws of the smallest spread that has one
            for (int level = 0; level < SPREAD_LEVELS && weights[i] == 0.0; ++level)
            {
                const double spread = sigma * static_cast<double>(1 << level);
                NavState best = s;
                double bestMove = INFINITY;
                for (int draw = 0; draw < DRAWS_PER_SPREAD; ++draw)
                {
                    NavState t = s;
                    for (int k = 0; k < dims; ++k)
                    {
                        t.p[k] = s.p[k] + rng.normal(0.0, spread);
                    }
                    const double move = distance(s, t);
                    if (move < bestMove && explains(model, t, o, a) && freeMove(model, s, t, move))
                    {
                        best = t;
                        bestMove = move;
                    }
                }
                if (std::isfinite(bestMove))
                {
                    s = best;
                    weights[i] = 1.0;
                }
            }
        }
    }
}  // namespace ropras::scenarios
