// The vector backends (private headers of ompl_ext): the AVX2 backend agrees with the portable scalar one,
// and the vectorized sin/cos is accurate over and beyond the joint range.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>
#include <limits>
#include <random>

#include "../../ompl_ext/src/collision/simd/Avx2Vec.h"
#include "../../ompl_ext/src/collision/simd/ScalarVec.h"
#include "../../ompl_ext/src/collision/simd/SinCos.h"

namespace
{
    using ropras::ompl_ext::simd::ScalarVec;

    template <class V>
    double maxSinCosError(double lo, double hi, int n)
    {
        double worst = 0.0;
        for (int k = 0; k < n; k += V::WIDTH)
        {
            float in[V::WIDTH], s[V::WIDTH], c[V::WIDTH];
            for (int i = 0; i < V::WIDTH; ++i)
                in[i] = static_cast<float>(lo + (hi - lo) * (k + i) / (n - 1));
            V vs, vc;
            ropras::ompl_ext::simd::sinCos(V::load(in), vs, vc);
            vs.store(s);
            vc.store(c);
            for (int i = 0; i < V::WIDTH; ++i)
            {
                // reference at the float argument actually used
                worst = std::max(worst, std::abs(s[i] - std::sin(static_cast<double>(in[i]))));
                worst = std::max(worst, std::abs(c[i] - std::cos(static_cast<double>(in[i]))));
            }
        }
        return worst;
    }
}  // namespace

TEST(SimdTest, ScalarSinCosAccurateOverJointRange)
{
    EXPECT_LT(maxSinCosError<ScalarVec>(-2.0 * M_PI, 2.0 * M_PI, 400000), 2e-7);
    EXPECT_LT(maxSinCosError<ScalarVec>(-1.0e-3, 1.0e-3, 8000), 1e-9 + 2e-7);
}

TEST(SimdTest, ScalarSinCosRangeReductionFarOut)
{
    // beyond the joint range the reduction keeps the error at float resolution of the argument
    EXPECT_LT(maxSinCosError<ScalarVec>(-200.0, 200.0, 400000), 5e-7);
}

TEST(SimdTest, SinCosQuadrantsExact)
{
    float in[8] = {0.0f,
                   static_cast<float>(M_PI / 2),
                   static_cast<float>(M_PI),
                   static_cast<float>(-M_PI / 2),
                   static_cast<float>(3 * M_PI / 2),
                   static_cast<float>(-M_PI),
                   static_cast<float>(2 * M_PI),
                   static_cast<float>(M_PI / 4)};
    ScalarVec s, c;
    ropras::ompl_ext::simd::sinCos(ScalarVec::load(in), s, c);
    for (int i = 0; i < 8; ++i)
    {
        EXPECT_NEAR(s.v[i], std::sin(static_cast<double>(in[i])), 2e-7) << "x = " << in[i];
        EXPECT_NEAR(c.v[i], std::cos(static_cast<double>(in[i])), 2e-7) << "x = " << in[i];
    }
}

TEST(SimdTest, ScalarMaskOperations)
{
    using M = ropras::ompl_ext::simd::ScalarMask;
    EXPECT_EQ(M::firstLanes(3).bits(), 0x7u);
    EXPECT_EQ(M::firstLanes(0).bits(), 0x0u);
    EXPECT_EQ(M::firstLanes(9).bits(), 0xFFu);
    EXPECT_EQ(M::fromBits(0xA5u).bits(), 0xA5u);
    EXPECT_EQ((M::fromBits(0xF0u) & M::fromBits(0x3Cu)).bits(), 0x30u);
    EXPECT_EQ((M::fromBits(0xF0u) | M::fromBits(0x0Cu)).bits(), 0xFCu);
    EXPECT_EQ(andNot(M::fromBits(0xF0u), M::fromBits(0x30u)).bits(), 0xC0u);
    EXPECT_FALSE(M::none().any());
    EXPECT_TRUE(M::fromBits(0x80u).any());
}

#ifdef ROPRAS_SIMD_HAVE_AVX2
namespace
{
    using ropras::ompl_ext::simd::Avx2Vec;

    void expectSame(const ScalarVec &a, const Avx2Vec &b, const char *what)
    {
        float fb[8];
        b.store(fb);
        for (int i = 0; i < 8; ++i)
        {
            if (std::isnan(a.v[i]))
                EXPECT_TRUE(std::isnan(fb[i])) << what << " lane " << i;
            else
                EXPECT_EQ(a.v[i], fb[i]) << what << " lane " << i;
        }
    }
}  // namespace

