// AVX2 + FMA 8-float backend (intrinsics). Defines ROPRAS_SIMD_HAVE_AVX2 when the compiler targets AVX2 and FMA.
#ifndef ROPRAS_OMPL_EXT_SIMD_AVX2_VEC_H
#define ROPRAS_OMPL_EXT_SIMD_AVX2_VEC_H

#if defined(__AVX2__) && defined(__FMA__)
#define ROPRAS_SIMD_HAVE_AVX2 1
#include <immintrin.h>

#include <cstddef>

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
        /// smallest / largest lane
        friend float hmin(const Avx2Vec &a) noexcept
        {
            __m128 m = _mm_min_ps(_mm256_castps256_ps128(a.v), _mm256_extractf128_ps(a.v, 1));
            m = _mm_min_ps(m, _mm_movehl_ps(m, m));
            return _mm_cvtss_f32(_mm_min_ss(m, _mm_shuffle_ps(m, m, 1)));
        }
        friend float hmax(const Avx2Vec &a) noexcept
        {
            __m128 m = _mm_max_ps(_mm256_castps256_ps128(a.v), _mm256_extractf128_ps(a.v, 1));
            m = _mm_max_ps(m, _mm_movehl_ps(m, m));
            return _mm_cvtss_f32(_mm_max_ss(m, _mm_shuffle_ps(m, m, 1)));
        }
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
        /// a with its sign flipped in the lanes where \a s is -0.0f (s holds +0.0f or -0.0f: an XOR of sign bits)
        friend Avx2Vec flipSign(const Avx2Vec &a, const Avx2Vec &s) noexcept { return {_mm256_xor_ps(a.v, s.v)}; }
        /** \brief WIDTH rows of \a dof <= 8 doubles (row-major, consecutive) into \a out as dof vectors of WIDTH
            floats (out[8 j + i] = rows[dof i + j]): each row loaded and converted in two halves (masked, never past
            the row), then an 8 x 8 transpose in registers. True when every value satisfies lo[j] <= v <= hi[j]
            (NaN fails). */
        static bool loadRows(const double *rows, int dof, const double *lo, const double *hi, float *out) noexcept
        {
            const __m256i lanes = _mm256_setr_epi64x(0, 1, 2, 3);
            const __m256i m0 = _mm256_cmpgt_epi64(_mm256_set1_epi64x(dof), lanes);
            const __m256i m1 = _mm256_cmpgt_epi64(_mm256_set1_epi64x(dof - 4), lanes);
            const __m256d zero = _mm256_setzero_pd();
            const __m256d lo0 = _mm256_maskload_pd(lo, m0), lo1 = dof > 4 ? _mm256_maskload_pd(lo + 4, m1) : zero;
            const __m256d hi0 = _mm256_maskload_pd(hi, m0), hi1 = dof > 4 ? _mm256_maskload_pd(hi + 4, m1) : zero;
            __m256d ok0 = _mm256_castsi256_pd(_mm256_set1_epi64x(-1)), ok1 = ok0;
            __m256 r[8];
            for (int i = 0; i < 8; ++i)
            {
                // masked lanes read 0.0, and 0 <= 0 <= 0 with the masked limits: they always pass
                const __m256d a = _mm256_maskload_pd(rows + dof * i, m0);
                const __m256d b = dof > 4 ? _mm256_maskload_pd(rows + dof * i + 4, m1) : _mm256_setzero_pd();
                ok0 = _mm256_and_pd(
                    ok0, _mm256_and_pd(_mm256_cmp_pd(a, lo0, _CMP_GE_OQ), _mm256_cmp_pd(a, hi0, _CMP_LE_OQ)));
                ok1 = _mm256_and_pd(
                    ok1, _mm256_and_pd(_mm256_cmp_pd(b, lo1, _CMP_GE_OQ), _mm256_cmp_pd(b, hi1, _CMP_LE_OQ)));
                r[i] = _mm256_set_m128(_mm256_cvtpd_ps(b), _mm256_cvtpd_ps(a));
            }
            // 8 x 8 transpose: rows i -> columns j
            const __m256 t0 = _mm256_unpacklo_ps(r[0], r[1]), t1 = _mm256_unpackhi_ps(r[0], r[1]);
            const __m256 t2 = _mm256_unpacklo_ps(r[2], r[3]), t3 = _mm256_unpackhi_ps(r[2], r[3]);
            const __m256 t4 = _mm256_unpacklo_ps(r[4], r[5]), t5 = _mm256_unpackhi_ps(r[4], r[5]);
            const __m256 t6 = _mm256_unpacklo_ps(r[6], r[7]), t7 = _mm256_unpackhi_ps(r[6], r[7]);
            const __m256 u0 = _mm256_shuffle_ps(t0, t2, 0x44), u1 = _mm256_shuffle_ps(t0, t2, 0xEE);
            const __m256 u2 = _mm256_shuffle_ps(t1, t3, 0x44), u3 = _mm256_shuffle_ps(t1, t3, 0xEE);
            const __m256 u4 = _mm256_shuffle_ps(t4, t6, 0x44), u5 = _mm256_shuffle_ps(t4, t6, 0xEE);
            const __m256 u6 = _mm256_shuffle_ps(t5, t7, 0x44), u7 = _mm256_shuffle_ps(t5, t7, 0xEE);
            const __m256 c[8] = {_mm256_permute2f128_ps(u0, u4, 0x20), _mm256_permute2f128_ps(u1, u5, 0x20),
                                 _mm256_permute2f128_ps(u2, u6, 0x20), _mm256_permute2f128_ps(u3, u7, 0x20),
                                 _mm256_permute2f128_ps(u0, u4, 0x31), _mm256_permute2f128_ps(u1, u5, 0x31),
                                 _mm256_permute2f128_ps(u2, u6, 0x31), _mm256_permute2f128_ps(u3, u7, 0x31)};
            // one store per variable, unrolled: the loop over c[] became a call to memcpy
            switch (dof)
            {
                case 8:
                    _mm256_storeu_ps(out + 56, c[7]);
                    [[fallthrough]];
                case 7:
                    _mm256_storeu_ps(out + 48, c[6]);
                    [[fallthrough]];
                case 6:
                    _mm256_storeu_ps(out + 40, c[5]);
                    [[fallthrough]];
                case 5:
                    _mm256_storeu_ps(out + 32, c[4]);
                    [[fallthrough]];
                case 4:
                    _mm256_storeu_ps(out + 24, c[3]);
                    [[fallthrough]];
                case 3:
                    _mm256_storeu_ps(out + 16, c[2]);
                    [[fallthrough]];
                case 2:
                    _mm256_storeu_ps(out + 8, c[1]);
                    [[fallthrough]];
                case 1:
                    _mm256_storeu_ps(out, c[0]);
                    break;
                default:
                    break;
            }
            return _mm256_movemask_pd(_mm256_and_pd(ok0, ok1)) == 0xF;
        }
        friend Avx2Vec select(const Avx2Mask &m, const Avx2Vec &a, const Avx2Vec &b) noexcept
        {
            return {_mm256_blendv_ps(b.v, a.v, m.m)};
        }
    };
}  // namespace ropras::ompl_ext::simd

#endif
#endif
