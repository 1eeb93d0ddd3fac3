#include "ropras/ompl_ext/kinematics/InverseKinematics.h"

#include <time.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <string>

#include "ropras/core/Error.h"

namespace ropras::ompl_ext
{
    namespace
    {
        using Vector6 = Eigen::Matrix<double, 6, 1>;
        using Matrix6 = Eigen::Matrix<double, 6, 6>;
        constexpr double PI = 3.14159265358979323846;
        // An attempt gives up (a restart does better) after STALL_STEPS accepted steps in a row that each keep more
        // than STALL_RATIO of the squared error, or when rejected steps raise the damping factor past MAX_FACTOR.
        // Chosen on bench-ik (Panda and ropras_arm, 1000 targets, seed 2): 4 / 1e4 solve 98.8 % / 99.1 % where
        // 8 / 1e8 solved 98.6 % / 98.7 %, with 12-18 % fewer steps per target.
        constexpr int STALL_STEPS = 4;
        constexpr double STALL_RATIO = 0.95;
        constexpr double MAX_FACTOR = 1e4;

        double nowSeconds() noexcept
        {
            timespec t{};
            clock_gettime(CLOCK_MONOTONIC, &t);
            return static_cast<double>(t.tv_sec) + 1e-9 * static_cast<double>(t.tv_nsec);
        }

        /// the task-space error (position, then a rotation vector) of a tip pose, and its two magnitudes
        void residual(const IkTarget &target, const Eigen::Isometry3d &tip, Vector6 &e, double &position,
                      double &orientation) noexcept
        {
            e.head<3>() = target.position() - tip.translation();
            position = e.head<3>().norm();
            switch (target.kind())
            {
                case IkTargetKind::Position:
                    e.tail<3>().setZero();
                    orientation = 0.0;
                    break;
                case IkTargetKind::PositionAxis:
                {
                    const Eigen::Vector3d a = tip.linear() * target.toolAxis();
                    e.tail<3>() = a.cross(target.approach());
                    orientation = std::atan2(e.tail<3>().norm(), a.dot(target.approach()));
                    break;
                }
                case IkTargetKind::Pose:
                {
                    Eigen::Quaterniond d = target.orientation() * Eigen::Quaterniond(tip.linear()).conjugate();
                    if (d.w() < 0.0)
                        d.coeffs() = -d.coeffs();
                    const double s = d.vec().norm();
                    orientation = 2.0 * std::atan2(s, d.w());
                    e.tail<3>() =
                        s > 1e-12 ? Eigen::Vector3d(d.vec() * (orientation / s)) : Eigen::Vector3d(2.0 * d.vec());
                    break;
                }
            }
        }

        bool converged(double position, double orientation, const IkOptions &o) noexcept
        {
            return position <= o.positionTolerance && orientation <= o.orientationTolerance;
        }

        void swapWorkspaces(ChainWorkspace &a, ChainWorkspace &b) noexcept
        {
            a.jointRotation.swap(b.jointRotation);
            a.jointTranslation.swap(b.jointTranslation);
            std::swap(a.tip, b.tip);
            a.jacobianData.swap(b.jacobianData);
        }

        /// a chain joint's value moved into its limits (continuous joints wrap into [-pi, pi])
        double intoLimits(const ChainJoint &j, double v) noexcept
        {
            if (j.continuous)
                return std::remainder(v, 2.0 * PI);
            return std::clamp(v, j.lower, j.upper);
        }
    }  // namespace

    void IkOptions::validate() const
    {
        auto check = [](double v, const char *name, bool allowZero)
        {
            if (!std::isfinite(v) || v < 0.0 || (!allowZero && v == 0.0))
                throw Error(std::string("IK options: ") + name + " " + std::to_string(v) + " must be a finite number " +
                            (allowZero ? ">= 0" : "> 0"));
        };
        check(positionTolerance, "positionTolerance", false);
        check(orientationTolerance, "orientationTolerance", false);
        check(timeLimit, "timeLimit", true);
        check(maxStep, "maxStep", false);
        check(damping, "damping", false);
        if (maxIterations == 0)
            throw Error("IK options: maxIterations must be >= 1");
        if (restarts > 100000000)
            throw Error("IK options: restarts " + std::to_string(restarts) + " is absurd (at most 1e8)");
    }