TEST(SimdTest, Avx2SinCosMatchesScalarBackend)
{
    EXPECT_LT(maxSinCosError<Avx2Vec>(-2.0 * M_PI, 2.0 * M_PI, 400000), 2e-7);
    EXPECT_LT(maxSinCosError<Avx2Vec>(-200.0, 200.0, 400000), 5e-7);
    std::mt19937 rng(7);
    std::uniform_real_distribution<float> u(-10.0f, 10.0f);
    for (int k = 0; k < 1000; ++k)
    {
        float in[8];
        for (float &x : in)
            x = u(rng);
        ScalarVec ss, sc;
        Avx2Vec as, ac;
        ropras::ompl_ext::simd::sinCos(ScalarVec::load(in), ss, sc);
        ropras::ompl_ext::simd::sinCos(Avx2Vec::load(in), as, ac);
        expectSame(ss, as, "sin");
        expectSame(sc, ac, "cos");
    }
}

TEST(SimdTest, Avx2OperationsMatchScalarBackend)
{
    std::mt19937 rng(11);
    std::uniform_real_distribution<float> u(-5.0f, 5.0f);
    for (int k = 0; k < 2000; ++k)
    {
        float a[8], b[8], c[8];
        for (int i = 0; i < 8; ++i)
        {
            a[i] = u(rng);
            b[i] = u(rng);
            c[i] = u(rng);
        }
        if (k % 7 == 0)
            b[3] = a[3];  // equal lanes exercise <= versus <
        const ScalarVec sa = ScalarVec::load(a), sb = ScalarVec::load(b), sc = ScalarVec::load(c);
        const Avx2Vec va = Avx2Vec::load(a), vb = Avx2Vec::load(b), vc = Avx2Vec::load(c);
        expectSame(sa + sb, va + vb, "add");
        expectSame(sa - sb, va - vb, "sub");
        expectSame(sa * sb, va * vb, "mul");
        expectSame(sa / sb, va / vb, "div");
        expectSame(fma(sa, sb, sc), fma(va, vb, vc), "fma");
        expectSame(fnma(sa, sb, sc), fnma(va, vb, vc), "fnma");
        expectSame(min(sa, sb), min(va, vb), "min");
        expectSame(max(sa, sb), max(va, vb), "max");
        expectSame(abs(sa), abs(va), "abs");
        expectSame(sqrt(abs(sa)), sqrt(abs(va)), "sqrt");
        expectSame(round(sa), round(va), "round");
        expectSame(floor(sa), floor(va), "floor");
        EXPECT_EQ(cmpLt(sa, sb).bits(), cmpLt(va, vb).bits());
        EXPECT_EQ(cmpLe(sa, sb).bits(), cmpLe(va, vb).bits());
        EXPECT_EQ(cmpGt(sa, sb).bits(), cmpGt(va, vb).bits());
        EXPECT_EQ(cmpGe(sa, sb).bits(), cmpGe(va, vb).bits());
        expectSame(select(cmpLt(sa, sb), sa, sc), select(cmpLt(va, vb), va, vc), "select");
        EXPECT_EQ((cmpLt(sa, sb) & cmpLt(sb, sc)).bits(), (cmpLt(va, vb) & cmpLt(vb, vc)).bits());
        EXPECT_EQ(andNot(cmpLt(sa, sb), cmpLt(sb, sc)).bits(), andNot(cmpLt(va, vb), cmpLt(vb, vc)).bits());
    }
    for (int n = 0; n <= 8; ++n)
        EXPECT_EQ(ropras::ompl_ext::simd::Avx2Mask::firstLanes(n).bits(), (1u << n) - 1u);
    for (unsigned b = 0; b < 256; ++b)
        EXPECT_EQ(ropras::ompl_ext::simd::Avx2Mask::fromBits(b).bits(), b);
    // NaN never compares true (a NaN sphere can never be reported as touching by accident in either backend)
    const float nan = std::nanf("");
    float a[8] = {nan, 1, 2, 3, 4, 5, 6, 7};
    EXPECT_EQ(cmpLe(Avx2Vec::load(a), Avx2Vec::broadcast(100.0f)).bits() & 1u, 0u);
    EXPECT_EQ(cmpLe(ScalarVec::load(a), ScalarVec::broadcast(100.0f)).bits() & 1u, 0u);
}
#else
TEST(SimdTest, Avx2BackendNotCompiled)
{
    GTEST_SKIP() << "this build does not target AVX2+FMA; only the scalar backend is compiled";
}
#endif

