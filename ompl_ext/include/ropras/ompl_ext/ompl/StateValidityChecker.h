#ifndef ROPRAS_OMPL_EXT_STATE_VALIDITY_CHECKER_H
#define ROPRAS_OMPL_EXT_STATE_VALIDITY_CHECKER_H

#include <ompl/base/StateValidityChecker.h>
#include <memory>

#include "ropras/ompl_ext/collision/CollisionChecker.h"
#include "ropras/ompl_ext/scene/Environment.h"

namespace ropras::ompl_ext
{
    /** \brief OMPL state validity checker backed by the vectorized CollisionChecker.

        The space must be a RealVectorStateSpace whose dimensions are the robot's planning joints (see
        createStateSpace()). isValid() reads the state's values in place (no copy, no allocation) and is
        safe to call from several threads at once.

        The environment is held by shared ownership: setEnvironment() swaps it in O(1) (a shared_ptr
        assignment). Swap between queries, not while a planner is running on another thread. */
    class StateValidityChecker : public ompl::base::StateValidityChecker
    {
    public:
        StateValidityChecker(const ompl::base::SpaceInformationPtr &si, std::shared_ptr<const CollisionChecker> checker,
                             std::shared_ptr<const Environment> environment);

        bool isValid(const ompl::base::State *state) const override;
        /// checks \a count states; writes one verdict each and returns how many are valid
        std::size_t isValidBatch(const ompl::base::State *const *states, std::size_t count, bool *valid) const;

        void setEnvironment(std::shared_ptr<const Environment> environment);
        const std::shared_ptr<const Environment> &environment() const { return environment_; }
        const std::shared_ptr<const CollisionChecker> &checker() const { return checker_; }

    private:
        std::shared_ptr<const CollisionChecker> checker_;
        std::shared_ptr<const Environment> environment_;
        unsigned int dof_;
    };
}  // namespace ropras::ompl_ext

#endif
