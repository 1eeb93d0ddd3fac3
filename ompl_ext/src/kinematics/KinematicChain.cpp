#include "ropras/ompl_ext/kinematics/KinematicChain.h"

#include <algorithm>
#include <cmath>

#include "ropras/core/Error.h"

namespace ropras::ompl_ext
{
    namespace
    {
        /// the motion of a URDF joint at value v, in the joint frame
        Eigen::Isometry3d jointMotion(const UrdfJoint &j, double v)
        {
            Eigen::Isometry3d m = Eigen::Isometry3d::Identity();
            if (j.type == JointType::Revolute || j.type == JointType::Continuous)
                m.linear() = Eigen::AngleAxisd(v, j.axis).toRotationMatrix();
            else if (j.type == JointType::Prismatic)
                m.translation() = j.axis * v;
            return m;
        }

        /// (R, t) <- (R, t) * offset * Motion(v): the chain's one step, shared by the single and the Jacobian path
        inline void step(const ChainJoint &j, double v, Eigen::Matrix3d &r, Eigen::Vector3d &t) noexcept
        {
            t += r * j.offset.translation();
            r = r * j.offset.linear();
            if (j.prismatic)
            {
                t += r.col(2) * v;
                return;
            }
            const double c = std::cos(v), s = std::sin(v);
            const Eigen::Vector3d c0 = r.col(0);
            r.col(0) = c * c0 + s * r.col(1);
            r.col(1) = c * r.col(1) - s * c0;
        }
    }  // namespace

    KinematicChain::KinematicChain(std::shared_ptr<const RobotModel> robot, const std::string &tipLink)
        : robot_(std::move(robot)), tipName_(tipLink)
    {
        if (!robot_)
            throw Error("KinematicChain: no robot model given");
        tipLink_ = robot_->linkIndex(tipLink);  // throws Error naming the link
        const auto &links = robot_->links();
        const auto &urdfJoints = robot_->urdfJoints();
        std::vector<int> path;  // URDF joints from the tip up to the root
        for (int l = tipLink_; links[static_cast<std::size_t>(l)].parentJoint >= 0;)
        {
            const int j = links[static_cast<std::size_t>(l)].parentJoint;
            path.push_back(j);
            l = urdfJoints[static_cast<std::size_t>(j)].parentLink;
        }
        std::reverse(path.begin(), path.end());

        // pending: the constant transform since the last moving joint's moved frame (the world at the root)
        Eigen::Isometry3d pending = robot_->basePose();
        for (const int ji : path)
        {
            const UrdfJoint &uj = urdfJoints[static_cast<std::size_t>(ji)];
            pending = pending * uj.origin;
            if (uj.variable < 0)
            {
                pending = pending * jointMotion(uj, uj.heldValue);
                continue;
            }
            // Motion(axis, v) = A Motion(z, v) A^T with A taking z to the axis: A goes into this offset, A^T into
            // the next one
            const Eigen::Matrix3d a =
                Eigen::Quaterniond::FromTwoVectors(Eigen::Vector3d::UnitZ(), uj.axis).toRotationMatrix();
            const PlanningJoint &pj = robot_->joints()[static_cast<std::size_t>(uj.variable)];
            ChainJoint cj;
            cj.name = uj.name;
            cj.variable = uj.variable;
            cj.prismatic = uj.type == JointType::Prismatic;
            cj.continuous = uj.type == JointType::Continuous;
            cj.lower = pj.lower;
            cj.upper = pj.upper;
            cj.offset = pending;
            cj.offset.linear() = pending.linear() * a;
            joints_.push_back(cj);
            pending = Eigen::Isometry3d::Identity();
            pending.linear() = a.transpose();
        }
        tipOffset_ = pending;
    }

    Eigen::Isometry3d KinematicChain::tipPose(const double *q) const noexcept
    {
        Eigen::Matrix3d r = Eigen::Matrix3d::Identity();
        Eigen::Vector3d t = Eigen::Vector3d::Zero();
        for (const ChainJoint &j : joints_)
            step(j, q[j.variable], r, t);
        Eigen::Isometry3d out;
        out.linear() = r * tipOffset_.linear();
        out.translation() = t + r * tipOffset_.translation();
        out.makeAffine();
        return out;
    }

    void KinematicChain::forward(const double *q, ChainWorkspace &ws) const noexcept
    {
        Eigen::Matrix3d r = Eigen::Matrix3d::Identity();
        Eigen::Vector3d t = Eigen::Vector3d::Zero();
        for (std::size_t i = 0; i < joints_.size(); ++i)
        {
            const ChainJoint &j = joints_[i];
            // the joint's origin and axis (z) are those before its own motion
            const Eigen::Vector3d origin = t + r * j.offset.translation();
            step(j, q[j.variable], r, t);
            ws.jointRotation[i] = r;
            ws.jointTranslation[i] = j.prismatic ? origin : t;
        }
        ws.tip.linear() = r * tipOffset_.linear();
        ws.tip.translation() = t + r * tipOffset_.translation();
        ws.tip.makeAffine();
    }

    void KinematicChain::jacobian(const double *q, ChainWorkspace &ws) const noexcept
    {
        forward(q, ws);
        const Eigen::Vector3d tip = ws.tip.translation();
        ChainWorkspace::Jacobian jacobian = ws.jacobian();
        for (std::size_t i = 0; i < joints_.size(); ++i)
        {
            const auto col = static_cast<Eigen::Index>(i);
            const Eigen::Vector3d z = ws.jointRotation[i].col(2);
            if (joints_[i].prismatic)
            {
                jacobian.block<3, 1>(0, col) = z;
                jacobian.block<3, 1>(3, col).setZero();
            }
            else
            {
                jacobian.block<3, 1>(0, col) = z.cross(tip - ws.jointTranslation[i]);
                jacobian.block<3, 1>(3, col) = z;
            }
        }
    }
}  // namespace ropras::ompl_ext
