#ifndef ROPRAS_POMDP_RANDOM_MACRO_POLICY_H
#define ROPRAS_POMDP_RANDOM_MACRO_POLICY_H

#include <memory>
#include <string>

#include "ropras/core/Error.h"
#include "ropras/pomdp/Model.h"
#include "ropras/pomdp/ReferencePolicy.h"

namespace ropras::pomdp
{
    /** \brief Ref-Basic's reference policy: a macro of uniformly random length in [minLength, maxLength]
        whose primitive actions are drawn uniformly from the model's finite action set. */
    template <class M>
    class RandomMacroPolicy final : public ReferencePolicy<M>
    {
    public:
        using typename ReferencePolicy<M>::State;
        using typename ReferencePolicy<M>::Action;

        /** \brief Throws ropras::Error if minLength is 0, maxLength < minLength or the model has no actions. */
        RandomMacroPolicy(std::shared_ptr<const M> model, unsigned minLength, unsigned maxLength)
            : model_(std::move(model)), minLength_(minLength), maxLength_(maxLength)
        {
            static_assert(hasActionSet<M>, "RandomMacroPolicy needs Model::numActions() and Model::action(i)");
            if (minLength == 0 || maxLength < minLength)
            {
                throw Error("RandomMacroPolicy: macro length range [" + std::to_string(minLength) + ", " +
                            std::to_string(maxLength) + "] is invalid (need 1 <= min <= max)");
            }
            if (!model_ || model_->numActions() == 0)
            {
                throw Error("RandomMacroPolicy: no model or the model has no actions");
            }
        }

        bool sample(const State &, BeliefView<State>, Rng &rng, std::vector<Action> &out) override
        {
            const unsigned length = minLength_ + static_cast<unsigned>(rng.uniformIndex(maxLength_ - minLength_ + 1));
            const std::size_t n = model_->numActions();
            for (unsigned i = 0; i < length; ++i)
            {
                out.push_back(model_->action(static_cast<std::size_t>(rng.uniformIndex(n))));
            }
            return true;
        }

        std::string name() const override { return "random-macro"; }

    private:
        std::shared_ptr<const M> model_;
        unsigned minLength_;
        unsigned maxLength_;
    };
}  // namespace ropras::pomdp

#endif
