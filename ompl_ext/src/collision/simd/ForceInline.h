// ROPRAS_SIMD_FORCE_INLINE: for the small kernel helpers that must be inlined into their loops (GCC's heuristics
// keep some of them out of line once the large kernels calling them grow, costing a call per obstacle or link).
#ifndef ROPRAS_OMPL_EXT_SIMD_FORCE_INLINE_H
#define ROPRAS_OMPL_EXT_SIMD_FORCE_INLINE_H

#if defined(__GNUC__) || defined(__clang__)
#define ROPRAS_SIMD_FORCE_INLINE inline __attribute__((always_inline))
#else
#define ROPRAS_SIMD_FORCE_INLINE inline
#endif

#endif
