// Collision kernels of a batch (one configuration per lane) for any 8-lane backend V.
#ifndef ROPRAS_OMPL_EXT_SIMD_BATCH_KERNELS_H
#define ROPRAS_OMPL_EXT_SIMD_BATCH_KERNELS_H

#include <algorithm>
#include <cstdint>
#include <type_traits>

#include "BatchFrames.h"
#include "BroadPhase.h"
#include "ForceInline.h"
#include "KinematicProgram.h"
#include "ObstacleTests.h"
#include "Placed.h"
#include "ropras/ompl_ext/scene/Environment.h"

namespace ropras::ompl_ext::simd
{
    template <class V>
    struct AttachedKernels;

    /** \brief Collision verdicts of WIDTH configurations, one per lane, after BatchFrames::framesBatch:
        obstacles (obstacle-major, culled by the robot box, the link group boxes and the link bounds), attached
        bodies, then self pairs. */
    template <class V>
    struct BatchKernels
    {
        using Mask = typename V::Mask;
        using Frames = BatchFrames<V>;

        template <class Exact>
        static unsigned obstacleBatch(const KinematicProgram &p, float *buf, Placed &placed, int li, unsigned active,
                                      const ObstacleBox &ob, const Exact &exact) noexcept
        {
            const ScratchLayout &l = p.batch;
            constexpr int W = WIDTH;
            const LinkOp &link = p.links[static_cast<std::size_t>(li)];
            const unsigned cand = sphereTouchesBox(V::load(buf + l.lx + W * li), V::load(buf + l.ly + W * li),
                                                   V::load(buf + l.lz + W * li), V::broadcast(link.br), ob)
                                      .bits() &
                                  active;
            if (cand == 0u)
                return 0u;
            // the exact test on the link bounding sphere before its spheres
            const unsigned near = exact(V::load(buf + l.lx + W * li), V::load(buf + l.ly + W * li),
                                        V::load(buf + l.lz + W * li), V::broadcast(link.br), cand) &
                                  cand;
            if (near == 0u)
                return 0u;
            Frames::ensureBatch(p, buf, placed, li);
            unsigned hit = 0u;
            for (int s = link.first; s < link.first + link.count; ++s)
            {
                hit |= exact(V::load(buf + l.sx + W * s), V::load(buf + l.sy + W * s), V::load(buf + l.sz + W * s),
                             V::broadcast(p.sr[static_cast<std::size_t>(s)]), near & ~hit);
                if ((near & ~hit) == 0u)
                    break;
            }
            return hit & near;
        }

        /// per-lane axis-aligned boxes around the link bounds of each link group (LinkGroup), WIDTH lanes each
        struct GroupBoxes
        {
            V lo[MAX_LINK_GROUPS][3], hi[MAX_LINK_GROUPS][3];
        };

        /// the group boxes of every lane, and the box around every link bound of the \a active lanes
        static Aabb groupBoxesBatch(const KinematicProgram &p, const float *buf, unsigned active,
                                    GroupBoxes &g) noexcept
        {
            const ScratchLayout &l = p.batch;
            constexpr int W = WIDTH;
            const Mask lanes = Mask::fromBits(active);
            const V far = V::broadcast(1e30f), nfar = V::broadcast(-1e30f);
            V lo[3] = {far, far, far}, hi[3] = {nfar, nfar, nfar};
            const std::size_t offsets[3] = {l.lx, l.ly, l.lz};
            for (std::size_t gi = 0; gi < p.groups.size(); ++gi)
            {
                const LinkGroup &grp = p.groups[gi];
                V glo[3] = {far, far, far}, ghi[3] = {nfar, nfar, nfar};
                for (int li = grp.begin; li < grp.end; ++li)
                {
                    const V r = V::broadcast(p.links[static_cast<std::size_t>(li)].br);
                    for (int i = 0; i < 3; ++i)
                    {
                        const V c = V::load(buf + offsets[i] + W * li);
                        glo[i] = min(glo[i], c - r);
                        ghi[i] = max(ghi[i], c + r);
                    }
                }
                for (int i = 0; i < 3; ++i)
                {
                    g.lo[gi][i] = glo[i];
                    g.hi[gi][i] = ghi[i];
                    lo[i] = min(lo[i], select(lanes, glo[i], far));
                    hi[i] = max(hi[i], select(lanes, ghi[i], nfar));
                }
            }
            Aabb box;
            for (int i = 0; i < 3; ++i)
            {
                box.lo[i] = hmin(lo[i]);
                box.hi[i] = hmax(hi[i]);
            }
            return box;
        }

