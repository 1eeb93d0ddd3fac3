#include "ropras/ompl_ext/ompl/MotionValidator.h"

#include <ompl/base/SpaceInformation.h>
#include <ompl/base/spaces/RealVectorStateSpace.h>
#include <cmath>

#include "ropras/core/Error.h"

namespace ropras::ompl_ext
{
    namespace
    {
        const double *values(const ompl::base::State *state)
        {
            return state->as<ompl::base::RealVectorStateSpace::StateType>()->values;
        }
    }  // namespace

    MotionValidator::MotionValidator(const ompl::base::SpaceInformationPtr &si,
                                     std::shared_ptr<const CollisionChecker> checker,
                                     std::shared_ptr<const Environment> environment, double resolution)
        : ompl::base::MotionValidator(si), checker_(std::move(checker)), environment_(std::move(environment))
    {
        if (!checker_)
            throw Error("MotionValidator: null CollisionChecker");
        if (!environment_)
            throw Error("MotionValidator: null Environment");
        auto *space = dynamic_cast<const ompl::base::RealVectorStateSpace *>(si->getStateSpace().get());
        if (space == nullptr || space->getDimension() != checker_->robot().dof())
            throw Error(
                "MotionValidator: the state space must be a RealVectorStateSpace with one dimension per "
                "planning joint of robot '" +
                checker_->robot().name() + "' (" + std::to_string(checker_->robot().dof()) + ")");
        setResolution(resolution);
    }

    void MotionValidator::setResolution(double resolution)
    {
        if (!std::isfinite(resolution) || resolution <= 0.0)
            throw Error("MotionValidator: resolution must be finite and > 0 (got " + std::to_string(resolution) + ")");
        resolution_ = resolution;
    }

    void MotionValidator::setEnvironment(std::shared_ptr<const Environment> environment)
    {
        if (!environment)
            throw Error("MotionValidator::setEnvironment: null Environment");
        environment_ = std::move(environment);
    }

    void MotionValidator::count(bool valid) const
    {
        // OMPL's counters are plain mutable unsigned ints; increment them atomically so concurrent
        // checkMotion calls from several threads keep exact counts.
        __atomic_fetch_add(valid ? &valid_ : &invalid_, 1u, __ATOMIC_RELAXED);
    }

    bool MotionValidator::checkMotion(const ompl::base::State *s1, const ompl::base::State *s2) const
    {
        const bool ok = checker_->isMotionValid(*environment_, values(s1), values(s2), resolution_);
        count(ok);
        return ok;
    }

    bool MotionValidator::checkMotion(const ompl::base::State *s1, const ompl::base::State *s2,
                                      std::pair<ompl::base::State *, double> &lastValid) const
    {
        double t = 0.0;
        const bool ok = checker_->isMotionValid(*environment_, values(s1), values(s2), resolution_, &t);
        count(ok);
        if (!ok)
        {
            lastValid.second = t;
            if (lastValid.first != nullptr)
                si_->getStateSpace()->interpolate(s1, s2, t, lastValid.first);
        }
        return ok;
    }
}  // namespace ropras::ompl_ext
