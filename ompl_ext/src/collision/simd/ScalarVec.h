// Portable 8-lane float "vector" with the same interface as the AVX2 backend. Always compiles.
#ifndef ROPRAS_OMPL_EXT_SIMD_SCALAR_VEC_H
#define ROPRAS_OMPL_EXT_SIMD_SCALAR_VEC_H

#include <cmath>
#include <cstddef>
#include <cstdint>
#include <cstring>

namespace ropras::ompl_ext::simd
{
    /** \brief Lane mask of the scalar backend: one bool per lane. */
    struct ScalarMask
    {
        static constexpr int WIDTH = 8;
        bool m[WIDTH];

        friend ScalarMask operator&(const ScalarMask &a, const ScalarMask &b) noexcept
        {
            ScalarMask r;
            for (int i = 0; i < WIDTH; ++i)
                r.m[i] = a.m[i] && b.m[i];
            return r;
        }
        friend ScalarMask operator|(const ScalarMask &a, const ScalarMask &b) noexcept
        {
            ScalarMask r;
            for (int i = 0; i < WIDTH; ++i)
                r.m[i] = a.m[i] || b.m[i];
            return r;
        }
        /// a & ~b
        friend ScalarMask andNot(const ScalarMask &a, const ScalarMask &b) noexcept
        {
            ScalarMask r;
            for (int i = 0; i < WIDTH; ++i)
                r.m[i] = a.m[i] && !b.m[i];
            return r;
        }
        /// bit i set when lane i is set
        unsigned bits() const noexcept
        {
            unsigned b = 0;
            for (int i = 0; i < WIDTH; ++i)
                b |= static_cast<unsigned>(m[i]) << i;
            return b;
        }
        bool any() const noexcept { return bits() != 0; }
        static ScalarMask none() noexcept
        {
            ScalarMask r;
            for (int i = 0; i < WIDTH; ++i)
                r.m[i] = false;
            return r;
        }
        /// lanes [0, n) set
        static ScalarMask firstLanes(int n) noexcept
        {
            ScalarMask r;
            for (int i = 0; i < WIDTH; ++i)
                r.m[i] = i < n;
            return r;
        }
        static ScalarMask fromBits(unsigned b) noexcept
        {
            ScalarMask r;
            for (int i = 0; i < WIDTH; ++i)
                r.m[i] = ((b >> i) & 1u) != 0;
            return r;
        }
    };

    /** \brief 8 floats processed lane by lane. */
    struct ScalarVec
    {
        static constexpr int WIDTH = 8;
        using Mask = ScalarMask;
        float v[WIDTH];

        static const char *name() noexcept { return "scalar"; }

        static ScalarVec broadcast(float x) noexcept
        {
            ScalarVec r;
            for (int i = 0; i < WIDTH; ++i)
                r.v[i] = x;
            return r;
        }
        static ScalarVec zero() noexcept { return broadcast(0.0f); }
        static ScalarVec load(const float *p) noexcept
        {
            ScalarVec r;
            std::memcpy(r.v, p, sizeof(r.v));
            return r;
        }
        void store(float *p) const noexcept { std::memcpy(p, v, sizeof(v)); }
        /// lanes 0, 1, ..., 7
        static ScalarVec iota() noexcept
        {
            ScalarVec r;
            for (int i = 0; i < WIDTH; ++i)
                r.v[i] = static_cast<float>(i);
            return r;
        }
        float lane(int i) const noexcept { return v[i]; }

#define ROPRAS_SCALAR_BINARY(op)                                                  \
    friend ScalarVec operator op(const ScalarVec &a, const ScalarVec &b) noexcept \
    {                                                                             \
        ScalarVec r;                                                              \
        for (int i = 0; i < WIDTH; ++i)                                           \
            r.v[i] = a.v[i] op b.v[i];                                            \
        return r;                                                                 \
    }
        ROPRAS_SCALAR_BINARY(+)
        ROPRAS_SCALAR_BINARY(-)
        ROPRAS_SCALAR_BINARY(*)
        ROPRAS_SCALAR_BINARY(/)
#undef ROPRAS_SCALAR_BINARY

#define ROPRAS_SCALAR_COMPARE(fn, op)                                     \
    friend ScalarMask fn(const ScalarVec &a, const ScalarVec &b) noexcept \
    {                                                                     \
        ScalarMask r;                                                     \
        for (int i = 0; i < WIDTH; ++i)                                   \
            r.m[i] = a.v[i] op b.v[i];                                    \
        return r;                                                         \
    }
        ROPRAS_SCALAR_COMPARE(cmpLt, <)
        ROPRAS_SCALAR_COMPARE(cmpLe, <=)
        ROPRAS_SCALAR_COMPARE(cmpGt, >)
        ROPRAS_SCALAR_COMPARE(cmpGe, >=)
#undef ROPRAS_SCALAR_COMPARE

