#ifndef ROPRAS_TEST_SHARED_DIR_H
#define ROPRAS_TEST_SHARED_DIR_H

// Where the reference data (../shared: robots, MotionBenchMaker problems) is; tests that need it skip without it.
#include <gtest/gtest.h>

#include <filesystem>
#include <string>

namespace ropras::test
{
    inline const std::string SHARED = ROPRAS_SHARED_DIR;

    inline std::string sharedFile(const std::string &relative)
    {
        return SHARED + "/" + relative;
    }
}  // namespace ropras::test

/// skips the current test, naming the directory looked for, when ../shared is absent
#define REQUIRE_SHARED()                                                                                              \
    if (!std::filesystem::is_directory(ropras::test::SHARED + "/robots"))                                             \
    {                                                                                                                 \
        GTEST_SKIP() << "../shared not found: " << ropras::test::SHARED << " (this test needs its robots/ and mbm/)"; \
    }

#endif
