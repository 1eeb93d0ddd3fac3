// ShelfMoveModel's observations: proximity sensing of the cans, its likelihood and the tree's observation bins.
#include <algorithm>
#include <cmath>

#include "ropras/scenarios/manipulation/ShelfMoveModel.h"

namespace ropras::scenarios
{
    namespace
    {
        std::uint64_t mix(std::uint64_t h, std::int64_t v) noexcept
        {
            h ^= static_cast<std::uint64_t>(v) + 0x9e3779b97f4a7c15ULL + (h << 6) + (h >> 2);
            h *= 0xbf58476d1ce4e5b9ULL;
            return h ^ (h >> 31);
        }

        std::int64_t cell(double v, double bin) noexcept
        {
            const double c = std::floor(v / bin);
            return static_cast<std::int64_t>(std::isfinite(c) ? std::fmax(-1e15, std::fmin(1e15, c)) : 0.0);
        }
    }  // namespace

    void ShelfMoveModel::observe(const State &n, pomdp::Rng &rng, Observation &o) const noexcept
    {
        for (std::size_t j = 0; j < ARM_DOF; ++j)
        {
            o.q[j] = n.q[j] + config_.observationSigma * rng.normal();
        }
        o.held = n.held;
        o.detected = 0;
        const Eigen::Vector3d p = endEffector(n);
        const double w = config_.canObservationNoise;
        for (std::size_t k = 0; k < SHELF_CANS; ++k)
        {
            const Eigen::Vector3d c(n.can[k][0], n.can[k][1], n.can[k][2]);
            if (static_cast<int>(k) == n.held || (c - p).norm() > config_.senseDistance)
            {
                continue;
            }
            o.detected = static_cast<std::uint8_t>(o.detected | (1u << k));
            for (int a = 0; a < 3; ++a)
            {
                o.can[k][a] = c[a] + w * (2.0 * rng.uniform01() - 1.0);
            }
        }
    }

    double ShelfMoveModel::observationProbability(const Observation &o, const State &next,
                                                  const Action &) const noexcept
    {
        if (o.held != next.held)
        {
            return 0.0;
        }
        const Eigen::Vector3d p = endEffector(next);
        const double w = config_.canObservationNoise;
        double log = logNorm_;
        for (std::size_t j = 0; j < ARM_DOF; ++j)
        {
            const double d = (o.q[j] - next.q[j]) / config_.observationSigma;
            log -= 0.5 * d * d;
        }
        for (std::size_t k = 0; k < SHELF_CANS; ++k)
        {
            const Eigen::Vector3d c(next.can[k][0], next.can[k][1], next.can[k][2]);
            const bool expected = static_cast<int>(k) != next.held && (c - p).norm() <= config_.senseDistance;
            const bool seen = (o.detected >> k) & 1u;
            if (expected != seen)
            {
                return 0.0;
            }
            if (!seen)
            {
                continue;
            }
            for (int a = 0; a < 3; ++a)
            {
                // U(-w, w), softened outside the box by a Gaussian tail (no 0/1 likelihoods)
                const double excess = std::max(0.0, std::abs(o.can[k][a] - c[a]) - w) / config_.observationSoftening;
                log += -std::log(2.0 * w) - 0.5 * excess * excess;
            }
        }
        return std::exp(log);
    }

    std::uint64_t ShelfMoveModel::observationKey(const Observation &o) const noexcept
    {
        std::uint64_t h = mix(0x9e3779b97f4a7c15ULL, o.held + 1);
        h = mix(h, o.detected);
        for (std::size_t k = 0; k < SHELF_CANS; ++k)
        {
            if ((o.detected >> k) & 1u)
            {
                for (int a = 0; a < 3; ++a)
                {
                    h = mix(h, cell(o.can[k][a], config_.observationCanBin));
                }
            }
        }
        if (config_.observationJointBin > 0.0)
        {
            for (std::size_t j = 0; j < ARM_DOF; ++j)
            {
                h = mix(h, cell(o.q[j], config_.observationJointBin));
            }
        }
        return h;
    }
}  // namespace ropras::scenarios
