#ifndef ROPRAS_SCENARIOS_MANIPULATION_SHELF_MOVE_WORLD_H
#define ROPRAS_SCENARIOS_MANIPULATION_SHELF_MOVE_WORLD_H

#include <Eigen/Geometry>
#include <cstddef>
#include <memory>

#include "ropras/pomdp/World.h"
#include "ropras/scenarios/manipulation/ShelfMoveModel.h"

namespace ropras::scenarios
{
    /** \brief What really happens in Shelf-Move: Bullet rigid-body dynamics (btDiscreteDynamicsWorld). The shelf's
        boxes and a floor (z = 0) are static; the cans are dynamic cylinders (world.can_mass, can_friction,
        can_restitution) under gravity; the arm's collision links are kinematic bodies (their spheres, posed by the
        robot's reference FK) moved to each step's configuration; a held can is a kinematic body attached to the
        end effector at the model's grasp transform.

        A step draws the model's motion noise (ShelfMoveModel::proposeMotion), then the world decides:
        - the motion: the straight joint motion is checked at the model's samples (PandaArm::motionSamples) by
          Bullet contact queries of the arm links and the held can against the shelf, the cans not held and the
          arm's self-collision pairs; a touching sample blocks the step at the sample before it (as the model).
          With world.push_cans, cans do not block: the arm moves along the motion in physics steps (at most
          world.push_joint_speed) and pushes them; only the shelf and self-collision block;
        - Close: grasps the can whose actual axis segment is within grasp_tolerance of the grasp point and whose
          actual axis is within grasp_axis_tolerance of the end effector's x axis, when the held can (snapped
          into the hand) touches nothing;
        - Open: releases the held can when its centre is within place_tolerance of a slot whose footprint no
          other can occupies and the open hand is clear of it; the can becomes dynamic at its pose in the hand
          and is stepped until it settles (world.settle_*; it may tip or slide). The target settled upright
          within place_tolerance of the reserved slot is the goal.
        The state's can centres are the bodies' centres; observations are the model's rule (ShelfMoveModel::
        observe) on them. The state's event fields record grasps and releases; worldReport flags releases that
        settled off the model's snap or tipped, pushes, and steps where the model's blocked / valid verdict on the
        same motion differs. Not thread-safe: one instance per episode. */
    class ShelfMoveWorld final : public pomdp::World<ShelfMoveModel>
    {
    public:
        explicit ShelfMoveWorld(std::shared_ptr<const ShelfMoveModel> model);
        ~ShelfMoveWorld() override;
        ShelfMoveWorld(const ShelfMoveWorld &) = delete;
        ShelfMoveWorld &operator=(const ShelfMoveWorld &) = delete;

        /// rebuilds the Bullet world: the cans upright at \a initial's centres (at rest), the held one in the hand
        void reset(const State &initial) override;
        const State &state() const override { return state_; }
        pomdp::StepResult<State, Observation> step(const Action &action, pomdp::Rng &rng) override;

        /** \brief The world's verdict on the straight motion from the current joints to \a target (with what is
            held): true when valid; else \a fraction (if non-null) gets the last valid sample's fraction. With
            push_cans only the shelf and self-collision count. Leaves the arm where it was. With \a within > 0,
            shapes closer than \a within (m) count as touching (how near a motion passes to contact). */
        bool motionValid(const double *target, double *fraction = nullptr, double within = 0.0);
        /// whether the arm at \a q (and the held can) touches the shelf, a can not held (unless push_cans) or itself
        bool collides(const double *q, double within = 0.0);
        /// the can Close would grasp now (-1: none)
        int graspableCan();
        /// the slot Open would release the held can over now (-1: none)
        int releaseSlot();

        Eigen::Isometry3d canPose(std::size_t k) const;
        /// the angle (rad) between can \a k's axis and the vertical (0: upright or upside down)
        double canTilt(std::size_t k) const;

        /// how a dropped can came to rest
        struct Settling
        {
            int can{-1};
            Eigen::Vector3d from{Eigen::Vector3d::Zero()};  ///< its centre when dropped
            Eigen::Vector3d to{Eigen::Vector3d::Zero()};    ///< its centre at rest
            double tilt{0.0};                               ///< canTilt at rest
            double seconds{0.0};                            ///< simulated time to rest
            bool settled{false};                            ///< false: still moving after settle_seconds
        };
        /** \brief Drops can \a k (not held) from \a pose with zero velocity and steps the world until every can
            settles (or settle_seconds); the state's can centres follow. The release's physics; also for tests. */
        Settling drop(std::size_t k, const Eigen::Isometry3d &pose);
        /// the last release's (or drop's) settling
        const Settling &lastSettling() const { return settling_; }

        /// counts since construction
        struct Statistics
        {
            std::size_t steps{0};
            std::size_t blockedSteps{0};          ///< the world blocked the motion
            std::size_t verdictDisagreements{0};  ///< the model's verdict on the same motion differed
            std::size_t grasps{0};
            std::size_t releases{0};
            std::size_t movedReleases{0};   ///< settled more than report_distance from the model's snap
            std::size_t tippedReleases{0};  ///< settled tilted more than tip_angle
            std::size_t pushedSteps{0};     ///< a can not held moved more than report_distance
        };
        const Statistics &statistics() const { return statistics_; }

    private:
        struct Impl;
        void readCans();
        bool grasp(int k);
        void release(int slot, pomdp::StepResult<State, Observation> &out);
        void pushAlong(const double *target, double *fraction);

        std::shared_ptr<const ShelfMoveModel> model_;
        std::unique_ptr<Impl> impl_;
        State state_{};
        Settling settling_;
        Statistics statistics_;
    };
}  // namespace ropras::scenarios

#endif
