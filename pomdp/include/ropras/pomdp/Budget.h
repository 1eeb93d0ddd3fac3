#ifndef ROPRAS_POMDP_BUDGET_H
#define ROPRAS_POMDP_BUDGET_H

#include <cstddef>

namespace ropras::pomdp
{
    /** \brief Computation budget of one planning call: a simulation count, a time limit, or both (the
        search stops at whichever is reached first). validate() throws ropras::Error when neither is set or
        a value is negative or not finite. */
    struct Budget
    {
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
