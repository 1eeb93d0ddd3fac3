#ifndef ROPRAS_POMDP_RNG_H
#define ROPRAS_POMDP_RNG_H

#include "ropras/core/Rng.h"

namespace ropras::pomdp
{
    /// the project's generator (xoshiro256++), under the name the POMDP code has always used
    using Rng = core::Rng;
}  // namespace ropras::pomdp

#endif
