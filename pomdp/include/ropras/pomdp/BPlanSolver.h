#ifndef ROPRAS_POMDP_B_PLAN_SOLVER_H
#define ROPRAS_POMDP_B_PLAN_SOLVER_H

#include <memory>
#include <string>
#include <vector>

#include "ropras/core/Error.h"
#include "ropras/pomdp/Model.h"
#include "ropras/pomdp/ReferencePolicy.h"
#include "ropras/pomdp/Solver.h"

namespace ropras::pomdp
{
    /** \brief B-plan (the paper's B-VAMP baseline): no tree search. Samples a state from the tracked belief
        and executes the reference policy's macro-action from it. Up to \c attempts reference calls per
        plan(); when all fail, the result is the model's rollout action from the sampled state (valid, and
        the failures are counted). The budget is only validated (B-plan does one reference call). */
    template <class M>
    class BPlanSolver final : public Solver<M>
    {
    public:
        using State = typename M::State;
        using Action = typename M::Action;

        BPlanSolver(std::shared_ptr<const M> model, std::unique_ptr<ReferencePolicy<M>> reference, unsigned attempts)
            : model_(std::move(model)), reference_(std::move(reference)), attempts_(attempts)
        {
            if (!model_ || !reference_)
            {
                throw Error("BPlanSolver: missing model or reference policy");
            }
            if (attempts_ == 0)
            {
                throw Error("BPlanSolver: attempts must be >= 1");
            }
        }

        std::string name() const override { return "bplan"; }

        PlanResult<Action> plan(BeliefView<State> belief, const Budget &budget, Rng &rng) override
        {
            if (belief.empty())
            {
                throw Error("bplan: plan() called with an empty belief");
            }
            detail::BudgetGuard guard(budget);
            PlanResult<Action> result;
            const State &start = belief[rng.uniformIndex(belief.size)];
            for (unsigned i = 0; i < attempts_; ++i)
            {
                result.action.clear();
                ++result.statistics.referenceRequested;
                if (reference_->sample(start, belief, rng, result.action) && !result.action.empty())
                {
                    result.valid = true;
                    break;
                }
                ++result.statistics.referenceFailed;
            }
            if (!result.valid)
            {
                result.action.assign(1, rolloutActionOf(*model_, start, rng));
                result.valid = true;
            }
            result.statistics.seconds = guard.elapsed();
            result.statistics.referenceSeconds = result.statistics.seconds;
            return result;
        }

    private:
        std::shared_ptr<const M> model_;
        std::unique_ptr<ReferencePolicy<M>> reference_;
        unsigned attempts_;
    };
}  // namespace ropras::pomdp

#endif
