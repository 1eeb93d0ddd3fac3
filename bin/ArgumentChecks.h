#ifndef ROPRAS_BIN_ARGUMENT_CHECKS_H
#define ROPRAS_BIN_ARGUMENT_CHECKS_H

#include <CLI/CLI.hpp>
#include <cmath>
#include <map>
#include <string>
#include <vector>

#include "ropras/core/Error.h"

namespace ropras::bin
{
    /** \brief CLI11 check of a numeric option: finite, at least (or, with \a strict, above) \a min, and with
        \a whole an integer. Used instead of CLI::PositiveNumber / CLI::NonNegativeNumber, which let "nan" through
        (every comparison with NaN is false) and print their range with 300 digits; and on unsigned options, which
        CLI11 would otherwise read "-1" into as 2^64 - 1. */
    inline CLI::Validator numberCheck(double min, bool strict, bool whole, const std::string &name)
    {
        return CLI::Validator(
            [=](std::string &input)
            {
                double value = 0.0;
                const bool ok = CLI::detail::lexical_cast(input, value) && std::isfinite(value) &&
                                (strict ? value > min : value >= min) && (!whole || value == std::floor(value));
                if (ok)
                    return std::string();
                return "Value " + input + " must be " + (whole ? "a whole number" : "a finite number") +
                       (strict ? " > " : " >= ") + std::to_string(static_cast<long long>(min));
            },
            name);
    }

    /// a finite number > 0 (times, resolutions)
    inline const CLI::Validator POSITIVE_NUMBER = numberCheck(0.0, true, false, "POSITIVE");
    /// a finite number >= 0
    inline const CLI::Validator NON_NEGATIVE_NUMBER = numberCheck(0.0, false, false, "NON-NEGATIVE");
    /// a whole number >= 1 (counts that must not be zero)
    inline const CLI::Validator POSITIVE_COUNT = numberCheck(1.0, false, true, "COUNT >= 1");
    /// a whole number >= 0
    inline const CLI::Validator NON_NEGATIVE_COUNT = numberCheck(0.0, false, true, "COUNT >= 0");
    /// "key=value" options (e.g. repeated --param) as a map; a malformed entry throws Error naming \a option
    inline std::map<std::string, std::string> keyValueOptions(const std::vector<std::string> &list,
                                                              const std::string &option)
    {
        std::map<std::string, std::string> out;
        for (const std::string &kv : list)
        {
            const auto eq = kv.find('=');
            if (eq == std::string::npos || eq == 0)
                throw Error(option + " expects key=value, got '" + kv + "'");
            out[kv.substr(0, eq)] = kv.substr(eq + 1);
        }
        return out;
    }
}  // namespace ropras::bin

#endif
