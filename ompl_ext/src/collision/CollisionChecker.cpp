#include "ropras/ompl_ext/collision/CollisionChecker.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>
#include <string>
#include <unordered_set>
#include <vector>

#include "collision/simd/Avx2Vec.h"
#include "collision/simd/Kernels.h"
#include "collision/simd/KinematicProgram.h"
#include "collision/simd/ScalarVec.h"
#include "model/EnclosingSphere.h"
#include "ropras/core/Error.h"
#include "ropras/ompl_ext/model/SphereReach.h"

namespace ropras::ompl_ext
{
    namespace
    {
        using simd::KinematicProgram;
        using simd::WIDTH;

        /// offset rotation entries within this of 0 or +-1 make a signed permutation (folded in the batch path)
        constexpr double PERMUTATION_TOLERANCE = 1e-9;

        /// collision links with more than WIDTH spheres become program links of at most this many spheres
        constexpr std::size_t SUB_LINK_SPHERES = 6;

        /// per-thread scratch: grows to the largest layout any checker asked for on this thread, then stays
        float *threadScratch(std::size_t floats) noexcept
        {
            static thread_local std::vector<float> buffer;
            if (buffer.size() < floats)
                buffer.resize(floats);
            return buffer.data();
        }

        /// a bounding radius enlarged for float rounding: culling with it may never drop a touching sphere
        float withRoundingSlack(double radius)
        {
            return static_cast<float>(radius * (1.0 + 1e-5) + 1e-6);
        }

        std::size_t roundUp(std::size_t n)
        {
            return (n + WIDTH - 1) / WIDTH * WIDTH;
        }

