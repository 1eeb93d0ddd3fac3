// Collision kernels of the bodies attached to robot links (Environment::attach), for any 8-lane backend V.
// Included at the end of Kernels.h: the single and batch checks call them after FK, with the frames in scratch.
#ifndef ROPRAS_OMPL_EXT_SIMD_ATTACHED_KERNELS_H
#define ROPRAS_OMPL_EXT_SIMD_ATTACHED_KERNELS_H

#include <algorithm>
#include <cstdint>

#include "Kernels.h"

namespace ropras::ompl_ext::simd
{
    /// bodies attached to the robot, over an Environment and its bases
    template <class F>
    inline bool forEachAttached(const Environment &env, const F &f) noexcept
    {
        for (const Environment *e = &env; e != nullptr; e = e->base())
            for (std::size_t i = 0; i < e->attachedCount(); ++i)
                if (f(e->attachedSpheres(i)))
                    return true;
        return false;
    }

    template <class V>
    struct AttachedKernels
    {
        using K = Kernels<V>;
        using Mask = typename V::Mask;

        // ------------------------------------------------------------ single configuration

        /// a frame of the single path: columns (c0 c1 c2 t), 4 floats each; world point of (x, y, z)
        static void placeSingle(const float *m, float x, float y, float z, float *out) noexcept
        {
            for (int i = 0; i < 3; ++i)
                out[i] = m[i] * x + m[4 + i] * y + m[8 + i] * z + m[12 + i];
        }

        /// world centres of spheres [s, s + WIDTH) of \a a
        static void placeChunk(const float *m, const AttachedSpheres &a, std::size_t s, V &x, V &y, V &z) noexcept
        {
            const V lx = V::load(a.x.data() + s), ly = V::load(a.y.data() + s), lz = V::load(a.z.data() + s);
            x = fma(V::broadcast(m[0]), lx,
                    fma(V::broadcast(m[4]), ly, fma(V::broadcast(m[8]), lz, V::broadcast(m[12]))));
            y = fma(V::broadcast(m[1]), lx,
                    fma(V::broadcast(m[5]), ly, fma(V::broadcast(m[9]), lz, V::broadcast(m[13]))));
            z = fma(V::broadcast(m[2]), lx,
                    fma(V::broadcast(m[6]), ly, fma(V::broadcast(m[10]), lz, V::broadcast(m[14]))));
        }

        static_assert(OBSTACLE_BOX_LANES == WIDTH, "the obstacle box chunks hold one vector per coordinate");

        /// lanes of the eight obstacle boxes of \a c that the sphere (bx, by, bz; rr = radius^2) touches
        static unsigned nearBoxes(const ObstacleBoxChunk &c, const V &bx, const V &by, const V &bz,
                                  const V &rr) noexcept
        {
            const V zero = V::zero();
            const V dx = max(abs(V::load(c.cx) - bx) - V::load(c.ex), zero);
            const V dy = max(abs(V::load(c.cy) - by) - V::load(c.ey), zero);
            const V dz = max(abs(V::load(c.cz) - bz) - V::load(c.ez), zero);
            return cmpLe(fma(dx, dx, fma(dy, dy, dz * dz)), rr).bits();
        }

        /// one chunk of WIDTH placed body spheres (x, y, z, r; padding repeats real spheres) against a primitive of e
        static bool hitPrimitive(const Environment &e, const PrimitiveRef &ref, const V &x, const V &y, const V &z,
                                 const V &r) noexcept
        {
            const auto i = static_cast<std::size_t>(ref.slot);
            switch (ref.type)
            {
                case ShapeType::Sphere:
                    return hitObstacle(x, y, z, r, e.spheres()[i]).bits() != 0u;
                case ShapeType::Box:
                    return hitObstacle(x, y, z, r, e.boxes()[i]).bits() != 0u;
                case ShapeType::Cylinder:
                    return hitObstacle(x, y, z, r, e.cylinders()[i]).bits() != 0u;
                case ShapeType::Capsule:
                    return hitObstacle(x, y, z, r, e.capsules()[i]).bits() != 0u;
                case ShapeType::PointCloud:
                {
                    const CloudObstacle &o = e.clouds()[i];
                    if (o.boundRadius < 0.0f)
                        return false;
                    const unsigned cand = boundTest(x, y, z, r, o.cx, o.cy, o.cz, o.boundRadius).bits();
                    return cand != 0u && hitCloud(x, y, z, r, o, cand) != 0u;
                }
            }
            return false;
        }

