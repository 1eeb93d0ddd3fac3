#ifndef ROPRAS_OMPL_EXT_IK_TARGET_H
#define ROPRAS_OMPL_EXT_IK_TARGET_H

#include <Eigen/Geometry>

namespace ropras::ompl_ext
{
    /** \brief What an inverse-kinematics target constrains. */
    enum class IkTargetKind
    {
        Position,      ///< the tip's origin only (3 constraints)
        PositionAxis,  ///< the tip's origin and the world direction of one tip axis (5 constraints)
        Pose           ///< the tip's full pose (6 constraints)
    };

    /** \brief A workspace target for InverseKinematics, in the world frame. Built only through the factories,
        which check their input and throw ropras::Error naming the bad value (NaN or infinite numbers, a zero
        approach or tool axis, a quaternion that is not of unit norm, a rotation that is not orthonormal), so a
        target that exists is always valid. */
    class IkTarget
    {
    public:
        static IkTarget position(const Eigen::Vector3d &position);
        /** \brief The tip's \a toolAxis (in the tip frame, default +z) must point along the world \a approach.
            Both are normalized; a zero or non-finite one throws Error. */
        static IkTarget positionAxis(const Eigen::Vector3d &position, const Eigen::Vector3d &approach,
                                     const Eigen::Vector3d &toolAxis = Eigen::Vector3d::UnitZ());
        /// the quaternion's norm must be 1 within 1e-6 (it is then normalized)
        static IkTarget pose(const Eigen::Vector3d &position, const Eigen::Quaterniond &orientation);
        /// the rotation must be orthonormal with determinant +1 (within 1e-6)
        static IkTarget pose(const Eigen::Isometry3d &pose);

        IkTargetKind kind() const { return kind_; }
        const Eigen::Vector3d &position() const { return position_; }
        /// PositionAxis: the unit world direction the tool axis must take
        const Eigen::Vector3d &approach() const { return approach_; }
        /// PositionAxis: the unit tool axis in the tip frame
        const Eigen::Vector3d &toolAxis() const { return toolAxis_; }
        /// Pose: the target orientation
        const Eigen::Quaterniond &orientation() const { return orientation_; }

    private:
        IkTarget() = default;
        IkTargetKind kind_{IkTargetKind::Position};
        Eigen::Vector3d position_{Eigen::Vector3d::Zero()};
        Eigen::Vector3d approach_{Eigen::Vector3d::UnitZ()};
        Eigen::Vector3d toolAxis_{Eigen::Vector3d::UnitZ()};
        Eigen::Quaterniond orientation_{Eigen::Quaterniond::Identity()};
    };
}  // namespace ropras::ompl_ext

#endif
