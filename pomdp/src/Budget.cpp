#include "ropras/pomdp/Budget.h"

#include <cmath>
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
        if (simulations == 0 && seconds == 0.0)
        {
            throw Error("pomdp::Budget: neither a simulation count nor a time limit is set (both are 0)");
        }
    }
}  // namespace ropras::pomdp
