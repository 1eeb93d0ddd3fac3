// Which links of one check have their spheres placed in scratch: kernels place a link's spheres only when an
// obstacle or a self pair needs them.
#ifndef ROPRAS_OMPL_EXT_SIMD_PLACED_H
#define ROPRAS_OMPL_EXT_SIMD_PLACED_H

#include <cstdint>

namespace ropras::ompl_ext::simd
{
    /// links whose spheres are placed (bit per link); models with more than 64 links place all at once
    struct Placed
    {
        std::uint64_t bits{0};
        bool all{false};
        bool has(int li) const noexcept { return all || ((bits >> li) & 1u) != 0u; }
        void set(int li) noexcept { bits |= std::uint64_t{1} << li; }
    };
}  // namespace ropras::ompl_ext::simd

#endif