        /// the scalar sphere-versus-box test (for Environments with too few primitives for a chunk)
        static bool sphereTouchesAabb(const float *c, float r, const ObstacleAabb &b) noexcept
        {
            const float dx = std::max(std::abs(c[0] - b.cx) - b.ex, 0.0f);
            const float dy = std::max(std::abs(c[1] - b.cy) - b.ey, 0.0f);
            const float dz = std::max(std::abs(c[2] - b.cz) - b.ez, 0.0f);
            return dx * dx + dy * dy + dz * dz <= r * r;
        }

        /** \brief The body (carried by frame \a m, bound centre \a bound) against the obstacles of env and its bases:
            its bound against eight obstacle boxes at a time (Environment::obstacleBoxChunks; one at a time in an
            Environment without chunks), then its spheres, a chunk at a time, against each obstacle that survives. */
        static bool obstaclesSingle(const Environment &env, const AttachedSpheres &a, const float *m,
                                    const float *bound) noexcept
        {
            const V bx = V::broadcast(bound[0]), by = V::broadcast(bound[1]), bz = V::broadcast(bound[2]);
            const V rr = V::broadcast(a.br * a.br);
            // the spheres are placed for the first obstacle whose box the bound touches (most checks meet none)
            V x0, y0, z0;
            bool placed0 = false;
            const auto survivor = [&](const Environment &e, const PrimitiveRef &ref)
            {
                if (!placed0)
                {
                    placeChunk(m, a, 0, x0, y0, z0);
                    placed0 = true;
                }
                if (hitPrimitive(e, ref, x0, y0, z0, V::load(a.r.data())))
                    return true;
                for (std::size_t s = WIDTH; s < a.x.size(); s += WIDTH)
                {
                    V x, y, z;
                    placeChunk(m, a, s, x, y, z);
                    if (hitPrimitive(e, ref, x, y, z, V::load(a.r.data() + s)))
                        return true;
                }
                return false;
            };
            for (const Environment *e = &env; e != nullptr; e = e->base())
            {
                if (e->primitiveCount() == 0)  // a particle's overlay that holds only attached bodies
                    continue;
                if (const ObstacleTree *tree = e->obstacleTree())
                {
                    // the broad phase: the primitives whose boxes overlap the bound's box
                    const Aabb q{{bound[0] - a.br, bound[1] - a.br, bound[2] - a.br},
                                 {bound[0] + a.br, bound[1] + a.br, bound[2] + a.br}};
                    if (forEachNearPrimitive<V>(*tree, q,
                                                [&](std::size_t k) {
                                                    return sphereTouchesAabb(bound, a.br, e->primitiveBox(k)) &&
                                                           survivor(*e, e->primitiveRef(k));
                                                }))
                        return true;
                    continue;
                }
                const std::vector<ObstacleBoxChunk> &chunks = e->obstacleBoxChunks();
                if (chunks.empty())
                    for (std::size_t k = 0; k < e->primitiveCount(); ++k)
                    {
                        if (sphereTouchesAabb(bound, a.br, e->primitiveBox(k)) && survivor(*e, e->primitiveRef(k)))
                            return true;
                    }
                for (std::size_t c = 0; c < chunks.size(); ++c)
                {
                    unsigned bits = nearBoxes(chunks[c], bx, by, bz, rr);
                    while (bits != 0u)
                    {
                        const PrimitiveRef &ref =
                            e->primitiveRef(c * OBSTACLE_BOX_LANES + static_cast<std::size_t>(__builtin_ctz(bits)));
                        bits &= bits - 1u;
                        if (survivor(*e, ref))
                            return true;
                    }
                }
            }
            return false;
        }

