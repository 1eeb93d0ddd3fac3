#ifndef ROPRAS_POMDP_SEARCH_STATISTICS_H
#define ROPRAS_POMDP_SEARCH_STATISTICS_H

#include <cstddef>
#include <string>

namespace ropras::pomdp
{
    /** \brief Statistics of one planning call (all solvers fill the same fields). Time spent in the model
        and in the reference policy is only measured when the solver's \c profile setting is on (it costs
        two clock reads per measured call). */
    struct SearchStatistics
    {
        std::size_t simulations{0};
        std::size_t beliefNodes{0};
        std::size_t actionNodes{0};
        /** \brief Deepest tree level reached (macro-action levels below the root). */
        std::size_t maxDepth{0};
        std::size_t referenceRequested{0};
        std::size_t referenceFailed{0};
        std::size_t modelSteps{0};
        /** \brief ROP-RAS3's belief fill (fill_particles): particles moved into new nodes, and those kept. */
        std::size_t fillTried{0};
        std::size_t fillKept{0};
        double seconds{0.0};
        double referenceSeconds{0.0};
        double modelSeconds{0.0};
        /** \brief Planning calls that stopped because the tree reached its memory cap (the solver parameter
            max_tree_mb) before the budget was used up: 0 or 1 per call, summed by accumulate(). */
        std::size_t memoryCapped{0};
        /** \brief Bytes the search tree held at the end of the call (the largest over accumulated calls). */
        std::size_t treeBytes{0};
        /** \brief Value estimate at the root (soft value V for reference-based solvers, max Q for UCB ones). */
        double rootValue{0.0};

        /** \brief Accumulates \a other (counters and times add, maxDepth takes the maximum). */
        void accumulate(const SearchStatistics &other) noexcept
        {
            simulations += other.simulations;
            beliefNodes += other.beliefNodes;
            actionNodes += other.actionNodes;
            maxDepth = maxDepth > other.maxDepth ? maxDepth : other.maxDepth;
            referenceRequested += other.referenceRequested;
            referenceFailed += other.referenceFailed;
            modelSteps += other.modelSteps;
            fillTried += other.fillTried;
            fillKept += other.fillKept;
            memoryCapped += other.memoryCapped;
            treeBytes = treeBytes > other.treeBytes ? treeBytes : other.treeBytes;
            seconds += other.seconds;
            referenceSeconds += other.referenceSeconds;
            modelSeconds += other.modelSeconds;
            rootValue = other.rootValue;
        }
    };
}  // namespace ropras::pomdp

#endif
