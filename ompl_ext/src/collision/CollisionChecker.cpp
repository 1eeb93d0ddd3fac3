#include "ropras/ompl_ext/collision/CollisionChecker.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <string>
#include <vector>

#include "collision/simd/Avx2Vec.h"
#include "collision/simd/Kernels.h"
#include "collision/simd/KinematicProgram.h"
#include "collision/simd/ProgramCompiler.h"
#include "collision/simd/ScalarVec.h"
#include "ropras/core/Error.h"

namespace ropras::ompl_ext
{
    namespace
    {
        using simd::KinematicProgram;
        using simd::WIDTH;

        /// per-thread scratch: grows to the largest layout any checker asked for on this thread, then stays
        float *threadScratch(std::size_t floats) noexcept
        {
            static thread_local std::vector<float> buffer;
            if (buffer.size() < floats)
                buffer.resize(floats);
            return buffer.data();
        }

        bool withinLimits(const KinematicProgram &p, const double *q) noexcept
        {
            // lowerCheck / upperCheck are +-DBL_MAX for continuous joints: NaN fails both comparisons, +-inf one
            const double *lo = p.lowerCheck.data(), *hi = p.upperCheck.data();
            for (int j = 0; j < p.dof; ++j)
                if (!(q[j] >= lo[j] && q[j] <= hi[j]))
                    return false;
            return true;
        }

        /// joint values of lane \a lane into the batch q block (angles reduced for sin/cos)
        void putLane(const KinematicProgram &p, const double *q, int lane, float *qBlock) noexcept
        {
            for (int j = 0; j < p.dof; ++j)
                qBlock[WIDTH * j + lane] =
                    p.rotational[static_cast<std::size_t>(j)] ? simd::angleArgument(q[j]) : static_cast<float>(q[j]);
        }

        template <class V>
        struct Backend
        {
            using K = simd::Kernels<V>;

            static bool isValid(const KinematicProgram &p, const Environment &env, const double *q) noexcept
            {
                if (!withinLimits(p, q))
                    return false;
                return K::validSingle(p, env, q, threadScratch(p.single.total));
            }

            /** \brief WIDTH rows straight into the batch q block (AVX2: row loads, conversion and an 8 x 8
                transpose in registers), limits compared in double. False when some row is non-finite or out of its
                limits, or some angle needs the double reduction (|q| >= 64), or dof > WIDTH: the caller then takes
                the row-by-row path. */
            static bool loadRows(const KinematicProgram &p, const double *rows, float *qBlock) noexcept
            {
                if (p.dof > WIDTH || !V::loadRows(rows, p.dof, p.lowerCheck.data(), p.upperCheck.data(), qBlock))
                    return false;
                for (const int j : p.reduceCheck)
                    if (cmpGe(abs(V::load(qBlock + WIDTH * j)), V::broadcast(64.0f)).any())
                        return false;
                return true;
            }

            /// \a self false: the robot's self pairs are not tested (CollisionChecker::obstacleHitsBatch)
            static std::size_t isValidBatch(const KinematicProgram &p, const Environment &env, const double *qs,
                                            std::size_t count, bool *valid, bool self = true) noexcept
            {
                const auto dof = static_cast<std::size_t>(p.dof);
                float *buf = threadScratch(std::max(p.batch.total, p.single.total));
                std::size_t nValid = 0;
                for (std::size_t start = 0; start < count; start += WIDTH)
                {
                    const std::size_t n = std::min<std::size_t>(WIDTH, count - start);
                    if (n == 1 && self)
                    {
                        const double *q = qs + start * dof;
                        valid[start] = withinLimits(p, q) && K::validSingle(p, env, q, buf);
                        nValid += valid[start] ? 1 : 0;
                        continue;
                    }
                    if (n == WIDTH && loadRows(p, qs + start * dof, buf + p.batch.q))
                    {
                        // every row finite, within its limits and with angles in the float range: no fix-ups
                        K::framesBatch(p, buf);
                        constexpr unsigned all = (1u << WIDTH) - 1u;
                        const unsigned ok = all & ~K::collideBatch(p, env, buf, all, false, self);
                        for (std::size_t i = 0; i < n; ++i)
                        {
                            valid[start + i] = ((ok >> i) & 1u) != 0u;
                            nValid += valid[start + i] ? 1 : 0;
                        }
                        continue;
                    }
                    unsigned active = 0u;
                    int firstGood = -1;
                    for (std::size_t i = 0; i < n; ++i)
                        if (withinLimits(p, qs + (start + i) * dof))
                        {
                            active |= 1u << i;
                            if (firstGood < 0)
                                firstGood = static_cast<int>(i);
                        }
                    if (active == 0u)
                    {
                        for (std::size_t i = 0; i < n; ++i)
                            valid[start + i] = false;
                        continue;
                    }
                    // inactive lanes repeat a good configuration so that every lane computes finite numbers
                    for (int i = 0; i < WIDTH; ++i)
                    {
                        const bool own = (active >> i) & 1u;
                        const std::size_t row = start + static_cast<std::size_t>(own ? i : firstGood);
                        putLane(p, qs + row * dof, i, buf + p.batch.q);
                    }
                    K::framesBatch(p, buf);
                    const unsigned ok = active & ~K::collideBatch(p, env, buf, active, false, self);
                    for (std::size_t i = 0; i < n; ++i)
                    {
                        valid[start + i] = ((ok >> i) & 1u) != 0u;
                        nValid += valid[start + i] ? 1 : 0;
                    }
                }
                return nValid;
            }