        /// the body (carried by frame \a m) against the robot links it may not touch: link bounds WIDTH at a time
        /// against the body's bound, then, for a link that reaches it, the body's spheres (placed a chunk at a time)
        /// against each of the link's spheres
        static bool robotSingle(const KinematicProgram &p, const AttachedSpheres &a, float *buf, Placed &placed,
                                const float *m, const float *bound) noexcept
        {
            const ScratchLayout &l = p.single;
            const float *lx = buf + l.lx, *ly = buf + l.ly, *lz = buf + l.lz;
            const V bx = V::broadcast(bound[0]), by = V::broadcast(bound[1]), bz = V::broadcast(bound[2]);
            const V br = V::broadcast(a.br), frame = V::broadcast(static_cast<float>(a.frame));
            for (int c = 0; c < p.linkPadded; c += WIDTH)
            {
                const V dx = V::load(lx + c) - bx, dy = V::load(ly + c) - by, dz = V::load(lz + c) - bz;
                const V rr = V::load(p.linkRadius.data() + c) + br;
                // the links of the body's own frame (their contact never changes, see alwaysCollides) leave with
                // one compare; the links it may touch on other frames one by one
                const Mask own = cmpLe(abs(V::load(p.linkFrame.data() + c) - frame), V::broadcast(0.25f));
                unsigned bits = cmpLe(fma(dx, dx, fma(dy, dy, dz * dz)), rr * rr).bits() & ~own.bits();
                while (bits != 0u)
                {
                    const int li = c + __builtin_ctz(bits);
                    bits &= bits - 1u;
                    const LinkOp &link = p.links[static_cast<std::size_t>(li)];
                    if (a.touchesOtherFrames && a.skipLink[static_cast<std::size_t>(link.collisionLink)] != 0)
                        continue;
                    K::ensure(p, buf, placed, li);
                    for (std::size_t s = 0; s < a.x.size(); s += WIDTH)
                    {
                        V x, y, z;
                        placeChunk(m, a, s, x, y, z);
                        const V r = V::load(a.r.data() + s);
                        for (int k = link.first; k < link.first + link.count; ++k)
                            if (boundTest(x, y, z, r, buf[l.sx + k], buf[l.sy + k], buf[l.sz + k],
                                          p.sr[static_cast<std::size_t>(k)])
                                    .bits() != 0u)
                                return true;
                    }
                }
            }
            return false;
        }

        /// the body against the obstacles, then against the robot
        static bool bodySingle(const KinematicProgram &p, const Environment &env, const AttachedSpheres &a, float *buf,
                               Placed &placed, const float *m, const float *bound) noexcept
        {
            return obstaclesSingle(env, a, m, bound) || robotSingle(p, a, buf, placed, m, bound);
        }

        /// two bodies carried by different frames
        static bool pairSingle(const AttachedSpheres &a, const float *ma, const AttachedSpheres &b,
                               const float *mb) noexcept
        {
            for (int i = 0; i < a.count; ++i)
            {
                float ca[3];
                const auto ii = static_cast<std::size_t>(i);
                placeSingle(ma, a.x[ii], a.y[ii], a.z[ii], ca);
                for (std::size_t s = 0; s < b.x.size(); s += WIDTH)
                {
                    V x, y, z;
                    placeChunk(mb, b, s, x, y, z);
                    if (boundTest(x, y, z, V::load(b.r.data() + s), ca[0], ca[1], ca[2], a.r[ii]).bits() != 0u)
                        return true;
                }
            }
            return false;
        }

        /** \brief After framesSingle: true when a body attached to the robot (of env or its bases) touches an
            obstacle, a robot link other than its own and its touch links, or a body carried by another frame.
            A body attached for another robot model makes every configuration invalid. */
        static bool collideSingle(const KinematicProgram &p, const Environment &env, float *buf,
                                  Placed &placed) noexcept
        {
            const float *frames = buf + p.single.frames;
            std::size_t bodies = 0;
            for (const Environment *e = &env; e != nullptr; e = e->base())
                bodies += e->attachedCount();
            return forEachAttached(env,
                                   [&](const AttachedSpheres &a)
                                   {
                                       if (a.robot.get() != p.model || a.alwaysCollides)
                                           return true;
                                       const float *m = frames + 16 * a.frame;
                                       float bound[3];
                                       placeSingle(m, a.bx, a.by, a.bz, bound);
                                       if (bodySingle(p, env, a, buf, placed, m, bound))
                                           return true;
                                       if (bodies < 2)
                                           return false;
                                       // bodies on other frames (the same frame carries both rigidly: their contact
                                       // never changes)
                                       bool later = false;
                                       return forEachAttached(env,
                                                              [&](const AttachedSpheres &b)
                                                              {
                                                                  if (&b == &a)
                                                                  {
                                                                      later = true;
                                                                      return false;
                                                                  }
                                                                  return later && b.robot.get() == p.model &&
                                                                         b.frame != a.frame &&
                                                                         pairSingle(a, m, b, frames + 16 * b.frame);
                                                              });
                                   });
        }