        /// lanes whose group box overlaps the obstacle box
        ROPRAS_SIMD_FORCE_INLINE static unsigned groupTouches(const GroupBoxes &g, int gi,
                                                              const ObstacleBox &b) noexcept
        {
            const Mask x =
                cmpLe(g.lo[gi][0], V::broadcast(b.cx + b.ex)) & cmpGe(g.hi[gi][0], V::broadcast(b.cx - b.ex));
            const Mask y =
                cmpLe(g.lo[gi][1], V::broadcast(b.cy + b.ey)) & cmpGe(g.hi[gi][1], V::broadcast(b.cy - b.ey));
            const Mask z =
                cmpLe(g.lo[gi][2], V::broadcast(b.cz + b.ez)) & cmpGe(g.hi[gi][2], V::broadcast(b.cz - b.ez));
            return (x & y & z).bits();
        }

        /// lanes where the boxes of groups a and b overlap
        ROPRAS_SIMD_FORCE_INLINE static unsigned groupsOverlap(const GroupBoxes &g, int a, int b) noexcept
        {
            Mask m = cmpLe(g.lo[a][0], g.hi[b][0]) & cmpLe(g.lo[b][0], g.hi[a][0]);
            for (int i = 1; i < 3; ++i)
                m = m & cmpLe(g.lo[a][i], g.hi[b][i]) & cmpLe(g.lo[b][i], g.hi[a][i]);
            return m.bits();
        }

        /// lanes whose configuration is in a free cell of self grid \a gi (SpherePairFreeCells)
        static unsigned freeCellLanes(const KinematicProgram &p, const float *buf, int gi) noexcept
        {
            const ScratchLayout &l = p.batch;
            constexpr int W = WIDTH;
            const SelfGrid &g = p.selfGrids[static_cast<std::size_t>(gi)];
            const V top = V::broadcast(static_cast<float>(g.cells - 1));
            const auto cellOf = [&](int d)
            {
                const V x = (V::load(buf + l.q + W * g.var[d]) - V::broadcast(g.lower[d])) * V::broadcast(g.inv[d]);
                return floor(min(max(x, V::zero()), top));
            };
            // cell numbers are integers below 2^24: exact in float
            const V cell =
                g.var[1] < 0 ? cellOf(0) : fma(cellOf(0), V::broadcast(static_cast<float>(g.cells)), cellOf(1));
            float c[W];
            cell.store(c);
            unsigned lanes = 0u;
            for (int i = 0; i < W; ++i)
                lanes |= (p.cellFree(g, static_cast<std::uint32_t>(c[i])) ? 1u : 0u) << i;
            return lanes;
        }

