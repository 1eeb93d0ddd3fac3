#ifndef ROPRAS_SCENARIOS_MANIPULATION_SPHERE_SEARCH_MODEL_H
#define ROPRAS_SCENARIOS_MANIPULATION_SPHERE_SEARCH_MODEL_H

#include <array>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <map>
#include <memory>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "ropras/ompl_ext/scene/Environment.h"
#include "ropras/pomdp/Model.h"
#include "ropras/pomdp/Rng.h"
#include "ropras/scenarios/manipulation/PandaArm.h"

namespace ropras::scenarios
{
    /** \brief The parameters of Sphere-Search (scenarios/manipulation/sphere-search/default.json; every key is
        described in doc/scenario-sphere-search.md). */
    struct SphereSearchConfig
    {
        std::array<double, ARM_DOF> start{};            ///< "start": the true initial configuration (rad)
        std::string endEffector{"panda_grasptarget"};   ///< "end_effector"
        std::array<std::array<double, 3>, 2> goals{};   ///< "goals": the two candidate goal centres (m)
        double goalRadius{0.1};                         ///< "goal_radius": success ball around the true goal
        std::array<double, 3> light{{0.55, 0.0, 0.8}};  ///< "light_center"
        double lightRadius{0.1};                        ///< "light_radius": inside, the goal is observed
        std::vector<std::array<double, 4>> obstacles;   ///< "obstacles": spheres [x, y, z, r]
        double step{0.1};                               ///< "step": L2 norm of a primitive dq (rad)
        bool waypointActions{false};                    ///< "action_mode": "delta" (false) or "waypoint"
        double transitionSigma{0.02};                   ///< "transition_sigma": N(0, s) per joint and step
        double observationSigma{0.02};                  ///< "observation_sigma": N(0, s) per observed joint
        double initialSigma{0.02};                      ///< "initial_sigma": N(0, s) per joint in b0
        double reinvigorateSigma{0.005};                ///< "reinvigorate_sigma": particle jitter per joint
        double stepReward{-0.1};                        ///< "step_reward"
        double goalReward{800.0};                       ///< "goal_reward" (terminal)
        double failReward{-800.0};                      ///< "fail_reward" (terminal when collision_terminal)
        bool collisionTerminal{true};                   ///< "collision_terminal"; false: a blocked step
        double discount{0.99};                          ///< "discount"
        std::size_t horizon{150};                       ///< "horizon"
        double resolution{0.02};                        ///< "resolution": motion-check step (rad, per joint)
        double observationJointBin{0.0};                ///< "observation_joint_bin": 0 = joints not binned
        bool heuristicValue{true};                      ///< "heuristic_value"
        double heuristicEndEffectorStep{0.03};          ///< "heuristic_ee_step": m of EE travel per step
        // "planning": the reference policy
        double planSeconds{0.1};         ///< "planning.plan_seconds": default time budget per planning call
        double referencePlanTime{0.01};  ///< "planning.reference_plan_time": per reference plan (s)
        double planningMargin{0.03};     ///< "planning.margin": the planner sees obstacles grown by this (m)
        double plannerRange{0.5};        ///< "planning.planner_range": VectorizedRRTConnect range (rad)
        std::size_t ikRestarts{10};      ///< "planning.ik_restarts": per IK target point
        std::size_t ikPoints{4};         ///< "planning.ik_points": target points tried per goal configuration
        double ikRadiusFraction{0.6};    ///< "planning.ik_radius_fraction": points within this share of a radius
        bool ikNearest{true};  ///< "planning.ik_choice": "nearest" pooled IK solution to the particle, or "uniform"
        std::map<std::string, double> defaults;  ///< "defaults": solver / filter / policy parameters
        nlohmann::json json;                     ///< the effective configuration

        /** \brief Reads and validates every key of \a json: throws ropras::Error naming \a scenario, the key
            and the value (missing, unknown, wrong type, non-finite, out of range). */
        static SphereSearchConfig fromJson(const nlohmann::json &json, const std::string &scenario);
    };

    /** \brief Sphere-Search (the paper's 7-DoF search for one of two goals, revealed by a light) as a POMDP.

        State: the joints q and the index of the true goal (0 or 1); the end effector (panda_grasptarget) is
        FK of q. Action: dq in R^7. Transition: q' = clamp(q + dq + N(0, transition_sigma) per joint) (a
        waypoint action: q' = clamp(w + N(0, transition_sigma))); the
        straight motion q -> q' is checked with the SIMD sphere checker (obstacles and self-collision) at
        \a resolution; a collision ends the episode with fail_reward (collision_terminal) or blocks the step
        at the last valid checked configuration. Then: reward step_reward, + goal_reward and terminal when the
        end effector is within goal_radius of the true goal. Observation: q' + N(0, observation_sigma) per
        joint, and the goal index when the end effector is within light_radius of the light (else None).

        Thread-safe when const; step() is noexcept and allocation-free. */
    class SphereSearchModel
    {
    public:
        struct State
        {
            double q[ARM_DOF]{0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0};
            int goal{0};
            /// the end effector has been in the light (the goal was observed) at some step of this state's history
            bool seen{false};
        };
        using Action = ArmAction;
        struct Observation
        {
            double q[ARM_DOF]{0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0};
            int goal{-1};  ///< -1: None (not in the light)
        };

