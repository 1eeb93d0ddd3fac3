#ifndef ROPRAS_SCENARIOS_MANIPULATION_RAY_DETECT_MODEL_H
#define ROPRAS_SCENARIOS_MANIPULATION_RAY_DETECT_MODEL_H

#include <Eigen/Geometry>
#include <array>
#include <cstddef>
#include <cstdint>
#include <memory>

#include "ropras/ompl_ext/kinematics/InverseKinematics.h"
#include "ropras/ompl_ext/scene/Environment.h"
#include "ropras/ompl_ext/scene/Shape.h"
#include "ropras/pomdp/Model.h"
#include "ropras/pomdp/Rng.h"
#include "ropras/scenarios/manipulation/PandaArm.h"
#include "ropras/scenarios/manipulation/RayDetectConfig.h"

namespace ropras::scenarios
{
    /** \brief Ray-Detect (the paper's 7-DoF reach to a can among four obstacles of uncertain pose, sensed by a
        line-of-sight detector at the end effector) as a POMDP.

        State: the joints q and the poses of the 4 obstacles (x, y, z, roll, pitch, yaw each: R^31). The static
        scene (table, target can) is one shared Environment; each state's obstacles are posed in a per-thread
        overlay over it (a per-particle scene, Environment(base) + setObjectPose). Action: dq in R^7.
        Transition: q' = clamp(q + dq + N(0, transition_sigma)); the straight motion q -> q' is checked in the
        state's scene at \a resolution; a colliding step is blocked at the last valid checked configuration (not
        terminal, no penalty). Reward step_reward, + goal_reward and terminal when the end effector is within
        goal_radius of goal_point. Observation: q' + N(0, observation_sigma) per joint, and the first obstacle
        the ray (from the end effector along its +z axis, ray_length) hits (ompl_ext::firstHit in the state's
        scene, obstacles only: the table and the can neither count nor occlude), with its pose + U(-a, a) per
        component, else None.

        Thread-safe when const; step() is noexcept (the per-thread scene is allocated once per thread). */
    class RayDetectModel
    {
    public:
        struct State
        {
            double q[ARM_DOF]{0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0};
            double poses[RAY_DETECT_OBSTACLES][6]{};
        };
        using Action = ArmAction;
        struct Observation
        {
            double q[ARM_DOF]{0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0};
            int object{-1};  ///< -1: None (the ray hits no obstacle)
            double pose[6]{0.0, 0.0, 0.0, 0.0, 0.0, 0.0};
        };
        /** \brief What the detector's ray hits in a state. */
        struct Detection
        {
            int object{-1};
            double distance{0.0};  ///< m from the ray's origin (the ray length when nothing is hit)
            Eigen::Vector3d origin{Eigen::Vector3d::Zero()};
            Eigen::Vector3d end{Eigen::Vector3d::Zero()};  ///< the hit point, or the ray's end
        };

        /** \brief Throws ropras::Error naming the key when the start is outside the joint limits or in
            collision with the nominal scene, the goal point is inside an obstacle, or the nominal layout is not
            physically possible (physicallyPossible). */
        RayDetectModel(const RayDetectConfig &config, std::shared_ptr<const PandaArm> arm);

        const RayDetectConfig &config() const noexcept { return config_; }
        const PandaArm &arm() const noexcept { return *arm_; }
        const std::shared_ptr<const PandaArm> &armPtr() const noexcept { return arm_; }
        /// the table and the can (the shared base of every particle's scene)
        const std::shared_ptr<const ompl_ext::Environment> &staticScene() const noexcept { return static_; }
        /// the obstacles over the static scene at their nominal poses (ids 0..3 = obstacle index)
        const std::shared_ptr<const ompl_ext::Environment> &nominalScene() const noexcept { return nominal_; }

        // ---- Model concept ----
        pomdp::StepResult<State, Observation> step(const State &s, const Action &a, pomdp::Rng &rng) const noexcept;
        double observationProbability(const Observation &o, const State &next, const Action &) const noexcept;
        State sampleInitialState(pomdp::Rng &rng) const noexcept;
        double discount() const noexcept { return config_.discount; }
        /// POMCP / Ref-Basic / rollouts: +-step on one joint (action 2j: +, 2j + 1: -)
        std::size_t numActions() const noexcept { return 2 * ARM_DOF; }
        Action action(std::size_t i) const noexcept;
        /** \brief None -> 0; a detection -> (object + 1) combined with the binned distance (observation_distance_bin)
            from the observed joints' end effector to the observed obstacle position; the joints are not binned. */
        std::uint64_t observationKey(const Observation &o) const noexcept;
        /** \brief Jitters the joints and the uncertain pose components (those with initial_sigma_pose > 0), kept
            only when the arm is collision-free in the jittered scene and the layout physically possible. */
        void reinvigorate(State &s, pomdp::Rng &rng) const noexcept;
        /** \brief heuristic_value: the discounted value of reaching the goal in d steps, d = the end effector's
            distance to the goal ball / heuristic_ee_step; else 0. */
        double heuristicValue(const State &s) const noexcept;