        void toFloat12(const Eigen::Isometry3d &t, float *out)
        {
            for (int i = 0; i < 3; ++i)
            {
                for (int j = 0; j < 3; ++j)
                    out[3 * i + j] = static_cast<float>(t.linear()(i, j));
                out[9 + i] = static_cast<float>(t.translation()(i));
            }
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

            static std::size_t isValidBatch(const KinematicProgram &p, const Environment &env, const double *qs,
                                            std::size_t count, bool *valid) noexcept
            {
                const auto dof = static_cast<std::size_t>(p.dof);
                float *buf = threadScratch(std::max(p.batch.total, p.single.total));
                std::size_t nValid = 0;
                for (std::size_t start = 0; start < count; start += WIDTH)
                {
                    const std::size_t n = std::min<std::size_t>(WIDTH, count - start);
                    if (n == 1)
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
                        const unsigned ok = all & ~K::collideBatch(p, env, buf, all, false);
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
                    const unsigned ok = active & ~K::collideBatch(p, env, buf, active, false);
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
                for (int i = 0; i < WIDTH; ++i)
                    putLane(p, qs + static_cast<std::size_t>(i) * static_cast<std::size_t>(p.dof), i, buf + p.batch.q);
                K::framesBatch(p, buf);
                simd::Placed placed;
                K::placeAllBatch(p, buf, placed);
                for (std::size_t s = 0; s < p.programIndexOfSphere.size(); ++s)
                {
                    const auto k = static_cast<std::size_t>(p.programIndexOfSphere[s]);
                    V::load(buf + p.batch.sx + WIDTH * k).store(out + (4 * s) * WIDTH);
                    V::load(buf + p.batch.sy + WIDTH * k).store(out + (4 * s + 1) * WIDTH);
                    V::load(buf + p.batch.sz + WIDTH * k).store(out + (4 * s + 2) * WIDTH);
                    V::broadcast(p.sr[k]).store(out + (4 * s + 3) * WIDTH);
                }
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
        KinematicProgram &p = program_->kp;
        const RobotModel &model = *robot_;
        p.model = robot_.get();
        p.dof = static_cast<int>(model.dof());

        p.rotational.assign(model.dof(), 0);
        // the limit test as one pair of comparisons (NaN fails both, infinities one; continuous joints: any finite)
        const double big = std::numeric_limits<double>::max();
        for (const PlanningJoint &joint : model.joints())
        {
            const bool unbounded = joint.type == JointType::Continuous;
            p.lowerCheck.push_back(unbounded ? -big : std::max(joint.lower, -big));
            p.upperCheck.push_back(unbounded ? big : std::min(joint.upper, big));
        }

        const auto &frames = model.frames();
        p.frames.resize(frames.size());
        for (std::size_t f = 0; f < frames.size(); ++f)
        {
            const KinematicFrame &frame = frames[f];
            simd::FrameOp &op = p.frames[f];
            if (frame.parent >= static_cast<int>(f) || (f > 0 && frame.parent < 0))
                throw Error("CollisionChecker: robot '" + model.name() + "' frame '" + frame.name +
                            "' is not in topological order (parent " + std::to_string(frame.parent) + ")");
            op.parent = frame.parent;
            op.variable = frame.variable;
            op.motion = simd::Motion::None;
            if (frame.variable >= p.dof)
                throw Error("CollisionChecker: robot '" + model.name() + "' frame '" + frame.name +
                            "' refers to variable " + std::to_string(frame.variable) + " of " + std::to_string(p.dof));
            if (frame.variable >= 0 && frame.motion == JointMotion::RotateZ)
            {
                op.motion = simd::Motion::RotateZ;
                p.rotational[static_cast<std::size_t>(frame.variable)] = 1;
            }
            else if (frame.variable >= 0 && frame.motion == JointMotion::TranslateZ)
                op.motion = simd::Motion::TranslateZ;
            toFloat12(frame.offset, op.offset);
            for (int k = 0; k < 3; ++k)
                for (int i = 0; i < 4; ++i)
                {
                    op.offsetPairs[8 * k + i] = static_cast<float>(frame.offset.linear()(k, 0));
                    op.offsetPairs[8 * k + 4 + i] = static_cast<float>(frame.offset.linear()(k, 1));
                    op.offsetPairs[24 + 8 * k + i] = static_cast<float>(frame.offset.linear()(k, 2));
                    op.offsetPairs[24 + 8 * k + 4 + i] = static_cast<float>(frame.offset.translation()(k));
                }
            // fold signed-permutation rotations and zero translation components
            op.permutation = true;
            op.flipColumns = 0u;
            int perm[3] = {0, 1, 2};  // column j of the offset rotation is +-e_perm[j]
            for (int j = 0; j < 3 && op.permutation; ++j)
            {
                int nonZero = 0;
                for (int i = 0; i < 3; ++i)
                {
                    const double v = frame.offset.linear()(i, j);
                    // URDFs write pi/2 with ~11 digits (cos = 5e-12): entries below 1e-9 are zero, far below
                    // float resolution (the float offset holds them as noise under 1e-9 of the other terms)
                    if (std::abs(v) > PERMUTATION_TOLERANCE)
                    {
                        ++nonZero;
                        perm[j] = i;
                        op.flipColumns |= (v < 0.0 ? 1u : 0u) << j;
                        if (std::abs(std::abs(v) - 1.0) > PERMUTATION_TOLERANCE)
                            op.permutation = false;
                    }
                }
                if (nonZero != 1)
                    op.permutation = false;
            }
            if (op.permutation)
            {
                op.permId = -1;
                for (int k = 0; k < 6; ++k)
                    if (std::equal(perm, perm + 3, simd::PERMUTATIONS[k]))
                        op.permId = k;
                if (op.permId < 0)  // two columns from the same source: not a permutation after all
                    op.permutation = false;
            }
            if (!op.permutation)
            {
                op.permId = 0;
                op.flipColumns = 0u;
            }
            op.translationMask = 0u;
            for (int k = 0; k < 3; ++k)
                if (frame.offset.translation()(k) != 0.0)
                    op.translationMask |= 1u << k;
        }

        // spheres in program order: collision link by collision link
        const auto &collisionLinks = model.collisionLinks();
        const auto &spheres = model.spheres();
        p.programIndexOfSphere.assign(spheres.size(), -1);
        // program links of each collision link: a link with more than WIDTH spheres is split into groups of at
        // most SUB_LINK_SPHERES neighbouring spheres, each with its own bound (tighter culling, fewer fine tests)
        std::vector<std::vector<int>> linkIndex(collisionLinks.size());
        for (std::size_t c = 0; c < collisionLinks.size(); ++c)
        {
            const CollisionLink &cl = collisionLinks[c];
            if (cl.sphereCount <= 0)
                continue;
            if (cl.frame < 0 || cl.frame >= static_cast<int>(frames.size()) || cl.firstSphere < 0 ||
                cl.firstSphere + cl.sphereCount > static_cast<int>(spheres.size()))
                throw Error("CollisionChecker: robot '" + model.name() + "' collision link '" + cl.name +
                            "' has an invalid frame or sphere range");
            std::vector<int> order(static_cast<std::size_t>(cl.sphereCount));
            for (int k = 0; k < cl.sphereCount; ++k)
                order[static_cast<std::size_t>(k)] = cl.firstSphere + k;
            std::vector<std::vector<int>> groups;
            if (cl.sphereCount <= WIDTH)
                groups.push_back(order);
            else
            {
                // sort along the axis of largest extent of the centres, then cut into equal contiguous groups
                Eigen::Vector3d lo = Eigen::Vector3d::Constant(1e300), hi = -lo;
                for (const int s : order)
                {
                    lo = lo.cwiseMin(spheres[static_cast<std::size_t>(s)].centerInFrame);
                    hi = hi.cwiseMax(spheres[static_cast<std::size_t>(s)].centerInFrame);
                }
                int axis = 0;
                (hi - lo).maxCoeff(&axis);
                std::stable_sort(order.begin(), order.end(),
                                 [&](int x, int y)
                                 {
                                     return spheres[static_cast<std::size_t>(x)].centerInFrame[axis] <
                                            spheres[static_cast<std::size_t>(y)].centerInFrame[axis];
                                 });
                const std::size_t n = order.size();
                const std::size_t g = (n + SUB_LINK_SPHERES - 1) / SUB_LINK_SPHERES;
                for (std::size_t k = 0; k < g; ++k)
                    groups.emplace_back(order.begin() + static_cast<std::ptrdiff_t>(k * n / g),
                                        order.begin() + static_cast<std::ptrdiff_t>((k + 1) * n / g));
            }
            for (const std::vector<int> &group : groups)
            {
                simd::LinkOp op;
                op.frame = cl.frame;
                op.collisionLink = static_cast<int>(c);
                Eigen::Vector3d centre = cl.boundCenterInFrame;
                double bound = cl.boundRadius;
                if (groups.size() > 1)
                {
                    std::vector<Sphere> members;
                    for (const int s : group)
                        members.push_back({spheres[static_cast<std::size_t>(s)].centerInFrame,
                                           spheres[static_cast<std::size_t>(s)].radius});
                    const Sphere e = enclosingSphere(members);
                    centre = e.center;
                    bound = e.radius;
                }
                op.bx = static_cast<float>(centre.x());
                op.by = static_cast<float>(centre.y());
                op.bz = static_cast<float>(centre.z());
                const int count = static_cast<int>(group.size());
                op.first = static_cast<int>(p.sx.size());
                op.count = count;
                op.padded = static_cast<int>(roundUp(static_cast<std::size_t>(count)));
                for (int k = 0; k < op.padded; ++k)
                {
                    // the block is padded with the group's own spheres again: whole-chunk tests need no masks
                    const int s = group[static_cast<std::size_t>(k % count)];
                    const CollisionSphere &sphere = spheres[static_cast<std::size_t>(s)];
                    if (k < count)
                        p.programIndexOfSphere[static_cast<std::size_t>(s)] = static_cast<int>(p.sx.size());
                    p.sx.push_back(static_cast<float>(sphere.centerInFrame.x()));
                    p.sy.push_back(static_cast<float>(sphere.centerInFrame.y()));
                    p.sz.push_back(static_cast<float>(sphere.centerInFrame.z()));
                    p.sr.push_back(static_cast<float>(sphere.radius));
                    // the bound must enclose every sphere (guards against a loose model bound)
                    bound = std::max(bound, (sphere.centerInFrame - centre).norm() + sphere.radius);
                }
                // float rounding slack: the bound may never cull a touching sphere
                op.br = withRoundingSlack(bound);
                linkIndex[c].push_back(static_cast<int>(p.links.size()));
                p.links.push_back(op);
            }
        }
        // links grouped by frame, for the batch frame loop (bounds placed while the frame is in registers)
        for (std::size_t f = 0; f < p.frames.size(); ++f)
        {
            p.frames[f].linkBegin = static_cast<int>(p.frameLinks.size());
            for (std::size_t l = 0; l < p.links.size(); ++l)
                if (p.links[l].frame == static_cast<int>(f))
                    p.frameLinks.push_back(static_cast<int>(l));
            p.frames[f].linkEnd = static_cast<int>(p.frameLinks.size());
        }
        for (std::size_t s = 0; s < spheres.size(); ++s)
            if (p.programIndexOfSphere[s] < 0)
                throw Error("CollisionChecker: robot '" + model.name() + "' sphere " + std::to_string(s) +
                            " belongs to no collision link");
        p.sphereSlots = static_cast<int>(p.sx.size());
        p.linkPadded = static_cast<int>(roundUp(p.links.size()));
        p.linkRadius.assign(static_cast<std::size_t>(p.linkPadded), 0.0f);
        p.linkBoundPairs.assign(16 * p.links.size(), 1.0f);
        for (std::size_t l = 0; l < p.links.size(); ++l)
        {
            p.linkRadius[l] = p.links[l].br;
            for (int i = 0; i < 4; ++i)
            {
                p.linkBoundPairs[16 * l + static_cast<std::size_t>(i)] = p.links[l].bx;
                p.linkBoundPairs[16 * l + 4 + static_cast<std::size_t>(i)] = p.links[l].by;
                p.linkBoundPairs[16 * l + 8 + static_cast<std::size_t>(i)] = p.links[l].bz;
            }
        }
        // the sphere at each program slot (RobotModel order; padding repeats a sphere of the same link)
        std::vector<int> sphereOfSlot(p.sx.size(), -1);
        for (std::size_t s = 0; s < spheres.size(); ++s)
            sphereOfSlot[static_cast<std::size_t>(p.programIndexOfSphere[s])] = static_cast<int>(s);
        // self pairs: program links of both collision links, with the sphere pairs that can touch within the joint
        // limits (reachableSpherePairs); a program pair none of whose sphere pairs can touch is dropped
        std::vector<std::uint8_t> pairMasks;  // per program pair WIDTH masks: per slot of A, the slots of B
        std::vector<int> pairGrid;            // per program pair: its grid of free cells or -1
        for (const auto &pair : model.selfCollisionPairs())
        {
            if (pair.first < 0 || pair.second < 0 || pair.first >= static_cast<int>(collisionLinks.size()) ||
                pair.second >= static_cast<int>(collisionLinks.size()))
                throw Error("CollisionChecker: robot '" + model.name() + "' self-collision pair (" +
                            std::to_string(pair.first) + ", " + std::to_string(pair.second) + ") out of range");
            const SphereReach reach = reachableSpherePairs(model, pair.first, pair.second);
            // its grid of free cells, when the batch q block holds the grid's variables unreduced (|limits| <= 64)
            int grid = -1;
            const SpherePairFreeCells &cells = reach.freeCells;
            bool usable = !cells.variables.empty() && cells.variables.size() <= 2 && cells.cells > 0;
            simd::SelfGrid g;
            g.cells = cells.cells;
            for (std::size_t d = 0; usable && d < cells.variables.size(); ++d)
            {
                const PlanningJoint &joint = model.joints()[static_cast<std::size_t>(cells.variables[d])];
                usable = std::abs(joint.lower) <= 64.0 && std::abs(joint.upper) <= 64.0;
                g.var[d] = cells.variables[d];
                g.lower[d] = static_cast<float>(cells.lower[d]);
                g.inv[d] = static_cast<float>(1.0 / cells.width[d]);
            }
            // link pairs over the same grid share it: a cell is free when it is free for each of them
            const auto sameGrid = [&g](const simd::SelfGrid &o)
            {
                return o.cells == g.cells && std::equal(o.var, o.var + 2, g.var) &&
                       std::equal(o.lower, o.lower + 2, g.lower) && std::equal(o.inv, o.inv + 2, g.inv);
            };
            const auto shared = std::find_if(p.selfGrids.begin(), p.selfGrids.end(), sameGrid);
            if (usable && shared != p.selfGrids.end())
            {
                for (std::size_t w = 0; w < cells.bits.size(); ++w)
                    p.selfGridBits[static_cast<std::size_t>(shared->bitsOffset) + w] &= cells.bits[w];
                grid = static_cast<int>(shared - p.selfGrids.begin());
            }
            else if (usable && static_cast<int>(p.selfGrids.size()) < simd::MAX_SELF_GRIDS)
            {
                g.bitsOffset = static_cast<int>(p.selfGridBits.size());
                p.selfGridBits.insert(p.selfGridBits.end(), cells.bits.begin(), cells.bits.end());
                grid = static_cast<int>(p.selfGrids.size());
                p.selfGrids.push_back(g);
            }
            std::unordered_set<std::uint64_t> reachable;
            for (const auto &sp : reach.pairs)
                reachable.insert(static_cast<std::uint64_t>(sp.first) << 32 | static_cast<std::uint32_t>(sp.second));
            for (const int a : linkIndex[static_cast<std::size_t>(pair.first)])
                for (const int b : linkIndex[static_cast<std::size_t>(pair.second)])
                {
                    const simd::LinkOp &la = p.links[static_cast<std::size_t>(a)];
                    const simd::LinkOp &lb = p.links[static_cast<std::size_t>(b)];
                    std::uint8_t masks[WIDTH] = {};
                    bool any = false;
                    for (int i = 0; i < la.count; ++i)
                        for (int j = 0; j < lb.count; ++j)
                        {
                            const auto sa =
                                static_cast<std::uint64_t>(sphereOfSlot[static_cast<std::size_t>(la.first + i)]);
                            const auto sb =
                                static_cast<std::uint32_t>(sphereOfSlot[static_cast<std::size_t>(lb.first + j)]);
                            if (reachable.count(sa << 32 | sb) != 0)
                            {
                                masks[i] = static_cast<std::uint8_t>(masks[i] | 1u << j);
                                any = true;
                            }
                        }
                    if (!any)
                        continue;
                    p.selfPairs.emplace_back(a, b);
                    pairMasks.insert(pairMasks.end(), masks, masks + WIDTH);
                    pairGrid.push_back(grid);
                }
        }

        // link groups: consecutive links, a new group once the current one has `size` links and the frame
        // changes (at most MAX_LINK_GROUPS: every group but the last has at least `size` links)
        const std::size_t nProgramLinks = p.links.size();
        const std::size_t size = std::max<std::size_t>(
            {2, (nProgramLinks + 3) / 4, (nProgramLinks + simd::MAX_LINK_GROUPS - 2) / (simd::MAX_LINK_GROUPS - 1)});
        std::vector<int> groupOf(nProgramLinks, 0);
        for (std::size_t l = 0; l < nProgramLinks; ++l)
        {
            if (p.groups.empty() || (static_cast<std::size_t>(p.groups.back().end - p.groups.back().begin) >= size &&
                                     p.links[l].frame != p.links[l - 1].frame))
                p.groups.push_back({static_cast<int>(l), static_cast<int>(l)});
            p.groups.back().end = static_cast<int>(l) + 1;
            groupOf[l] = static_cast<int>(p.groups.size()) - 1;
        }
        p.groupOfLink = groupOf;
        // self pairs sorted by the groups of their links (their sphere masks along); one range per group pair
        {
            std::vector<std::size_t> order(p.selfPairs.size());
            for (std::size_t k = 0; k < order.size(); ++k)
                order[k] = k;
            const auto groupsOf = [&](std::size_t k)
            {
                return std::make_pair(groupOf[static_cast<std::size_t>(p.selfPairs[k].first)],
                                      groupOf[static_cast<std::size_t>(p.selfPairs[k].second)]);
            };
            std::stable_sort(order.begin(), order.end(),
                             [&](std::size_t x, std::size_t y) { return groupsOf(x) < groupsOf(y); });
            std::vector<std::pair<int, int>> sorted;
            for (const std::size_t k : order)
            {
                sorted.push_back(p.selfPairs[k]);
                p.selfPairGrid.push_back(pairGrid[k]);
                const std::uint8_t *m = pairMasks.data() + WIDTH * k;
                unsigned aMask = 0u;
                for (int i = 0; i < WIDTH; ++i)
                {
                    p.selfPairSphereMasks.push_back(m[i]);
                    aMask |= (m[i] != 0 ? 1u : 0u) << i;
                }
                p.selfPairSlotsA.push_back(static_cast<std::uint8_t>(aMask));
            }
            p.selfPairs = std::move(sorted);
        }
        // per pair: the spheres around the members that can touch (much smaller than the link bounds when few
        // sphere pairs can touch, e.g. the Panda's link5 against link7); used when one is at most 95 % of its bound
        for (std::size_t k = 0; k < p.selfPairs.size(); ++k)
        {
            const simd::LinkOp &la = p.links[static_cast<std::size_t>(p.selfPairs[k].first)];
            const simd::LinkOp &lb = p.links[static_cast<std::size_t>(p.selfPairs[k].second)];
            const std::uint8_t *m = p.selfPairSphereMasks.data() + WIDTH * k;
            const auto sphereAt = [&p](int slot)
            {
                const auto k = static_cast<std::size_t>(slot);
                return Sphere{Eigen::Vector3d(p.sx[k], p.sy[k], p.sz[k]), p.sr[k]};
            };
            unsigned bMask = 0u;
            std::vector<Sphere> members[2];
            for (int i = 0; i < WIDTH; ++i)
            {
                bMask |= m[i];
                if (m[i] != 0)
                    members[0].push_back(sphereAt(la.first + i));
            }
            for (int j = 0; j < WIDTH; ++j)
                if ((bMask >> j & 1u) != 0u)
                    members[1].push_back(sphereAt(lb.first + j));
            float near[2][4];
            for (int side = 0; side < 2; ++side)
            {
                const Sphere e = enclosingSphere(members[side]);  // encloses every member exactly (its contract)
                near[side][0] = static_cast<float>(e.center.x());
                near[side][1] = static_cast<float>(e.center.y());
                near[side][2] = static_cast<float>(e.center.z());
                near[side][3] = withRoundingSlack(e.radius);
            }
            p.selfPairNear.insert(p.selfPairNear.end(), near[0], near[0] + 4);
            p.selfPairNear.insert(p.selfPairNear.end(), near[1], near[1] + 4);
            const float reach = near[0][3] + near[1][3];
            p.selfPairNearReach2.push_back(reach * reach);
            p.selfPairUseNear.push_back(near[0][3] <= 0.95f * la.br || near[1][3] <= 0.95f * lb.br ? 1 : 0);
        }
        for (std::size_t k = 0; k < p.selfPairs.size(); ++k)
        {
            const int ga = groupOf[static_cast<std::size_t>(p.selfPairs[k].first)];
            const int gb = groupOf[static_cast<std::size_t>(p.selfPairs[k].second)];
            if (p.selfPairRanges.empty() || p.selfPairRanges.back().groupA != ga ||
                p.selfPairRanges.back().groupB != gb)
                p.selfPairRanges.push_back({ga, gb, static_cast<int>(k), static_cast<int>(k)});
            p.selfPairRanges.back().end = static_cast<int>(k) + 1;
        }

        // rows: within a range, consecutive pairs (a, b), (a, b + 1), ... (at most WIDTH)
        for (simd::SelfPairRange &range : p.selfPairRanges)
        {
            range.rowBegin = static_cast<int>(p.selfPairRows.size());
            for (int k = range.begin; k < range.end; ++k)
            {
                const auto &pair = p.selfPairs[static_cast<std::size_t>(k)];
                if (static_cast<int>(p.selfPairRows.size()) > range.rowBegin)
                {
                    simd::SelfPairRow &row = p.selfPairRows.back();
                    if (row.a == pair.first && row.bFirst + row.count == pair.second && row.count < WIDTH)
                    {
                        ++row.count;
                        continue;
                    }
                }
                p.selfPairRows.push_back({pair.first, pair.second, 1, k});
            }
            range.rowEnd = static_cast<int>(p.selfPairRows.size());
        }
        for (const simd::SelfPairRow &row : p.selfPairRows)
            for (int i = 0; i < WIDTH; ++i)
            {
                float reach2 = -1.0f;
                if (i < row.count)
                {
                    const float rs = p.links[static_cast<std::size_t>(row.a)].br +
                                     p.links[static_cast<std::size_t>(row.bFirst + i)].br;
                    reach2 = rs * rs;
                }
                p.selfRowReach2.push_back(reach2);
            }

        for (const auto &pair : p.selfPairs)
        {
            const float rs =
                p.links[static_cast<std::size_t>(pair.first)].br + p.links[static_cast<std::size_t>(pair.second)].br;
            p.selfPairReach2.push_back(rs * rs);
            p.selfPairOffsetA.push_back(WIDTH * pair.first);
            p.selfPairOffsetB.push_back(WIDTH * pair.second);
        }

        // scratch layouts
        const std::size_t dofPad = roundUp(model.dof()), nFrames = p.frames.size();
        const std::size_t nSpheres = static_cast<std::size_t>(p.sphereSlots), nLinks = p.links.size();
        std::size_t at = 0;
        const auto take = [&at](std::size_t n)
        {
            const std::size_t start = at;
            at += roundUp(n);
            return start;
        };
        p.single.sin = take(dofPad);
        p.single.cos = take(dofPad);
        p.single.q = take(dofPad);
        p.single.frames = take(16 * nFrames);
        p.single.sx = take(nSpheres);
        p.single.sy = take(nSpheres);
        p.single.sz = take(nSpheres);
        // link bounds padded: the self-pair rows load WIDTH links from any link, and framesSingle writes the
        // padding [links, links + 2 WIDTH) with two vector stores
        p.single.lx = take(static_cast<std::size_t>(p.linkPadded + 2 * WIDTH));
        p.single.ly = take(static_cast<std::size_t>(p.linkPadded + 2 * WIDTH));
        p.single.lz = take(static_cast<std::size_t>(p.linkPadded + 2 * WIDTH));
        p.single.total = at;
        at = 0;
        p.batch.sin = take(WIDTH * model.dof());
        p.batch.cos = take(WIDTH * model.dof());
        p.batch.q = take(WIDTH * model.dof());
        p.batch.frames = take(12 * WIDTH * nFrames);
        p.batch.sx = take(WIDTH * nSpheres);
        p.batch.sy = take(WIDTH * nSpheres);
        p.batch.sz = take(WIDTH * nSpheres);
        p.batch.lx = take(WIDTH * nLinks);
        p.batch.ly = take(WIDTH * nLinks);
        p.batch.lz = take(WIDTH * nLinks);
        p.batch.total = at;
        // the angles a batch must look at for the double reduction: rotational joints whose limits reach past 64
        for (int j = 0; j < p.dof; ++j)
            if (p.rotational[static_cast<std::size_t>(j)] &&
                (p.lowerCheck[static_cast<std::size_t>(j)] < -64.0 || p.upperCheck[static_cast<std::size_t>(j)] > 64.0))
                p.reduceCheck.push_back(j);
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

    bool CollisionChecker::allValid(const Environment &env, const double *qs, std::size_t count) const noexcept
    {
        return ROPRAS_DISPATCH(allValid(program_->kp, env, qs, count));
    }

    bool CollisionChecker::isMotionValid(const Environment &env, const double *q0, const double *q1, double resolution,
                                         double *lastValidFraction, bool checkStart) const noexcept
    {
        return ROPRAS_DISPATCH(isMotionValid(program_->kp, env, q0, q1, resolution, lastValidFraction, checkStart));
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
