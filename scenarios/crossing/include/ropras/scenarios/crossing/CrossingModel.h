#ifndef ROPRAS_SCENARIOS_CROSSING_MODEL_H
#define ROPRAS_SCENARIOS_CROSSING_MODEL_H

#include <array>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <limits>
#include <vector>

#include "ropras/pomdp/Model.h"
#include "ropras/pomdp/Rng.h"
#include "ropras/scenarios/crossing/CrossingConfig.h"

namespace ropras::scenarios
{
    /** \brief What a step of stretch-crossing ended with (State::event; recorded for the result tables). */
    enum class CrossingEvent : std::uint8_t
    {
        None = 0,
        TooClose = 1,    ///< closer than close_distance to the pedestrian (not touching)
        Goal = 2,        ///< terminal, goal_reward
        Pedestrian = 3,  ///< terminal, collision_reward: the robot touched the pedestrian
        Obstacle = 4     ///< terminal, collision_reward: the robot touched a table or a wall
    };

    /** \brief The state of stretch-crossing: the base pose, the wheel-derived twist (v, omega) that the
        acceleration limits carry from one action to the next, the pedestrian's centre (x, y; its height is
        pedestrian_height), and the last step's event. */
    struct CrossingState
    {
        double x{0}, y{0}, theta{0};
        double v{0}, w{0};
        double px{0}, py{0};
        CrossingEvent event{CrossingEvent::None};
    };

    /** \brief The robot's pose observation: (x, y, theta) + N(0, observation_sigma). */
    struct CrossingObservation
    {
        double x{0}, y{0}, theta{0};
    };

    /** \brief A collision sphere of the robot in the base frame (held lift and arm). */
    struct CrossingSphere
    {
        double x, y, z, radius;
    };

    /** \brief One primitive action: a twist (v m/s, omega rad/s) held for action_duration. */
    struct CrossingTwist
    {
        double v, w;
    };

    /** \brief The Stretch pedestrian crossing (the paper's physical demonstration) as a POMDP model.

        Actions: 2 x |linear_speeds| x |angular_speeds| + 1 twists (default 45): for each speed s, forward (s, w)
        for every w, backward (-s, -w) for every w (the demo code's naming flips w in reverse), then
        (straight_speed, 0). One action: v^ = v + N(0, speed_noise[0]), w^ = w + N(0, speed_noise[1]) drawn once;
        each wheel ramps toward its target (v^ -/+ w^ L / 2, clipped to +-wheel_speed_limit) by at most
        wheel_acceleration x substep per substep, and the base follows the exact arc of the substep's wheel speeds;
        action_duration / substep substeps. The pedestrian advances pedestrian_step per action (linearly within
        it; stopped by the walls). After every substep: a collision with the pedestrian or a table / wall ends the
        episode (collision_reward; the robot stays at its last free pose, v = w = 0); the base centre within
        goal_tolerance of the goal ends it with goal_reward; otherwise the smallest clearance to the pedestrian
        counts, and if it was below close_distance the step costs close_reward. Every step costs step_reward.

        The collision test is a template parameter of simulate(): the model uses its analytic test (the
        robot's spheres against the pedestrian sphere, the table boxes and the lab walls), the world a Bullet
        collision world; everything else is shared. Thread-safe when const; step() is noexcept and
        allocation-free. */
    class CrossingModel
    {
    public:
        using State = CrossingState;
        using Action = std::uint8_t;
        using Observation = CrossingObservation;
        using Result = pomdp::StepResult<State, Observation>;

        /** \brief Throws ropras::Error for no spheres, more than 255 actions or a start in collision. */
        CrossingModel(const CrossingConfig &config, std::vector<CrossingSphere> spheres);

        const CrossingConfig &config() const noexcept { return config_; }
        const std::vector<CrossingSphere> &spheres() const noexcept { return spheres_; }
        const std::vector<CrossingTwist> &twists() const noexcept { return twists_; }
        /// the largest distance of a sphere's surface from the base axis (m)
        double boundingRadius() const noexcept { return boundingRadius_; }

        // ---- Model concept ----
        Result step(const State &s, Action a, pomdp::Rng &rng) const noexcept
        {
            Result out;
            simulate(
                s, a, 1.0, rng, [this](const State &q) noexcept { return contact(q); }, out);
            return out;
        }
        double observationProbability(const Observation &o, const State &next, Action) const noexcept;
        State sampleInitialState(pomdp::Rng &rng) const noexcept;
        double discount() const noexcept { return config_.discount; }
        std::size_t numActions() const noexcept { return twists_.size(); }
        Action action(std::size_t i) const noexcept { return static_cast<Action>(i % twists_.size()); }
        std::uint64_t observationKey(const Observation &o) const noexcept;
        void reinvigorate(State &s, pomdp::Rng &rng) const noexcept;
        double heuristicValue(const State &s) const noexcept;
        bool reachedGoal(const State &s) const noexcept { return s.event == CrossingEvent::Goal; }