        /// lanes of \a c where the spheres of self pair \a k (whose link bounds touch there) touch
        static unsigned selfPairBatch(const KinematicProgram &p, float *buf, Placed &placed, int k, unsigned c) noexcept
        {
            const ScratchLayout &l = p.batch;
            constexpr int W = WIDTH;
            const auto &pair = p.selfPairs[static_cast<std::size_t>(k)];
            const LinkOp &a = p.links[static_cast<std::size_t>(pair.first)];
            const LinkOp &b = p.links[static_cast<std::size_t>(pair.second)];
            if (p.selfPairUseNear[static_cast<std::size_t>(k)] != 0)
            {
                // the spheres around the members that can touch, placed from the frames
                const float *near = p.selfPairNear.data() + 8 * static_cast<std::size_t>(k);
                V ca[3], cb[3];
                Frames::placePointBatch(buf + l.frames + 12 * W * a.frame, near, ca);
                Frames::placePointBatch(buf + l.frames + 12 * W * b.frame, near + 4, cb);
                const V dx = ca[0] - cb[0], dy = ca[1] - cb[1], dz = ca[2] - cb[2];
                c &= cmpLe(fma(dx, dx, fma(dy, dy, dz * dz)),
                           V::broadcast(p.selfPairNearReach2[static_cast<std::size_t>(k)]))
                         .bits();
                if (c == 0u)
                    return 0u;
            }
            Frames::ensureBatch(p, buf, placed, pair.first);
            Frames::ensureBatch(p, buf, placed, pair.second);
            const V bx = V::load(buf + l.lx + W * pair.second), by = V::load(buf + l.ly + W * pair.second),
                    bz = V::load(buf + l.lz + W * pair.second);
            // only the sphere pairs that can touch within the joint limits (selfPairSphereMasks)
            const std::uint8_t *masks = p.selfPairSphereMasks.data() + static_cast<std::size_t>(W) * k;
            unsigned hit = 0u;
            for (unsigned slots = p.selfPairSlotsA[static_cast<std::size_t>(k)]; slots != 0u && c != 0u;
                 slots &= slots - 1u)
            {
                const int t = __builtin_ctz(slots);
                const int i = a.first + t;
                const V x = V::load(buf + l.sx + W * i), y = V::load(buf + l.sy + W * i),
                        z = V::load(buf + l.sz + W * i);
                const float ri = p.sr[static_cast<std::size_t>(i)];
                unsigned partners = masks[t];
                unsigned near = c;
                if ((partners & (partners - 1u)) != 0u)
                {
                    // two or more partners: first the lanes where sphere i reaches b's bounding sphere
                    const V ex = x - bx, ey = y - by, ez = z - bz;
                    const float rb = ri + b.br;
                    near &= cmpLe(fma(ex, ex, fma(ey, ey, ez * ez)), V::broadcast(rb * rb)).bits();
                }
                for (; partners != 0u && near != 0u; partners &= partners - 1u)
                {
                    const int j = b.first + __builtin_ctz(partners);
                    const V fx = x - V::load(buf + l.sx + W * j), fy = y - V::load(buf + l.sy + W * j),
                            fz = z - V::load(buf + l.sz + W * j);
                    const float rs = ri + p.sr[static_cast<std::size_t>(j)];
                    const unsigned h = cmpLe(fma(fx, fx, fma(fy, fy, fz * fz)), V::broadcast(rs * rs)).bits() & near;
                    near &= ~h;
                    c &= ~h;
                    hit |= h;
                }
            }
            return hit;
        }

        /// lanes of \a lanes where some self-collision pair touches
        static unsigned selfBatch(const KinematicProgram &p, float *buf, Placed &placed, const GroupBoxes &g,
                                  unsigned lanes, bool stopOnAny) noexcept
        {
            const ScratchLayout &l = p.batch;
            unsigned hit = 0u;
            const float *lx = buf + l.lx, *ly = buf + l.ly, *lz = buf + l.lz;
            // lanes in a free cell of each grid, computed when a pair first needs it
            unsigned gridLanes[MAX_SELF_GRIDS];
            std::uint32_t gridKnown = 0u;
            const auto gridFree = [&](int gi)
            {
                if (((gridKnown >> gi) & 1u) == 0u)
                {
                    gridLanes[gi] = freeCellLanes(p, buf, gi);
                    gridKnown |= 1u << gi;
                }
                return gridLanes[gi];
            };
            for (const SelfPairRange &range : p.selfPairRanges)
            {
                // the boxes of the two link groups first: no pair of the range can touch where they are apart
                const unsigned groupLanes = groupsOverlap(g, range.groupA, range.groupB) & lanes & ~hit;
                if (groupLanes == 0u)
                    continue;
                for (int base = range.begin; base < range.end; base += 64)
                {
                    const int end = std::min(range.end, base + 64);
                    unsigned cand[64];
                    std::uint64_t any = 0u;
                    // the link bounds of every pair first, without branches
                    for (int k = base; k < end; ++k)
                    {
                        const auto kk = static_cast<std::size_t>(k);
                        const int a = p.selfPairOffsetA[kk], b = p.selfPairOffsetB[kk];
                        const V dx = V::load(lx + a) - V::load(lx + b);
                        const V dy = V::load(ly + a) - V::load(ly + b);
                        const V dz = V::load(lz + a) - V::load(lz + b);
                        const unsigned c =
                            cmpLe(fma(dx, dx, fma(dy, dy, dz * dz)), V::broadcast(p.selfPairReach2[kk])).bits() &
                            groupLanes;
                        cand[k - base] = c;
                        any |= static_cast<std::uint64_t>(c != 0u) << (k - base);
                    }
                    while (any != 0u)
                    {
                        const int k = base + __builtin_ctzll(any);
                        any &= any - 1u;
                        unsigned c = cand[k - base] & ~hit;
                        if (c == 0u)
                            continue;
                        const int grid = p.selfPairGrid[static_cast<std::size_t>(k)];
                        if (grid >= 0)
                        {
                            c &= ~gridFree(grid);
                            if (c == 0u)
                                continue;
                        }
                        hit |= selfPairBatch(p, buf, placed, k, c);
                        if ((lanes & ~hit) == 0u || (stopOnAny && hit != 0u))
                            return hit;
                    }
                }
            }
            return hit;
        }

