#ifndef ROPRAS_POMDP_SEARCH_TREE_H
#define ROPRAS_POMDP_SEARCH_TREE_H

#include <cstdint>
#include <limits>
#include <vector>

#include "ropras/pomdp/MacroAction.h"
#include "ropras/pomdp/SearchStatistics.h"
#include "ropras/pomdp/Solver.h"

namespace ropras::pomdp::detail
{
    /** \brief Pieces shared by the tree-search solvers (ROP-RAS3, POMCP, R-POMCP). */

    /// the macro-action of an action node (fields macroOffset, macroLength) kept in the solver's flat pool
    template <class Action, class ActionNode>
    inline MacroView<Action> macroOf(const std::vector<Action> &pool, const ActionNode &node) noexcept
    {
        return MacroView<Action>{pool.data() + node.macroOffset, node.macroLength};
    }

    /// the result of a planning call: \a statistics and, when \a best is non-null, its macro-action (valid)
    template <class Action, class ActionNode>
    inline PlanResult<Action> planResultOf(const SearchStatistics &statistics, const std::vector<Action> &pool,
                                           const ActionNode *best)
    {
        PlanResult<Action> result;
        result.statistics = statistics;
        if (best)
        {
            const auto macro = macroOf(pool, *best);
            result.action.assign(macro.begin(), macro.end());
            result.valid = true;
        }
        return result;
    }

    /// executeMacro, counting model steps and, when \a profile, the time spent in the model
    template <class M>
    inline MacroStepResult<typename M::State, typename M::Observation> executeMacroCounted(
        const M &model, const typename M::State &s, MacroView<typename M::Action> macro, Rng &rng, bool profile,
        SearchStatistics &stats) noexcept
    {
        MacroStepResult<typename M::State, typename M::Observation> step;
        if (profile)
        {
            const auto start = Clock::now();
            step = executeMacro(model, s, macro, rng);
            stats.modelSeconds += secondsSince(start);
        }
        else
        {
            step = executeMacro(model, s, macro, rng);
        }
        stats.modelSteps += step.steps;
        return step;
    }

    /** \brief The observation child of an action node with \a key: searched in the sibling list that starts at
        \a firstChild, created (and linked in front) when absent. \a beliefs is the solver's node pool; its nodes
        have `key` and `nextSibling`. */
    template <class BeliefNodes>
    inline std::uint32_t observationChild(BeliefNodes &beliefs, std::uint32_t &firstChild, std::uint64_t key)
    {
        constexpr std::uint32_t NONE = std::numeric_limits<std::uint32_t>::max();
        for (std::uint32_t c = firstChild; c != NONE; c = beliefs[c].nextSibling)
            if (beliefs[c].key == key)
                return c;
        beliefs.emplace_back();
        beliefs.back().key = key;
        beliefs.back().nextSibling = firstChild;
        firstChild = static_cast<std::uint32_t>(beliefs.size() - 1);
        return firstChild;
    }
}  // namespace ropras::pomdp::detail

#endif
