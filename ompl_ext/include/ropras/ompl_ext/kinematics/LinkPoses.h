#ifndef ROPRAS_OMPL_EXT_LINK_POSES_H
#define ROPRAS_OMPL_EXT_LINK_POSES_H

#include <Eigen/Geometry>
#include <cstddef>
#include <memory>
#include <string>
#include <vector>

#include "ropras/ompl_ext/kinematics/KinematicChain.h"

namespace ropras::ompl_ext
{
    /** \brief World pose of any link of a robot, for one configuration or a batch (double precision).

        A const model holding the KinematicChain root -> link of every link, built once. The link-index methods
        are noexcept and allocation-free; the name methods look the name up first and throw Error naming it
        when the robot has no such link. q is the full planning vector (RobotModel::dof() values). */
    class LinkPoses
    {
    public:
        explicit LinkPoses(std::shared_ptr<const RobotModel> robot);

        const RobotModel &robot() const { return *robot_; }
        /// the chain root -> link (throws Error for an unknown name)
        const KinematicChain &chain(const std::string &link) const;
        const KinematicChain &chain(int link) const { return chains_[static_cast<std::size_t>(link)]; }

        Eigen::Isometry3d linkPose(const double *q, const std::string &link) const;
        Eigen::Isometry3d linkPose(const double *q, int link) const noexcept;
        /// the poses of \a count configurations (rows of dof() values) of one link: 12 doubles each (rotation
        /// column-major, then translation), as KinematicChain::tipPosesBatch
        void linkPosesBatch(const double *qs, std::size_t count, int link, double *out) const noexcept;
        void linkPosesBatch(const double *qs, std::size_t count, const std::string &link, double *out) const;

    private:
        std::shared_ptr<const RobotModel> robot_;
        std::vector<KinematicChain> chains_;  ///< indexed like RobotModel::links()
    };
}  // namespace ropras::ompl_ext

#endif
