#include "ropras/ompl_ext/planners/HaltonSequence.h"

#include <gtest/gtest.h>

#include "ropras/core/Error.h"

using ropras::ompl_ext::HaltonSequence;

TEST(HaltonSequence, IncrementalMatchesClosedForm)
{
    HaltonSequence halton;
    halton.reset(7);
    double point[7];
    for (std::uint64_t i = 1; i <= 20000; ++i)
    {
        halton.next(point);
        ASSERT_EQ(halton.index(), i);
        for (std::size_t k = 0; k < 7; ++k)
        {
            ASSERT_NEAR(point[k], HaltonSequence::radicalInverse(i, HaltonSequence::base(k)), 1e-12)
                << "index " << i << " dimension " << k;
            ASSERT_GE(point[k], 0.0);
            ASSERT_LT(point[k], 1.0);
        }
    }
}

TEST(HaltonSequence, AllDimensionsMatchClosedFormThroughSeveralCarries)
{
    // 32 dimensions (bases up to 131): 40000 points carry into the third digit of every base, the fourth of bases
    // up to 31 and far up in the small bases; the carry recomputes the higher digits' value, so no drift either.
    HaltonSequence halton;
    halton.reset(HaltonSequence::MAX_DIMENSIONS);
    double point[HaltonSequence::MAX_DIMENSIONS];
    for (std::uint64_t i = 1; i <= 40000; ++i)
    {
        halton.next(point);
        for (std::size_t k = 0; k < HaltonSequence::MAX_DIMENSIONS; ++k)
            ASSERT_NEAR(point[k], HaltonSequence::radicalInverse(i, HaltonSequence::base(k)), 1e-13)
                << "index " << i << " dimension " << k;
    }
    // reset() starts over in fewer dimensions
    halton.reset(3);
    halton.next(point);
    EXPECT_DOUBLE_EQ(point[2], 0.2);
}

TEST(HaltonSequence, KnownValuesAndReset)
{
    HaltonSequence halton;
    halton.reset(2);
    double p[2];
    halton.next(p);  // index 1: 1/2, 1/3
    EXPECT_DOUBLE_EQ(p[0], 0.5);
    EXPECT_DOUBLE_EQ(p[1], 1.0 / 3.0);
    halton.next(p);  // index 2: 1/4, 2/3
    EXPECT_DOUBLE_EQ(p[0], 0.25);
    EXPECT_DOUBLE_EQ(p[1], 2.0 / 3.0);
    halton.next(p);  // index 3: 3/4, 1/9
    EXPECT_DOUBLE_EQ(p[0], 0.75);
    EXPECT_NEAR(p[1], 1.0 / 9.0, 1e-15);
    halton.reset(2);
    halton.next(p);
    EXPECT_DOUBLE_EQ(p[0], 0.5);
    EXPECT_EQ(halton.index(), 1u);
}

TEST(HaltonSequence, RejectsTooManyDimensions)
{
    HaltonSequence halton;
    EXPECT_THROW(halton.reset(HaltonSequence::MAX_DIMENSIONS + 1), ropras::Error);
    EXPECT_THROW(HaltonSequence::base(HaltonSequence::MAX_DIMENSIONS), ropras::Error);
}