            /** \brief True when all \a count rows are valid; stops at the first block of WIDTH rows in which some
                lane collides (VAMP's query: the block is decided by its first collision in any lane). */
            static bool allValid(const KinematicProgram &p, const Environment &env, const double *qs,
                                 std::size_t count) noexcept
            {
                const auto dof = static_cast<std::size_t>(p.dof);
                float *buf = threadScratch(std::max(p.batch.total, p.single.total));
                constexpr unsigned all = (1u << WIDTH) - 1u;
                for (std::size_t start = 0; start < count; start += WIDTH)
                {
                    const std::size_t n = std::min<std::size_t>(WIDTH, count - start);
                    const double *rows = qs + start * dof;
                    if (n == 1)
                    {
                        if (!withinLimits(p, rows) || !K::validSingle(p, env, rows, buf))
                            return false;
                        continue;
                    }
                    if (n < WIDTH || !loadRows(p, rows, buf + p.batch.q))
                    {
                        // a short block, or some row needs a look: every row within its limits, missing lanes
                        // repeat the last row
                        for (std::size_t i = 0; i < n; ++i)
                            if (!withinLimits(p, rows + i * dof))
                                return false;
                        for (int i = 0; i < WIDTH; ++i)
                            putLane(p, rows + std::min<std::size_t>(static_cast<std::size_t>(i), n - 1) * dof, i,
                                    buf + p.batch.q);
                    }
                    K::framesBatch(p, buf);
                    if (K::collideBatch(p, env, buf, all, true) != 0u)
                        return false;
                }
                return true;
            }

            /// fills the batch q block with samples idx[i] / n of q0 -> q0 + d
            static void putSamples(const KinematicProgram &p, const float *q0, const float *d, const double *idx,
                                   double n, float *qBlock) noexcept
            {
                float t[WIDTH];
                for (int i = 0; i < WIDTH; ++i)
                    t[i] = static_cast<float>(idx[i] / n);
                const V tv = V::load(t);
                for (int j = 0; j < p.dof; ++j)
                    fma(tv, V::broadcast(d[j]), V::broadcast(q0[j])).store(qBlock + WIDTH * j);
            }

