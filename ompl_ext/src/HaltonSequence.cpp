#include "ropras/ompl_ext/HaltonSequence.h"

#include <algorithm>
#include <cmath>
#include <iterator>

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
        counters_.resize(dimensions);
        for (std::size_t k = 0; k < dimensions; ++k)
        {
            Counter &c = counters_[k];
            c.base = PRIMES[k];
            std::fill(std::begin(c.digits), std::end(c.digits), 0u);
            double p = 1.0 / c.base;
            for (double &power : c.powers)
            {
                power = p;
                p /= c.base;
            }
            c.value = 0.0;
        }
        index_ = 0;
    }

    void HaltonSequence::next(double *out) noexcept
    {
        ++index_;
        // Base 2 in closed form: the radical inverse is the index with its bits reversed, no carry loop (whose
        // branch goes either way half of the time in base 2).
        if (!counters_.empty())
        {
            std::uint64_t bits = index_;
            bits = ((bits >> 1) & 0x5555555555555555ULL) | ((bits & 0x5555555555555555ULL) << 1);
            bits = ((bits >> 2) & 0x3333333333333333ULL) | ((bits & 0x3333333333333333ULL) << 2);
            bits = ((bits >> 4) & 0x0f0f0f0f0f0f0f0fULL) | ((bits & 0x0f0f0f0f0f0f0f0fULL) << 4);
            bits = __builtin_bswap64(bits);
            // the top 53 bits, exactly representable; truncating the rest keeps the value in [0, 1)
            out[0] = static_cast<double>(bits >> 11) * 0x1.0p-53;
        }
        for (std::size_t k = 1; k < counters_.size(); ++k)
        {
            Counter &c = counters_[k];
            std::size_t j = 0;
            // Carry: digits equal to base-1 roll over to 0, each removing (base-1) * base^-(j+1).
            while (c.digits[j] == c.base - 1)
            {
                c.digits[j] = 0;
                c.value -= (c.base - 1) * c.powers[j];
                ++j;
            }
            ++c.digits[j];
            c.value += c.powers[j];
            // Guard against drift from the running sum (never leaves [0, 1)).
            if (c.value < 0.0)
                c.value = 0.0;
            else if (c.value >= 1.0)
                c.value = std::nextafter(1.0, 0.0);
            out[k] = c.value;
        }
    }
}  // namespace ropras::ompl_ext
