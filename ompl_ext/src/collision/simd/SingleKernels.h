// Forward kinematics and collision kernels of one configuration, for any 8-lane backend V: scalar FK, then
// vectorized over spheres.
#ifndef ROPRAS_OMPL_EXT_SIMD_SINGLE_KERNELS_H
#define ROPRAS_OMPL_EXT_SIMD_SINGLE_KERNELS_H

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <type_traits>

#include "BroadPhase.h"
#include "ForceInline.h"
#include "FrameRows.h"
#include "KinematicProgram.h"
#include "ObstacleTests.h"
#include "Placed.h"
#include "SinCos.h"
#include "ropras/ompl_ext/scene/Environment.h"

namespace ropras::ompl_ext::simd
{
    /// world boxes (x, y, z, unused) of the link groups (LinkGroup) of one configuration
    struct GroupBoxesSingle
    {
        Row4 lo[MAX_LINK_GROUPS], hi[MAX_LINK_GROUPS];
    };

    template <class V>
    struct AttachedKernels;

    /** \brief The check of one configuration: scalar FK (framesSingle), then the link bounds and spheres,
        vectorized over spheres, against obstacles (envSingle) and self pairs (selfSingle). */
    template <class V>
    struct SingleKernels
    {
        using Mask = typename V::Mask;

        /// joint values of one configuration as floats, their sines and cosines (rotational joints)
        static void jointsSingle(const KinematicProgram &p, const double *q, float *buf) noexcept
        {
            const ScratchLayout &l = p.single;
            float *sn = buf + l.sin, *cs = buf + l.cos, *qf = buf + l.q;
            for (int j = 0; j < p.dof; j += WIDTH)
            {
                const int n = std::min(WIDTH, p.dof - j);
                float in[WIDTH] = {0, 0, 0, 0, 0, 0, 0, 0};
                for (int k = 0; k < n; ++k)
                {
                    const double v = q[j + k];
                    qf[j + k] = static_cast<float>(v);
                    in[k] = p.rotational[static_cast<std::size_t>(j + k)] ? angleArgument(v) : 0.0f;
                }
                V s, c;
                sinCos(V::load(in), s, c);
                s.store(sn + j);  // the regions are padded to a multiple of WIDTH
                c.store(cs + j);
            }
        }

        /** \brief Frame \a op from its parent (pa, pb) into (a, b): a frame as two 8-float vectors a = (c0 | c1),
            b = (c2 | t). Column k of the parent in both halves, times the offset's pairs (FrameOp::offsetPairs),
            then the joint's motion with its sine and cosine (sn, cs) or its value (qf). */
        static void composeFrameSingle(const FrameOp &op, const Row8 &pa, const Row8 &pb, const float *sn,
                                       const float *cs, const float *qf, Row8 &a, Row8 &b) noexcept
        {
            const Row8 zero = {};
            const Row8 c0 = __builtin_shuffle(pa, LOW_TWICE), c1 = __builtin_shuffle(pa, HIGH_TWICE);
            const Row8 c2 = __builtin_shuffle(pb, LOW_TWICE);
            const float *k = op.offsetPairs;
            a = c0 * loadRow<Row8>(k) + c1 * loadRow<Row8>(k + 8) + c2 * loadRow<Row8>(k + 16);
            b = c0 * loadRow<Row8>(k + 24) + c1 * loadRow<Row8>(k + 32) + c2 * loadRow<Row8>(k + 40) +
                __builtin_shuffle(pb, zero, ZERO_LOW);
            if (op.motion == Motion::RotateZ)
            {
                // (c0 | c1) <- c (c0 | c1) + (s | -s) (c1 | c0)
                const float cv = cs[op.variable], sv = sn[op.variable];
                const Row8 sPair = {sv, sv, sv, sv, -sv, -sv, -sv, -sv};
                a = a * cv + sPair * __builtin_shuffle(a, SWAP_HALVES);
            }
            else if (op.motion == Motion::TranslateZ)
            {
                // t += q c2: (c2 | t) + (0 | q) (c2 | c2)
                const float d = qf[op.variable];
                const Row8 dPair = {0.0f, 0.0f, 0.0f, 0.0f, d, d, d, d};
                b += dPair * __builtin_shuffle(b, LOW_TWICE);
            }
        }