// The world boxes the kernels cull obstacles with are conservative: no sphere that penetrates an obstacle
// (exact double-precision signed distance) nor one the exact float kernel test reports is ever culled.
#include "../../ompl_ext/src/collision/simd/Kernels.h"

namespace
{
    using ropras::ompl_ext::Environment;
    using ropras::ompl_ext::simd::obstacleBox;
    using ropras::ompl_ext::simd::ObstacleBox;

    struct CullCounts
    {
        int culled{0}, kept{0}, missed{0};
    };

    /// spheres around the first obstacle of \a env (query form \a o): every penetrating one must be kept
    template <class O, class Exact>
    CullCounts checkCulling(const Environment &env, const O &o, const Exact &exact, std::mt19937_64 &rng)
    {
        const ObstacleBox box = obstacleBox(o);
        std::uniform_real_distribution<double> around(-0.8, 0.8), radius(0.005, 0.15);
        CullCounts counts;
        for (int k = 0; k < 4000; k += ScalarVec::WIDTH)
        {
            float x[8], y[8], z[8], r[8];
            for (int i = 0; i < 8; ++i)
            {
                x[i] = static_cast<float>(box.cx + around(rng));
                y[i] = static_cast<float>(box.cy + around(rng));
                z[i] = static_cast<float>(box.cz + around(rng));
                r[i] = static_cast<float>(radius(rng));
            }
            const ScalarVec vx = ScalarVec::load(x), vy = ScalarVec::load(y), vz = ScalarVec::load(z),
                            vr = ScalarVec::load(r);
            const unsigned keep = ropras::ompl_ext::simd::sphereTouchesBox(vx, vy, vz, vr, box).bits();
            const unsigned hit = exact(vx, vy, vz, vr);
            for (int i = 0; i < 8; ++i)
            {
                const bool kept = ((keep >> i) & 1u) != 0u;
                const double d = env.signedDistance(Eigen::Vector3d(x[i], y[i], z[i]), r[i]);
                if (!kept && (((hit >> i) & 1u) != 0u || d <= -1e-5))
                    ++counts.missed;
                kept ? ++counts.kept : ++counts.culled;
            }
        }
        return counts;
    }

    Eigen::Isometry3d randomPose(std::mt19937_64 &rng)
    {
        std::normal_distribution<double> g(0.0, 1.0);
        Eigen::Isometry3d p = Eigen::Isometry3d::Identity();
        p.linear() = Eigen::Quaterniond(g(rng), g(rng), g(rng), g(rng)).normalized().toRotationMatrix();
        p.translation() = Eigen::Vector3d(g(rng), g(rng), g(rng)) * 0.5;
        return p;
    }
}  // namespace

TEST(SimdTest, ObstacleCullingBoxesAreConservative)
{
    using namespace ropras::ompl_ext;
    using namespace ropras::ompl_ext::simd;
    std::mt19937_64 rng(2024);
    std::uniform_real_distribution<double> size(0.02, 0.6);
    CullCounts total;
    const auto add = [&](const CullCounts &c)
    {
        total.culled += c.culled;
        total.kept += c.kept;
        total.missed += c.missed;
    };
    for (int trial = 0; trial < 30; ++trial)
    {
        {
            Environment env;
            env.addBox("b", randomPose(rng), Eigen::Vector3d(size(rng), size(rng), 0.2 * size(rng)));
            const BoxObstacle &o = env.boxes()[0];
            add(checkCulling(
                env, o,
                [&](const ScalarVec &x, const ScalarVec &y, const ScalarVec &z, const ScalarVec &r)
                { return hitBox(x, y, z, r, o).bits(); },
                rng));
        }
        {
            Environment env;
            env.addCylinder("c", randomPose(rng), 0.5 * size(rng), size(rng));
            const CylinderObstacle &o = env.cylinders()[0];
            add(checkCulling(
                env, o,
                [&](const ScalarVec &x, const ScalarVec &y, const ScalarVec &z, const ScalarVec &r)
                { return hitCylinder(x, y, z, r, o).bits(); },
                rng));
        }
        {
            Environment env;
            env.addCapsule("k", randomPose(rng), 0.3 * size(rng), size(rng));
            const CapsuleObstacle &o = env.capsules()[0];
            add(checkCulling(
                env, o,
                [&](const ScalarVec &x, const ScalarVec &y, const ScalarVec &z, const ScalarVec &r)
                { return hitCapsule(x, y, z, r, o).bits(); },
                rng));
        }
        {
            Environment env;
            env.addSphere("s", randomPose(rng).translation(), 0.5 * size(rng));
            const SphereObstacle &o = env.spheres()[0];
            add(checkCulling(
                env, o,
                [&](const ScalarVec &x, const ScalarVec &y, const ScalarVec &z, const ScalarVec &r)
                { return hitSphere(x, y, z, r, o).bits(); },
                rng));
        }
    }
    EXPECT_EQ(total.missed, 0) << "a culling box dropped a penetrating sphere";
    // both outcomes are exercised, and the boxes do cull
    EXPECT_GT(total.culled, 50000);
    EXPECT_GT(total.kept, 5000);
}

