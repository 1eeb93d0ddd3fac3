#ifndef ROPRAS_SCENARIOS_MANIPULATION_SHELF_MOVE_PLANNING_H
#define ROPRAS_SCENARIOS_MANIPULATION_SHELF_MOVE_PLANNING_H

#include <array>
#include <cstddef>
#include <cstdint>
#include <memory>
#include <vector>

#include "ropras/core/Rng.h"
#include "ropras/ompl_ext/kinematics/InverseKinematics.h"
#include "ropras/pomdp/OmplReferencePolicy.h"
#include "ropras/pomdp/TargetSpace.h"
#include "ropras/scenarios/manipulation/ShelfMoveModel.h"

namespace ropras::scenarios
{
    /** \brief An informative state of Shelf-Move: grasp can \a can (a side grasp at its centre, then Close),
        sense can \a can (the end effector within sense_distance of its centre) or place the held can on slot
        \a slot (then Open). \a point is the workspace point the end effector goes to (the Dynamic heuristic's
        distance is measured to it). */
    struct ShelfTarget
    {
        enum class Kind
        {
            Grasp,
            Sense,
            Place
        };
        Kind kind{Kind::Grasp};
        int can{-1};
        int slot{-1};
        std::array<double, 3> point{{0.0, 0.0, 0.0}};
    };

    /** \brief Goal configurations of ShelfTargets in a particle's scene: full-pose IK for a grasp (the end
        effector at the can's centre, its z axis along grasp_approach, its x axis vertical: both signs are
        tried) and for a place (the same orientations, the held can's centre place_lift above the slot
        centre); position IK for a sense target: points at planning.sense_fraction x sense_distance from the
        can centre, toward the robot and tilted up by 0, 30, 60 and 90 degrees (yaw 0, +-30 degrees).
        Every solution is collision-free in the scene passed (attached can included). Not thread-safe. */
    class ShelfMoveIk
    {
    public:
        ShelfMoveIk(std::shared_ptr<const ShelfMoveModel> model, std::size_t restarts, std::uint64_t seed);

        /** \brief A configuration for \a target, seen from \a particle, collision-free in \a scene; false
            when none was found. noexcept (IK outcomes are values). */
        bool solve(const ShelfMoveModel::State &particle, const ShelfTarget &target, const ompl_ext::Environment &scene,
                   double *q) noexcept;

        /** \brief The grasp orientations of the end effector: z along the approach turned about the vertical by each
            yaw of graspYaws(), x up or down (two per yaw, yaw by yaw in their order). */
        std::vector<Eigen::Matrix3d> graspOrientations() const;
        /// the approach's turns about the vertical (rad) that grasps and places try, in order (default:
        /// planning.grasp_yaws)
        const std::vector<double> &graspYaws() const noexcept { return yaws_; }
        /// throws ropras::Error for an empty list or a non-finite angle (radians, unlike the degrees of the key)
        void setGraspYaws(std::vector<double> yaws);

    private:
        std::shared_ptr<const ShelfMoveModel> model_;
        std::vector<double> yaws_;
        ompl_ext::InverseKinematics ik_;
        ompl_ext::IkWorkspace workspace_;
        ompl_ext::IkOptions options_;
        core::Rng rng_;
    };

    /** \brief The informative states of Shelf-Move, conditioned on what the particle holds. Holding
        nothing: the goal is grasping the target can, or, while a can blocks its grasp (blockingCan), grasping
        that can (the goal chain: "grasp the target if it is reachable"); the others are grasping each other can and
       sensing each can. Holding the target: the goal is placing it on the reserved slot; the others are the other slots
       and sensing. Holding another can: the goal is the free slot (not the reserved one) nearest to the hand; the
       others are the slots but the reserved one (an obstacle there would block the goal) and sensing. A can parked at a
       slot other than the reserved one (within place_tolerance: moved out of the way) is neither grasped nor sensed
       again: right after a release the hand is at it, so the 1/distance weights would otherwise pick it again and
       again. Distance: the end effector's to the target's point. Entropy bins: the x, y cells (entropy_bin) of the cans
       not held (H normalised by log N). */
    class ShelfMoveTargetSpace final : public pomdp::TargetSpace<ShelfMoveModel::State, ShelfTarget>
    {
    public:
        explicit ShelfMoveTargetSpace(std::shared_ptr<const ShelfMoveModel> model);

