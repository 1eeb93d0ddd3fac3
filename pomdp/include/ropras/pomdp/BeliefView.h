#ifndef ROPRAS_POMDP_BELIEF_VIEW_H
#define ROPRAS_POMDP_BELIEF_VIEW_H

#include <cstddef>

namespace ropras::pomdp
{
    /** \brief Non-owning view of an unweighted particle belief (the particles of a tree node or a resampled
        filter belief). */
    template <class State>
    struct BeliefView
    {
        const State *particles{nullptr};
        std::size_t size{0};

        bool empty() const noexcept { return size == 0; }
        const State &operator[](std::size_t i) const noexcept { return particles[i]; }
        const State *begin() const noexcept { return particles; }
        const State *end() const noexcept { return particles + size; }
    };
}  // namespace ropras::pomdp

#endif
