#include "ropras/pomdp/Budget.h"

#include <cmath>
#include <cstdio>
#include <string>

#include "ropras/core/Error.h"

namespace ropras::pomdp
{
    void Budget::validate() const
    {
        if (!std::isfinite(seconds) || seconds < 0.0)
        {
            throw Error("pomdp::Budget: seconds = " + std::to_string(seconds) + " is not a finite value >= 0");
        }
        if (seconds > MAX_SECONDS)
        {
            char text[32];
            std::snprintf(text, sizeof(text), "%g", seconds);
            throw Error("pomdp::Budget: seconds = " + std::string(text) + " exceeds the maximum " +
                        std::to_string(static_cast<long long>(MAX_SECONDS)) + " s of one planning call");
        }
        if (simulations > MAX_SIMULATIONS)
        {
            throw Error("pomdp::Budget: simulations = " + std::to_string(simulations) + " exceeds the maximum " +
                        std::to_string(MAX_SIMULATIONS) + " of one planning call");
        }
        if (simulations == 0 && seconds == 0.0)
        {
            throw Error("pomdp::Budget: neither a simulation count nor a time limit is set (both are 0)");
        }
    }
}  // namespace ropras::pomdp