        ShelfTarget goal(const ShelfMoveModel::State &particle) const override;
        std::size_t numInformative(const ShelfMoveModel::State &particle) const override;
        ShelfTarget informative(const ShelfMoveModel::State &particle, std::size_t i) const override;
        double distance(const ShelfMoveModel::State &agent, const ShelfTarget &target) const override;
        std::uint64_t entropyBin(const ShelfMoveModel::State &particle) const override;
        std::size_t numEntropyBins() const override { return 0; }

        /// grasp / sense can \a can where \a particle has it (no model needed: also for
        /// ShelfMoveModel::graspableLayout)
        static ShelfTarget grasp(const ShelfMoveModel::State &particle, int can);
        static ShelfTarget sense(const ShelfMoveModel::State &particle, int can);
        ShelfTarget place(int slot) const;

        /** \brief The goal chain's first link: the can (not held, not parked) that stands in front of the target
            (smaller x, on its board, within planning.blocking_halfwidth sideways) nearest to the hand, whose
            grasp is then the goal; -1 when the target's grasp is not blocked. Conservative with turned approaches
            (planning.grasp_yaws): one front can moved, a turned grasp of the target may pass beside the other. */
        int blockingCan(const ShelfMoveModel::State &particle) const noexcept;
        /// can \a can (not held) stands within place_tolerance of a slot other than the reserved one
        bool parked(const ShelfMoveModel::State &particle, int can) const noexcept;

    private:
        /// the slots offered when holding: every slot but the reserved one
        std::size_t otherSlot(std::size_t i) const;
        /// the informative states of a particle, in order: grasps, placements (other slots), sensing
        struct Candidates
        {
            int grasped[SHELF_CANS]{};  ///< holding nothing: the obstacles not parked
            int sensed[SHELF_CANS]{};   ///< the cans not parked
            std::size_t numGrasped{0}, numPlaced{0}, numSensed{0};
        };
        Candidates candidates(const ShelfMoveModel::State &particle) const noexcept;
        std::shared_ptr<const ShelfMoveModel> model_;
    };

    /** \brief The OMPL planning adapter of Shelf-Move: the configuration is the joints; a target's
        configuration comes from ShelfMoveIk in the particle's planning scene (the shelf grown by
        planning.margin, the particle's cans, the held can attached), which is also the scene the planner
        plans in; its trueEnvironment (the same without the margin) is where the reference policy plans for a
        particle whose arm lies inside the margin (as after a grasp deep in the shelf); PathToMacroAction "entire motion
       path": the whole path cut into steps of L2 norm <= step, as joint displacements, the last one carrying Close
       (grasp targets) or Open (place targets). The IK and the last target are mutable: one adapter per reference policy
       (one thread). */
    class ShelfMoveAdapter final
        : public pomdp::OmplPlanningAdapter<ShelfMoveModel::State, ShelfMoveAction, ShelfTarget>
    {
    public:
        ShelfMoveAdapter(std::shared_ptr<const ShelfMoveModel> model, std::unique_ptr<ShelfMoveIk> ik);

        void configuration(const ShelfMoveModel::State &state, double *q) const override;
        bool targetConfiguration(const ShelfMoveModel::State &start, const ShelfTarget &target,
                                 double *q) const override;
        std::shared_ptr<const ompl_ext::Environment> environment(const ShelfMoveModel::State &particle) const override;
        std::shared_ptr<const ompl_ext::Environment> trueEnvironment(
            const ShelfMoveModel::State &particle) const override;
        bool pathToMacroAction(const ShelfMoveModel::State &start, const double *waypoints, std::size_t count,
                               std::vector<ShelfMoveAction> &out) const override;

    private:
        std::shared_ptr<const ShelfMoveModel> model_;
        std::unique_ptr<ShelfMoveIk> ik_;
        mutable ShelfTarget last_{};
        mutable std::shared_ptr<ompl_ext::Environment> scene_;
        mutable ShelfMoveModel::State sceneOf_{};
        mutable std::shared_ptr<const ompl_ext::Environment> trueScene_;  ///< of sceneOf_, made when asked for
        /// makes scene_ the planning scene of \a particle (kept while the particle is the same)
        void select(const ShelfMoveModel::State &particle) const;
        mutable std::vector<double> points_;
    };
}  // namespace ropras::scenarios

#endif
