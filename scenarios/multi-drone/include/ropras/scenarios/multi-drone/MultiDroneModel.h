#ifndef ROPRAS_SCENARIOS_MULTI_DRONE_MODEL_H
#define ROPRAS_SCENARIOS_MULTI_DRONE_MODEL_H

#include <array>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <nlohmann/json_fwd.hpp>
#include <string>

#include "ropras/pomdp/Model.h"
#include "ropras/pomdp/Rng.h"

namespace ropras::scenarios
{
    /** \brief Number of drones of the Multi-Drone Tag problem (fixed: the action set is Discrete(4 x 6)). */
    constexpr std::size_t MULTI_DRONE_COUNT = 4;
    /** \brief Primitive actions: each moves ONE drone by one axis step (+x, -x, +y, -y, +z, -z). */
    constexpr std::size_t MULTI_DRONE_ACTIONS = MULTI_DRONE_COUNT * 6;

    /** \brief The parameters of Multi-Drone Tag (scenarios/multi-drone/default.json; doc/scenario-multi-drone.md). */
    struct MultiDroneConfig
    {
        std::array<double, 3> lower{-15.0, -15.0, -2.0};  ///< "bounds"[0]
        std::array<double, 3> upper{15.0, 15.0, 2.0};     ///< "bounds"[1]
        double droneRadius{0.3};                          ///< drones are spheres; they block each other
        double stepSize{0.5};                             ///< one axis move of a drone (m)
        double targetStep{0.3};                           ///< the target's flight per primitive step (m)
        double detectionRange{3.0};                       ///< a drone closer than this sees the target
        double captureRadius{1.0};                        ///< a drone this close captures it (< detectionRange)
        double observationSigma{0.5};                     ///< N(0, sigma) per axis on the observed target
        double observationBin{1.0};                       ///< observation binning of the search tree (m)
        double stepReward{-0.1};
        double captureReward{600.0};
        double discount{0.99};
        std::size_t horizon{400};
        double reinvigorateSigma{0.1};  ///< particle reinvigoration: N(0, sigma) on the target position
        std::array<std::array<double, 3>, MULTI_DRONE_COUNT> starts{};

        /** \brief Reads and validates every key of \a json (the effective configuration: default.json with
            the user's overrides): throws ropras::Error naming \a scenario, the key and the value for a
            missing, unknown, non-finite or out-of-range value (capture_radius >= detection_range, negative
            sizes, starts outside the box or overlapping). */
        static MultiDroneConfig fromJson(const nlohmann::json &json, const std::string &scenario);
        /// throws ropras::Error (see fromJson)
        void validate(const std::string &scenario) const;
    };

    /** \brief Multi-Drone Tag (the paper's Multi-Drone with a teleporting target) as a POMDP model.

        State: 4 drone positions + the target position (15 doubles). Drones are fully observed: their
        motion is deterministic given the actions, so the belief only spreads over the target.

        Action a in [0, 24): drone a / 6 moves by stepSize along axis move a % 6 (+x, -x, +y, -y, +z, -z);
        the other drones hover. Reading of the paper's Discrete(24): 24 = 4 drones x 6 axis moves (a joint
        move of all drones would be 6^4 = 1296 actions). A move is blocked (the drone stays) when its centre
        would leave the box or its sphere would touch another drone's.

        Then, unless a drone already captured it, the target flees: it moves targetStep along the direction
        from the closest drone to itself (deterministic, known to the drones); crossing the x or y bound
        teleports it to the opposite side (wrap), z is clamped. Captured (terminal, +captureReward) when a
        drone is within captureRadius after the drone move or after the target's move; every step costs
        stepReward. Observation: when a drone is within detectionRange of the (new) target position, the
        target position + N(0, observationSigma) per axis; otherwise None.

        Thread-safe when const; step() is noexcept and allocation-free. */
    class MultiDroneModel
    {
    public:
        struct State
        {
            double drone[MULTI_DRONE_COUNT][3];
            double target[3];
        };
        using Action = std::uint8_t;
        struct Observation
        {
            double position[3]{0.0, 0.0, 0.0};
            bool seen{false};  ///< false = None
        };

        explicit MultiDroneModel(const MultiDroneConfig &config);

        const MultiDroneConfig &config() const noexcept { return config_; }

        // ---- Model concept ----
        pomdp::StepResult<State, Observation> step(const State &s, Action a, pomdp::Rng &rng) const noexcept
        {
            pomdp::StepResult<State, Observation> out;
            out.next = s;
            double p[3];
            if (proposeMove(s, a, p) && !dronesOverlap(s, droneOf(a), p))
            {
                setDrone(out.next, droneOf(a), p);
            }
            finishStep(out, rng);
            return out;
        }

        double observationProbability(const Observation &o, const State &next, Action) const noexcept
        {
            if (!detected(next))
            {
                return o.seen ? 0.0 : 1.0;
            }
            if (!o.seen)
            {
                return 0.0;
            }
            double q = 0.0;
            for (int k = 0; k < 3; ++k)
            {
                const double d = (o.position[k] - next.target[k]) / config_.observationSigma;
                q += d * d;
            }
            return gaussianNorm_ * std::exp(-0.5 * q);
        }

