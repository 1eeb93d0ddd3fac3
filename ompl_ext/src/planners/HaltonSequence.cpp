#include "ropras/ompl_ext/planners/HaltonSequence.h"

#include <algorithm>
#include <cmath>
#include <iterator>
#if defined(__AVX2__) && defined(__FMA__)
#include <immintrin.h>
#endif

#include "ropras/core/Error.h"

namespace ropras::ompl_ext
{
    namespace
    {
        constexpr unsigned PRIMES[HaltonSequence::MAX_DIMENSIONS] = {2,  3,  5,  7,   11,  13,  17,  19,  23,  29, 31,
                                                                     37, 41, 43, 47,  53,  59,  61,  67,  71,  73, 79,
                                                                     83, 89, 97, 101, 103, 107, 109, 113, 127, 131};
    }  // namespace

    unsigned HaltonSequence::base(std::size_t dimension)
    {
        if (dimension >= MAX_DIMENSIONS)
            throw Error("HaltonSequence: dimension " + std::to_string(dimension) + " exceeds the maximum of " +
                        std::to_string(MAX_DIMENSIONS));
        return PRIMES[dimension];
    }

    double HaltonSequence::radicalInverse(std::uint64_t index, unsigned base)
    {
        const double inv = 1.0 / base;
        double f = inv, value = 0.0;
        while (index > 0)
        {
            value += f * static_cast<double>(index % base);
            index /= base;
            f *= inv;
        }
        return value;
    }

    void HaltonSequence::reset(std::size_t dimensions)
    {
        if (dimensions > MAX_DIMENSIONS)
            throw Error("HaltonSequence: " + std::to_string(dimensions) + " dimensions exceed the maximum of " +
                        std::to_string(MAX_DIMENSIONS));
        dimensions_ = dimensions;
        digits_.assign(dimensions, Digits());
        std::fill(std::begin(bases_), std::end(bases_), 0);
        std::fill(std::begin(low_), std::end(low_), 0);
        std::fill(std::begin(inv_), std::end(inv_), 0.0);
        std::fill(std::begin(high_), std::end(high_), 0.0);
        for (std::size_t k = 0; k < dimensions; ++k)
        {
            bases_[k] = static_cast<std::int32_t>(PRIMES[k]);
            low_[k] = 0;
            inv_[k] = 1.0 / PRIMES[k];
            high_[k] = 0.0;
            double p = 1.0 / PRIMES[k];
            for (double &power : digits_[k].powers)
            {
                power = p;
                p /= PRIMES[k];
            }
        }
        index_ = 0;
    }

    void HaltonSequence::carry(std::size_t k) noexcept
    {
        Digits &d = digits_[k];
        const unsigned last = static_cast<unsigned>(bases_[k]) - 1;
        std::size_t j = 1;
        while (d.digits[j] == last)  // at most MAX_DIGITS - 1 digits for a 64-bit index
            d.digits[j++] = 0;
        ++d.digits[j];
        d.top = std::max(d.top, j);
        // the value of digits 1..top, smallest terms first (as the closed form)
        double high = 0.0;
        for (std::size_t i = d.top; i >= 1; --i)
            high = high + d.digits[i] * d.powers[i];
        high_[k] = high;
    }

    void HaltonSequence::next(double *out) noexcept
    {
        ++index_;
        // Base 2 in closed form: the radical inverse is the index with its bits reversed, no carry loop (whose
        // branch goes either way half of the time in base 2).
        if (dimensions_ > 0)
        {
            std::uint64_t bits = index_;
            bits = ((bits >> 1) & 0x5555555555555555ULL) | ((bits & 0x5555555555555555ULL) << 1);
            bits = ((bits >> 2) & 0x3333333333333333ULL) | ((bits & 0x3333333333333333ULL) << 2);
            bits = ((bits >> 4) & 0x0f0f0f0f0f0f0f0fULL) | ((bits & 0x0f0f0f0f0f0f0f0fULL) << 4);
            bits = __builtin_bswap64(bits);
            // the top 53 bits, exactly representable; truncating the rest keeps the value in [0, 1)
            out[0] = static_cast<double>(bits >> 11) * 0x1.0p-53;
        }
#if defined(__AVX2__) && defined(__FMA__)
        // Eight dimensions per step: digit 0 + 1 in int lanes, the wrapped lanes (about one per point for the
        // seven joints of an arm) carry one by one, then high + digit / base in two double registers.
        const __m256i one = _mm256_set1_epi32(1);
        const __m256d belowOne = _mm256_set1_pd(0x1.fffffffffffffp-1);
        for (std::size_t k = 1; k < dimensions_; k += 8)
        {
            const std::size_t lanes = std::min<std::size_t>(8, dimensions_ - k);
            __m256i low = _mm256_add_epi32(_mm256_loadu_si256(reinterpret_cast<const __m256i *>(low_ + k)), one);
            const __m256i wrap =
                _mm256_cmpeq_epi32(low, _mm256_loadu_si256(reinterpret_cast<const __m256i *>(bases_ + k)));
            low = _mm256_andnot_si256(wrap, low);
            _mm256_storeu_si256(reinterpret_cast<__m256i *>(low_ + k), low);
            for (unsigned m =
                     static_cast<unsigned>(_mm256_movemask_ps(_mm256_castsi256_ps(wrap))) & ((1u << lanes) - 1u);
                 m != 0u; m &= m - 1u)
                carry(k + static_cast<std::size_t>(__builtin_ctz(m)));
            const __m256d v0 = _mm256_min_pd(
                _mm256_add_pd(_mm256_loadu_pd(high_ + k), _mm256_mul_pd(_mm256_cvtepi32_pd(_mm256_castsi256_si128(low)),
                                                                        _mm256_loadu_pd(inv_ + k))),
                belowOne);
            const __m256d v1 = _mm256_min_pd(
                _mm256_add_pd(
                    _mm256_loadu_pd(high_ + k + 4),
                    _mm256_mul_pd(_mm256_cvtepi32_pd(_mm256_extracti128_si256(low, 1)), _mm256_loadu_pd(inv_ + k + 4))),
                belowOne);
            // only the dimensions there are (out has no room beyond them)
            const __m256i count = _mm256_set1_epi64x(static_cast<long long>(lanes));
            _mm256_maskstore_pd(out + k, _mm256_cmpgt_epi64(count, _mm256_setr_epi64x(0, 1, 2, 3)), v0);
            _mm256_maskstore_pd(out + k + 4, _mm256_cmpgt_epi64(count, _mm256_setr_epi64x(4, 5, 6, 7)), v1);
        }
#else
        for (std::size_t k = 1; k < dimensions_; ++k)
        {
            std::int32_t digit = low_[k] + 1;
            if (digit == bases_[k])  // digit 0 wraps once every base points
            {
                digit = 0;
                carry(k);
            }
            low_[k] = digit;
            const double value = high_[k] + static_cast<double>(digit) * inv_[k];
            // high < 1/base and digit / base <= 1 - 1/base: below 1 except for rounding at astronomic indices
            out[k] = std::min(value, 0x1.fffffffffffffp-1);
        }
#endif
    }
}  // namespace ropras::ompl_ext
