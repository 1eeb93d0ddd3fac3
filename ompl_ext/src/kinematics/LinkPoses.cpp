#include "ropras/ompl_ext/kinematics/LinkPoses.h"

#include "ropras/core/Error.h"

namespace ropras::ompl_ext
{
    LinkPoses::LinkPoses(std::shared_ptr<const RobotModel> robot) : robot_(std::move(robot))
    {
        if (!robot_)
            throw Error("LinkPoses: no robot model given");
        chains_.reserve(robot_->links().size());
        for (const Link &link : robot_->links())
            chains_.emplace_back(robot_, link.name);
    }

    const KinematicChain &LinkPoses::chain(const std::string &link) const
    {
        return chains_[static_cast<std::size_t>(robot_->linkIndex(link))];
    }

    Eigen::Isometry3d LinkPoses::linkPose(const double *q, const std::string &link) const
    {
        return chain(link).tipPose(q);
    }

    Eigen::Isometry3d LinkPoses::linkPose(const double *q, int link) const noexcept
    {
        return chains_[static_cast<std::size_t>(link)].tipPose(q);
    }

    void LinkPoses::linkPosesBatch(const double *qs, std::size_t count, int link, double *out) const noexcept
    {
        chains_[static_cast<std::size_t>(link)].tipPosesBatch(qs, count, out);
    }

    void LinkPoses::linkPosesBatch(const double *qs, std::size_t count, const std::string &link, double *out) const
    {
        chain(link).tipPosesBatch(qs, count, out);
    }
}  // namespace ropras::ompl_ext
