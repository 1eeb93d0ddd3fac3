#include "ropras/ompl_ext/motion/JointSteps.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <sstream>

#include "ropras/core/Error.h"

namespace ropras::ompl_ext
{
    namespace
    {
        double segmentLength(const double *a, const double *b, std::size_t dof, StepNorm norm)
        {
            double length = 0.0;
            for (std::size_t k = 0; k < dof; ++k)
            {
                const double v = b[k] - a[k];
                length = norm == StepNorm::L2 ? length + v * v : std::max(length, std::abs(v));
            }
            return norm == StepNorm::L2 ? std::sqrt(length) : length;
        }

        void checkPath(const double *waypoints, std::size_t count, std::size_t dof, const JointStepOptions &options)
        {
            if (!(options.step > 0.0) || !std::isfinite(options.step))
                throw Error("discretizeJointPath: the step must be positive and finite, got " +
                            std::to_string(options.step));
            if (dof == 0)
                throw Error("discretizeJointPath: dof must be at least 1");
            if (count < 2 || waypoints == nullptr)
                throw Error("discretizeJointPath: a path needs at least two waypoints, got " + std::to_string(count));
            for (std::size_t i = 0; i < count * dof; ++i)
                if (!std::isfinite(waypoints[i]))
                {
                    std::ostringstream msg;
                    msg << "discretizeJointPath: waypoint " << i / dof << " joint " << i % dof << " is not finite ("
                        << waypoints[i] << ")";
                    throw Error(msg.str());
                }
        }
    }  // namespace

    std::size_t discretizeJointPath(const double *waypoints, std::size_t count, std::size_t dof,
                                    const JointStepOptions &options, std::vector<double> &points)
    {
        checkPath(waypoints, count, dof, options);
        const double step = options.step;
        std::size_t added = 0;
        for (std::size_t s = 0; s + 1 < count; ++s)
        {
            const double *a = waypoints + s * dof;
            const double *b = a + dof;
            const double length = segmentLength(a, b, dof, options.norm);
            if (length == 0.0)
                continue;
            const std::size_t pieces = segmentPieces(length, step);
            for (std::size_t i = 1; i <= pieces; ++i)
            {
                if (options.maxSteps != 0 && added >= options.maxSteps)
                    return added;
                const double u = options.split == StepSplit::Equal
                                     ? static_cast<double>(i) / static_cast<double>(pieces)
                                     : static_cast<double>(i) * step / length;
                for (std::size_t k = 0; k < dof; ++k)
                    points.push_back(i == pieces ? b[k] : a[k] + u * (b[k] - a[k]));
                ++added;
            }
        }
        return added;
    }

    std::size_t discretizeJointPath(const double *waypoints, std::size_t count, std::size_t dof, double step,
                                    std::size_t maxPoints, std::vector<double> &points)
    {
        JointStepOptions options;
        options.step = step;
        options.norm = StepNorm::L2;
        options.split = StepSplit::Equal;
        options.maxSteps = maxPoints;
        return discretizeJointPath(waypoints, count, dof, options, points);
    }

    std::size_t jointSteps(const double *waypoints, std::size_t count, std::size_t dof, const JointStepOptions &options,
                           std::vector<double> &steps)
    {
        const std::size_t before = steps.size();
        const std::size_t n = discretizeJointPath(waypoints, count, dof, options, steps);
        // points -> increments, from the last (each needs the point before it, the first needs waypoint 0)
        for (std::size_t i = n; i-- > 0;)
        {
            double *row = steps.data() + before + i * dof;
            const double *previous = i == 0 ? waypoints : row - dof;
            for (std::size_t k = 0; k < dof; ++k)
                row[k] -= previous[k];
        }
        return n;
    }

    JointStepExecutor::JointStepExecutor(std::shared_ptr<const CollisionChecker> checker, double resolution,
                                         std::vector<double> noiseStddev)
        : checker_(std::move(checker)), dof_(0), resolution_(resolution), noise_(std::move(noiseStddev))
    {
        if (!checker_)
            throw Error("JointStepExecutor: null CollisionChecker");
        dof_ = checker_->robot().dof();
        if (!(resolution_ > 0.0) || !std::isfinite(resolution_))
            throw Error("JointStepExecutor: the resolution must be positive and finite, got " +
                        std::to_string(resolution_));
        if (!noise_.empty() && noise_.size() != dof_)
            throw Error("JointStepExecutor: " + std::to_string(noise_.size()) + " noise deviations for a robot of " +
                        std::to_string(dof_) + " joints");
        for (std::size_t j = 0; j < noise_.size(); ++j)
            if (!std::isfinite(noise_[j]) || noise_[j] < 0.0)
                throw Error("JointStepExecutor: the noise deviation of joint " + std::to_string(j) +
                            " must be finite and >= 0, got " + std::to_string(noise_[j]));
    }

    StepOutcome JointStepExecutor::execute(const Environment &env, const double *q, const double *dq, core::Rng &rng,
                                           double *out) const
    {
        const auto &joints = checker_->robot().joints();
        for (std::size_t j = 0; j < dof_; ++j)
        {
            if (!std::isfinite(q[j]) || !std::isfinite(dq[j]))
                throw Error("JointStepExecutor::execute: joint " + joints[j].name + ": non-finite q " +
                            std::to_string(q[j]) + " or dq " + std::to_string(dq[j]));
            if (joints[j].type != JointType::Continuous && (q[j] < joints[j].lower || q[j] > joints[j].upper))
                throw Error("JointStepExecutor::execute: joint " + joints[j].name + " at " + std::to_string(q[j]) +
                            " is outside its limits [" + std::to_string(joints[j].lower) + ", " +
                            std::to_string(joints[j].upper) + "]");
        }
        std::array<double, 64> small{};
        std::vector<double> large;
        double *target = small.data();
        if (dof_ > small.size())
        {
            large.resize(dof_);
            target = large.data();
        }
        double largest = 0.0;
        for (std::size_t j = 0; j < dof_; ++j)
        {
            double v = q[j] + dq[j] + (noise_.empty() ? 0.0 : noise_[j] * rng.normal());
            if (joints[j].type != JointType::Continuous)
                v = std::clamp(v, joints[j].lower, joints[j].upper);
            target[j] = v;
            largest = std::max(largest, std::abs(v - q[j]));
        }
        if (largest / resolution_ > 1e8)  // isMotionValid refuses such motions: say so instead of "blocked"
            throw Error("JointStepExecutor::execute: a joint change of " + std::to_string(largest) +
                        " is more than 1e8 resolutions (" + std::to_string(resolution_) + ")");
        StepOutcome outcome;
        double fraction = 0.0;
        if (checker_->isMotionValid(env, q, target, resolution_, &fraction))
        {
            std::copy(target, target + dof_, out);
            return outcome;
        }
        outcome.blocked = true;
        outcome.fraction = fraction;
        for (std::size_t j = 0; j < dof_; ++j)
            out[j] = q[j] + fraction * (target[j] - q[j]);
        return outcome;
    }
}  // namespace ropras::ompl_ext
