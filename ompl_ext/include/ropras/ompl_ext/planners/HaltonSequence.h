#ifndef ROPRAS_OMPL_EXT_HALTON_SEQUENCE_H
#define ROPRAS_OMPL_EXT_HALTON_SEQUENCE_H

#include <cstddef>
#include <cstdint>
#include <vector>

namespace ropras::ompl_ext
{
    /** \brief The Halton sequence in up to 32 dimensions (bases: the first primes), generated incrementally.
        Base 2 is the index with its bits reversed (no carry loop). Every other base keeps its lowest digit apart:
        a point is high + digit0 / base, where high (the value of the higher digits) changes only when digit0
        wraps, once every base points; the carry then walks the higher digits and recomputes high from them (no
        running sum that could drift). Point i (from 1) equals radicalInverse(i, base_k) in dimension k to
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
        /// the higher digits of one dimension (digit 0 lives in low_), touched once every base points
        struct Digits
        {
            unsigned digits[MAX_DIGITS]{};  ///< least significant first; digits[0] unused
            double powers[MAX_DIGITS]{};    ///< base^-(j+1)
            std::size_t top{0};             ///< highest digit index ever non-zero
        };
        void carry(std::size_t k) noexcept;

        std::size_t dimensions_{0};
        // hot per-point data, one array per field, padded by 8 so that the AVX2 path loads whole registers
        static constexpr std::size_t PADDED = MAX_DIMENSIONS + 8;
        std::int32_t bases_[PADDED]{};  ///< 0 in the padding: never wraps
        std::int32_t low_[PADDED]{};    ///< digit 0 per dimension
        double inv_[PADDED]{};          ///< 1 / base
        double high_[PADDED]{};         ///< value of digits 1.. per dimension
        std::vector<Digits> digits_;
        std::uint64_t index_{0};
    };
}  // namespace ropras::ompl_ext

#endif
