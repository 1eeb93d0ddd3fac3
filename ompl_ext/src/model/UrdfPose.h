#ifndef ROPRAS_OMPL_EXT_SRC_URDF_POSE_H
#define ROPRAS_OMPL_EXT_SRC_URDF_POSE_H

#include <urdf_model/pose.h>

#include <Eigen/Geometry>

#include "ropras/ompl_ext/model/RobotModel.h"

/// URDF poses and joint motions as Eigen transforms (the builder's and the reference FK's)
namespace ropras::ompl_ext::urdf_pose
{
    /// a URDF <origin> as a rigid transform (the quaternion normalized)
    Eigen::Isometry3d toIsometry(const urdf::Pose &pose);

    /// the motion of a URDF joint at value v, in the joint frame
    Eigen::Isometry3d jointMotion(JointType type, const Eigen::Vector3d &axis, double v);

    inline bool finitePose(const Eigen::Isometry3d &t)
    {
        return t.matrix().allFinite();
    }
}  // namespace ropras::ompl_ext::urdf_pose

#endif
