// AVX2 + FMA 8-float backend (intrinsics). Defines ROPRAS_SIMD_HAVE_AVX2 when the compiler targets AVX2 and FMA.
#ifndef ROPRAS_OMPL_EXT_SIMD_AVX2_VEC_H
#define ROPRAS_OMPL_EXT_SIMD_AVX2_VEC_H

#if defined(__AVX2__) && defined(__FMA__)
#define ROPRAS_SIMD_HAVE_AVX2 1
#include <immintrin.h>

namespace ropras::ompl_ext::simd
{
    /** \brief Lane mask of the AVX2 backend: all bits set in a lane that is true. */
    struct Avx2Mask
    {
        static constexpr int WIDTH = 8;
        __m256 m;

        friend Avx2Mask operator&(const Avx2Mask &a, const Avx2Mask &b) noexcept { return {_mm256_and_ps(a.m, b.m)}; }
        friend Avx2Mask operator|(const Avx2Mask &a, const Avx2Mask &b) noexcept { return {_mm256_or_ps(a.m, b.m)}; }
        /// a & ~b
        friend Avx2Mask andNot(const Avx2Mask &a, const Avx2Mask &b) noexcept { return {_mm256_andnot_ps(b.m, a.m)}; }
        unsigned bits() const noexcept { return static_cast<unsigned>(_mm256_movemask_ps(m)); }
        bool any() const noexcept { return _mm256_testz_ps(m, m) == 0; }
        static Avx2Mask none() noexcept { return {_mm256_setzero_ps()}; }
        static Avx2Mask firstLanes(int n) noexcept
        {
            const __m256i lanes = _mm256_setr_epi32(0, 1, 2, 3, 4, 5, 6, 7);
            return {_mm256_castsi256_ps(_mm256_cmpgt_epi32(_mm256_set1_epi32(n), lanes))};
        }
        static Avx2Mask fromBits(unsigned b) noexcept
        {
            const __m256i bit = _mm256_setr_epi32(1, 2, 4, 8, 16, 32, 64, 128);
            const __m256i x = _mm256_and_si256(_mm256_set1_epi32(static_cast<int>(b)), bit);
            return {_mm256_castsi256_ps(_mm256_cmpeq_epi32(x, bit))};
        }
    };

    /** \brief 8 floats in one AVX register. */
    struct Avx2Vec
    {
        static constexpr int WIDTH = 8;
        using Mask = Avx2Mask;
        __m256 v;

        static const char *name() noexcept { return "avx2"; }

        static Avx2Vec broadcast(float x) noexcept { return {_mm256_set1_ps(x)}; }
        static Avx2Vec zero() noexcept { return {_mm256_setzero_ps()}; }
        static Avx2Vec load(const float *p) noexcept { return {_mm256_loadu_ps(p)}; }
        void store(float *p) const noexcept { _mm256_storeu_ps(p, v); }
        static Avx2Vec iota() noexcept { return {_mm256_setr_ps(0, 1, 2, 3, 4, 5, 6, 7)}; }
        float lane(int i) const noexcept
        {
            alignas(32) float tmp[WIDTH];
            _mm256_store_ps(tmp, v);
            return tmp[i];
        }

        friend Avx2Vec operator+(const Avx2Vec &a, const Avx2Vec &b) noexcept { return {_mm256_add_ps(a.v, b.v)}; }
        friend Avx2Vec operator-(const Avx2Vec &a, const Avx2Vec &b) noexcept { return {_mm256_sub_ps(a.v, b.v)}; }
        friend Avx2Vec operator*(const Avx2Vec &a, const Avx2Vec &b) noexcept { return {_mm256_mul_ps(a.v, b.v)}; }
        friend Avx2Vec operator/(const Avx2Vec &a, const Avx2Vec &b) noexcept { return {_mm256_div_ps(a.v, b.v)}; }
        friend Avx2Mask cmpLt(const Avx2Vec &a, const Avx2Vec &b) noexcept
        {
            return {_mm256_cmp_ps(a.v, b.v, _CMP_LT_OQ)};
        }
        friend Avx2Mask cmpLe(const Avx2Vec &a, const Avx2Vec &b) noexcept
        {
            return {_mm256_cmp_ps(a.v, b.v, _CMP_LE_OQ)};
        }
        friend Avx2Mask cmpGt(const Avx2Vec &a, const Avx2Vec &b) noexcept
        {
            return {_mm256_cmp_ps(a.v, b.v, _CMP_GT_OQ)};
        }
        friend Avx2Mask cmpGe(const Avx2Vec &a, const Avx2Vec &b) noexcept
        {
            return {_mm256_cmp_ps(a.v, b.v, _CMP_GE_OQ)};
        }
        /// a * b + c
        friend Avx2Vec fma(const Avx2Vec &a, const Avx2Vec &b, const Avx2Vec &c) noexcept
        {
            return {_mm256_fmadd_ps(a.v, b.v, c.v)};
        }
        /// c - a * b
        friend Avx2Vec fnma(const Avx2Vec &a, const Avx2Vec &b, const Avx2Vec &c) noexcept
        {
            return {_mm256_fnmadd_ps(a.v, b.v, c.v)};
        }
        friend Avx2Vec min(const Avx2Vec &a, const Avx2Vec &b) noexcept { return {_mm256_min_ps(a.v, b.v)}; }
        friend Avx2Vec max(const Avx2Vec &a, const Avx2Vec &b) noexcept { return {_mm256_max_ps(a.v, b.v)}; }
        friend Avx2Vec abs(const Avx2Vec &a) noexcept { return {_mm256_andnot_ps(_mm256_set1_ps(-0.0f), a.v)}; }
        friend Avx2Vec sqrt(const Avx2Vec &a) noexcept { return {_mm256_sqrt_ps(a.v)}; }
        friend Avx2Vec round(const Avx2Vec &a) noexcept
        {
            return {_mm256_round_ps(a.v, _MM_FROUND_TO_NEAREST_INT | _MM_FROUND_NO_EXC)};
        }
        friend Avx2Vec floor(const Avx2Vec &a) noexcept
        {
            return {_mm256_round_ps(a.v, _MM_FROUND_TO_NEG_INF | _MM_FROUND_NO_EXC)};
        }
        friend Avx2Vec select(const Avx2Mask &m, const Avx2Vec &a, const Avx2Vec &b) noexcept
        {
            return {_mm256_blendv_ps(b.v, a.v, m.m)};
        }
    };
}  // namespace ropras::ompl_ext::simd

#endif
#endif
