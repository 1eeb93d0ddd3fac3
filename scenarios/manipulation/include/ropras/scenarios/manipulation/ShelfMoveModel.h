#ifndef ROPRAS_SCENARIOS_MANIPULATION_SHELF_MOVE_MODEL_H
#define ROPRAS_SCENARIOS_MANIPULATION_SHELF_MOVE_MODEL_H

#include <Eigen/Geometry>
#include <array>
#include <cstddef>
#include <cstdint>
#include <memory>

#include "ropras/ompl_ext/scene/Environment.h"
#include "ropras/pomdp/Model.h"
#include "ropras/pomdp/Rng.h"
#include "ropras/scenarios/manipulation/PandaArm.h"
#include "ropras/scenarios/manipulation/ShelfMoveConfig.h"

namespace ropras::scenarios
{
    /** \brief What a Shelf-Move primitive does after its motion: nothing, close the gripper (grasp the can
        whose axis the end effector is at) or open it (release the held can at a slot). The reference policy
        puts Close or Open on the last primitive of a macro-action (the event ends the macro). */
    enum class GripperEvent : std::uint8_t
    {
        None,
        Close,
        Open
    };

    /** \brief What the gripper did in the step into a state (recorded as the episode's "events"). */
    enum class ShelfEvent : std::uint8_t
    {
        None,
        Grasped,  ///< Close grasped can eventCan
        Released  ///< Open released can eventCan over slot eventSlot
    };

    /// ShelfMoveModel::State::worldReport bits, set by ShelfMoveWorld only (the model never sets them)
    constexpr std::uint8_t SHELF_REPORT_MOVED = 1;    ///< the released can settled off the model's snap
    constexpr std::uint8_t SHELF_REPORT_TIPPED = 2;   ///< the released can settled tilted (tip_angle)
    constexpr std::uint8_t SHELF_REPORT_VERDICT = 4;  ///< the model's blocked / valid verdict differed
    constexpr std::uint8_t SHELF_REPORT_PUSHED = 8;   ///< a can not held moved during the step (push_cans)

    /** \brief A Shelf-Move primitive: a joint displacement dq in R^7 (rad) or, when \c waypoint is set, the
        configuration to move to (dq holds it; action_mode = "waypoint"), and a trailing gripper event. */
    struct ShelfMoveAction
    {
        double dq[ARM_DOF]{0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0};
        GripperEvent event{GripperEvent::None};
        bool waypoint{false};
    };

    /** \brief Shelf-Move (the paper's 7-DoF pick-and-place of a target can from the back of a shelf into the
        reserved slot of its top shelf) as a POMDP. doc/scenario-shelf-move.md describes every rule.

        State: joints q, the centres of the 4 upright cans, and which can is held (-1: none). A held can is
        rigidly attached to the end effector (its centre grasp_offset along the end effector's z, its axis along
        the end effector's x axis): the state's centre of a held can is FK of q. Transition: q' = clamp(q + dq +
        N(0, transition_sigma)) (a waypoint action: clamp(w + N(0, transition_sigma))); the straight motion q -> q' is
       checked with the SIMD sphere checker in the state's scene (the static shelf, the cans not held as cylinders, the
       held can as an attached body of the end effector) at \a resolution; a colliding motion is blocked at its last
       valid checked configuration (no penalty). Then the event: Close grasps the can whose axis segment is within
        grasp_tolerance of the end effector when nothing is held and the end effector's x axis is within
        grasp_axis_tolerance of vertical; Open releases the held can when its centre is within
        place_tolerance of a free slot: the can snaps upright onto the slot. Releasing the target can in the
        reserved slot is the goal (goal_reward, terminal). Every step costs step_reward. Observation: q' +
        N(0, observation_sigma), whether a can is held (the gripper knows), and, for each can not held whose
        centre is within sense_distance of the end effector, its centre + U(-w, w) per axis (w =
        can_observation_noise); the others are None.

        Thread-safe when const; step() is noexcept and allocation-free once the calling thread has its copy
        of the scenes (made on its first call). */
    class ShelfMoveModel
    {
    public:
        struct State
        {
            double q[ARM_DOF]{0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0};
            double can[SHELF_CANS][3]{};
            int held{-1};
            /// what the step into this state did (for the recording; no rule reads it)
            ShelfEvent event{ShelfEvent::None};
            std::int8_t eventCan{-1};
            std::int8_t eventSlot{-1};
            std::uint8_t worldReport{0};  ///< SHELF_REPORT_* bits (the world's view of the step)
        };
        using Action = ShelfMoveAction;
        struct Observation
        {
            double q[ARM_DOF]{0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0};
            double can[SHELF_CANS][3]{};
            std::uint8_t detected{0};  ///< bit k: can k observed (else None)
            int held{-1};
        };