        /** \brief Scalar FK into buf: frames and world link bounds, and the link group boxes into \a groups when
            given. q must be finite. Spheres: placeLink / placeAll. */
        static void framesSingle(const KinematicProgram &p, const double *q, float *buf,
                                 GroupBoxesSingle *groups = nullptr) noexcept
        {
            jointsSingle(p, q, buf);
            const ScratchLayout &l = p.single;
            const float *sn = buf + l.sin, *cs = buf + l.cos, *qf = buf + l.q;
            // frames as four 4-float columns (c0 c1 c2 t, w = 0): column j of P * O is sum_k P.c_k O_kj, the
            // translation sum_k P.c_k O_k3 + P.t; a frame whose parent is the previous frame stays in registers,
            // and its link bounds are placed from the registers (R b + t: three FMAs per link)
            float *t = buf + l.frames;
            float *lx = buf + l.lx, *ly = buf + l.ly, *lz = buf + l.lz;
            GroupBoxesSingle scratchGroups;
            GroupBoxesSingle &g = groups != nullptr ? *groups : scratchGroups;
            const Row4 far = {1e30f, 1e30f, 1e30f, 1e30f};
            for (std::size_t gi = 0; gi < p.groups.size(); ++gi)
            {
                g.lo[gi] = far;
                g.hi[gi] = -far;
            }
            // the program's arrays in locals: the stores below may alias anything (members would be reloaded)
            const FrameOp *frames = p.frames.data();
            const LinkOp *links = p.links.data();
            const float *boundPairs = p.linkBoundPairs.data();
            const int *frameLinks = p.frameLinks.data(), *groupOfLink = p.groupOfLink.data();
            const int nFrames = static_cast<int>(p.frames.size());
            // a frame without parent has the identity as parent
            const Row8 identityA = {1, 0, 0, 0, 0, 1, 0, 0}, identityB = {0, 0, 1, 0, 0, 0, 0, 0};
            Row8 pa = identityA, pb = identityB;
            for (int f = 0; f < nFrames; ++f)
            {
                const FrameOp &op = frames[f];
                if (op.parent < 0)
                {
                    pa = identityA;
                    pb = identityB;
                }
                else if (op.parent != f - 1)
                {
                    pa = loadRow<Row8>(t + 16 * op.parent);
                    pb = loadRow<Row8>(t + 16 * op.parent + 8);
                }
                Row8 a, b;
                composeFrameSingle(op, pa, pb, sn, cs, qf, a, b);
                storeRow(t + 16 * f, a);
                storeRow(t + 16 * f + 8, b);
                pa = a;
                pb = b;
                for (int k = op.linkBegin; k < op.linkEnd; ++k)
                {
                    const int li = frameLinks[k];
                    // (c0 bx + c2 bz | c1 by + t): the bound centre is the sum of the halves
                    const float *bp = boundPairs + 16 * li;
                    const Row8 h = a * loadRow<Row8>(bp) + b * loadRow<Row8>(bp + 8);
                    const Row4 w = lowHalf(h) + highHalf(h);
                    lx[li] = w[0];
                    ly[li] = w[1];
                    lz[li] = w[2];
                    const int gi = groupOfLink[li];
                    const float br = links[li].br;
                    const Row4 lo = w - br, hi = w + br;
                    g.lo[gi] = g.lo[gi] < lo ? g.lo[gi] : lo;
                    g.hi[gi] = g.hi[gi] > hi ? g.hi[gi] : hi;
                }
            }
            // padding (one more WIDTH past linkPadded for the self-pair rows): never near anything; the padded
            // range [links, linkPadded + WIDTH) is shorter than 2 WIDTH
            const V pad = V::broadcast(1e18f);
            const int nLinks = static_cast<int>(p.links.size());
            for (float *r : {lx, ly, lz})
            {
                pad.store(r + nLinks);
                pad.store(r + nLinks + WIDTH);
            }
        }

