#ifndef ROPRAS_BIN_ARGUMENT_CHECKS_H
#define ROPRAS_BIN_ARGUMENT_CHECKS_H

#include <CLI/CLI.hpp>
#include <charconv>
#include <cmath>
#include <cstdint>
#include <limits>
#include <map>
#include <sstream>
#include <string>
#include <vector>

#include "ropras/core/Error.h"

namespace ropras::bin
{
    /** \brief CLI11 check of a numeric option: finite, at least (or, with \a strict, above) \a min, at most
        \a max, and with \a whole an integer. Used instead of CLI::PositiveNumber / CLI::NonNegativeNumber, which
        let "nan" through (every comparison with NaN is false) and print their range with 300 digits. Counts use
        countCheck() instead (exact integers). */
    inline CLI::Validator numberCheck(double min, bool strict, bool whole, const std::string &name,
                                      double max = std::numeric_limits<double>::infinity())
    {
        return CLI::Validator(
            [=](std::string &input)
            {
                double value = 0.0;
                const bool ok = CLI::detail::lexical_cast(input, value) && std::isfinite(value) &&
                                (strict ? value > min : value >= min) && (!whole || value == std::floor(value));
                if (!ok)
                    return "Value " + input + " must be " + (whole ? "a whole number" : "a finite number") +
                           (strict ? " > " : " >= ") + std::to_string(static_cast<long long>(min));
                if (value > max)
                {
                    std::ostringstream limit;
                    limit << max;
                    return "Value " + input + " exceeds the maximum " + limit.str();
                }
                return std::string();
            },
            name);
    }

    /** \brief CLI11 check of a count option: a whole number written in decimal digits, in [\a min, \a max].
        Parsed exactly (no detour through double, which rounds 2^64 - 1 up to 2^64), so "-1" never wraps around
        to 2^64 - 1 and 18446744073709551616 is refused instead of saturating. */
    inline CLI::Validator countCheck(std::uint64_t min, std::uint64_t max, const std::string &name)
    {
        return CLI::Validator(
            [=](std::string &input)
            {
                std::uint64_t value = 0;
                const char *first = input.data();
                const char *last = input.data() + input.size();
                if (first != last && *first == '+')
                    ++first;
                const auto parsed = std::from_chars(first, last, value);
                const bool digits = first != last && *first >= '0' && *first <= '9' && parsed.ptr == last;
                if (digits && parsed.ec == std::errc() && value >= min && value <= max)
                    return std::string();
                if (digits && (parsed.ec == std::errc::result_out_of_range || value > max))
                    return "Value " + input + " exceeds the maximum " + std::to_string(max);
                return "Value " + input + " must be a whole number >= " + std::to_string(min) +
                       (max < std::numeric_limits<std::uint64_t>::max() ? " and <= " + std::to_string(max)
                                                                        : std::string());
            },
            name);
    }

    /// a finite number > 0 (times, resolutions)
    inline const CLI::Validator POSITIVE_NUMBER = numberCheck(0.0, true, false, "POSITIVE");
    /// a finite number >= 0
    inline const CLI::Validator NON_NEGATIVE_NUMBER = numberCheck(0.0, false, false, "NON-NEGATIVE");
    /// a planning time limit: a finite number in (0, 86400] s (pomdp::Budget::MAX_SECONDS)
    inline const CLI::Validator PLAN_SECONDS = numberCheck(0.0, true, false, "SECONDS", 86400.0);
    /// a planning time limit or 0 (no limit): [0, 86400] s
    inline const CLI::Validator PLAN_SECONDS_OR_ZERO = numberCheck(0.0, false, false, "SECONDS", 86400.0);
    /// simulations per planning call: [1, 10^9] (pomdp::Budget::MAX_SIMULATIONS)
    inline const CLI::Validator SIMULATIONS = countCheck(1, 1000000000, "COUNT");
    /// simulations per planning call or 0 (no limit): [0, 10^9]
    inline const CLI::Validator SIMULATIONS_OR_ZERO = countCheck(0, 1000000000, "COUNT");
    /// episodes of one experiment: [1, 10^6] (scenarios::MAX_EPISODES)
    inline const CLI::Validator EPISODES = countCheck(1, 1000000, "COUNT");
    /// the largest count any count option accepts (each option may have a smaller maximum)
    constexpr std::uint64_t MAX_COUNT = 1000000000000ULL;  // 10^12
    /// a whole number in [1, 10^12] (counts that must not be zero; memory is checked where they allocate)
    inline const CLI::Validator POSITIVE_COUNT = countCheck(1, MAX_COUNT, "COUNT >= 1");
    /// a whole number in [0, 10^12]
    inline const CLI::Validator NON_NEGATIVE_COUNT = countCheck(0, MAX_COUNT, "COUNT >= 0");
    /// repetitions of a benchmark: [1, 10^6]
    inline const CLI::Validator REPEATS = countCheck(1, 1000000, "COUNT");
    /// a random seed: any whole number in [0, 2^64 - 1], exactly
    inline const CLI::Validator SEED = countCheck(0, std::numeric_limits<std::uint64_t>::max(), "SEED");
    /// a 32-bit random seed (the commands whose seed is an `unsigned`): [0, 2^32 - 1], exactly
    inline const CLI::Validator SEED32 = countCheck(0, std::numeric_limits<std::uint32_t>::max(), "SEED");
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