        /** \brief Collision lanes of a batch after framesBatch. \a active: lanes to check (bits); stops as soon
            as every active lane collides, or at the first collision when \a stopOnAny. Without \a self, the
            robot's self pairs are not tested (obstacles and attached bodies only). */
        static unsigned collideBatch(const KinematicProgram &p, const Environment &env, float *buf, unsigned active,
                                     bool stopOnAny, bool self = true) noexcept
        {
            Placed placed;
            if (p.links.size() > 64)
                Frames::placeAllBatch(p, buf, placed);
            unsigned hit = 0u;
            const auto done = [&] { return stopOnAny ? hit != 0u : (active & ~hit) == 0u; };
            GroupBoxes groups;
            const Aabb box = groupBoxesBatch(p, buf, active, groups);
            const int nGroups = static_cast<int>(p.groups.size());
            // obstacle-major: the robot box rejects far obstacles once, then the per-lane group boxes, then the
            // links of the groups that touch (only in the lanes that touch); returns true when decided (done())
            const auto obstacle = [&](const ObstacleBox &ob, const auto &exact) __attribute__((always_inline))
            {
                if (!overlaps(box, ob))
                    return false;
                for (int gi = 0; gi < nGroups; ++gi)
                {
                    const unsigned lanes = groupTouches(groups, gi, ob) & active & ~hit;
                    if (lanes == 0u)
                        continue;
                    const LinkGroup &grp = p.groups[static_cast<std::size_t>(gi)];
                    for (int li = grp.begin; li < grp.end; ++li)
                    {
                        hit |= obstacleBatch(p, buf, placed, li, lanes & ~hit, ob, exact);
                        if (done())
                            return true;
                    }
                }
                return false;
            };
            const auto decides = [&](const auto &o)
            {
                if constexpr (std::is_same_v<std::decay_t<decltype(o)>, CloudObstacle>)
                    return o.boundRadius >= 0.0f &&
                           obstacle(obstacleBox(o),
                                    [&](const V &x, const V &y, const V &z, const V &r, unsigned cand)
                                    {
                                        const unsigned near =
                                            boundTest(x, y, z, r, o.cx, o.cy, o.cz, o.boundRadius).bits() & cand;
                                        return near != 0u ? hitCloud(x, y, z, r, o, near) : 0u;
                                    });
                else
                    return obstacle(obstacleBox(o), [&](const V &x, const V &y, const V &z, const V &r, unsigned)
                                    { return hitObstacle(x, y, z, r, o).bits(); });
            };
            const auto sweep = [&](const auto &obstacles)
            {
                for (const auto &o : obstacles)
                    if (decides(o))
                        return true;
                return false;
            };
            for (const Environment *e = &env; e != nullptr; e = e->base())  // the overlay, then its bases
            {
                if (const ObstacleTree *tree = e->obstacleTree())
                {
                    // the broad phase: only the primitives whose boxes overlap the box around every active lane
                    if (forEachNearPrimitive<V>(*tree, box,
                                                [&](std::size_t k) { return withPrimitive(*e, k, decides); }))
                        return hit;
                    continue;
                }
                if (sweep(e->spheres()) || sweep(e->boxes()) || sweep(e->cylinders()) || sweep(e->capsules()) ||
                    sweep(e->clouds()))
                    return hit;
            }
            if (env.hasAttachedBodies())
            {
                hit |= AttachedKernels<V>::collideBatch(p, env, buf, placed, active & ~hit, stopOnAny);
                if (done())
                    return hit;
            }
            if (self)
                hit |= selfBatch(p, buf, placed, groups, active & ~hit, stopOnAny);
            return hit;
        }
    };
}  // namespace ropras::ompl_ext::simd

#endif
