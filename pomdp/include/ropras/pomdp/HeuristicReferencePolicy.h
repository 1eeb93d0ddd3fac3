#ifndef ROPRAS_POMDP_HEURISTIC_REFERENCE_POLICY_H
#define ROPRAS_POMDP_HEURISTIC_REFERENCE_POLICY_H

#include <functional>
#include <memory>
#include <string>
#include <vector>

#include "ropras/core/Error.h"
#include "ropras/pomdp/ReferencePolicy.h"
#include "ropras/pomdp/SamplingHeuristic.h"

namespace ropras::pomdp
{
    /** \brief SampleMacroActionSBMP as a reference policy: target <- heuristic(b), then
        macro <- connector(start, target).

        The connector is where the motion planner goes: e.g. "plan from the particle's configuration to the
        target with OMPL planner X under a per-plan time limit, then PathToMacroAction". It returns false
        when it finds nothing (a counted failure, never fatal) and must not throw. */
    template <class M, class Target>
    class HeuristicReferencePolicy final : public ReferencePolicy<M>
    {
    public:
        using typename ReferencePolicy<M>::State;
        using typename ReferencePolicy<M>::Action;
        using Connector =
            std::function<bool(const State &start, const Target &target, Rng &rng, std::vector<Action> &out)>;

        HeuristicReferencePolicy(std::unique_ptr<SamplingHeuristic<State, Target>> heuristic, Connector connector,
                                 std::string connectorName)
            : heuristic_(std::move(heuristic)),
              connector_(std::move(connector)),
              connectorName_(std::move(connectorName))
        {
            if (!heuristic_ || !connector_)
            {
                throw Error("HeuristicReferencePolicy: missing heuristic or connector");
            }
        }

        bool sample(const State &start, BeliefView<State> belief, Rng &rng, std::vector<Action> &out) override
        {
            if (!heuristic_->sample(start, belief, rng, target_))
            {
                return false;
            }
            return connector_(start, target_, rng, out) && !out.empty();
        }

        std::string name() const override { return heuristic_->name() + "+" + connectorName_; }

    private:
        std::unique_ptr<SamplingHeuristic<State, Target>> heuristic_;
        Connector connector_;
        std::string connectorName_;
        Target target_{};
    };
}  // namespace ropras::pomdp

#endif