        /** \brief Throws ropras::Error naming the key when the start is outside the joint limits or in
            collision, a can is not standing on a board, cans overlap, or a slot is not on a board. */
        ShelfMoveModel(const ShelfMoveConfig &config, std::shared_ptr<const PandaArm> arm);

        const ShelfMoveConfig &config() const noexcept { return config_; }
        const PandaArm &arm() const noexcept { return *arm_; }
        const std::shared_ptr<const PandaArm> &armPtr() const noexcept { return arm_; }

        // ---- Model concept ----
        pomdp::StepResult<State, Observation> step(const State &s, const Action &a, pomdp::Rng &rng) const noexcept;
        double observationProbability(const Observation &o, const State &next, const Action &a) const noexcept;
        State sampleInitialState(pomdp::Rng &rng) const noexcept;
        double discount() const noexcept { return config_.discount; }
        /// the goal: the target can released (not held) within place_tolerance of the reserved slot, standing (its
        /// centre within 1 cm of the slot's height: a can that tipped over in the world is not)
        bool reachedGoal(const State &s) const noexcept;
        /// POMCP / Ref-Basic / rollouts: +-step on one joint (2j: +, 2j + 1: -), 14 = close, 15 = open
        std::size_t numActions() const noexcept { return 2 * ARM_DOF + 2; }
        Action action(std::size_t i) const noexcept;
        /// held, the detection pattern and the detected centres binned at observation_can_bin (+ joints)
        std::uint64_t observationKey(const Observation &o) const noexcept;
        /** \brief With probability reinvigorate_probability: jitters the joints (reinvigorate_sigma) and the x,
            y of every can not held (reinvigorate_can_sigma); the jitter is kept only when the result is
            physically valid (validState), so cans never interpenetrate, float or overlap the arm. */
        void reinvigorate(State &s, pomdp::Rng &rng) const noexcept;

