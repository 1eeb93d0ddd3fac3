#ifndef ROPRAS_POMDP_PARTICLE_ARENA_H
#define ROPRAS_POMDP_PARTICLE_ARENA_H

#include <cstddef>
#include <cstdint>
#include <vector>

#include "ropras/pomdp/BeliefView.h"
#include "ropras/pomdp/Rng.h"

namespace ropras::pomdp
{
    /** \brief Flat storage for the unweighted particle sets (or any small per-node lists, e.g. child
        indices) of all nodes of a search tree.

        Each node owns a contiguous Segment of one shared vector; a full segment is moved to the end with
        twice the capacity (the abandoned space is bounded by the live space). clear() keeps the capacity,
        so a solver that reuses its arena across searches does no heap allocation once warmed up. An
        optional per-node cap keeps a uniform subsample of everything added (reservoir sampling). */
    template <class State>
    class ParticleArena
    {
    public:
        struct Segment
        {
            std::uint32_t offset{0};
            std::uint32_t size{0};
            std::uint32_t capacity{0};
            /** \brief Particles ever offered to this segment (for reservoir sampling). */
            std::uint32_t seen{0};
        };

        void clear() noexcept { data_.clear(); }

        void reserve(std::size_t n) { data_.reserve(n); }

        /** \brief Adds \a s to \a segment; with \a cap > 0 the segment keeps a uniform subsample of size cap. */
        void add(Segment &segment, const State &s, std::uint32_t cap, Rng &rng)
        {
            ++segment.seen;
            if (cap > 0 && segment.size >= cap)
            {
                const auto j = rng.uniformIndex(segment.seen);
                if (j < segment.size)
                {
                    data_[segment.offset + j] = s;
                }
                return;
            }
            if (segment.size == segment.capacity)
            {
                grow(segment);
            }
            data_[segment.offset + segment.size] = s;
            ++segment.size;
        }

        /** \brief Replaces the content of \a segment with \a n particles. */
        void assign(Segment &segment, const State *particles, std::size_t n)
        {
            segment = Segment{};
            segment.offset = static_cast<std::uint32_t>(data_.size());
            data_.insert(data_.end(), particles, particles + n);
            segment.size = segment.capacity = segment.seen = static_cast<std::uint32_t>(n);
        }

        /** \brief A uniformly chosen particle of a non-empty segment. */
        const State &sample(const Segment &segment, Rng &rng) const noexcept
        {
            return data_[segment.offset + rng.uniformIndex(segment.size)];
        }

        BeliefView<State> view(const Segment &segment) const noexcept
        {
            return BeliefView<State>{data_.data() + segment.offset, segment.size};
        }

        std::size_t storedParticles() const noexcept { return data_.size(); }

        /** \brief Bytes in use (segments and the space abandoned by moved ones; the capacity may be up to twice). */
        std::size_t usedBytes() const noexcept { return data_.size() * sizeof(State); }

    private:
        void grow(Segment &segment)
        {
            if (segment.capacity == 0)
            {
                segment.offset = static_cast<std::uint32_t>(data_.size());
                data_.emplace_back();
                segment.capacity = 1;
                return;
            }
            const std::uint32_t newCapacity = 2u * segment.capacity;
            if (segment.offset + segment.capacity == data_.size())
            {
                data_.resize(segment.offset + newCapacity);
            }
            else
            {
                const auto newOffset = static_cast<std::uint32_t>(data_.size());
                data_.resize(newOffset + newCapacity);
                for (std::uint32_t i = 0; i < segment.size; ++i)
                {
                    data_[newOffset + i] = data_[segment.offset + i];
                }
                segment.offset = newOffset;
            }
            segment.capacity = newCapacity;
        }

        std::vector<State> data_;
    };
}  // namespace ropras::pomdp

#endif
