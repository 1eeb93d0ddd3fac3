#ifndef ROPRAS_CORE_RNG_H
#define ROPRAS_CORE_RNG_H

#include <cmath>
#include <cstdint>
#include <limits>

namespace ropras::core
{
    /** \brief Small, fast, seedable random number generator (xoshiro256++), a UniformRandomBitGenerator.

        Every source of randomness in ropras takes an Rng (or a seed) explicitly: the same seed gives the same
        result. Seeding goes through SplitMix64 so that nearby seeds give unrelated streams. Copyable (a copy
        continues the same stream independently). */
    class Rng
    {
    public:
        using result_type = std::uint64_t;

        explicit Rng(std::uint64_t seed = 0) noexcept { reseed(seed); }

        void reseed(std::uint64_t seed) noexcept
        {
            std::uint64_t x = seed;
            for (auto &word : state_)
            {
                word = splitMix64(x);
            }
        }

        static constexpr result_type min() noexcept { return 0; }
        static constexpr result_type max() noexcept { return std::numeric_limits<result_type>::max(); }

        result_type operator()() noexcept
        {
            const std::uint64_t result = rotl(state_[0] + state_[3], 23) + state_[0];
            const std::uint64_t t = state_[1] << 17;
            state_[2] ^= state_[0];
            state_[3] ^= state_[1];
            state_[1] ^= state_[2];
            state_[0] ^= state_[3];
            state_[2] ^= t;
            state_[3] = rotl(state_[3], 45);
            return result;
        }

        /** \brief Uniform double in [0, 1) with 53 random bits. */
        double uniform01() noexcept { return static_cast<double>((*this)() >> 11) * 0x1.0p-53; }

        /** \brief Uniform double in [lo, hi). */
        double uniform(double lo, double hi) noexcept { return lo + (hi - lo) * uniform01(); }

        /** \brief Uniform integer in [0, n); n must be > 0 (Lemire's multiply-shift, negligible bias). */
        std::uint64_t uniformIndex(std::uint64_t n) noexcept
        {
            __extension__ typedef unsigned __int128 Wide;
            return static_cast<std::uint64_t>((static_cast<Wide>((*this)()) * n) >> 64);
        }

        /** \brief true with probability p. */
        bool bernoulli(double p) noexcept { return uniform01() < p; }

        /** \brief Standard normal sample (Box-Muller; one of the pair is cached). */
        double normal() noexcept
        {
            if (hasSpare_)
            {
                hasSpare_ = false;
                return spare_;
            }
            double u1 = uniform01();
            while (u1 <= 0.0)
            {
                u1 = uniform01();
            }
            const double u2 = uniform01();
            const double radius = std::sqrt(-2.0 * std::log(u1));
            const double angle = 6.283185307179586 * u2;
            spare_ = radius * std::sin(angle);
            hasSpare_ = true;
            return radius * std::cos(angle);
        }

        /** \brief Normal sample with the given mean and standard deviation. */
        double normal(double mean, double stddev) noexcept { return mean + stddev * normal(); }

        /** \brief A fresh seed derived from this stream (to seed an independent Rng). */
        std::uint64_t split() noexcept
        {
            std::uint64_t x = (*this)();
            return splitMix64(x);
        }

        /** \brief One step of SplitMix64: advances \a x and returns the next output (for seeding). */
        static std::uint64_t splitMix64(std::uint64_t &x) noexcept
        {
            std::uint64_t z = (x += 0x9e3779b97f4a7c15ULL);
            z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9ULL;
            z = (z ^ (z >> 27)) * 0x94d049bb133111ebULL;
            return z ^ (z >> 31);
        }

    private:
        static std::uint64_t rotl(std::uint64_t x, int k) noexcept { return (x << k) | (x >> (64 - k)); }

        std::uint64_t state_[4]{};
        double spare_{0.0};
        bool hasSpare_{false};
    };
}  // namespace ropras::core

#endif