    const char *ikStatusName(IkStatus status) noexcept
    {
        switch (status)
        {
            case IkStatus::Solved:
                return "solved";
            case IkStatus::NotConverged:
                return "not converged";
            case IkStatus::NoValidSolution:
                return "no valid solution";
            case IkStatus::TimedOut:
                return "timed out";
        }
        return "?";
    }

    IkWorkspace::IkWorkspace(const KinematicChain &chain)
        : current(chain.size()),
          trial(chain.size()),
          q(chain.robot().dof()),
          qTrial(chain.robot().dof()),
          qBest(chain.robot().dof()),
          jacobian(6 * chain.size()),
          step(chain.size())
    {
    }

    InverseKinematics::InverseKinematics(KinematicChain chain) : chain_(std::move(chain)) {}

    InverseKinematics::InverseKinematics(std::shared_ptr<const RobotModel> robot, const std::string &tipLink)
        : chain_(std::move(robot), tipLink)
    {
    }

    void InverseKinematics::errors(const IkTarget &target, const double *q, double &position,
                                   double &orientation) const noexcept
    {
        Vector6 e;
        residual(target, chain_.tipPose(q), e, position, orientation);
    }

    // One damped least-squares descent from ws.q. The damping is factor * |e|^2 + options.damping (Sugihara's
    // Levenberg-Marquardt); a step that does not lower |e|^2 is rejected and the factor raised; an accepted one
    // lowers it. Gives up when the factor explodes, when progress stalls, or at maxIterations.
    bool InverseKinematics::attempt(const IkTarget &target, IkWorkspace &ws, const IkOptions &options, double deadline,
                                    IkResult &result, double &cost) const noexcept
    {
        const auto &joints = chain_.joints();
        const auto n = static_cast<Eigen::Index>(joints.size());
        Vector6 e, eTrial;
        double position = 0.0, orientation = 0.0;
        chain_.jacobian(ws.q.data(), ws.current);
        residual(target, ws.current.tip, e, position, orientation);
        cost = e.squaredNorm();
        if (converged(position, orientation, options))
            return true;
        if (n == 0)
            return false;  // nothing moves
        double factor = 1.0;
        int slow = 0;
        Eigen::Map<Eigen::Matrix<double, 6, Eigen::Dynamic>> j(ws.jacobian.data(), 6, n);
        Eigen::Map<Eigen::VectorXd> dq(ws.step.data(), n);
        for (std::size_t it = 0; it < options.maxIterations; ++it)
        {
            if (deadline > 0.0 && it % 4 == 0 && nowSeconds() > deadline)  // every 4 steps: a few us
                return false;
            const double mu = factor * cost + options.damping;
            if (target.kind() == IkTargetKind::Position)
            {
                // three rows: the 3x3 system of the position alone
                const auto jv = ws.current.jacobian().topRows<3>();
                Eigen::Matrix3d a = jv * jv.transpose();
                a.diagonal().array() += mu;
                const Eigen::Vector3d y = a.llt().solve(e.head<3>());
                dq.noalias() = jv.transpose() * y;
            }
            else
            {
                j = ws.current.jacobian();
                if (target.kind() == IkTargetKind::PositionAxis)
                {
                    // only the axis's direction matters: drop the angular velocity about the current tool axis
                    const Eigen::Vector3d a = ws.current.tip.linear() * target.toolAxis();
                    j.bottomRows<3>() = (Eigen::Matrix3d::Identity() - a * a.transpose()) * j.bottomRows<3>();
                }
                Matrix6 a = j * j.transpose();
                a.diagonal().array() += mu;
                const Vector6 y = a.llt().solve(e);
                dq.noalias() = j.transpose() * y;
            }
            const double biggest = dq.cwiseAbs().maxCoeff();
            if (biggest > options.maxStep)
                dq *= options.maxStep / biggest;
            ws.qTrial = ws.q;
            for (Eigen::Index i = 0; i < n; ++i)
            {
                const ChainJoint &cj = joints[static_cast<std::size_t>(i)];
                const auto v = static_cast<std::size_t>(cj.variable);
                ws.qTrial[v] = intoLimits(cj, ws.q[v] + dq[i]);
            }
            chain_.jacobian(ws.qTrial.data(), ws.trial);
            double pTrial = 0.0, oTrial = 0.0;
            residual(target, ws.trial.tip, eTrial, pTrial, oTrial);
            const double costTrial = eTrial.squaredNorm();
            ++result.iterations;
            if (costTrial < cost)
            {
                slow = costTrial > STALL_RATIO * cost ? slow + 1 : 0;
                swapWorkspaces(ws.current, ws.trial);
                ws.q.swap(ws.qTrial);
                e = eTrial;
                cost = costTrial;
                factor = std::max(factor * 0.25, 1e-6);
                if (converged(pTrial, oTrial, options))
                    return true;
                if (slow >= STALL_STEPS)
                    return false;  // crawling along a joint limit or a singularity: a restart does better
            }
            else
            {
                factor *= 8.0;
                if (factor > MAX_FACTOR)
                    return false;
            }
        }
        return false;
    }

