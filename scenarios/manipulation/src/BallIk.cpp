#include "ropras/scenarios/manipulation/BallIk.h"

#include "ropras/ompl_ext/kinematics/IkTarget.h"

namespace ropras::scenarios
{
    bool solvePositionInBall(const ompl_ext::InverseKinematics &ik, const Eigen::Vector3d &center, double radius,
                             std::size_t points, const double *seed, core::Rng &rng, ompl_ext::IkWorkspace &workspace,
                             const ompl_ext::IkOptions &options, const ompl_ext::ConfigurationPredicate *valid,
                             double *q, std::size_t *solves) noexcept
    {
        for (std::size_t attempt = 0; attempt < points; ++attempt)
        {
            // a point uniform in the ball (rejection from the cube)
            Eigen::Vector3d offset;
            do
            {
                offset = Eigen::Vector3d(rng.uniform(-1, 1), rng.uniform(-1, 1), rng.uniform(-1, 1));
            } while (offset.squaredNorm() > 1.0);
            if (solves != nullptr)
                ++*solves;
            if (ik.solve(ompl_ext::IkTarget::position(center + radius * offset), seed, rng, workspace, q, options,
                         valid)
                    .status == ompl_ext::IkStatus::Solved)
                return true;
        }
        return false;
    }
}  // namespace ropras::scenarios
