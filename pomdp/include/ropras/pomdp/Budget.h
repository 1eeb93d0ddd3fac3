#ifndef ROPRAS_POMDP_BUDGET_H
#define ROPRAS_POMDP_BUDGET_H

#include <cstddef>

namespace ropras::pomdp
{
    /** \brief Computation budget of one planning call: a simulation count, a time limit, or both (the
        search stops at whichever is reached first). validate() throws ropras::Error when neither is set or
        a value is negative, not finite or above its maximum. (The tree solvers also stop when their tree reaches
        its memory cap, the parameter max_tree_mb, and count that in SearchStatistics::memoryCapped.) */
    struct Budget
    {
        /// the largest time limit of one planning call: one day
        static constexpr double MAX_SECONDS = 86400.0;
        /// the largest simulation count of one planning call: 10^9
        static constexpr std::size_t MAX_SIMULATIONS = 1000000000;

        /** \brief Maximum number of simulations (0 = no limit). */
        std::size_t simulations{0};
        /** \brief Maximum wall-clock seconds (0 = no limit). */
        double seconds{0.0};

        static Budget ofSimulations(std::size_t n) { return Budget{n, 0.0}; }
        static Budget ofSeconds(double s) { return Budget{0, s}; }

        void validate() const;
    };
}  // namespace ropras::pomdp

#endif