        /** \brief Drones at config().starts, the target uniform over the box outside every capture ball. */
        State sampleInitialState(pomdp::Rng &rng) const noexcept;
        double discount() const noexcept { return config_.discount; }
        std::size_t numActions() const noexcept { return MULTI_DRONE_ACTIONS; }
        Action action(std::size_t i) const noexcept { return static_cast<Action>(i % MULTI_DRONE_ACTIONS); }
        /** \brief None -> 0; seen -> a hash of the position binned at observationBin (never 0). */
        std::uint64_t observationKey(const Observation &o) const noexcept;
        /** \brief Jitters the target by N(0, reinvigorateSigma) per axis (wrapped in x, y, clamped in z). */
        void reinvigorate(State &s, pomdp::Rng &rng) const noexcept;
        /** \brief Captured: a drone within captureRadius of the target. */
        bool reachedGoal(const State &s) const noexcept { return minTargetDistance(s) <= config_.captureRadius; }

        // ---- shared rules (also used by MultiDroneWorld) ----
        /** \brief The drone that \a a moves. */
        static std::size_t droneOf(Action a) noexcept { return static_cast<std::size_t>(a / 6) % MULTI_DRONE_COUNT; }
        /** \brief The position drone a / 6 would move to under \a a; false when it would leave the box. */
        bool proposeMove(const State &s, Action a, double *p) const noexcept
        {
            const std::size_t d = droneOf(a);
            const int axis = (a % 6) / 2;
            const double sign = (a % 2) == 0 ? 1.0 : -1.0;
            for (int k = 0; k < 3; ++k)
            {
                p[k] = s.drone[d][k];
            }
            p[axis] += sign * config_.stepSize;
            return p[axis] >= config_.lower[axis] && p[axis] <= config_.upper[axis];
        }
        /** \brief Analytic drone-drone blocking: would drone \a d at \a p touch another drone (centres
            closer than two radii)? */
        bool dronesOverlap(const State &s, std::size_t d, const double *p) const noexcept
        {
            const double limit = 4.0 * config_.droneRadius * config_.droneRadius;
            for (std::size_t j = 0; j < MULTI_DRONE_COUNT; ++j)
            {
                if (j != d && squaredDistance(s.drone[j], p) < limit)
                {
                    return true;
                }
            }
            return false;
        }
        static void setDrone(State &s, std::size_t d, const double *p) noexcept
        {
            for (int k = 0; k < 3; ++k)
            {
                s.drone[d][k] = p[k];
            }
        }
        /** \brief Everything after the drone move, on \a out.next (drones already moved): capture, the
            target's flight, capture again, reward, terminal flag, observation (noise from \a rng). */
        void finishStep(pomdp::StepResult<State, Observation> &out, pomdp::Rng &rng) const noexcept
        {
            out.reward = config_.stepReward;
            if (!reachedGoal(out.next))
            {
                fleeTarget(out.next);
            }
            if (reachedGoal(out.next))
            {
                out.reward += config_.captureReward;
                out.terminal = true;
            }
            if (detected(out.next))
            {
                out.observation.seen = true;
                for (int k = 0; k < 3; ++k)
                {
                    out.observation.position[k] = out.next.target[k] + config_.observationSigma * rng.normal();
                }
            }
        }
        /** \brief The target's deterministic flight: targetStep away from the closest drone (ties: the lowest
            index; exactly on a drone: +x), x / y wrapped to the opposite side, z clamped. */
        void fleeTarget(State &s) const noexcept
        {
            std::size_t closest = 0;
            double best = squaredDistance(s.drone[0], s.target);
            for (std::size_t j = 1; j < MULTI_DRONE_COUNT; ++j)
            {
                const double d2 = squaredDistance(s.drone[j], s.target);
                if (d2 < best)
                {
                    best = d2;
                    closest = j;
                }
            }
            double u[3] = {1.0, 0.0, 0.0};
            const double length = std::sqrt(best);
            if (length > 1e-12)
            {
                for (int k = 0; k < 3; ++k)
                {
                    u[k] = (s.target[k] - s.drone[closest][k]) / length;
                }
            }
            for (int k = 0; k < 3; ++k)
            {
                s.target[k] += config_.targetStep * u[k];
            }
            wrapTarget(s.target);
        }
        /** \brief x / y wrapped into the box (teleport to the opposite side), z clamped. */
        void wrapTarget(double *t) const noexcept
        {
            for (int k = 0; k < 2; ++k)
            {
                const double width = config_.upper[k] - config_.lower[k];
                if (t[k] > config_.upper[k])
                {
                    t[k] -= width * std::ceil((t[k] - config_.upper[k]) / width);
                }
                else if (t[k] < config_.lower[k])
                {
                    t[k] += width * std::ceil((config_.lower[k] - t[k]) / width);
                }
            }
            t[2] = std::fmin(std::fmax(t[2], config_.lower[2]), config_.upper[2]);
        }
        /** \brief Whether a drone is within detectionRange of the target. */
        bool detected(const State &s) const noexcept { return minTargetDistance(s) <= config_.detectionRange; }
        double minTargetDistance(const State &s) const noexcept
        {
            double best = squaredDistance(s.drone[0], s.target);
            for (std::size_t j = 1; j < MULTI_DRONE_COUNT; ++j)
            {
                best = std::fmin(best, squaredDistance(s.drone[j], s.target));
            }
            return std::sqrt(best);
        }
        static double squaredDistance(const double *a, const double *b) noexcept
        {
            const double dx = a[0] - b[0], dy = a[1] - b[1], dz = a[2] - b[2];
            return dx * dx + dy * dy + dz * dz;
        }

    private:
        MultiDroneConfig config_;
        double gaussianNorm_;
    };
}  // namespace ropras::scenarios

#endif
