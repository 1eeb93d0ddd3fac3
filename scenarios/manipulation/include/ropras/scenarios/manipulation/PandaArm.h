#ifndef ROPRAS_SCENARIOS_MANIPULATION_PANDA_ARM_H
#define ROPRAS_SCENARIOS_MANIPULATION_PANDA_ARM_H

#include <Eigen/Geometry>
#include <cstddef>
#include <memory>
#include <string>

#include "ropras/ompl_ext/collision/CollisionChecker.h"
#include "ropras/ompl_ext/kinematics/KinematicChain.h"
#include "ropras/ompl_ext/model/RobotModel.h"
#include "ropras/pomdp/Rng.h"

namespace ropras::scenarios
{
    /** \brief Joints of the arm scenarios' robot (the Panda: 7 revolute joints, fingers fixed open). */
    constexpr std::size_t ARM_DOF = 7;

    /** \brief A primitive action of the arm scenarios: a joint displacement dq in R^7 (rad), or, when
        \c waypoint is set, the configuration to move to (dq then holds that configuration; the reference
        policy emits such actions with the configuration key action_mode = "waypoint"). */
    struct ArmAction
    {
        double dq[ARM_DOF]{0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0};
        bool waypoint{false};
    };

    /** \brief The project's Panda (robots/panda/panda.urdf + panda.srdf, compiled into the library: no file is
        read at run time), its SIMD sphere collision checker and the end-effector chain, shared by the arm
        scenarios' model, world and planner. A const model: every method is thread-safe. */
    class PandaArm
    {
    public:
        /** \brief Loads the embedded Panda; \a endEffector names the link whose origin is the end effector
            (default panda_grasptarget, 0.105 m beyond the hand). Throws ropras::Error naming the link when the
            robot has none of that name. */
        explicit PandaArm(const std::string &endEffector = "panda_grasptarget");

        const std::shared_ptr<const ompl_ext::RobotModel> &robot() const { return robot_; }
        const std::shared_ptr<const ompl_ext::CollisionChecker> &checker() const { return checker_; }
        const ompl_ext::KinematicChain &endEffectorChain() const { return chain_; }
        const std::string &endEffector() const { return chain_.tipName(); }

        double lower(std::size_t j) const { return robot_->joints()[j].lower; }
        double upper(std::size_t j) const { return robot_->joints()[j].upper; }

        /// world pose of the end effector at \a q (ARM_DOF values; double precision; noexcept, no allocation)
        Eigen::Isometry3d endEffectorPose(const double *q) const noexcept { return chain_.tipPose(q); }
        Eigen::Vector3d endEffectorPosition(const double *q) const noexcept { return chain_.tipPose(q).translation(); }

        /// clamps \a q into the joint limits
        void clamp(double *q) const noexcept;

        /** \brief The commanded end of a primitive of the arm scenarios (their shared transition rule): \a target
            = clamp(q + dq + N(0, sigma)) per joint, or clamp(dq + N(0, sigma)) when \a waypoint (dq is then the
            configuration to move to). Draws ARM_DOF normals from \a rng, in joint order. */
        void proposeMotion(const double *q, const double *dq, bool waypoint, double sigma, pomdp::Rng &rng,
                           double *target) const noexcept;

        /// \a out = q0 + fraction (q1 - q0): where a motion blocked at \a fraction stops
        static void interpolate(const double *q0, const double *q1, double fraction, double *out) noexcept;

        /** \brief Throws ropras::Error "\a prefix joint J = V is outside its limits [L, U]" for the first of the
            ARM_DOF values of \a q outside its joint's limits (a configuration key's check). */
        void requireWithinLimits(const double *q, const std::string &prefix) const;

        /** \brief How many configurations a motion q0 -> q1 is checked at, excluding q0: ceil(largest joint
            change / \a resolution), at least 1 — the rule of CollisionChecker::isMotionValid, so the Bullet
            world checks the same configurations q0 + (k / n)(q1 - q0), k = 1..n. */
        static std::size_t motionSamples(const double *q0, const double *q1, double resolution) noexcept;

    private:
        std::shared_ptr<const ompl_ext::RobotModel> robot_;
        std::shared_ptr<const ompl_ext::CollisionChecker> checker_;
        ompl_ext::KinematicChain chain_;
    };

    /** \brief The embedded Panda as a RobotModel, loaded once (throws ropras::Error if it is not a 7-joint arm). */
    std::shared_ptr<const ompl_ext::RobotModel> loadEmbeddedPanda();

    /** \brief A PandaArm for \a endEffector, made once per link name and shared (thread-safe). */
    std::shared_ptr<const PandaArm> sharedPandaArm(const std::string &endEffector);
}  // namespace ropras::scenarios

#endif
