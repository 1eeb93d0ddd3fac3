#ifndef ROPRAS_BIN_SEQUENTIAL_MOTION_VALIDATOR_H
#define ROPRAS_BIN_SEQUENTIAL_MOTION_VALIDATOR_H

#include <ompl/base/MotionValidator.h>
#include <ompl/base/SpaceInformation.h>
#include <ompl/base/spaces/RealVectorStateSpace.h>
#include <algorithm>
#include <cmath>
#include <utility>

namespace ropras::bin
{
    namespace ob = ompl::base;

    /** Motion validator over any state validity function that checks exactly the configurations the ropras
        MotionValidator checks (max-joint step, samples i/n), s2 first then in order: the fair baseline. */
    class SequentialMotionValidator : public ob::MotionValidator
    {
    public:
        SequentialMotionValidator(const ob::SpaceInformationPtr &si, double resolution)
            : ob::MotionValidator(si), resolution_(resolution), dof_(si->getStateDimension())
        {
        }
        bool checkMotion(const ob::State *s1, const ob::State *s2) const override
        {
            std::pair<ob::State *, double> unused{nullptr, 0.0};
            return checkMotion(s1, s2, unused);
        }
        bool checkMotion(const ob::State *s1, const ob::State *s2, std::pair<ob::State *, double> &last) const override
        {
            const double *a = s1->as<ob::RealVectorStateSpace::StateType>()->values;
            const double *b = s2->as<ob::RealVectorStateSpace::StateType>()->values;
            double linf = 0.0;
            for (unsigned k = 0; k < dof_; ++k)
                linf = std::max(linf, std::abs(b[k] - a[k]));
            const int n = std::max(1, static_cast<int>(std::ceil(linf / resolution_)));
            int firstBad = 0;
            if (!si_->isValid(s2))
                firstBad = n;
            ob::State *s = si_->allocState();
            for (int i = 1; i < n && (firstBad == 0 || i < firstBad); ++i)
            {
                si_->getStateSpace()->interpolate(s1, s2, static_cast<double>(i) / n, s);
                if (!si_->isValid(s))
                {
                    firstBad = i;
                    break;
                }
            }
            si_->freeState(s);
            if (firstBad == 0)
            {
                ++valid_;
                return true;
            }
            ++invalid_;
            last.second = static_cast<double>(firstBad - 1) / n;
            if (last.first != nullptr)
                si_->getStateSpace()->interpolate(s1, s2, last.second, last.first);
            return false;
        }

    private:
        double resolution_;
        unsigned dof_;
    };
}  // namespace ropras::bin

#endif