        /// a * b + c
        friend ScalarVec fma(const ScalarVec &a, const ScalarVec &b, const ScalarVec &c) noexcept
        {
            ScalarVec r;
            for (int i = 0; i < WIDTH; ++i)
                r.v[i] = std::fma(a.v[i], b.v[i], c.v[i]);
            return r;
        }
        /// c - a * b
        friend ScalarVec fnma(const ScalarVec &a, const ScalarVec &b, const ScalarVec &c) noexcept
        {
            ScalarVec r;
            for (int i = 0; i < WIDTH; ++i)
                r.v[i] = std::fma(-a.v[i], b.v[i], c.v[i]);
            return r;
        }
        friend ScalarVec min(const ScalarVec &a, const ScalarVec &b) noexcept
        {
            ScalarVec r;
            for (int i = 0; i < WIDTH; ++i)
                r.v[i] = a.v[i] < b.v[i] ? a.v[i] : b.v[i];
            return r;
        }
        friend ScalarVec max(const ScalarVec &a, const ScalarVec &b) noexcept
        {
            ScalarVec r;
            for (int i = 0; i < WIDTH; ++i)
                r.v[i] = a.v[i] > b.v[i] ? a.v[i] : b.v[i];
            return r;
        }
        /// smallest / largest lane
        friend float hmin(const ScalarVec &a) noexcept
        {
            float m = a.v[0];
            for (int i = 1; i < WIDTH; ++i)
                m = a.v[i] < m ? a.v[i] : m;
            return m;
        }
        friend float hmax(const ScalarVec &a) noexcept
        {
            float m = a.v[0];
            for (int i = 1; i < WIDTH; ++i)
                m = a.v[i] > m ? a.v[i] : m;
            return m;
        }
        friend ScalarVec abs(const ScalarVec &a) noexcept
        {
            ScalarVec r;
            for (int i = 0; i < WIDTH; ++i)
                r.v[i] = std::fabs(a.v[i]);
            return r;
        }
        friend ScalarVec sqrt(const ScalarVec &a) noexcept
        {
            ScalarVec r;
            for (int i = 0; i < WIDTH; ++i)
                r.v[i] = std::sqrt(a.v[i]);
            return r;
        }
        /// round to nearest, ties to even (the current rounding mode)
        friend ScalarVec round(const ScalarVec &a) noexcept
        {
            ScalarVec r;
            for (int i = 0; i < WIDTH; ++i)
                r.v[i] = std::nearbyint(a.v[i]);
            return r;
        }
        friend ScalarVec floor(const ScalarVec &a) noexcept
        {
            ScalarVec r;
            for (int i = 0; i < WIDTH; ++i)
                r.v[i] = std::floor(a.v[i]);
            return r;
        }
        /// a with its sign flipped in the lanes where \a s is -0.0f (s holds +0.0f or -0.0f: an XOR of sign bits)
        friend ScalarVec flipSign(const ScalarVec &a, const ScalarVec &s) noexcept
        {
            ScalarVec r;
            for (int i = 0; i < WIDTH; ++i)
                r.v[i] = std::signbit(s.v[i]) ? -a.v[i] : a.v[i];
            return r;
        }
        /** \brief WIDTH rows of \a dof <= 8 doubles (row-major, consecutive) into \a out as dof vectors of WIDTH
            floats (out[8 j + i] = rows[dof i + j]). True when every value satisfies lo[j] <= v <= hi[j] (NaN
            fails). */
        static bool loadRows(const double *rows, int dof, const double *lo, const double *hi, float *out) noexcept
        {
            bool ok = true;
            for (int i = 0; i < WIDTH; ++i)
                for (int j = 0; j < dof; ++j)
                {
                    const double x = rows[dof * i + j];
                    out[WIDTH * j + i] = static_cast<float>(x);
                    ok = ok && x >= lo[j] && x <= hi[j];
                }
            return ok;
        }
        /// m ? a : b per lane
        friend ScalarVec select(const ScalarMask &m, const ScalarVec &a, const ScalarVec &b) noexcept
        {
            ScalarVec r;
            for (int i = 0; i < WIDTH; ++i)
                r.v[i] = m.m[i] ? a.v[i] : b.v[i];
            return r;
        }
    };
}  // namespace ropras::ompl_ext::simd

#endif
