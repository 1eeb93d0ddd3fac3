#include "ropras/ompl_ext/ompl/StateValidityChecker.h"

#include <ompl/base/SpaceInformation.h>
#include <ompl/base/spaces/RealVectorStateSpace.h>

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

    StateValidityChecker::StateValidityChecker(const ompl::base::SpaceInformationPtr &si,
                                               std::shared_ptr<const CollisionChecker> checker,
                                               std::shared_ptr<const Environment> environment)
        : ompl::base::StateValidityChecker(si), checker_(std::move(checker)), environment_(std::move(environment))
    {
        if (!checker_)
            throw Error("StateValidityChecker: null CollisionChecker");
        if (!environment_)
            throw Error("StateValidityChecker: null Environment");
        auto *space = dynamic_cast<const ompl::base::RealVectorStateSpace *>(si->getStateSpace().get());
        if (space == nullptr)
            throw Error("StateValidityChecker: the state space must be a RealVectorStateSpace (got " +
                        si->getStateSpace()->getName() + ")");
        dof_ = space->getDimension();
        if (dof_ != checker_->robot().dof())
            throw Error("StateValidityChecker: the state space has " + std::to_string(dof_) +
                        " dimensions but robot '" + checker_->robot().name() + "' has " +
                        std::to_string(checker_->robot().dof()) + " planning joints");
    }

    bool StateValidityChecker::isValid(const ompl::base::State *state) const
    {
        return checker_->isValid(*environment_, values(state));
    }

    std::size_t StateValidityChecker::isValidBatch(const ompl::base::State *const *states, std::size_t count,
                                                   bool *valid) const
    {
        // Gather into a per-thread row-major buffer (sized once per thread), then one batched check.
        thread_local std::vector<double> rows;
        const std::size_t need = count * dof_;
        if (rows.size() < need)
            rows.resize(need);
        for (std::size_t i = 0; i < count; ++i)
            std::copy(values(states[i]), values(states[i]) + dof_, rows.data() + i * dof_);
        return checker_->isValidBatch(*environment_, rows.data(), count, valid);
    }

    void StateValidityChecker::setEnvironment(std::shared_ptr<const Environment> environment)
    {
        if (!environment)
            throw Error("StateValidityChecker::setEnvironment: null Environment");
        environment_ = std::move(environment);
    }
}  // namespace ropras::ompl_ext
