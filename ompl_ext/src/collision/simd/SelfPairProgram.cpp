#include "collision/simd/SelfPairProgram.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <string>
#include <unordered_set>
#include <vector>

#include "model/EnclosingSphere.h"
#include "ropras/core/Error.h"
#include "ropras/ompl_ext/model/SphereReach.h"

namespace ropras::ompl_ext::simd
{
    namespace
    {
        /** \brief The grid of free cells of a self pair's reach in p.selfGrids (shared with the pairs over the same
            grid), when the batch q block holds the grid's variables unreduced (|limits| <= 64); -1 if none. */
        int selfGridOf(const RobotModel &model, const SphereReach &reach, KinematicProgram &p)
        {
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
            return grid;
        }

        /// per program pair WIDTH masks (per slot of A, the slots of B) and its grid of free cells or -1
        struct SelfPairCandidates
        {
            std::vector<std::uint8_t> masks;
            std::vector<int> grid;
        };

        /** \brief The program pairs of self pair \a pair (collision links), with the sphere pairs that can touch
            within the joint limits (\a reach); a program pair none of whose sphere pairs can touch is dropped. */
        void addSelfPairs(const std::pair<int, int> &pair, const SphereReach &reach, int grid,
                          const std::vector<std::vector<int>> &linkIndex, const std::vector<int> &sphereOfSlot,
                          KinematicProgram &p, SelfPairCandidates &candidates)
        {
            std::vector<std::uint8_t> &pairMasks = candidates.masks;
            std::vector<int> &pairGrid = candidates.grid;
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

        /// self pairs: program links of both collision links, with the sphere pairs that can touch within the
        /// joint limits (reachableSpherePairs)
        SelfPairCandidates compileSelfPairs(const RobotModel &model, const std::vector<std::vector<int>> &linkIndex,
                                            KinematicProgram &p)
        {
            const auto &collisionLinks = model.collisionLinks();
            const std::vector<int> &sphereOfSlot = p.sphereOfSlot;
            SelfPairCandidates candidates;
            for (const auto &pair : model.selfCollisionPairs())
            {
                if (pair.first < 0 || pair.second < 0 || pair.first >= static_cast<int>(collisionLinks.size()) ||
                    pair.second >= static_cast<int>(collisionLinks.size()))
                    throw Error("CollisionChecker: robot '" + model.name() + "' self-collision pair (" +
                                std::to_string(pair.first) + ", " + std::to_string(pair.second) + ") out of range");
                const SphereReach reach = reachableSpherePairs(model, pair.first, pair.second);
                addSelfPairs(pair, reach, selfGridOf(model, reach, p), linkIndex, sphereOfSlot, p, candidates);
            }
            return candidates;
        }

        /// link groups: returns the group of each program link
        std::vector<int> compileLinkGroups(KinematicProgram &p)
        {
            // link groups: consecutive links, a new group once the current one has `size` links and the frame
            // changes (at most MAX_LINK_GROUPS: every group but the last has at least `size` links)
            const std::size_t nProgramLinks = p.links.size();
            const std::size_t size =
                std::max<std::size_t>({2, (nProgramLinks + 3) / 4,
                                       (nProgramLinks + simd::MAX_LINK_GROUPS - 2) / (simd::MAX_LINK_GROUPS - 1)});
            std::vector<int> groupOf(nProgramLinks, 0);
            for (std::size_t l = 0; l < nProgramLinks; ++l)
            {
                if (p.groups.empty() ||
                    (static_cast<std::size_t>(p.groups.back().end - p.groups.back().begin) >= size &&
                     p.links[l].frame != p.links[l - 1].frame))
                    p.groups.push_back({static_cast<int>(l), static_cast<int>(l)});
                p.groups.back().end = static_cast<int>(l) + 1;
                groupOf[l] = static_cast<int>(p.groups.size()) - 1;
            }
            p.groupOfLink = groupOf;
            return groupOf;
        }

        /// self pairs sorted by the groups of their links (their sphere masks along); one range per group pair
        void sortSelfPairs(const std::vector<int> &groupOf, const SelfPairCandidates &candidates, KinematicProgram &p)
        {
            const std::vector<std::uint8_t> &pairMasks = candidates.masks;
            const std::vector<int> &pairGrid = candidates.grid;
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

        /// per pair: the spheres around the members that can touch (much smaller than the link bounds when few
        /// sphere pairs can touch, e.g. the Panda's link5 against link7); used when one is at most 95 % of its
        /// bound
        void compileNearSpheres(KinematicProgram &p)
        {
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
        }

        /// the ranges of pairs per group pair, their rows (single path) and per-pair reach (batch path)
        void compileSelfRanges(const std::vector<int> &groupOf, KinematicProgram &p)
        {
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
                const float rs = p.links[static_cast<std::size_t>(pair.first)].br +
                                 p.links[static_cast<std::size_t>(pair.second)].br;
                p.selfPairReach2.push_back(rs * rs);
                p.selfPairOffsetA.push_back(WIDTH * pair.first);
                p.selfPairOffsetB.push_back(WIDTH * pair.second);
            }
        }

    }  // namespace

    float withRoundingSlack(double radius)
    {
        return static_cast<float>(radius * (1.0 + 1e-5) + 1e-6);
    }

    void compileSelfPairProgram(const RobotModel &model, const std::vector<std::vector<int>> &linkIndex,
                                KinematicProgram &p)
    {
        const SelfPairCandidates candidates = compileSelfPairs(model, linkIndex, p);
        const std::vector<int> groupOf = compileLinkGroups(p);
        sortSelfPairs(groupOf, candidates, p);
        compileNearSpheres(p);
        compileSelfRanges(groupOf, p);
    }
}  // namespace ropras::ompl_ext::simd
