// Small GCC/Clang vectors of the single-configuration path: a frame as 4-float columns (Row4) or as two 8-float
// halves (Row8), their loads, stores and shuffles, and the angle argument fed to sin/cos.
#ifndef ROPRAS_OMPL_EXT_SIMD_FRAME_ROWS_H
#define ROPRAS_OMPL_EXT_SIMD_FRAME_ROWS_H

#include <cmath>
#include <cstring>

namespace ropras::ompl_ext::simd
{
    /// the float joint value fed to sin/cos: continuous joints far from zero are reduced in double first
    inline float angleArgument(double v) noexcept
    {
        if (std::abs(v) > 64.0)
            v = std::remainder(v, 6.283185307179586476925);
        return static_cast<float>(v);
    }

    /// 4 floats with GCC/Clang vector extensions (SSE where available, plain code elsewhere)
    typedef float Row4 __attribute__((vector_size(16)));
    /// 8 floats with GCC/Clang vector extensions (AVX where available): two 4-float columns side by side
    typedef float Row8 __attribute__((vector_size(32)));

    /// a Row4 or Row8 from unaligned memory
    template <class R = Row4>
    inline R loadRow(const float *p) noexcept
    {
        R r;
        std::memcpy(&r, p, sizeof(r));
        return r;
    }

    template <class R>
    inline void storeRow(float *p, const R &r) noexcept
    {
        std::memcpy(p, &r, sizeof(r));
    }

    typedef int Index8 __attribute__((vector_size(32)));
    constexpr Index8 LOW_TWICE = {0, 1, 2, 3, 0, 1, 2, 3};
    constexpr Index8 HIGH_TWICE = {4, 5, 6, 7, 4, 5, 6, 7};
    constexpr Index8 SWAP_HALVES = {4, 5, 6, 7, 0, 1, 2, 3};
    /// with a second operand of zeros: (0 | high half)
    constexpr Index8 ZERO_LOW = {8, 9, 10, 11, 4, 5, 6, 7};

    inline Row4 lowHalf(const Row8 &r) noexcept
    {
        return Row4{r[0], r[1], r[2], r[3]};
    }

    inline Row4 highHalf(const Row8 &r) noexcept
    {
        return Row4{r[4], r[5], r[6], r[7]};
    }
}  // namespace ropras::ompl_ext::simd

#endif
