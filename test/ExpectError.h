#ifndef ROPRAS_TEST_EXPECT_ERROR_H
#define ROPRAS_TEST_EXPECT_ERROR_H

#include <gtest/gtest.h>

#include <functional>
#include <string>
#include <vector>

#include "ropras/core/Error.h"

namespace ropras::test
{
    /// \a f must throw ropras::Error whose message contains every one of \a needles (file names, values, ...)
    inline void expectErrorMentions(const std::function<void()> &f, const std::vector<std::string> &needles)
    {
        try
        {
            f();
            ADD_FAILURE() << "no ropras::Error thrown (expected one mentioning " << needles.front() << ")";
        }
        catch (const Error &e)
        {
            for (const std::string &n : needles)
                EXPECT_NE(std::string(e.what()).find(n), std::string::npos)
                    << "message '" << e.what() << "' does not mention '" << n << "'";
        }
    }
}  // namespace ropras::test

#endif
