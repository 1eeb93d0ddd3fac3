// ropras::core::Rng against an independent implementation (Python, from the published xoshiro256++ and SplitMix64
// algorithms) and against the moments of the distributions it draws from.
#include "ropras/core/Rng.h"

#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <cstdint>
#include <vector>

using ropras::core::Rng;

TEST(Rng, SplitMix64MatchesTheReferenceSequence)
{
    std::uint64_t x = 0;
    EXPECT_EQ(Rng::splitMix64(x), 0xe220a8397b1dcdafULL);
    EXPECT_EQ(Rng::splitMix64(x), 0x6e789e6aa1b965f4ULL);
    EXPECT_EQ(Rng::splitMix64(x), 0x06c45d188009454fULL);
}

TEST(Rng, Xoshiro256PlusPlusMatchesTheReferenceSequence)
{
    // state = four SplitMix64 outputs of the seed, then the xoshiro256++ step (values computed in Python)
    const std::array<std::uint64_t, 4> seed0{0x53175d61490b23dfULL, 0x61da6f3dc380d507ULL, 0x5c0fdf91ec9a7bfcULL,
                                             0x02eebf8c3bbe5e1aULL};
    const std::array<std::uint64_t, 4> seed12345{0x8d948a82def8a568ULL, 0x3477f953796702a0ULL, 0x15caa2fce6db8d69ULL,
                                                 0x2cef8853c20c6dd0ULL};
    Rng a(0), b(12345);
    for (std::size_t i = 0; i < 4; ++i)
    {
        EXPECT_EQ(a(), seed0[i]) << "draw " << i;
        EXPECT_EQ(b(), seed12345[i]) << "draw " << i;
    }
    a.reseed(12345);
    EXPECT_EQ(a(), seed12345[0]) << "reseed restarts the stream";
}

TEST(Rng, UniformDrawsHaveTheMomentsOfTheirDistributions)
{
    Rng rng(3);
    const int n = 200000;
    double sum = 0.0, sumSq = 0.0;
    std::vector<int> bins(10, 0);
    for (int i = 0; i < n; ++i)
    {
        const double u = rng.uniform01();
        ASSERT_GE(u, 0.0);
        ASSERT_LT(u, 1.0);
        sum += u;
        sumSq += u * u;
        ++bins[static_cast<std::size_t>(rng.uniformIndex(10))];
    }
    const double mean = sum / n, variance = sumSq / n - mean * mean;
    EXPECT_NEAR(mean, 0.5, 4.0 * std::sqrt(1.0 / 12.0 / n));
    EXPECT_NEAR(variance, 1.0 / 12.0, 0.002);
    double chi2 = 0.0;
    for (int count : bins)
        chi2 += (count - n / 10.0) * (count - n / 10.0) / (n / 10.0);
    EXPECT_LT(chi2, 27.9) << "uniformIndex(10): chi-square with 9 degrees of freedom above its 0.1 % quantile";

    double nSum = 0.0, nSumSq = 0.0;
    for (int i = 0; i < n; ++i)
    {
        const double z = rng.normal(1.0, 2.0);
        nSum += z;
        nSumSq += z * z;
    }
    const double nMean = nSum / n;
    EXPECT_NEAR(nMean, 1.0, 4.0 * 2.0 / std::sqrt(n));
    EXPECT_NEAR(nSumSq / n - nMean * nMean, 4.0, 0.06);
}
