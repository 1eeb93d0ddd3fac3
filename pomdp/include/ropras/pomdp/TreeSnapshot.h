#ifndef ROPRAS_POMDP_TREE_SNAPSHOT_H
#define ROPRAS_POMDP_TREE_SNAPSHOT_H

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <limits>
#include <string>
#include <type_traits>
#include <vector>

#include "ropras/pomdp/MacroAction.h"

namespace ropras::pomdp
{
    /** \brief A copy of a search tree after a planning call, for inspection (`ropras run --dump-tree`) and
        the tree statistics of doc/pomdp.md. Nodes are in breadth-first order from the root (belief 0);
        indices refer to the two vectors. */
    struct TreeSnapshot
    {
        static constexpr std::uint32_t NONE = std::numeric_limits<std::uint32_t>::max();

        struct Belief
        {
            /// the action node this belief hangs under (NONE for the root)
            std::uint32_t parent{NONE};
            /// macro levels below the root
            std::uint32_t depth{0};
            /// primitive steps from the root (sum of the macro lengths on the path)
            std::uint32_t steps{0};
            /// the macro observation key of the branch (0 at the root)
            std::uint64_t key{0};
            std::uint32_t visits{0};
            /// V (soft value for ROP-RAS3, max Q for UCB solvers)
            double value{0.0};
            std::uint32_t particles{0};
            /// the action children (indices into actions)
            std::vector<std::uint32_t> children;
        };

        struct Action
        {
            std::uint32_t parent{0};
            std::uint32_t visits{0};
            double q{0.0};
            /// pi*(a|b) ~ exp(eta Q) over the visited siblings (ROP-RAS3); visit share for UCB solvers
            double piStar{0.0};
            std::uint32_t length{0};
            /// the macro-action in brief: its length and first primitive actions
            std::string brief;
            /// the observation children (indices into beliefs)
            std::vector<std::uint32_t> children;
        };

        std::string solver;
        std::size_t simulations{0};
        std::size_t referenceRequested{0};
        std::vector<Belief> beliefs;
        std::vector<Action> actions;
    };

    /** \brief The macro-action \a macro in brief: "len N: a0 a1 ..." (at most 12 primitive actions shown when
        they are numbers, else only the length). */
    template <class Action>
    std::string macroBrief(MacroView<Action> macro)
    {
        std::string out = "len " + std::to_string(macro.length);
        if constexpr (std::is_arithmetic_v<Action>)
        {
            out += ":";
            const std::size_t shown = std::min<std::size_t>(macro.length, 12);
            for (std::size_t i = 0; i < shown; ++i)
            {
                out += " " + std::to_string(static_cast<long long>(macro.data[i]));
            }
            if (shown < macro.length)
            {
                out += " ...";
            }
        }
        return out;
    }

    /** \brief Fills pi* of the actions of every belief of \a tree: exp(eta Q) normalised over its visited children
        (unvisited ones get 0). */
    inline void fillSoftPolicy(TreeSnapshot &tree, double eta)
    {
        for (const auto &b : tree.beliefs)
        {
            double top = -std::numeric_limits<double>::infinity();
            for (const auto a : b.children)
                if (tree.actions[a].visits > 0)
                    top = std::max(top, eta * tree.actions[a].q);
            double total = 0.0;
            for (const auto a : b.children)
                if (tree.actions[a].visits > 0)
                    total += std::exp(eta * tree.actions[a].q - top);
            for (const auto a : b.children)
            {
                auto &action = tree.actions[a];
                action.piStar = action.visits > 0 ? std::exp(eta * action.q - top) / total : 0.0;
            }
        }
    }

    /** \brief Summary statistics of a tree, per macro level (depth d = 0 is the root). */
    struct TreeLevelStatistics
    {
        std::size_t beliefs{0};
        /// belief nodes visited at most once (a node that only received the particle of its creation has 0)
        std::size_t visitedOnce{0};
        std::size_t actions{0};
        /// observation children of the actions of this level
        std::size_t observationChildren{0};
        std::size_t particles{0};
        std::size_t maxParticles{0};
        std::size_t minSteps{0};
        std::size_t maxSteps{0};
    };

    /** \brief Per-level statistics of \a tree (index = macro level). */
    inline std::vector<TreeLevelStatistics> treeLevelStatistics(const TreeSnapshot &tree)
    {
        std::vector<TreeLevelStatistics> levels;
        for (const auto &b : tree.beliefs)
        {
            if (levels.size() <= b.depth)
            {
                levels.resize(b.depth + 1);
                levels[b.depth].minSteps = std::numeric_limits<std::size_t>::max();
            }
            auto &l = levels[b.depth];
            ++l.beliefs;
            l.visitedOnce += b.visits <= 1 ? 1 : 0;
            l.actions += b.children.size();
            for (const auto a : b.children)
                l.observationChildren += tree.actions[a].children.size();
            l.particles += b.particles;
            l.maxParticles = std::max<std::size_t>(l.maxParticles, b.particles);
            l.minSteps = std::min<std::size_t>(l.minSteps, b.steps);
            l.maxSteps = std::max<std::size_t>(l.maxSteps, b.steps);
        }
        return levels;
    }
}  // namespace ropras::pomdp

#endif