            static bool isMotionValid(const KinematicProgram &p, const Environment &env, const double *q0,
                                      const double *q1, double resolution, double *lastValid, bool checkStart) noexcept
            {
                if (lastValid != nullptr)
                    *lastValid = 0.0;
                if (!(resolution > 0.0) || !std::isfinite(resolution) || !withinLimits(p, q0) || !withinLimits(p, q1))
                    return false;
                double maxStep = 0.0;
                for (int j = 0; j < p.dof; ++j)
                    maxStep = std::max(maxStep, std::abs(q1[j] - q0[j]));
                const double steps = std::ceil(maxStep / resolution);
                if (!(steps <= 1e8))  // absurd resolution for the distance: refuse rather than run for hours
                    return false;
                const auto n = std::max<long long>(1, static_cast<long long>(steps));
                const long long k0 = checkStart ? 0 : 1;
                const long long samples = n - k0 + 1;
                float *buf = threadScratch(std::max(p.batch.total, p.single.total));
                if (samples == 1)  // only q1: the single-configuration path
                {
                    if (K::validSingle(p, env, q1, buf))
                        return true;
                    return false;  // lastValid = 0: q0 is the last configuration known valid
                }
                // q0 and d in float; angles reduced (q0 + t d stays close to the reduced range)
                float q0f[64], df[64];
                std::vector<float> bigQ0, bigD;
                float *q0p = q0f, *dp = df;
                if (p.dof > 64)
                {
                    // not reached for real arms; keeps arbitrary models correct (allocates)
                    bigQ0.resize(static_cast<std::size_t>(p.dof));
                    bigD.resize(static_cast<std::size_t>(p.dof));
                    q0p = bigQ0.data();
                    dp = bigD.data();
                }
                for (int j = 0; j < p.dof; ++j)
                {
                    const bool rot = p.rotational[static_cast<std::size_t>(j)];
                    q0p[j] = rot ? simd::angleArgument(q0[j]) : static_cast<float>(q0[j]);
                    dp[j] = static_cast<float>(q1[j] - q0[j]);
                }
                const double nd = static_cast<double>(n);
                // rake: lane i walks the i-th of WIDTH consecutive segments, all lanes advance together, visiting
                // the segment's offsets middle first in bit-reversed order (segment 4: 2 0 3 1), so that the
                // samples checked so far stay evenly spread and a collision inside the motion is found early
                const long long segment = (samples + WIDTH - 1) / WIDTH;
                int bits = 0;
                while ((1LL << bits) < segment)
                    ++bits;
                const long long half = (1LL << bits) >> 1;
                long long r = 0;
                const auto nextOffset = [&]
                {
                    for (;; ++r)
                    {
                        long long v = 0;
                        for (int b = 0; b < bits; ++b)
                            v |= ((r >> b) & 1LL) << (bits - 1 - b);
                        v ^= half;
                        if (v < segment)
                        {
                            ++r;
                            return v;
                        }
                    }
                };
                double idx[WIDTH];
                long long firstBad = -1;
                for (long long j = 0; j < segment && firstBad < 0; ++j)
                {
                    const long long offset = nextOffset();
                    for (int i = 0; i < WIDTH; ++i)
                        idx[i] = static_cast<double>(std::min(n, k0 + i * segment + offset));
                    putSamples(p, q0p, dp, idx, nd, buf + p.batch.q);
                    K::framesBatch(p, buf);
                    const unsigned hit = K::collideBatch(p, env, buf, (1u << WIDTH) - 1u, true);
                    if (hit != 0u)
                        firstBad = static_cast<long long>(idx[__builtin_ctz(hit)]);
                }
                if (firstBad < 0)
                    return true;
                if (lastValid == nullptr)
                    return false;
                // the first invalid sample: scan the samples before firstBad in order, WIDTH at a time
                for (long long base = k0; base < firstBad; base += WIDTH)
                {
                    for (int i = 0; i < WIDTH; ++i)
                        idx[i] = static_cast<double>(std::min(firstBad - 1, base + i));
                    putSamples(p, q0p, dp, idx, nd, buf + p.batch.q);
                    K::framesBatch(p, buf);
                    const unsigned hit = K::collideBatch(p, env, buf, (1u << WIDTH) - 1u, false);
                    if (hit != 0u)
                    {
                        firstBad = static_cast<long long>(idx[__builtin_ctz(hit)]);
                        break;
                    }
                }
                *lastValid = firstBad <= 0 ? 0.0 : static_cast<double>(firstBad - 1) / nd;
                return false;
            }

            static void sphereCenters(const KinematicProgram &p, const double *q, float *out) noexcept
            {
                float *buf = threadScratch(p.single.total);
                K::framesSingle(p, q, buf);
                simd::Placed placed;
                K::placeAll(p, buf, placed);
                for (std::size_t s = 0; s < p.programIndexOfSphere.size(); ++s)
                {
                    const auto k = static_cast<std::size_t>(p.programIndexOfSphere[s]);
                    out[4 * s] = buf[p.single.sx + k];
                    out[4 * s + 1] = buf[p.single.sy + k];
                    out[4 * s + 2] = buf[p.single.sz + k];
                    out[4 * s + 3] = p.sr[k];
                }
            }

            static void sphereCentersBatch(const KinematicProgram &p, const double *qs, float *out) noexcept
            {
                float *buf = threadScratch(p.batch.total);
                // rows within their limits load in registers (loadRows); any other row lane by lane, the same values
                if (!loadRows(p, qs, buf + p.batch.q))
                    for (int i = 0; i < WIDTH; ++i)
                        putLane(p, qs + static_cast<std::size_t>(i) * static_cast<std::size_t>(p.dof), i,
                                buf + p.batch.q);
                K::framesBatch(p, buf);
                K::sphereCentersBatch(p, buf, out);
            }
        };

        using ScalarBackend = Backend<simd::ScalarVec>;
#ifdef ROPRAS_SIMD_HAVE_AVX2
        using Avx2Backend = Backend<simd::Avx2Vec>;
#endif
    }  // namespace