        // ---- shared rules (also used by RayDetectWorld and the planning side) ----
        /// the commanded motion's end: clamp(q + dq + noise)
        void proposeMotion(const State &s, const Action &a, pomdp::Rng &rng, double *target) const noexcept
        {
            arm_->proposeMotion(s.q, a.dq, a.waypoint, config_.transitionSigma, rng, target);
        }
        /** \brief The state's scene: the calling thread's overlay over the static scene with the 4 obstacles
            posed as in \a s (valid until the thread's next call). */
        const ompl_ext::Environment &scene(const State &s) const noexcept;
        /// the detector's ray in \a s (its scene), firstHit against the obstacles only
        Detection detect(const State &s) const noexcept;
        /** \brief Everything after the motion, on \a out.next (joints already moved): goal, reward, terminal
            flag and the observation of \a detection (noise from \a rng). */
        void finishStep(pomdp::StepResult<State, Observation> &out, const Detection &detection,
                        pomdp::Rng &rng) const noexcept;
        bool reachedGoal(const State &s) const noexcept;
        Eigen::Vector3d endEffector(const State &s) const noexcept { return arm_->endEffectorPosition(s.q); }
        /// the detector's ray: origin = end effector, direction = its +z axis (unit)
        void ray(const double *q, Eigen::Vector3d &origin, Eigen::Vector3d &direction) const noexcept;

        static void setJoints(State &s, const double *q) noexcept
        {
            for (std::size_t j = 0; j < ARM_DOF; ++j)
            {
                s.q[j] = q[j];
            }
        }
        /// the initial state at the configured (nominal) poses and the start configuration
        State nominalState() const noexcept;
        /** \brief Whether the obstacles' layout in \a s can exist: finite poses, no obstacle overlapping another
            one or the can, none reaching into the goal ball (goal_point, goal_radius). Box, cylinder and sphere
            tests through ompl_ext::shapesIntersect (FCL), not the arm's sphere model. The initial belief, the true
            world and reinvigoration draw only such layouts. */
        bool physicallyPossible(const State &s) const noexcept;
        /** \brief Whether the arm can reach the goal in \a s: a configuration collision-free in the state's scene
            (no margin) whose end effector is within planning.ik_radius_fraction * goal_radius of goal_point, found
            by position IK from the start configuration (planning.ik_points random points of that ball, 100
            restarts each, tolerance 0.1 mm). False for a layout that is not physically possible. IK is incomplete:
            false means that none was found. With reachable_goal (default) the initial belief and the true world
            draw only states where it holds. */
        bool goalReachable(const State &s, pomdp::Rng &rng) const noexcept;

    private:
        /// what layoutConflict's \a second names besides an obstacle index
        static constexpr int CAN = -2, GOAL_BALL = -3, NON_FINITE = -4;
        /** \brief The first conflict of \a s's layout (physicallyPossible): obstacle \a first overlaps obstacle
            \a second (>= 0), CAN or GOAL_BALL, or has a NON_FINITE pose; false (and -1, -1) when there is none. */
        bool layoutConflict(const State &s, int &first, int &second) const noexcept;
        /// goalReachable for a layout already known to be physically possible
        bool reachableLayout(const State &s, pomdp::Rng &rng) const noexcept;

        RayDetectConfig config_;
        std::shared_ptr<const PandaArm> arm_;
        std::shared_ptr<const ompl_ext::Environment> static_;
        std::shared_ptr<const ompl_ext::Environment> nominal_;
        std::uint64_t instance_{0};
        double logNorm_{0.0};
        std::array<double, 6> kernelSigma_{};
        /// physicallyPossible's fixed shapes: the boxes (posed per state), the can and the goal ball where they stand
        std::array<ompl_ext::Shape, RAY_DETECT_OBSTACLES> boxShapes_;
        ompl_ext::Shape canShape_, ballShape_;
        Eigen::Isometry3d canPose_{Eigen::Isometry3d::Identity()}, ballPose_{Eigen::Isometry3d::Identity()};
        std::shared_ptr<const ompl_ext::InverseKinematics> ik_;  ///< the end effector's chain (goalReachable)
        ompl_ext::IkOptions goalIk_;
    };

    /** \brief The pose (x, y, z, roll, pitch, yaw; R = Rz Ry Rx) as an isometry. */
    Eigen::Isometry3d rayDetectPose(const double *pose) noexcept;

    /** \brief The static scene of \a config (table box "table", can cylinder "target"), each grown by \a margin. */
    std::shared_ptr<const ompl_ext::Environment> rayDetectStaticScene(const RayDetectConfig &config, double margin);

    /** \brief An overlay over \a base holding the 4 obstacle boxes ("obstacle0".."obstacle3", ids 0..3) at their
        nominal poses, each grown by \a margin. */
    std::shared_ptr<ompl_ext::Environment> rayDetectObstacleScene(const RayDetectConfig &config,
                                                                  std::shared_ptr<const ompl_ext::Environment> base,
                                                                  double margin);

    /** \brief Moves the 4 obstacles of \a env (ids 0..3) to the poses of \a s. */
    void poseRayDetectObstacles(const RayDetectModel::State &s, ompl_ext::Environment &env);
}  // namespace ropras::scenarios

#endif