        // ------------------------------------------------------------ batch: one configuration per lane

        /// at most this many spheres of a body are placed at once in the batch path
        static constexpr int CHUNK = 16;

        /// world centres (WIDTH lanes each) of spheres [first, first + n) of \a a, n <= CHUNK
        static void placeBatch(const float *frame, const AttachedSpheres &a, int first, int n, V *x, V *y,
                               V *z) noexcept
        {
            for (int k = 0; k < n; ++k)
            {
                const auto s = static_cast<std::size_t>(first + k);
                const float b[3] = {a.x[s], a.y[s], a.z[s]};
                V out[3];
                K::placePointBatch(frame, b, out);
                x[k] = out[0];
                y[k] = out[1];
                z[k] = out[2];
            }
        }

        /// lanes of \a lanes where one chunk of placed body spheres touches an obstacle of env or its bases
        static unsigned obstaclesBatch(const Environment &env, const AttachedSpheres &a, const V *bound, int first,
                                       int n, const V *x, const V *y, const V *z, unsigned lanes) noexcept
        {
            unsigned hit = 0u;
            const V br = V::broadcast(a.br);
            /// one obstacle; true when every lane has collided
            const auto one = [&](const auto &o, const auto &exact)
            {
                const unsigned near = sphereTouchesBox(bound[0], bound[1], bound[2], br, o.aabb).bits() & lanes & ~hit;
                for (int k = 0; k < n && near != 0u; ++k)
                    hit |= exact(x[k], y[k], z[k], V::broadcast(a.r[static_cast<std::size_t>(first + k)]), o,
                                 near & ~hit) &
                           near;
                return (lanes & ~hit) == 0u;
            };
            const auto sweep = [&](const auto &obstacles, const auto &exact)
            {
                for (const auto &o : obstacles)
                    if (one(o, exact))
                        return true;
                return false;
            };
            const auto plain = [](const V &px, const V &py, const V &pz, const V &pr, const auto &o, unsigned)
            { return hitObstacle(px, py, pz, pr, o).bits(); };
            const auto cloud =
                [](const V &px, const V &py, const V &pz, const V &pr, const CloudObstacle &o, unsigned cand)
            {
                if (o.boundRadius < 0.0f)
                    return 0u;
                const unsigned c = boundTest(px, py, pz, pr, o.cx, o.cy, o.cz, o.boundRadius).bits() & cand;
                return c != 0u ? hitCloud(px, py, pz, pr, o, c) : 0u;
            };
            for (const Environment *e = &env; e != nullptr; e = e->base())
            {
                if (const ObstacleTree *tree = e->obstacleTree())
                {
                    // the broad phase: the primitives whose boxes overlap the box around the lanes' bounds
                    const Mask m = Mask::fromBits(lanes);
                    const V far = V::broadcast(1e30f), nfar = V::broadcast(-1e30f);
                    Aabb q;
                    for (int i = 0; i < 3; ++i)
                    {
                        q.lo[i] = hmin(select(m, bound[i] - br, far));
                        q.hi[i] = hmax(select(m, bound[i] + br, nfar));
                    }
                    const auto visit = [&](const auto &o)
                    {
                        if constexpr (std::is_same_v<std::decay_t<decltype(o)>, CloudObstacle>)
                            return one(o, cloud);
                        else
                            return one(o, plain);
                    };
                    if (forEachNearPrimitive<V>(*tree, q, [&](std::size_t k) { return withPrimitive(*e, k, visit); }))
                        break;
                    continue;
                }
                if (sweep(e->spheres(), plain) || sweep(e->boxes(), plain) || sweep(e->cylinders(), plain) ||
                    sweep(e->capsules(), plain) || sweep(e->clouds(), cloud))
                    break;
            }
            return hit;
        }

