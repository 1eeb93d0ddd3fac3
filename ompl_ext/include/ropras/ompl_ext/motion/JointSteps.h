#ifndef ROPRAS_OMPL_EXT_JOINT_STEPS_H
#define ROPRAS_OMPL_EXT_JOINT_STEPS_H

#include <cmath>
#include <cstddef>
#include <memory>
#include <vector>

#include "ropras/core/Rng.h"
#include "ropras/ompl_ext/collision/CollisionChecker.h"

namespace ropras::ompl_ext
{
    /// the norm a joint step's size is measured in
    enum class StepNorm
    {
        L2,   ///< Euclidean
        Linf  ///< largest joint change
    };

    /// how a straight segment of the path is cut
    enum class StepSplit
    {
        Equal,  ///< ceil(length / step) equal pieces: every step has norm <= step
        Exact   ///< pieces of norm exactly step, then the remainder (norm in (0, step]) ending on the waypoint
    };

    struct JointStepOptions
    {
        double step{0.1};  ///< the primitive's norm (rad or m), > 0 and finite
        StepNorm norm{StepNorm::L2};
        StepSplit split{StepSplit::Exact};
        std::size_t maxSteps{0};  ///< at most this many steps (a truncated macro ends on the path); 0 = whole path
    };

    /** \brief The number of primitive steps a straight segment of norm \a length (> 0) is cut into with steps
        of at most \a step: ceil(length / step), at least 1, where a remainder below 1e-9 steps is rounding
        (a segment of exactly k steps is k pieces). The rule of discretizeJointPath, for callers that need
        the count without the points. */
    inline std::size_t segmentPieces(double length, double step) noexcept
    {
        const double pieces = std::ceil(length / step - 1e-9);
        return pieces > 1.0 ? static_cast<std::size_t>(pieces) : 1;
    }

    /** \brief Cuts a piecewise-linear joint-space path (\a waypoints, \a count x \a dof, row-major) into
        primitive steps and appends the end of every step to \a points (\a dof values each; the start is not
        appended). Every waypoint after the first is a point, so a straight move between consecutive points
        lies on a segment of the path (it never cuts a corner the planner validated), and the whole path
        ends on the last waypoint. Zero-length segments add nothing. Returns the number of points appended.
        Throws ropras::Error naming the value for a non-positive or non-finite step, a non-finite waypoint,
        dof 0 or fewer than two waypoints; nothing is appended then. */
    std::size_t discretizeJointPath(const double *waypoints, std::size_t count, std::size_t dof,
                                    const JointStepOptions &options, std::vector<double> &points);

    /** \brief The pomdp form: L2 norm, equal pieces of at most \a step, at most \a maxPoints (0 = all). */
    std::size_t discretizeJointPath(const double *waypoints, std::size_t count, std::size_t dof, double step,
                                    std::size_t maxPoints, std::vector<double> &points);

    /** \brief The same cut as discretizeJointPath, appended to \a steps as increments dq (row-major, \a dof
        values each): waypoints[0] + the sum of the first k steps is the k-th point (to rounding). */
    std::size_t jointSteps(const double *waypoints, std::size_t count, std::size_t dof, const JointStepOptions &options,
                           std::vector<double> &steps);

    /// what executing one step did
    struct StepOutcome
    {
        bool blocked{false};   ///< the motion met an obstacle (or self-collision) and stopped before its end
        double fraction{1.0};  ///< how far along the (noisy, clamped) motion the robot got, in [0, 1]
    };

    /** \brief Executes primitive joint steps as motions in an Environment: the commanded dq plus Gaussian
        noise (per joint standard deviation, drawn from the caller's core::Rng), the target clamped into the
        joint limits (continuous joints are not clamped), then the straight motion from the current
        configuration checked with CollisionChecker::isMotionValid at \a resolution (largest joint change
        between checked configurations). A valid motion ends at the target; a blocked one ends at the last
        valid checked configuration (q + fraction (target - q); fraction 0 leaves the robot where it was).
        The current configuration is taken as valid (it is not checked). Const and thread-safe (each thread
        its own Rng); no allocation for arms of up to 64 joints. */
    class JointStepExecutor
    {
    public:
        /** \brief Throws ropras::Error for a null checker, a non-positive or non-finite \a resolution, or a
            noise vector whose size is not the robot's dof (empty = no noise) or holds a negative or
            non-finite value. */
        JointStepExecutor(std::shared_ptr<const CollisionChecker> checker, double resolution,
                          std::vector<double> noiseStddev = {});

        /** \brief Moves from \a q by \a dq (dof() values each) and writes the reached configuration to
            \a out (may alias \a q). Throws ropras::Error naming the value for a non-finite \a q or \a dq, or
            a \a q outside the joint limits. */
        StepOutcome execute(const Environment &env, const double *q, const double *dq, core::Rng &rng,
                            double *out) const;

        std::size_t dof() const { return dof_; }
        double resolution() const { return resolution_; }
        const std::vector<double> &noiseStddev() const { return noise_; }

    private:
        std::shared_ptr<const CollisionChecker> checker_;
        std::size_t dof_;
        double resolution_;
        std::vector<double> noise_;
    };
}  // namespace ropras::ompl_ext

#endif