    IkResult InverseKinematics::solve(const IkTarget &target, const double *seed, core::Rng &rng, IkWorkspace &ws,
                                      double *q, const IkOptions &options,
                                      const ConfigurationPredicate *valid) const noexcept
    {
        const std::size_t dof = chain_.robot().dof();
        const auto &joints = chain_.joints();
        const double deadline =
            options.timeLimit > 0.0 && options.timeLimit < 1e9 ? nowSeconds() + options.timeLimit : 0.0;
        std::copy(seed, seed + dof, ws.q.begin());
        for (const ChainJoint &j : joints)
        {
            double &v = ws.q[static_cast<std::size_t>(j.variable)];
            v = std::isfinite(v) ? intoLimits(j, v) : 0.5 * (j.lower + j.upper);
        }
        IkResult result;
        double bestCost = std::numeric_limits<double>::infinity();
        bool reached = false, timedOut = false;
        for (std::size_t k = 0; k <= options.restarts; ++k)
        {
            if (k > 0)
            {
                if (deadline > 0.0 && nowSeconds() > deadline)
                {
                    timedOut = true;
                    break;
                }
                for (const ChainJoint &j : joints)
                    ws.q[static_cast<std::size_t>(j.variable)] = rng.uniform(j.lower, j.upper);
            }
            ++result.attempts;
            double cost = 0.0;
            const bool ok = attempt(target, ws, options, deadline, result, cost);
            if (ok && (valid == nullptr || !*valid || (*valid)(ws.q.data())))
            {
                std::copy(ws.q.begin(), ws.q.end(), q);
                result.status = IkStatus::Solved;
                errors(target, q, result.positionError, result.orientationError);
                return result;
            }
            reached = reached || ok;
            if (cost < bestCost)
            {
                bestCost = cost;
                ws.qBest = ws.q;
            }
        }
        timedOut = timedOut || (deadline > 0.0 && nowSeconds() > deadline);
        result.status = reached ? IkStatus::NoValidSolution : timedOut ? IkStatus::TimedOut : IkStatus::NotConverged;
        std::copy(ws.qBest.begin(), ws.qBest.end(), q);
        errors(target, q, result.positionError, result.orientationError);
        return result;
    }

    IkResult InverseKinematics::solve(const IkTarget &target, const std::vector<double> &seed, core::Rng &rng,
                                      std::vector<double> &q, const IkOptions &options,
                                      const ConfigurationPredicate &valid) const
    {
        options.validate();
        const std::size_t dof = chain_.robot().dof();
        if (seed.size() != dof)
            throw Error("IK seed has " + std::to_string(seed.size()) + " values; robot '" + chain_.robot().name() +
                        "' has " + std::to_string(dof) + " planning joints");
        for (std::size_t i = 0; i < dof; ++i)
            if (!std::isfinite(seed[i]))
                throw Error("IK seed value " + std::to_string(seed[i]) + " of joint '" +
                            chain_.robot().joints()[i].name + "' is not finite");
        IkWorkspace ws(chain_);
        q.resize(dof);
        return solve(target, seed.data(), rng, ws, q.data(), options, valid ? &valid : nullptr);
    }
}  // namespace ropras::ompl_ext
