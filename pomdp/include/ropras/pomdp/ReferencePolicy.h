#ifndef ROPRAS_POMDP_REFERENCE_POLICY_H
#define ROPRAS_POMDP_REFERENCE_POLICY_H

#include <string>
#include <vector>

#include "ropras/pomdp/BeliefView.h"
#include "ropras/pomdp/Rng.h"

namespace ropras::pomdp
{
    /** \brief A (stochastic) reference policy pibar(. | b) over macro-actions: the source of new actions in
        the reference-based solvers (ROP-RAS3, Ref-Basic, RBSS), of R-POMCP's per-node macro set and of
        B-plan's executed macro.

        The solvers only call sample(); how the macro is produced is the policy's business: uniformly random
        primitive sequences (RandomMacroPolicy), a sampling heuristic plus a connector
        (HeuristicReferencePolicy), or an OMPL planner chosen by name planning from \a start to a target from
        a SamplingHeuristic under a per-plan time limit, converted by the model's PathToMacroAction. Such a
        policy plugs in without changing any solver.

        Contract: sample() appends the macro's primitive actions to \a out (cleared by the caller) and
        returns true, or returns false when no macro could be produced (e.g. the motion planner found no
        path in time): the solver counts the failure and carries on, it is never fatal. sample() must not
        throw. A policy object is used by one solver (one thread) at a time. */
    template <class M>
    class ReferencePolicy
    {
    public:
        using State = typename M::State;
        using Action = typename M::Action;

        virtual ~ReferencePolicy() = default;

        /** \brief Samples a macro-action for the belief \a belief, starting from \a start (a particle of it). */
        virtual bool sample(const State &start, BeliefView<State> belief, Rng &rng, std::vector<Action> &out) = 0;

        /** \brief Short name for logs and statistics. */
        virtual std::string name() const = 0;
    };
}  // namespace ropras::pomdp

#endif
