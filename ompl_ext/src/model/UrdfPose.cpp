#include "model/UrdfPose.h"

namespace ropras::ompl_ext::urdf_pose
{
    Eigen::Isometry3d toIsometry(const urdf::Pose &pose)
    {
        Eigen::Isometry3d t = Eigen::Isometry3d::Identity();
        t.translation() = Eigen::Vector3d(pose.position.x, pose.position.y, pose.position.z);
        t.linear() = Eigen::Quaterniond(pose.rotation.w, pose.rotation.x, pose.rotation.y, pose.rotation.z)
                         .normalized()
                         .toRotationMatrix();
        return t;
    }

    Eigen::Isometry3d jointMotion(JointType type, const Eigen::Vector3d &axis, double v)
    {
        Eigen::Isometry3d m = Eigen::Isometry3d::Identity();
        if (type == JointType::Revolute || type == JointType::Continuous)
        {
            m.linear() = Eigen::AngleAxisd(v, axis).toRotationMatrix();
        }
        else if (type == JointType::Prismatic)
        {
            m.translation() = axis * v;
        }
        return m;
    }
}  // namespace ropras::ompl_ext::urdf_pose