        // ---- shared rules (also used by CrossingWorld and the tracker) ----
        /** \brief One action from \a s: \a contact(q) returns CrossingEvent::None, Pedestrian or Obstacle for a
            candidate state q (pose and pedestrian after a substep); \a pedestrianScale scales the pedestrian's
            step (the world's speed noise; 1 in the model). Speed noise comes from \a rng. */
        template <class Contact>
        void simulate(const State &s, Action a, double pedestrianScale, pomdp::Rng &rng, Contact &&contact,
                      Result &out) const noexcept
        {
            const CrossingTwist &t = twists_[a % twists_.size()];
            const double v = t.v + config_.speedNoise[0] * rng.normal();
            const double w = t.w + config_.speedNoise[1] * rng.normal();
            out.reward = config_.stepReward;
            out.terminal = false;
            double clearance = std::numeric_limits<double>::infinity();
            State cur = s;
            cur.event = CrossingEvent::None;
            double vl = s.v - 0.5 * s.w * config_.wheelBase, vr = s.v + 0.5 * s.w * config_.wheelBase;
            const double tl = clampSpeed(v - 0.5 * w * config_.wheelBase);
            const double tr = clampSpeed(v + 0.5 * w * config_.wheelBase);
            for (std::size_t i = 0; i < substeps_; ++i)
            {
                State next = cur;
                driveSubstep(next, vl, vr, tl, tr);
                movePedestrian(next, pedestrianScale / static_cast<double>(substeps_));
                const CrossingEvent hit = contact(static_cast<const State &>(next));
                if (hit != CrossingEvent::None)
                {
                    cur.px = next.px;
                    cur.py = next.py;
                    cur.v = cur.w = 0.0;
                    cur.event = hit;
                    out.reward += config_.collisionReward;
                    out.terminal = true;
                    break;
                }
                cur = next;
                clearance = std::fmin(clearance, pedestrianClearance(cur));
                if (atGoal(cur))
                {
                    cur.event = CrossingEvent::Goal;
                    out.reward += config_.goalReward;
                    out.terminal = true;
                    break;
                }
            }
            if (cur.event != CrossingEvent::Pedestrian && cur.event != CrossingEvent::Obstacle &&
                clearance < config_.closeDistance)
            {
                out.reward += config_.closeReward;
                if (cur.event == CrossingEvent::None)
                {
                    cur.event = CrossingEvent::TooClose;
                }
            }
            out.next = cur;
            out.observation.x = cur.x + config_.observationSigma[0] * rng.normal();
            out.observation.y = cur.y + config_.observationSigma[1] * rng.normal();
            out.observation.theta = wrapAngle(cur.theta + config_.observationSigma[2] * rng.normal());
        }

        /** \brief The noise-free motion of the base under action \a a from \a s (no pedestrian, no collision
            test): what the lookahead tracker predicts. */
        void predict(State &s, Action a) const noexcept;

        /** \brief One substep of the drive: wheel speeds \a vl, \a vr ramp toward \a tl, \a tr (acceleration
            limit), then the exact arc of the new wheel speeds over the substep; v and w of \a s follow. */
        void driveSubstep(State &s, double &vl, double &vr, double tl, double tr) const noexcept
        {
            const double dv = config_.wheelAcceleration * dt_;
            vl += std::fmax(-dv, std::fmin(dv, tl - vl));
            vr += std::fmax(-dv, std::fmin(dv, tr - vr));
            const double v = 0.5 * (vl + vr);
            const double w = (vr - vl) / config_.wheelBase;
            if (std::abs(w) < 1e-9)
            {
                s.x += v * dt_ * std::cos(s.theta);
                s.y += v * dt_ * std::sin(s.theta);
            }
            else
            {
                const double r = v / w;
                const double th = s.theta + w * dt_;
                s.x += r * (std::sin(th) - std::sin(s.theta));
                s.y -= r * (std::cos(th) - std::cos(s.theta));
                s.theta = wrapAngle(th);
            }
            s.v = v;
            s.w = w;
        }
        /** \brief The pedestrian advances \a fraction of pedestrian_step (its sphere stays inside the lab). */
        void movePedestrian(State &s, double fraction) const noexcept
        {
            const double r = config_.pedestrianRadius;
            s.px = std::fmin(std::fmax(s.px + fraction * config_.pedestrianStep[0], config_.labLo[0] + r),
                             config_.labHi[0] - r);
            s.py = std::fmin(std::fmax(s.py + fraction * config_.pedestrianStep[1], config_.labLo[1] + r),
                             config_.labHi[1] - r);
        }
        /** \brief The analytic collision test: Pedestrian, Obstacle (table or wall) or None. */
        CrossingEvent contact(const State &s) const noexcept;
        /** \brief The smallest distance between the robot's spheres and the pedestrian's sphere (negative when
            they overlap); a lower bound when it exceeds close_distance. */
        double pedestrianClearance(const State &s) const noexcept;
        bool atGoal(const State &s) const noexcept
        {
            const double dx = s.x - config_.goal[0], dy = s.y - config_.goal[1];
            return dx * dx + dy * dy < config_.goalTolerance * config_.goalTolerance;
        }
        double clampSpeed(double v) const noexcept
        {
            return std::fmax(-config_.wheelSpeedLimit, std::fmin(config_.wheelSpeedLimit, v));
        }
        /// the world position of sphere \a k at the base pose of \a s
        void spherePosition(const State &s, std::size_t k, double *p) const noexcept
        {
            const double c = std::cos(s.theta), sn = std::sin(s.theta);
            const CrossingSphere &b = spheres_[k];
            p[0] = s.x + c * b.x - sn * b.y;
            p[1] = s.y + sn * b.x + c * b.y;
            p[2] = b.z;
        }
        static double wrapAngle(double a) noexcept
        {
            constexpr double PI = 3.14159265358979323846;
            if (a > PI || a <= -PI)
            {
                a = std::remainder(a, 2.0 * PI);
                if (a <= -PI)
                {
                    a += 2.0 * PI;
                }
            }
            return a;
        }

    private:
        CrossingConfig config_;
        std::vector<CrossingSphere> spheres_;
        std::vector<CrossingTwist> twists_;
        double boundingRadius_{0.0};
        std::size_t substeps_{7};
        double dt_{0.1};
        double gaussianNorm_{1.0};
    };
}  // namespace ropras::scenarios

#endif