namespace
{
    /// loadRows of backend V: out[8 j + i] == (float) rows[dof i + j] bit for bit, true iff every value is within
    /// [lo_j, hi_j] (limits included, NaN and infinities outside), for every row length 1..8
    template <class V>
    void checkLoadRows(std::uint32_t seed)
    {
        std::mt19937 rng(seed);
        std::uniform_real_distribution<double> u(-4.0, 4.0);
        const double nan = std::nan(""), inf = std::numeric_limits<double>::infinity();
        int inside = 0, outside = 0;
        for (int k = 0; k < 4000; ++k)
        {
            const int dof = 1 + k % 8;
            double lo[8], hi[8], rows[64];
            for (int j = 0; j < dof; ++j)
            {
                lo[j] = -3.0 + 0.1 * u(rng);
                hi[j] = 3.0 + 0.1 * u(rng);
            }
            bool expected = true;
            for (int n = 0; n < 8 * dof; ++n)
            {
                const int j = n % dof;
                double x = 0.7 * u(rng);
                switch ((k / 8 + n) % 23)
                {
                    case 0:
                        x = (k % 3 == 0) ? lo[j] : hi[j];  // the limits themselves are inside
                        break;
                    case 1:
                        if (k % 5 == 0)
                            x = (k % 2 == 0) ? std::nextafter(hi[j], inf) : std::nextafter(lo[j], -inf);
                        break;
                    case 2:
                        if (k % 11 == 0)
                            x = (k % 2 == 0) ? nan : -inf;
                        break;
                    default:
                        break;
                }
                rows[n] = x;
                expected = expected && x >= lo[j] && x <= hi[j];
            }
            float out[64];
            for (float &o : out)
                o = -1234.0f;
            const bool ok = V::loadRows(rows, dof, lo, hi, out);
            EXPECT_EQ(ok, expected) << V::name() << " dof " << dof << " k " << k;
            (ok ? inside : outside) += 1;
            for (int i = 0; i < 8; ++i)
                for (int j = 0; j < dof; ++j)
                {
                    const float want = static_cast<float>(rows[dof * i + j]);
                    const float got = out[8 * j + i];
                    if (std::isnan(want))
                        EXPECT_TRUE(std::isnan(got)) << V::name() << " dof " << dof << " row " << i << " joint " << j;
                    else
                        EXPECT_EQ(got, want) << V::name() << " dof " << dof << " row " << i << " joint " << j;
                }
            for (int n = 8 * dof; n < 64; ++n)
                EXPECT_EQ(out[n], -1234.0f) << V::name() << ": wrote past dof columns";
        }
        EXPECT_GT(inside, 400);
        EXPECT_GT(outside, 400);
    }
}  // namespace

TEST(SimdTest, ScalarLoadRowsTransposesAndChecksLimits)
{
    checkLoadRows<ScalarVec>(21);
}

#ifdef ROPRAS_SIMD_HAVE_AVX2
TEST(SimdTest, Avx2LoadRowsAndFlipSignMatchScalarBackend)
{
    using ropras::ompl_ext::simd::Avx2Vec;
    checkLoadRows<Avx2Vec>(21);
    std::mt19937 rng(22);
    std::uniform_real_distribution<float> u(-5.0f, 5.0f);
    for (int k = 0; k < 1000; ++k)
    {
        float a[8], s[8], fs[8], fa[8];
        for (int i = 0; i < 8; ++i)
        {
            a[i] = u(rng);
            s[i] = ((k >> i) & 1) != 0 ? -0.0f : 0.0f;
        }
        flipSign(ScalarVec::load(a), ScalarVec::load(s)).store(fs);
        flipSign(Avx2Vec::load(a), Avx2Vec::load(s)).store(fa);
        for (int i = 0; i < 8; ++i)
        {
            EXPECT_EQ(fs[i], std::signbit(s[i]) ? -a[i] : a[i]);
            EXPECT_EQ(fa[i], fs[i]);
        }
    }
}
#endif
