#include "ropras/scenarios/multi-drone/MultiDroneModel.h"

#include <algorithm>
#include <cmath>
#include <nlohmann/json.hpp>
#include <set>
#include <string>
#include <vector>

#include "ropras/core/Error.h"
#include "ropras/scenarios/ConfigReader.h"

namespace ropras::scenarios
{
    namespace
    {
        constexpr double PI = 3.14159265358979323846;

        const std::set<std::string> &modelKeys()
        {
            static const std::set<std::string> keys{
                "bounds",         "drone_radius",      "step_size",          "target_step", "detection_range",
                "capture_radius", "observation_sigma", "observation_bin",    "step_reward", "capture_reward",
                "discount",       "horizon",           "reinvigorate_sigma", "starts"};
            return keys;
        }

        std::string where(const std::string &scenario, const std::string &key)
        {
            return "scenario " + scenario + ": key \"" + key + "\"";
        }

        std::array<double, 3> point(const std::vector<double> &row)
        {
            return {row[0], row[1], row[2]};
        }

        std::string str(const std::array<double, 3> &p)
        {
            return "[" + std::to_string(p[0]) + ", " + std::to_string(p[1]) + ", " + std::to_string(p[2]) + "]";
        }
    }  // namespace

    MultiDroneConfig MultiDroneConfig::fromJson(const nlohmann::json &json, const std::string &scenario)
    {
        const ConfigReader r(scenario, json);
        auto known = modelKeys();
        known.insert({"planning", "defaults", "solver_defaults"});
        r.requireKnown(known);
        MultiDroneConfig c;
        const auto bounds = r.rows("bounds", 3);
        if (bounds.size() != 2)
        {
            r.fail("bounds", "must be [[xmin, ymin, zmin], [xmax, ymax, zmax]], not " + r.at("bounds").dump());
        }
        c.lower = point(bounds[0]);
        c.upper = point(bounds[1]);
        c.droneRadius = r.number("drone_radius");
        c.stepSize = r.number("step_size");
        c.targetStep = r.number("target_step");
        c.detectionRange = r.number("detection_range");
        c.captureRadius = r.number("capture_radius");
        c.observationSigma = r.number("observation_sigma");
        c.observationBin = r.number("observation_bin");
        c.stepReward = r.number("step_reward");
        c.captureReward = r.number("capture_reward");
        c.discount = r.number("discount");
        c.horizon = r.count("horizon", 1, 10000000);
        c.reinvigorateSigma = r.number("reinvigorate_sigma");
        const auto starts = r.rows("starts", 3);
        if (starts.size() != MULTI_DRONE_COUNT)
        {
            r.fail("starts", "must list " + std::to_string(MULTI_DRONE_COUNT) + " drone positions [x, y, z], not " +
                                 r.at("starts").dump());
        }
        for (std::size_t d = 0; d < MULTI_DRONE_COUNT; ++d)
        {
            c.starts[d] = point(starts[d]);
        }
        c.validate(scenario);
        return c;
    }