        /// world centres of one link's spheres (whole padded block)
        ROPRAS_SIMD_FORCE_INLINE static void placeLink(const KinematicProgram &p, float *buf, int li) noexcept
        {
            const ScratchLayout &l = p.single;
            const LinkOp &link = p.links[static_cast<std::size_t>(li)];
            const float *m = buf + l.frames + 16 * link.frame;  // columns (c0 c1 c2 t), 4 floats each
            const V r00 = V::broadcast(m[0]), r01 = V::broadcast(m[4]), r02 = V::broadcast(m[8]);
            const V r10 = V::broadcast(m[1]), r11 = V::broadcast(m[5]), r12 = V::broadcast(m[9]);
            const V r20 = V::broadcast(m[2]), r21 = V::broadcast(m[6]), r22 = V::broadcast(m[10]);
            const V tx = V::broadcast(m[12]), ty = V::broadcast(m[13]), tz = V::broadcast(m[14]);
            for (int s = link.first; s < link.first + link.padded; s += WIDTH)
            {
                const V x = V::load(p.sx.data() + s), y = V::load(p.sy.data() + s), z = V::load(p.sz.data() + s);
                fma(r00, x, fma(r01, y, fma(r02, z, tx))).store(buf + l.sx + s);
                fma(r10, x, fma(r11, y, fma(r12, z, ty))).store(buf + l.sy + s);
                fma(r20, x, fma(r21, y, fma(r22, z, tz))).store(buf + l.sz + s);
            }
        }

        ROPRAS_SIMD_FORCE_INLINE static void ensure(const KinematicProgram &p, float *buf, Placed &placed,
                                                    int li) noexcept
        {
            if (!placed.has(li))
            {
                placeLink(p, buf, li);
                placed.set(li);
            }
        }

        static void placeAll(const KinematicProgram &p, float *buf, Placed &placed) noexcept
        {
            for (int li = 0; li < static_cast<int>(p.links.size()); ++li)
                placeLink(p, buf, li);
            placed.all = true;
        }

        /// true when any link's spheres touch the obstacle; candidates: link bounds touching the obstacle's box
        template <class Exact>
        static bool obstacleSingle(const KinematicProgram &p, float *buf, Placed &placed, const ObstacleBox &ob,
                                   const Exact &exact) noexcept
        {
            const ScratchLayout &l = p.single;
            for (int c = 0; c < p.linkPadded; c += WIDTH)
            {
                const V bx = V::load(buf + l.lx + c), by = V::load(buf + l.ly + c), bz = V::load(buf + l.lz + c),
                        br = V::load(p.linkRadius.data() + c);
                unsigned bits = sphereTouchesBox(bx, by, bz, br, ob).bits();
                if (bits == 0u)
                    continue;
                // the exact test on the link bounding spheres: far tighter than sphere-vs-sphere for boards
                bits &= exact(bx, by, bz, br);
                while (bits != 0u)
                {
                    const int li = c + __builtin_ctz(bits);
                    bits &= bits - 1u;
                    ensure(p, buf, placed, li);
                    const LinkOp &link = p.links[static_cast<std::size_t>(li)];
                    for (int s = link.first; s < link.first + link.padded; s += WIDTH)
                        if (exact(V::load(buf + l.sx + s), V::load(buf + l.sy + s), V::load(buf + l.sz + s),
                                  V::load(p.sr.data() + s)) != 0u)
                            return true;
                }
            }
            return false;
        }

        /// the box around every link bound, from the group boxes
        static Aabb aabbSingle(const KinematicProgram &p, const GroupBoxesSingle &g) noexcept
        {
            Row4 lo = g.lo[0], hi = g.hi[0];
            for (std::size_t gi = 1; gi < p.groups.size(); ++gi)
            {
                lo = lo < g.lo[gi] ? lo : g.lo[gi];
                hi = hi > g.hi[gi] ? hi : g.hi[gi];
            }
            return Aabb{{lo[0], lo[1], lo[2]}, {hi[0], hi[1], hi[2]}};
        }

        /// the robot box culls the obstacle, then its link bounds and spheres are tested
        template <class O, class Exact>
        static bool obstacleSingleCulled(const KinematicProgram &p, float *buf, Placed &placed, const Aabb &box,
                                         const O &o, const Exact &exact) noexcept
        {
            const ObstacleBox ob = obstacleBox(o);
            return overlaps(box, ob) && obstacleSingle(p, buf, placed, ob, exact);
        }

