#ifndef ROPRAS_OMPL_EXT_INVERSE_KINEMATICS_H
#define ROPRAS_OMPL_EXT_INVERSE_KINEMATICS_H

#include <Eigen/Core>
#include <cstddef>
#include <functional>
#include <memory>
#include <string>
#include <vector>

#include "ropras/core/Rng.h"
#include "ropras/ompl_ext/kinematics/IkTarget.h"
#include "ropras/ompl_ext/kinematics/KinematicChain.h"

namespace ropras::ompl_ext
{
    /** \brief A test a solution must pass besides reaching the target (e.g. collision-free, attachments
        included): called with the full planning vector; must not throw. See collisionFreePredicate(). */
    using ConfigurationPredicate = std::function<bool(const double *q)>;

    /** \brief Options of InverseKinematics::solve. */
    struct IkOptions
    {
        double positionTolerance{1e-5};     ///< m, on the tip origin's distance to the target
        double orientationTolerance{1e-4};  ///< rad, on the rotation angle (Pose) or the axis angle (PositionAxis)
        std::size_t maxIterations{100};     ///< damped least-squares steps per attempt (rejected steps count)
        std::size_t restarts{100};          ///< random restarts after the attempt from the seed
        double timeLimit{0.0};              ///< s for the whole solve (all attempts); 0: no limit
        double maxStep{0.5};                ///< largest change of one joint per step (rad or m)
        double damping{1e-4};               ///< the smallest damping (added to the squared residual, LM style)

        /// throws Error naming the first option that is NaN, negative or otherwise absurd
        void validate() const;
    };

    /** \brief Outcome of InverseKinematics::solve (never an exception for an unreachable target). */
    enum class IkStatus
    {
        Solved,           ///< within the tolerances, the joint limits, and accepted by the predicate
        NotConverged,     ///< every attempt ended outside the tolerances (unreachable, or too few restarts)
        NoValidSolution,  ///< some attempts reached the target, but the predicate rejected every one
        TimedOut          ///< the time limit ended the solve before a solution
    };

    const char *ikStatusName(IkStatus status) noexcept;

    struct IkResult
    {
        IkStatus status{IkStatus::NotConverged};
        double positionError{0.0};     ///< m, of the configuration returned
        double orientationError{0.0};  ///< rad, of the configuration returned (0 for Position)
        std::size_t iterations{0};     ///< steps over all attempts
        std::size_t attempts{0};       ///< 1 + restarts used
    };

    /** \brief Mutable per-thread workspace of InverseKinematics (allocated once, reused by every solve). */
    struct IkWorkspace
    {
        explicit IkWorkspace(const KinematicChain &chain);
        ChainWorkspace current, trial;
        std::vector<double> q, qTrial, qBest;  ///< full planning vectors
        std::vector<double> jacobian;          ///< 6 x chain joints: the rows the target constrains
        std::vector<double> step;              ///< the chain's joint step
    };

    /** \brief Inverse kinematics of one serial chain: damped least squares (Levenberg-Marquardt, damping from
        the squared residual) on the analytic geometric Jacobian, steps limited per joint and clamped into the
        joint limits (continuous joints wrap), random restarts uniform within the limits from a seeded core::Rng.
        Joints off the chain keep their seed values. A const model, thread-safe: each thread passes its own
        IkWorkspace and Rng; the solve itself is noexcept and allocation-free (the predicate aside). */
    class InverseKinematics
    {
    public:
        explicit InverseKinematics(KinematicChain chain);
        /// the chain from the robot's root to \a tipLink (Error naming the link if unknown)
        InverseKinematics(std::shared_ptr<const RobotModel> robot, const std::string &tipLink);

        const KinematicChain &chain() const { return chain_; }
        IkWorkspace makeWorkspace() const { return IkWorkspace(chain_); }

        /** \brief Solves for \a target from \a seed (dof() values, finite; clamped into the limits first) into
            \a q (dof() values; the best configuration found, also when not solved). \a options must be valid
            (IkOptions::validate); \a valid may be null. */
        IkResult solve(const IkTarget &target, const double *seed, core::Rng &rng, IkWorkspace &ws, double *q,
                       const IkOptions &options, const ConfigurationPredicate *valid = nullptr) const noexcept;

        /// checked convenience form: validates the options and the seed's size and values (Error naming them)
        IkResult solve(const IkTarget &target, const std::vector<double> &seed, core::Rng &rng, std::vector<double> &q,
                       const IkOptions &options = IkOptions(), const ConfigurationPredicate &valid = nullptr) const;

        /// position (m) and orientation (rad) errors of \a q against \a target
        void errors(const IkTarget &target, const double *q, double &position, double &orientation) const noexcept;

    private:
        bool attempt(const IkTarget &target, IkWorkspace &ws, const IkOptions &options, double deadline,
                     IkResult &result, double &cost) const noexcept;

        KinematicChain chain_;
    };
}  // namespace ropras::ompl_ext

#endif