    bool simdBackendAvailable(SimdBackend backend) noexcept
    {
        switch (backend)
        {
            case SimdBackend::Best:
            case SimdBackend::Scalar:
                return true;
            case SimdBackend::Avx2:
#ifdef ROPRAS_SIMD_HAVE_AVX2
                return true;
#else
                return false;
#endif
        }
        return false;
    }

    const char *simdBackendName(SimdBackend backend) noexcept
    {
        switch (backend)
        {
            case SimdBackend::Best:
                return "best";
            case SimdBackend::Scalar:
                return "scalar";
            case SimdBackend::Avx2:
                return "avx2";
        }
        return "unknown";
    }

    struct CollisionChecker::Program
    {
        KinematicProgram kp;
    };

    CollisionChecker::CollisionChecker(std::shared_ptr<const RobotModel> robot, SimdBackend backend)
        : robot_(std::move(robot)), backend_(backend)
    {
        if (!robot_)
            throw Error("CollisionChecker: null RobotModel");
        if (backend_ == SimdBackend::Best)
            backend_ = simdBackendAvailable(SimdBackend::Avx2) ? SimdBackend::Avx2 : SimdBackend::Scalar;
        if (!simdBackendAvailable(backend_))
            throw Error(std::string("CollisionChecker: SIMD backend '") + simdBackendName(backend_) +
                        "' is not compiled into this build (configure with ROPRAS_NATIVE_SIMD=ON on an AVX2+FMA "
                        "machine); use SimdBackend::Best or SimdBackend::Scalar");

        program_ = std::make_unique<Program>();
        program_->kp = simd::compileProgram(*robot_);
        const KinematicProgram &p = program_->kp;
        // size this thread's scratch now, so the first check on it does not allocate
        threadScratch(std::max(p.single.total, p.batch.total));
    }

    CollisionChecker::~CollisionChecker() = default;

    int CollisionChecker::width() const noexcept
    {
        return WIDTH;
    }

    std::size_t CollisionChecker::selfSpherePairs() const noexcept
    {
        std::size_t n = 0;
        for (const std::uint8_t mask : program_->kp.selfPairSphereMasks)
            n += static_cast<std::size_t>(__builtin_popcount(mask));
        return n;
    }

#ifdef ROPRAS_SIMD_HAVE_AVX2
#define ROPRAS_DISPATCH(call) (backend_ == SimdBackend::Avx2 ? Avx2Backend::call : ScalarBackend::call)
#else
#define ROPRAS_DISPATCH(call) ScalarBackend::call
#endif

    bool CollisionChecker::isValid(const Environment &env, const double *q) const noexcept
    {
        return ROPRAS_DISPATCH(isValid(program_->kp, env, q));
    }

    std::size_t CollisionChecker::isValidBatch(const Environment &env, const double *qs, std::size_t count,
                                               bool *valid) const noexcept
    {
        return ROPRAS_DISPATCH(isValidBatch(program_->kp, env, qs, count, valid));
    }

    std::size_t CollisionChecker::obstacleHitsBatch(const Environment &env, const double *qs, std::size_t count,
                                                    bool *hit) const noexcept
    {
        const std::size_t clear = ROPRAS_DISPATCH(isValidBatch(program_->kp, env, qs, count, hit, false));
        for (std::size_t i = 0; i < count; ++i)
            hit[i] = !hit[i];
        return count - clear;
    }

    bool CollisionChecker::allValid(const Environment &env, const double *qs, std::size_t count) const noexcept
    {
        return ROPRAS_DISPATCH(allValid(program_->kp, env, qs, count));
    }

    bool CollisionChecker::isMotionValid(const Environment &env, const double *q0, const double *q1, double resolution,
                                         double *lastValidFraction, bool checkStart) const noexcept
    {
        const bool valid =
            ROPRAS_DISPATCH(isMotionValid(program_->kp, env, q0, q1, resolution, lastValidFraction, checkStart));
        if (valid && lastValidFraction != nullptr)
            *lastValidFraction = 1.0;  // the whole motion: a caller may interpolate with it either way
        return valid;
    }

    void CollisionChecker::sphereCenters(const double *q, float *out) const noexcept
    {
        ROPRAS_DISPATCH(sphereCenters(program_->kp, q, out));
    }

    void CollisionChecker::sphereCentersBatch(const double *qs, float *out) const noexcept
    {
        ROPRAS_DISPATCH(sphereCentersBatch(program_->kp, qs, out));
    }
#undef ROPRAS_DISPATCH
}  // namespace ropras::ompl_ext
