// OMPL's RRTConnect with exact SIMD nearest neighbours in a JointStateSpace (private to PlannerRegistry).
#ifndef ROPRAS_OMPL_EXT_JOINT_RRT_CONNECT_H
#define ROPRAS_OMPL_EXT_JOINT_RRT_CONNECT_H

#include <ompl/geometric/planners/rrt/RRTConnect.h>
#include <ompl/util/RandomNumbers.h>
#include <memory>

#include "ropras/ompl_ext/ompl/JointStateSpace.h"
#include "ropras/ompl_ext/planners/JointNearestNeighbors.h"

namespace ropras::ompl_ext
{
    /** \brief OMPL's RRTConnect, unchanged, whose two trees are JointNearestNeighbors instead of GNAT when the
        state space is a JointStateSpace (createStateSpace) and no structure was set with setNearestNeighbors():
        the same nearest node (the exact Euclidean nearest, up to the last bit's rounding), found by one vector scan
        instead of GNAT's pivot walk. GNAT's pivot selector takes one seed from OMPL's seed sequence per tree:
        this planner takes the same two, so a run with the same seed draws the same samples as OMPL's own. */
    class JointRRTConnect : public ompl::geometric::RRTConnect
    {
    public:
        using ompl::geometric::RRTConnect::RRTConnect;

        void setup() override
        {
            if (!tStart_ && !tGoal_ && dynamic_cast<const JointStateSpace *>(si_->getStateSpace().get()) != nullptr)
            {
                const ompl::RNG startSeed, goalSeed;  // the seeds GNAT's two pivot selectors would take
                (void)startSeed;
                (void)goalSeed;
                tStart_ = std::make_shared<JointNearestNeighbors<Motion *>>(si_->getStateDimension());
                tGoal_ = std::make_shared<JointNearestNeighbors<Motion *>>(si_->getStateDimension());
            }
            ompl::geometric::RRTConnect::setup();
        }
    };
}  // namespace ropras::ompl_ext

#endif