        static bool envSingle(const KinematicProgram &p, const Environment &env, float *buf, Placed &placed,
                              const Aabb &box) noexcept
        {
            const auto hits = [&](const auto &o)
            {
                if constexpr (std::is_same_v<std::decay_t<decltype(o)>, CloudObstacle>)
                    return o.boundRadius >= 0.0f &&
                           obstacleSingleCulled(p, buf, placed, box, o,
                                                [&](const V &x, const V &y, const V &z, const V &r)
                                                {
                                                    const unsigned cand =
                                                        boundTest(x, y, z, r, o.cx, o.cy, o.cz, o.boundRadius).bits();
                                                    return cand != 0u ? hitCloud(x, y, z, r, o, cand) : 0u;
                                                });
                else
                    return obstacleSingleCulled(p, buf, placed, box, o,
                                                [&](const V &x, const V &y, const V &z, const V &r)
                                                { return hitObstacle(x, y, z, r, o).bits(); });
            };
            const auto anyHit = [&](const auto &obstacles)
            {
                for (const auto &o : obstacles)
                    if (hits(o))
                        return true;
                return false;
            };
            for (const Environment *e = &env; e != nullptr; e = e->base())  // the overlay, then its bases
            {
                if (e->primitiveCount() == 0)  // a particle's overlay that holds only attached bodies
                    continue;
                if (const ObstacleTree *tree = e->obstacleTree())
                {
                    // the broad phase: only the primitives whose boxes overlap the robot's
                    if (forEachNearPrimitive<V>(*tree, box, [&](std::size_t k) { return withPrimitive(*e, k, hits); }))
                        return true;
                    continue;
                }
                if (anyHit(e->spheres()) || anyHit(e->boxes()) || anyHit(e->cylinders()) || anyHit(e->capsules()) ||
                    anyHit(e->clouds()))
                    return true;
            }
            return false;
        }

        static bool selfSingle(const KinematicProgram &p, const double *q, float *buf, Placed &placed,
                               const GroupBoxesSingle &g) noexcept
        {
            const ScratchLayout &l = p.single;
            const float *lx = buf + l.lx, *ly = buf + l.ly, *lz = buf + l.lz;
            // per grid of free cells (SpherePairFreeCells): is q in a free cell? Looked up when first needed
            std::uint32_t gridKnown = 0u, gridFree = 0u;
            const auto inFreeCell = [&](int gi)
            {
                if (((gridKnown >> gi) & 1u) == 0u)
                {
                    const SelfGrid &sg = p.selfGrids[static_cast<std::size_t>(gi)];
                    const auto cellOf = [&](int d)
                    {
                        const double x = (q[sg.var[d]] - static_cast<double>(sg.lower[d])) * sg.inv[d];
                        return static_cast<std::uint32_t>(std::min(std::max(x, 0.0), sg.cells - 1.0));
                    };
                    const std::uint32_t cell =
                        sg.var[1] < 0 ? cellOf(0) : cellOf(0) * static_cast<std::uint32_t>(sg.cells) + cellOf(1);
                    gridFree |= (p.cellFree(sg, cell) ? 1u : 0u) << gi;
                    gridKnown |= 1u << gi;
                }
                return ((gridFree >> gi) & 1u) != 0u;
            };
            for (const SelfPairRange &range : p.selfPairRanges)
            {
                // no pair of the range touches when the boxes of the two groups are apart
                const int ga = range.groupA, gb = range.groupB;
                if (g.lo[ga][0] > g.hi[gb][0] || g.lo[gb][0] > g.hi[ga][0] || g.lo[ga][1] > g.hi[gb][1] ||
                    g.lo[gb][1] > g.hi[ga][1] || g.lo[ga][2] > g.hi[gb][2] || g.lo[gb][2] > g.hi[ga][2])
                    continue;
                // the link bounds of up to WIDTH pairs (one link against consecutive links) per vector
                for (int row = range.rowBegin; row < range.rowEnd; ++row)
                {
                    const SelfPairRow &r = p.selfPairRows[static_cast<std::size_t>(row)];
                    const V dx = V::load(lx + r.bFirst) - V::broadcast(lx[r.a]);
                    const V dy = V::load(ly + r.bFirst) - V::broadcast(ly[r.a]);
                    const V dz = V::load(lz + r.bFirst) - V::broadcast(lz[r.a]);
                    unsigned bits = cmpLe(fma(dx, dx, fma(dy, dy, dz * dz)),
                                          V::load(p.selfRowReach2.data() + static_cast<std::size_t>(WIDTH) * row))
                                        .bits();
                    while (bits != 0u)
                    {
                        const int k = r.pairBegin + __builtin_ctz(bits);
                        bits &= bits - 1u;
                        const int grid = p.selfPairGrid[static_cast<std::size_t>(k)];
                        if (grid >= 0 && inFreeCell(grid))
                            continue;
                        if (selfPairSingle(p, buf, placed, k))
                            return true;
                    }
                }
            }
            return false;
        }