    void MultiDroneConfig::validate(const std::string &scenario) const
    {
        for (int k = 0; k < 3; ++k)
        {
            if (!std::isfinite(lower[k]) || !std::isfinite(upper[k]) || !(upper[k] > lower[k]))
            {
                throw Error(where(scenario, "bounds") + ": lower " + str(lower) + " must be below upper " + str(upper) +
                            " on every axis");
            }
        }
        const auto positive = [&](const char *key, double value)
        {
            if (!(value > 0.0) || !std::isfinite(value))
            {
                throw Error(where(scenario, key) + " = " + nlohmann::json(value).dump() + " must be > 0");
            }
        };
        positive("drone_radius", droneRadius);
        positive("step_size", stepSize);
        positive("target_step", targetStep);
        positive("detection_range", detectionRange);
        positive("capture_radius", captureRadius);
        positive("observation_sigma", observationSigma);
        positive("observation_bin", observationBin);
        if (!(reinvigorateSigma >= 0.0) || !std::isfinite(reinvigorateSigma))
        {
            throw Error(where(scenario, "reinvigorate_sigma") + " = " + nlohmann::json(reinvigorateSigma).dump() +
                        " must be >= 0");
        }
        if (!(captureRadius < detectionRange))
        {
            throw Error(where(scenario, "capture_radius") + " = " + nlohmann::json(captureRadius).dump() +
                        " must be smaller than detection_range = " + nlohmann::json(detectionRange).dump());
        }
        if (!std::isfinite(stepReward) || !std::isfinite(captureReward))
        {
            throw Error(where(scenario, "step_reward") + " / capture_reward must be finite");
        }
        if (!(discount > 0.0 && discount <= 1.0))
        {
            throw Error(where(scenario, "discount") + " = " + nlohmann::json(discount).dump() + " must be in (0, 1]");
        }
        if (horizon == 0)
        {
            throw Error(where(scenario, "horizon") + " must be >= 1");
        }
        for (std::size_t d = 0; d < MULTI_DRONE_COUNT; ++d)
        {
            for (int k = 0; k < 3; ++k)
            {
                if (!std::isfinite(starts[d][k]) || starts[d][k] < lower[k] || starts[d][k] > upper[k])
                {
                    throw Error(where(scenario, "starts") + ": drone " + std::to_string(d + 1) + " at " +
                                str(starts[d]) + " is outside the bounds " + str(lower) + " .. " + str(upper));
                }
            }
            for (std::size_t j = 0; j < d; ++j)
            {
                const double dist = std::sqrt(MultiDroneModel::squaredDistance(starts[d].data(), starts[j].data()));
                if (dist < 2.0 * droneRadius)
                {
                    throw Error(where(scenario, "starts") + ": drones " + std::to_string(j + 1) + " and " +
                                std::to_string(d + 1) + " overlap (centres " + std::to_string(dist) +
                                " m apart, drone_radius " + std::to_string(droneRadius) + ")");
                }
            }
        }
        // The initial target is drawn outside every capture ball: some of the box must be left.
        const double volume = (upper[0] - lower[0]) * (upper[1] - lower[1]) * (upper[2] - lower[2]);
        const double balls =
            static_cast<double>(MULTI_DRONE_COUNT) * 4.0 / 3.0 * PI * captureRadius * captureRadius * captureRadius;
        if (!(balls < 0.5 * volume))
        {
            throw Error(where(scenario, "capture_radius") + " = " + nlohmann::json(captureRadius).dump() +
                        ": the capture balls of the drones cover half of the box or more");
        }
    }

    MultiDroneModel::MultiDroneModel(const MultiDroneConfig &config) : config_(config)
    {
        config_.validate("multi-drone");
        const double s2 = 2.0 * PI * config_.observationSigma * config_.observationSigma;
        gaussianNorm_ = 1.0 / (s2 * std::sqrt(s2));
    }

    MultiDroneModel::State MultiDroneModel::sampleInitialState(pomdp::Rng &rng) const noexcept
    {
        State s{};
        for (std::size_t d = 0; d < MULTI_DRONE_COUNT; ++d)
        {
            for (int k = 0; k < 3; ++k)
            {
                s.drone[d][k] = config_.starts[d][k];
            }
        }
        // Rejection sampling: the capture balls cover less than half of the box (validated), so this ends
        // quickly; the bound of 1000 attempts only guards against pathological values.
        for (int attempt = 0; attempt < 1000; ++attempt)
        {
            for (int k = 0; k < 3; ++k)
            {
                s.target[k] = rng.uniform(config_.lower[k], config_.upper[k]);
            }
            if (!reachedGoal(s))
            {
                break;
            }
        }
        return s;
    }

    std::uint64_t MultiDroneModel::observationKey(const Observation &o) const noexcept
    {
        if (!o.seen)
        {
            return 0;
        }
        std::uint64_t h = 0x9e3779b97f4a7c15ULL;
        for (int k = 0; k < 3; ++k)
        {
            const double cell = std::floor(o.position[k] / config_.observationBin);
            const auto v = static_cast<std::int64_t>(std::isfinite(cell) ? std::fmax(-1e15, std::fmin(1e15, cell)) : 0);
            h ^= static_cast<std::uint64_t>(v) + 0x9e3779b97f4a7c15ULL + (h << 6) + (h >> 2);
            h *= 0xbf58476d1ce4e5b9ULL;
            h ^= h >> 31;
        }
        return h | 1ULL;
    }

    void MultiDroneModel::reinvigorate(State &s, pomdp::Rng &rng) const noexcept
    {
        if (config_.reinvigorateSigma <= 0.0)
        {
            return;
        }
        for (int k = 0; k < 3; ++k)
        {
            s.target[k] += config_.reinvigorateSigma * rng.normal();
        }
        wrapTarget(s.target);
    }
}  // namespace ropras::scenarios
