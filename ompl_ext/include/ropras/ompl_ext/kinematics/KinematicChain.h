#ifndef ROPRAS_OMPL_EXT_KINEMATIC_CHAIN_H
#define ROPRAS_OMPL_EXT_KINEMATIC_CHAIN_H

#include <Eigen/Core>
#include <Eigen/Geometry>
#include <cstddef>
#include <memory>
#include <string>
#include <vector>

#include "ropras/ompl_ext/model/RobotModel.h"

namespace ropras::ompl_ext
{
    /** \brief One moving joint of a KinematicChain, re-expressed to rotate about (or slide along) its local +z. */
    struct ChainJoint
    {
        std::string name;                                         ///< the URDF joint
        int variable{-1};                                         ///< planning-variable index (RobotModel::joints())
        bool prismatic{false};                                    ///< slides along z instead of rotating about it
        bool continuous{false};                                   ///< no limits (wraps)
        double lower{0.0}, upper{0.0};                            ///< the planning joint's limits
        Eigen::Isometry3d offset{Eigen::Isometry3d::Identity()};  ///< previous joint's moved frame -> this joint frame
    };

    /** \brief Mutable per-thread workspace of a KinematicChain: the moved frame of every chain joint, the tip
        pose and the geometric Jacobian. Sized once by the constructor; the chain's methods never allocate. */
    struct ChainWorkspace
    {
        using Jacobian = Eigen::Map<Eigen::Matrix<double, 6, Eigen::Dynamic>>;

        explicit ChainWorkspace(std::size_t joints = 0)
            : jointRotation(joints), jointTranslation(joints), jacobianData(6 * joints)
        {
        }
        std::vector<Eigen::Matrix3d> jointRotation;     ///< world rotation of each joint's moved frame (z = axis)
        std::vector<Eigen::Vector3d> jointTranslation;  ///< world origin of each joint's frame
        Eigen::Isometry3d tip{Eigen::Isometry3d::Identity()};
        /// 6 x joints column-major: rows 0-2 the tip point's linear velocity, rows 3-5 the angular velocity (world)
        std::vector<double> jacobianData;

        /// jacobianData as a matrix. (Plain vectors, not Eigen's dynamic matrices, hold the data: a library built
        /// for AVX-512 and a program built without it would disagree on how Eigen allocates and frees them.)
        Jacobian jacobian()
        {
            return Jacobian(jacobianData.data(), 6, static_cast<Eigen::Index>(jointRotation.size()));
        }
    };

    /** \brief The serial chain from the robot's root link to one link (the tip), as a const model.

        Built from RobotModel::urdfJoints() and links(): planning joints on the path move; fixed joints, held
        joints (at their held value) and mimic joints are folded into constant transforms. The root carries the
        model's base pose, so poses are in the world frame, like RobotModel::linkTransformsReference. Every
        method takes the full planning vector q (RobotModel::dof() values) and reads only the chain's variables.
        FK and Jacobian are noexcept and allocation-free (double precision); batch FK works on blocks of 4
        configurations as structure of arrays (4-wide AVX2 when the compiler targets it). */
    class KinematicChain
    {
    public:
        /// throws Error naming the link when the robot has no link \a tipLink
        KinematicChain(std::shared_ptr<const RobotModel> robot, const std::string &tipLink);

        const RobotModel &robot() const { return *robot_; }
        const std::shared_ptr<const RobotModel> &robotPtr() const { return robot_; }
        const std::string &tipName() const { return tipName_; }
        int tipLink() const { return tipLink_; }
        /// moving joints on the chain, root to tip
        const std::vector<ChainJoint> &joints() const { return joints_; }
        std::size_t size() const { return joints_.size(); }
        /// tip frame in the last joint's moved frame (the root's pose when the chain has no moving joint)
        const Eigen::Isometry3d &tipOffset() const { return tipOffset_; }

        /// a workspace sized for this chain
        ChainWorkspace makeWorkspace() const { return ChainWorkspace(joints_.size()); }

        /// world pose of the tip at \a q
        Eigen::Isometry3d tipPose(const double *q) const noexcept;
        /// world pose of the tip and of every joint frame, into \a ws
        void forward(const double *q, ChainWorkspace &ws) const noexcept;
        /// forward() and then the geometric Jacobian of the tip (point and orientation), into \a ws.jacobian
        void jacobian(const double *q, ChainWorkspace &ws) const noexcept;
        /** \brief Tip poses of \a count configurations (rows of RobotModel::dof() values in \a qs). \a out gets 12
            doubles per configuration: the rotation column-major (9) then the translation (3). */
        void tipPosesBatch(const double *qs, std::size_t count, double *out) const noexcept;

    private:
        std::shared_ptr<const RobotModel> robot_;
        std::string tipName_;
        int tipLink_{-1};
        std::vector<ChainJoint> joints_;
        Eigen::Isometry3d tipOffset_{Eigen::Isometry3d::Identity()};
    };
}  // namespace ropras::ompl_ext

#endif