        /** \brief Throws ropras::Error naming the key when the start is outside the joint limits or in
            collision, or a goal or the light is inside an obstacle. */
        SphereSearchModel(const SphereSearchConfig &config, std::shared_ptr<const PandaArm> arm);

        const SphereSearchConfig &config() const noexcept { return config_; }
        const PandaArm &arm() const noexcept { return *arm_; }
        const std::shared_ptr<const PandaArm> &armPtr() const noexcept { return arm_; }
        /// the obstacles (the cage) as the model's checker sees them
        const std::shared_ptr<const ompl_ext::Environment> &environment() const noexcept { return environment_; }

        // ---- Model concept ----
        pomdp::StepResult<State, Observation> step(const State &s, const Action &a, pomdp::Rng &rng) const noexcept
        {
            pomdp::StepResult<State, Observation> out;
            out.next = s;
            double target[ARM_DOF];
            proposeMotion(s, a, rng, target);
            double fraction = 1.0;
            const bool valid =
                arm_->checker()->isMotionValid(*environment_, s.q, target, config_.resolution, &fraction);
            if (valid)
            {
                setJoints(out.next, target);
            }
            else if (!config_.collisionTerminal)
            {
                moveAlong(s.q, target, fraction, out.next.q);
            }
            finishStep(out, !valid, rng);
            return out;
        }

        double observationProbability(const Observation &o, const State &next, const Action &) const noexcept;
        State sampleInitialState(pomdp::Rng &rng) const noexcept;
        double discount() const noexcept { return config_.discount; }
        /// POMCP / Ref-Basic / rollouts: +-step on one joint (action 2j: +, 2j + 1: -)
        std::size_t numActions() const noexcept { return 2 * ARM_DOF; }
        Action action(std::size_t i) const noexcept;
        /// None -> 0; the goal index g -> g + 1, combined with the joints binned at observation_joint_bin (> 0)
        std::uint64_t observationKey(const Observation &o) const noexcept;
        /** \brief Jitters the joints by N(0, reinvigorate_sigma), kept only when the jittered configuration is
            valid; and, for a particle that has not been in the light (!seen), redraws the goal 50/50: a Gibbs move
            from the goal's exact conditional. Before the light, neither the joints' dynamics nor any observation
            depends on the goal, so p(goal | the particle's joints, the observations) is the prior 1/2; without
            this move the joint likelihood's resampling fixes the goal marginal at random (genetic drift) within a
            few steps (doc/scenario-sphere-search.md, "The belief"). */
        void reinvigorate(State &s, pomdp::Rng &rng) const noexcept;
        /** \brief heuristic_value: the discounted value of reaching the particle's goal in d steps, d = the end
            effector's distance to the goal ball / heuristic_ee_step; else 0. */
        double heuristicValue(const State &s) const noexcept;

        // ---- shared rules (also used by SphereSearchWorld) ----
        /// the commanded motion's end: clamp(q + dq + noise)
        void proposeMotion(const State &s, const Action &a, pomdp::Rng &rng, double *target) const noexcept
        {
            for (std::size_t j = 0; j < ARM_DOF; ++j)
            {
                target[j] = (a.waypoint ? 0.0 : s.q[j]) + a.dq[j] + config_.transitionSigma * rng.normal();
            }
            arm_->clamp(target);
        }
        static void setJoints(State &s, const double *q) noexcept
        {
            for (std::size_t j = 0; j < ARM_DOF; ++j)
            {
                s.q[j] = q[j];
            }
        }
        /// q0 + fraction (q1 - q0)
        static void moveAlong(const double *q0, const double *q1, double fraction, double *out) noexcept
        {
            for (std::size_t j = 0; j < ARM_DOF; ++j)
            {
                out[j] = q0[j] + fraction * (q1[j] - q0[j]);
            }
        }
        /** \brief Everything after the motion, on \a out.next (joints already moved): fail (collided and
            collision_terminal), goal, reward, terminal flag, observation (noise from \a rng). */
        void finishStep(pomdp::StepResult<State, Observation> &out, bool collided, pomdp::Rng &rng) const noexcept;

        bool inLight(const State &s) const noexcept;
        bool reachedGoal(const State &s) const noexcept;
        Eigen::Vector3d endEffector(const State &s) const noexcept { return arm_->endEffectorPosition(s.q); }
        const std::array<double, 3> &goalCenter(int goal) const noexcept
        {
            return config_.goals[static_cast<std::size_t>(goal & 1)];
        }

    private:
        SphereSearchConfig config_;
        std::shared_ptr<const PandaArm> arm_;
        std::shared_ptr<const ompl_ext::Environment> environment_;
        double logNorm_{0.0};
    };

    /** \brief The obstacle spheres of \a config, each grown by \a margin (m), as an Environment ("obstacle0"...). */
    std::shared_ptr<const ompl_ext::Environment> sphereSearchEnvironment(const SphereSearchConfig &config,
                                                                         double margin);
}  // namespace ropras::scenarios

#endif