        /// the spheres of self pair k (whose bounds touch)
        static bool selfPairSingle(const KinematicProgram &p, float *buf, Placed &placed, int k) noexcept
        {
            const ScratchLayout &l = p.single;
            const float *wx = buf + l.sx, *wy = buf + l.sy, *wz = buf + l.sz;
            const float *lx = buf + l.lx, *ly = buf + l.ly, *lz = buf + l.lz;
            const auto &pair = p.selfPairs[static_cast<std::size_t>(k)];
            const LinkOp &a = p.links[static_cast<std::size_t>(pair.first)];
            const LinkOp &b = p.links[static_cast<std::size_t>(pair.second)];
            if (p.selfPairUseNear[static_cast<std::size_t>(k)] != 0)
            {
                // the spheres around the members that can touch, placed from the frames (columns c0 c1 c2 t)
                const float *near = p.selfPairNear.data() + 8 * static_cast<std::size_t>(k);
                const float *fa = buf + l.frames + 16 * a.frame, *fb = buf + l.frames + 16 * b.frame;
                const Row4 d =
                    loadRow(fa) * near[0] + loadRow(fa + 4) * near[1] + loadRow(fa + 8) * near[2] + loadRow(fa + 12) -
                    (loadRow(fb) * near[4] + loadRow(fb + 4) * near[5] + loadRow(fb + 8) * near[6] + loadRow(fb + 12));
                if (d[0] * d[0] + d[1] * d[1] + d[2] * d[2] > p.selfPairNearReach2[static_cast<std::size_t>(k)])
                    return false;
            }
            ensure(p, buf, placed, pair.first);
            ensure(p, buf, placed, pair.second);
            // spheres of a that can touch b within the joint limits and reach b's bounding sphere, then those
            // against the spheres of b they can touch (every program link has at most WIDTH spheres: one vector)
            const std::uint8_t *masks = p.selfPairSphereMasks.data() + static_cast<std::size_t>(WIDTH) * k;
            unsigned near =
                boundTest(V::load(wx + a.first), V::load(wy + a.first), V::load(wz + a.first),
                          V::load(p.sr.data() + a.first), lx[pair.second], ly[pair.second], lz[pair.second], b.br)
                    .bits() &
                p.selfPairSlotsA[static_cast<std::size_t>(k)];
            if (near == 0u)
                return false;
            const V bx = V::load(wx + b.first), by = V::load(wy + b.first), bz = V::load(wz + b.first),
                    br = V::load(p.sr.data() + b.first);
            while (near != 0u)
            {
                const int t = __builtin_ctz(near);
                near &= near - 1u;
                const int i = a.first + t;
                if ((boundTest(bx, by, bz, br, wx[i], wy[i], wz[i], p.sr[static_cast<std::size_t>(i)]).bits() &
                     masks[t]) != 0u)
                    return true;
            }
            return false;
        }

        /// q within bounds and finite
        static bool validSingle(const KinematicProgram &p, const Environment &env, const double *q, float *buf) noexcept
        {
            GroupBoxesSingle groups;
            framesSingle(p, q, buf, &groups);
            Placed placed;
            if (p.links.size() > 64)
                placeAll(p, buf, placed);
            const Aabb box = aabbSingle(p, groups);
            return !envSingle(p, env, buf, placed, box) && !selfSingle(p, q, buf, placed, groups) &&
                   !(env.hasAttachedBodies() && AttachedKernels<V>::collideSingle(p, env, buf, placed));
        }
    };
}  // namespace ropras::ompl_ext::simd

#endif
