#ifndef ROPRAS_POMDP_SEARCH_TREE_H
#define ROPRAS_POMDP_SEARCH_TREE_H

#include <cstdint>
#include <limits>
#include <string>
#include <vector>

#include "ropras/core/Error.h"
#include "ropras/pomdp/MacroAction.h"
#include "ropras/pomdp/ParameterMap.h"
#include "ropras/pomdp/SearchStatistics.h"
#include "ropras/pomdp/Solver.h"
#include "ropras/pomdp/TreeSnapshot.h"

namespace ropras::pomdp::detail
{
    /** \brief Pieces shared by the tree-search solvers (ROP-RAS3, POMCP, R-POMCP). */

    /// default of the tree solvers' memory cap (parameter max_tree_mb): 1024 MiB
    constexpr double DEFAULT_MAX_TREE_MB = 1024.0;
    /// the largest max_tree_mb accepted (1 TiB)
    constexpr double MAX_TREE_MB = 1048576.0;
    /// elements a tree pool may hold: its nodes and particles are addressed by 32-bit indices, which must not wrap
    constexpr std::size_t MAX_POOL_ELEMENTS = std::size_t(1) << 31;

    /// reads the parameter max_tree_mb (in [1, MAX_TREE_MB]) of the solver \a solver
    inline double maxTreeMegabytes(const ParameterMap &p, const std::string &solver)
    {
        const double mb = p.get("max_tree_mb", DEFAULT_MAX_TREE_MB);
        if (!(mb >= 1.0 && mb <= MAX_TREE_MB))
        {
            throw Error(solver + ": max_tree_mb = " + std::to_string(mb) + " must be in [1, " +
                        std::to_string(static_cast<long long>(MAX_TREE_MB)) + "] (MiB)");
        }
        return mb;
    }

    /** \brief The memory cap of a search tree: full when its pools use \a bytes >= \a maxMegabytes MiB (their
        sizes: they keep their capacity from one search to the next) or the largest pool has \a largestPool >=
        MAX_POOL_ELEMENTS elements. Checked before every simulation but the first; as pools grow by doubling, a
        tree never holds more than twice the cap (three times while a pool moves). */
    inline bool treeFull(std::size_t bytes, std::size_t largestPool, double maxMegabytes) noexcept
    {
        return static_cast<double>(bytes) >= maxMegabytes * 1048576.0 || largestPool >= MAX_POOL_ELEMENTS;
    }

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
    /** \brief Starts the snapshot \a out of a tree searched by \a solver: the statistics and the root belief;
        returns the breadth-first queue of solver belief indices, holding the root (0). */
    inline std::vector<std::uint32_t> beginSnapshot(TreeSnapshot &out, const std::string &solver,
                                                    const SearchStatistics &stats)
    {
        out = TreeSnapshot{};
        out.solver = solver;
        out.simulations = stats.simulations;
        out.referenceRequested = stats.referenceRequested;
        out.beliefs.emplace_back();
        return {0};
    }

    /** \brief Appends the solver's action node \a node (pool \a pool) to snapshot \a out under snapshot belief
        \a parent, with its observation children (the sibling list of \a beliefs starting at node.firstChild);
        their solver indices are queued in \a order for the breadth-first walk. Returns the snapshot action. */
    template <class Action, class ActionNode, class BeliefNodes>
    TreeSnapshot::Action &snapshotAction(TreeSnapshot &out, std::uint32_t parent, const ActionNode &node,
                                         const std::vector<Action> &pool, const BeliefNodes &beliefs,
                                         std::vector<std::uint32_t> &order)
    {
        constexpr std::uint32_t NONE = std::numeric_limits<std::uint32_t>::max();
        const auto index = static_cast<std::uint32_t>(out.actions.size());
        out.beliefs[parent].children.push_back(index);
        out.actions.emplace_back();
        TreeSnapshot::Action &action = out.actions.back();
        action.parent = parent;
        action.visits = node.visits;
        action.q = node.q;
        action.length = node.macroLength;
        action.brief = macroBrief(macroOf(pool, node));
        for (std::uint32_t c = node.firstChild; c != NONE; c = beliefs[c].nextSibling)
        {
            action.children.push_back(static_cast<std::uint32_t>(order.size()));
            order.push_back(c);
            TreeSnapshot::Belief child;
            child.parent = index;
            child.depth = out.beliefs[parent].depth + 1;
            child.steps = out.beliefs[parent].steps + action.length;
            out.beliefs.push_back(child);
        }
        return action;
    }
}  // namespace ropras::pomdp::detail

#endif
