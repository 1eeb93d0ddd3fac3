// Position IK to a ball: the arm scenarios' goal configurations (Sphere-Search's goal and light, Ray-Detect's goal).
#ifndef ROPRAS_SCENARIOS_MANIPULATION_BALL_IK_H
#define ROPRAS_SCENARIOS_MANIPULATION_BALL_IK_H

#include <Eigen/Core>
#include <cstddef>

#include "ropras/core/Rng.h"
#include "ropras/ompl_ext/kinematics/InverseKinematics.h"

namespace ropras::scenarios
{
    /** \brief Position IK for up to \a points points drawn uniformly in the ball (\a center, \a radius), one solve
        each from \a seed, until one is solved (accepted by \a valid, which may be null). \a q gets the solution
        (or the last attempt's best); \a solves (may be null) is incremented once per IK solve. The draws come
        from \a rng in a fixed order (three uniforms per rejection round, then the solve's own). */
    bool solvePositionInBall(const ompl_ext::InverseKinematics &ik, const Eigen::Vector3d &center, double radius,
                             std::size_t points, const double *seed, core::Rng &rng, ompl_ext::IkWorkspace &workspace,
                             const ompl_ext::IkOptions &options, const ompl_ext::ConfigurationPredicate *valid,
                             double *q, std::size_t *solves = nullptr) noexcept;
}  // namespace ropras::scenarios

#endif
