// Vectorized sin and cos for any backend V (ScalarVec, Avx2Vec): Cody-Waite reduction by pi/2 in three parts,
// then minimax polynomials on [-pi/4, pi/4]. Absolute error ~1e-7 for |x| up to a few thousand radians.
#ifndef ROPRAS_OMPL_EXT_SIMD_SIN_COS_H
#define ROPRAS_OMPL_EXT_SIMD_SIN_COS_H

namespace ropras::ompl_ext::simd
{
    /** \brief s = sin(x), c = cos(x) lane by lane. */
    template <class V>
    inline void sinCos(const V &x, V &s, V &c) noexcept
    {
        // quadrant j = round(x * 2/pi); r = x - j * pi/2 with pi/2 split into three floats (sum exact to ~1e-24)
        const V j = round(x * V::broadcast(0.636619772367581343f));
        V r = fnma(j, V::broadcast(1.5703125f), x);
        r = fnma(j, V::broadcast(4.837512969970703125e-4f), r);
        r = fnma(j, V::broadcast(7.54978995489188216e-8f), r);
        const V r2 = r * r;
        // sin on [-pi/4, pi/4]: r + r^3 (s1 + r^2 (s2 + r^2 s3)); cos: 1 - r^2/2 + r^4 (c1 + r^2 (c2 + r^2 c3))
        V ps = fma(r2, V::broadcast(-1.9515295891e-4f), V::broadcast(8.3321608736e-3f));
        ps = fma(r2, ps, V::broadcast(-1.6666654611e-1f));
        ps = fma(r2 * r, ps, r);
        V pc = fma(r2, V::broadcast(2.443315711809948e-5f), V::broadcast(-1.388731625493765e-3f));
        pc = fma(r2, pc, V::broadcast(4.166664568298827e-2f));
        pc = fma(r2 * r2, pc, fnma(r2, V::broadcast(0.5f), V::broadcast(1.0f)));
        // quadrant q = j mod 4 in {0, 1, 2, 3}
        const V q = j - V::broadcast(4.0f) * floor(j * V::broadcast(0.25f));
        const auto odd = (cmpGt(q, V::broadcast(0.5f)) & cmpLt(q, V::broadcast(1.5f))) | cmpGt(q, V::broadcast(2.5f));
        const V sinBase = select(odd, pc, ps);
        const V cosBase = select(odd, ps, pc);
        // sin negative in quadrants 2, 3; cos negative in quadrants 1, 2
        const auto sinNeg = cmpGt(q, V::broadcast(1.5f));
        const auto cosNeg = cmpGt(q, V::broadcast(0.5f)) & cmpLt(q, V::broadcast(2.5f));
        s = select(sinNeg, V::zero() - sinBase, sinBase);
        c = select(cosNeg, V::zero() - cosBase, cosBase);
    }
}  // namespace ropras::ompl_ext::simd

#endif