        // ---- shared rules (also used by ShelfMoveWorld and the planner) ----
        /// the commanded motion's end: clamp(q + dq + N(0, transition_sigma)), or clamp(w + N(...)) for a waypoint
        void proposeMotion(const State &s, const Action &a, pomdp::Rng &rng, double *target) const noexcept
        {
            arm_->proposeMotion(s.q, a.dq, a.waypoint, config_.transitionSigma, rng, target);
        }
        /** \brief The model's verdict on the straight motion s.q -> \a target in the scene of \a s: true when
            valid; else \a fraction (if non-null) gets where it is blocked (the last valid checked configuration). */
        bool motionValid(const State &s, const double *target, double *fraction) const noexcept;
        /// the observation of \a n: joints + noise, held, the cans near the end effector + U(-w, w) (from \a rng)
        void observe(const State &n, pomdp::Rng &rng, Observation &o) const noexcept;
        /** \brief The gripper event and everything after it, on \a out.next (joints already moved, the held
            can already following them): grasp / release, reward, goal, observation (noise from \a rng). */
        void finishStep(pomdp::StepResult<State, Observation> &out, GripperEvent event, pomdp::Rng &rng) const noexcept;
        /// the held can (if any) re-posed from the joints
        void followHand(State &s) const noexcept;
        /// the can Close would grasp in \a s (-1: none)
        int graspableCan(const State &s) const noexcept;
        /// the slot Open would release the held can onto in \a s (-1: none)
        int releaseSlot(const State &s) const noexcept;
        /// whether can \a k of \a s may stand where it is: on a board, clear of the shelf's other boxes and
        /// of every other can not held (2 can_radius apart)
        bool canPlacementValid(const State &s, std::size_t k) const noexcept;
        /// \a s with can \a k standing on slot \a slot (its centre), not held
        State placedOnSlot(const State &s, std::size_t k, std::size_t slot) const noexcept;
        /// every can not held placed validly and the arm (with what it holds) collision-free
        bool validState(const State &s) const noexcept;
        /** \brief Whether the cans of \a s (nothing held) can be taken off the shelf one after another until the
            target is grasped: repeatedly, the target's grasp, else the first other can's grasp, has a collision-free
            full-pose IK solution (ShelfMoveIk, at least LAYOUT_IK_RESTARTS restarts, seeded from \a rng) in the
            planner's scene of the cans still standing, and a taken can is parked on the first free slot that is not
            reserved. Conservative: a parked can that stood in the way of a later grasp, or slots running out, would
            reject a layout that another order solves (with the default slots, away from the lower board's middle,
            and 4 free slots for 3 cans, taking any graspable can first loses nothing). Used by
            sampleInitialState with graspable_layout (doc/scenario-shelf-move.md); false on any failure. */
        bool graspableLayout(const State &s, pomdp::Rng &rng) const noexcept;
        /// the fewest IK restarts per grasp in graspableLayout (a missed solution would reject a solvable layout)
        static constexpr std::size_t LAYOUT_IK_RESTARTS = 24;

        /** \brief The scene of \a s for the SIMD checker: the calling thread's copy of the prototype for what
            \a s holds, its cans moved to \a s (noexcept; allocates only on the thread's first call). */
        const ompl_ext::Environment &scene(const State &s) const noexcept;
        /** \brief A new Environment for \a s (the planner's per-particle scene), over the static shelf grown by
            \a margin when \a planning (else the model's shelf). */
        std::shared_ptr<ompl_ext::Environment> makeScene(const State &s, bool planning) const;
        /// the static shelf (boards and walls as boxes), as the model sees it
        const std::shared_ptr<const ompl_ext::Environment> &shelf() const noexcept { return shelf_; }

        Eigen::Vector3d endEffector(const State &s) const noexcept { return arm_->endEffectorPosition(s.q); }
        /// where a held can's centre is: grasp_offset along the end effector's z from its origin
        Eigen::Vector3d graspPoint(const State &s) const noexcept
        {
            return arm_->endEffectorPose(s.q) * Eigen::Vector3d(0.0, 0.0, config_.graspOffset);
        }
        /// the pose of the held can in the end effector frame (centre at graspPoint, can axis along its x)
        Eigen::Isometry3d graspTransform() const;
        /// the index of the shelf box can \a k stands on (-1: none)
        int supportingBox(const double *center) const noexcept;
        static void setJoints(State &s, const double *q) noexcept
        {
            for (std::size_t j = 0; j < ARM_DOF; ++j)
            {
                s.q[j] = q[j];
            }
        }
        /// the true initial state (start joints, the configured can centres, nothing held)
        State trueInitialState() const noexcept;

    private:
        struct Scenes;
        void poseScene(ompl_ext::Environment &env, int held, const State &s) const noexcept;
        const Scenes &threadScenes() const noexcept;

        ShelfMoveConfig config_;
        std::shared_ptr<const PandaArm> arm_;
        std::shared_ptr<const ompl_ext::Environment> shelf_;          ///< margin 0
        std::shared_ptr<const ompl_ext::Environment> planningShelf_;  ///< grown by planning.margin
        /// per held state h (0 = nothing, 1 + k = can k): the shelf + the cans not held + the attached can
        std::array<std::shared_ptr<const ompl_ext::Environment>, SHELF_CANS + 1> prototypes_;
        std::array<std::shared_ptr<const ompl_ext::Environment>, SHELF_CANS + 1> planningPrototypes_;
        std::uint64_t id_{0};
        double logNorm_{0.0};
    };
}  // namespace ropras::scenarios

#endif