        /// lanes of \a lanes where one chunk of placed body spheres touches a robot link it may not touch
        static unsigned robotBatch(const KinematicProgram &p, const AttachedSpheres &a, float *buf, Placed &placed,
                                   const V *bound, int n, const V *x, const V *y, const V *z, const float *r,
                                   unsigned lanes) noexcept
        {
            const ScratchLayout &l = p.batch;
            constexpr int W = WIDTH;
            unsigned hit = 0u;
            for (int li = 0; li < static_cast<int>(p.links.size()) && (lanes & ~hit) != 0u; ++li)
            {
                const LinkOp &link = p.links[static_cast<std::size_t>(li)];
                if (a.skipLink[static_cast<std::size_t>(link.collisionLink)] != 0)
                    continue;
                const V dx = V::load(buf + l.lx + W * li) - bound[0], dy = V::load(buf + l.ly + W * li) - bound[1],
                        dz = V::load(buf + l.lz + W * li) - bound[2];
                const V rr = V::broadcast(link.br + a.br);
                const unsigned near = cmpLe(fma(dx, dx, fma(dy, dy, dz * dz)), rr * rr).bits() & lanes & ~hit;
                if (near == 0u)
                    continue;
                K::ensureBatch(p, buf, placed, li);
                for (int s = link.first; s < link.first + link.count; ++s)
                {
                    const V sx = V::load(buf + l.sx + W * s), sy = V::load(buf + l.sy + W * s),
                            sz = V::load(buf + l.sz + W * s);
                    const float sr = p.sr[static_cast<std::size_t>(s)];
                    for (int k = 0; k < n; ++k)
                    {
                        const V ex = sx - x[k], ey = sy - y[k], ez = sz - z[k];
                        const V rs = V::broadcast(sr + r[k]);
                        hit |= cmpLe(fma(ex, ex, fma(ey, ey, ez * ez)), rs * rs).bits() & near;
                    }
                }
            }
            return hit;
        }

        /// lanes where a chunk of body a (placed) touches body b (another frame)
        static unsigned pairBatch(const float *frameB, const AttachedSpheres &b, int n, const V *x, const V *y,
                                  const V *z, const float *r, unsigned lanes) noexcept
        {
            unsigned hit = 0u;
            for (int j = 0; j < b.count && (lanes & ~hit) != 0u; ++j)
            {
                V c[3];
                const auto jj = static_cast<std::size_t>(j);
                const float pb[3] = {b.x[jj], b.y[jj], b.z[jj]};
                K::placePointBatch(frameB, pb, c);
                for (int k = 0; k < n; ++k)
                {
                    const V ex = c[0] - x[k], ey = c[1] - y[k], ez = c[2] - z[k];
                    const V rs = V::broadcast(b.r[jj] + r[k]);
                    hit |= cmpLe(fma(ex, ex, fma(ey, ey, ez * ez)), rs * rs).bits() & lanes;
                }
            }
            return hit;
        }

        /** \brief After framesBatch: the lanes of \a active where a body attached to the robot collides (see
            collideSingle); stops at the first collision when \a stopOnAny. */
        static unsigned collideBatch(const KinematicProgram &p, const Environment &env, float *buf, Placed &placed,
                                     unsigned active, bool stopOnAny) noexcept
        {
            constexpr int W = WIDTH;
            const float *frames = buf + p.batch.frames;
            unsigned hit = 0u;
            const auto done = [&] { return (active & ~hit) == 0u || (stopOnAny && hit != 0u); };
            forEachAttached(env,
                            [&](const AttachedSpheres &a)
                            {
                                if (a.robot.get() != p.model || a.alwaysCollides)
                                {
                                    hit = active;
                                    return true;
                                }
                                const float *frame = frames + 12 * W * a.frame;
                                const float b[3] = {a.bx, a.by, a.bz};
                                V bound[3];
                                K::placePointBatch(frame, b, bound);
                                V x[CHUNK], y[CHUNK], z[CHUNK];
                                for (int first = 0; first < a.count; first += CHUNK)
                                {
                                    const int n = std::min(CHUNK, a.count - first);
                                    placeBatch(frame, a, first, n, x, y, z);
                                    const float *r = a.r.data() + first;
                                    hit |= obstaclesBatch(env, a, bound, first, n, x, y, z, active & ~hit);
                                    if (done())
                                        return true;
                                    hit |= robotBatch(p, a, buf, placed, bound, n, x, y, z, r, active & ~hit);
                                    if (done())
                                        return true;
                                    bool later = false;
                                    forEachAttached(
                                        env,
                                        [&](const AttachedSpheres &o)
                                        {
                                            if (&o == &a)
                                                later = true;
                                            else if (later && o.robot.get() == p.model && o.frame != a.frame)
                                                hit |= pairBatch(frames + 12 * W * o.frame, o, n, x, y, z, r,
                                                                 active & ~hit);
                                            return done();
                                        });
                                    if (done())
                                        return true;
                                }
                                return false;
                            });
            return hit & active;
        }
    };
}  // namespace ropras::ompl_ext::simd

#endif
