#ifndef ROPRAS_OMPL_EXT_HALTON_SEQUENCE_H
#define ROPRAS_OMPL_EXT_HALTON_SEQUENCE_H

#include <cstddef>
#include <cstdint>
#include <vector>

namespace ropras::ompl_ext
{
    /** \brief The Halton sequence in up to 32 dimensions (bases: the first primes), generated incrementally:
        each next() adds one in every base's digit counter and updates the radical inverse with the carries,
        O(1) amortized per dimension instead of one integer division per digit; base 2 is the index with its
        bits reversed (no carry loop). Point i (from 1) equals radicalInverse(i, base_k) in dimension k to
        rounding. */
    class HaltonSequence
    {
    public:
        static constexpr std::size_t MAX_DIMENSIONS = 32;

        /// restarts at index 0 in \a dimensions dimensions (at most MAX_DIMENSIONS)
        void reset(std::size_t dimensions);
        /// advances to the next index and writes its point, coordinates in [0, 1)
        void next(double *out) noexcept;
        std::uint64_t index() const { return index_; }

        /// the closed form, for tests: sum_j digit_j(index) * base^-(j+1)
        static double radicalInverse(std::uint64_t index, unsigned base);
        static unsigned base(std::size_t dimension);

        static constexpr std::size_t MAX_DIGITS = 64;  ///< enough for any 64-bit index in base >= 2

    private:
        /// one dimension's digit counter, in one block (no pointer chase per carry)
        struct Counter
        {
            unsigned base{2};
            double value{0.0};
            unsigned digits[MAX_DIGITS]{};  ///< least significant first
            double powers[MAX_DIGITS]{};    ///< base^-(j+1)
        };
        std::vector<Counter> counters_;
        std::uint64_t index_{0};
    };
}  // namespace ropras::ompl_ext

#endif
