#ifndef ROPRAS_OMPL_EXT_MOTION_VALIDATOR_H
#define ROPRAS_OMPL_EXT_MOTION_VALIDATOR_H

#include <ompl/base/MotionValidator.h>
#include <memory>

#include "ropras/ompl_ext/collision/CollisionChecker.h"
#include "ropras/ompl_ext/scene/Environment.h"

namespace ropras::ompl_ext
{
    /** \brief OMPL motion validator backed by the vectorized (raked) motion check.

        Contract, as OMPL documents it: \e s1 is assumed valid and \e s2 is checked. On failure,
        checkMotion(s1, s2, lastValid) sets lastValid.second to the time in [0, 1) of the last valid
        configuration on the motion (to within one resolution step) and, when lastValid.first is non-null,
        writes that configuration into it (s1 itself when the first step is already invalid). On success
        lastValid is left untouched. Both overloads update the valid_ / invalid_ counters (atomically, so
        concurrent calls from several threads keep exact counts).

        The resolution is a joint-space step (the largest change of any one joint between two checked
        configurations; default 1/32 rad), not OMPL's 1%-of-extent default. The environment is shared like
        in StateValidityChecker; pass the same pointer to both. */
    class MotionValidator : public ompl::base::MotionValidator
    {
    public:
        static constexpr double DEFAULT_RESOLUTION = 1.0 / 32.0;

        MotionValidator(const ompl::base::SpaceInformationPtr &si, std::shared_ptr<const CollisionChecker> checker,
                        std::shared_ptr<const Environment> environment, double resolution = DEFAULT_RESOLUTION);

        bool checkMotion(const ompl::base::State *s1, const ompl::base::State *s2) const override;
        bool checkMotion(const ompl::base::State *s1, const ompl::base::State *s2,
                         std::pair<ompl::base::State *, double> &lastValid) const override;

        /// joint-space step; throws ropras::Error unless finite and > 0
        void setResolution(double resolution);
        double resolution() const { return resolution_; }

        void setEnvironment(std::shared_ptr<const Environment> environment);
        const std::shared_ptr<const Environment> &environment() const { return environment_; }
        const std::shared_ptr<const CollisionChecker> &checker() const { return checker_; }

    private:
        void count(bool valid) const;
        std::shared_ptr<const CollisionChecker> checker_;
        std::shared_ptr<const Environment> environment_;
        double resolution_;
    };
}  // namespace ropras::ompl_ext

#endif
