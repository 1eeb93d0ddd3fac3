// Issue 17: a count option turns into bytes without overflow and is compared with the memory limit before anything
// is allocated, so that the error names the option and the amount (instead of std::bad_alloc).
#include "ropras/core/MemoryLimit.h"

#include <gtest/gtest.h>

#include <cstdint>
#include <limits>

#include "ExpectError.h"

using ropras::test::expectErrorMentions;

TEST(MemoryLimit, CountsTurnIntoBytesWithoutOverflow)
{
    const std::uint64_t saved = ropras::memoryLimit();
    EXPECT_GT(saved, 0u);
    ropras::setMemoryLimit(std::uint64_t(1) << 30);
    EXPECT_EQ(ropras::checkedBytes(1000, 48, "--samples 1000"), 48000u);
    EXPECT_EQ(ropras::checkedBytes(0, 48, "--samples 0"), 0u);
    expectErrorMentions([] { ropras::checkedBytes(1000000000, 48, "--samples 1000000000"); },
                        {"--samples 1000000000 asks for 1000000000 x 48 bytes = 45 GiB", "memory limit 1.0 GiB",
                         "ropras --max-memory"});
    // count x dof overflows 64 bits: still an error, never a small wrapped-around product
    expectErrorMentions([] { ropras::checkedBytes(std::numeric_limits<std::uint64_t>::max(), 48, "--samples max"); },
                        {"more than 2^64 bytes"});
    ropras::setMemoryLimit(saved);
}
