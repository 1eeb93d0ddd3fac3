#include "ropras/ompl_ext/model/SphereReach.h"

#include <Eigen/Geometry>
#include <algorithm>
#include <cmath>
#include <deque>
#include <string>

#include "ropras/core/Error.h"
#include "ropras/ompl_ext/model/RobotModel.h"

namespace ropras::ompl_ext
{
    namespace
    {
        /// one side of the path: the frames from below the common ancestor down to the link's frame
        struct Chain
        {
            std::vector<int> frames;  ///< top (child of the common ancestor) first
            int firstSphere{0}, sphereCount{0};
        };

        /// frames from \a frame up to the root, \a frame first
        std::vector<int> ancestry(const std::vector<KinematicFrame> &frames, int frame)
        {
            std::vector<int> up;
            for (int f = frame; f >= 0; f = frames[static_cast<std::size_t>(f)].parent)
                up.push_back(f);
            return up;
        }

        struct Box
        {
            std::vector<double> centre, half;
            std::vector<int> pairs;  ///< undecided pairs (indices into the candidate list)
        };
    }  // namespace

    SphereReach reachableSpherePairs(const RobotModel &model, int linkA, int linkB, const SphereReachOptions &options)
    {
        const auto &links = model.collisionLinks();
        const auto &spheres = model.spheres();
        const auto &frames = model.frames();
        const int nLinks = static_cast<int>(links.size());
        if (linkA < 0 || linkA >= nLinks || linkB < 0 || linkB >= nLinks)
            throw Error("reachableSpherePairs: robot '" + model.name() + "' has " + std::to_string(nLinks) +
                        " collision links; link index " + std::to_string(linkA < 0 || linkA >= nLinks ? linkA : linkB) +
                        " is out of range");
        if (!(options.margin >= 0.0) || !std::isfinite(options.margin) || options.boxBudget < 1 ||
            options.maxVariables < 0 || options.freeCellsPerJoint < 0 || options.freeCellsPerJoint > 1024)
            throw Error("reachableSpherePairs: invalid options (margin " + std::to_string(options.margin) +
                        " must be finite and >= 0, boxBudget " + std::to_string(options.boxBudget) +
                        " >= 1, maxVariables " + std::to_string(options.maxVariables) + " >= 0, freeCellsPerJoint " +
                        std::to_string(options.freeCellsPerJoint) + " in [0, 1024])");

        const CollisionLink &la = links[static_cast<std::size_t>(linkA)];
        const CollisionLink &lb = links[static_cast<std::size_t>(linkB)];
        SphereReach result;
        const auto keepAll = [&]
        {
            result.pairs.clear();
            for (int a = 0; a < la.sphereCount; ++a)
                for (int b = 0; b < lb.sphereCount; ++b)
                    result.pairs.emplace_back(la.firstSphere + a, lb.firstSphere + b);
        };

        // A pair with more than maxVariables moving frames (or a prismatic one) between its links is not analysed:
        // find that out on a walk that stops there (frames are in topological order, parent < index), so that a
        // long chain does not cost its depth for each of its O(n^2) link pairs
        {
            int a = la.frame, b = lb.frame, moving = 0;
            while (a != b && moving <= options.maxVariables)
            {
                int &up = a > b ? a : b;
                const KinematicFrame &f = frames[static_cast<std::size_t>(up)];
                if (f.motion == JointMotion::TranslateZ)
                    moving = options.maxVariables + 1;
                else if (f.motion == JointMotion::RotateZ)
                    ++moving;
                up = f.parent;
            }
            if (moving > options.maxVariables)
            {
                keepAll();
                return result;
            }
        }

        // the two chains below the deepest common ancestor
        const std::vector<int> upA = ancestry(frames, la.frame), upB = ancestry(frames, lb.frame);
        Chain chain[2];
        {
            std::size_t ia = upA.size(), ib = upB.size();
            while (ia > 0 && ib > 0 && upA[ia - 1] == upB[ib - 1])
            {
                --ia;
                --ib;
            }
            chain[0].frames.assign(upA.rbegin() + static_cast<std::ptrdiff_t>(upA.size() - ia), upA.rend());
            chain[1].frames.assign(upB.rbegin() + static_cast<std::ptrdiff_t>(upB.size() - ib), upB.rend());
        }
        chain[0].firstSphere = la.firstSphere;
        chain[0].sphereCount = la.sphereCount;
        chain[1].firstSphere = lb.firstSphere;
        chain[1].sphereCount = lb.sphereCount;

        // the joint-space box: one dimension per moving frame of either chain
        struct Dim
        {
            int side, position;  ///< chain and position in it
            double lower, upper;
        };
        std::vector<Dim> dims;
        for (int side = 0; side < 2; ++side)
            for (std::size_t k = 0; k < chain[side].frames.size(); ++k)
            {
                const KinematicFrame &f = frames[static_cast<std::size_t>(chain[side].frames[k])];
                if (f.motion == JointMotion::TranslateZ)
                {
                    keepAll();
                    return result;
                }
                if (f.motion == JointMotion::RotateZ)
                {
                    const PlanningJoint &j = model.joints()[static_cast<std::size_t>(f.variable)];
                    dims.push_back({side, static_cast<int>(k), j.lower, j.upper});
                }
            }
        if (static_cast<int>(dims.size()) > options.maxVariables || la.sphereCount == 0 || lb.sphereCount == 0)
        {
            keepAll();
            return result;
        }
        result.analysed = true;
        const std::size_t nDims = dims.size();

        // Lipschitz constants: per sphere and dimension, a bound on the sphere centre's distance from the joint's
        // axis (its distance from the joint frame's origin: the offsets below the joint plus the centre's offset)
        const auto sphereCount = [&](int side) { return static_cast<std::size_t>(chain[side].sphereCount); };
        std::vector<double> lipschitz[2];
        std::vector<double> dimWeight(nDims, 0.0);
        for (int side = 0; side < 2; ++side)
        {
            lipschitz[side].assign(sphereCount(side) * nDims, 0.0);
            for (std::size_t s = 0; s < sphereCount(side); ++s)
            {
                const CollisionSphere &sphere = spheres[static_cast<std::size_t>(chain[side].firstSphere) + s];
                for (std::size_t d = 0; d < nDims; ++d)
                {
                    if (dims[d].side != side)
                        continue;
                    // the point in the joint's frame is t_next + R (rest): its distance from the z axis is at most
                    // the xy part of the first offset below the joint plus the lengths of the others and the centre's
                    const std::size_t next = static_cast<std::size_t>(dims[d].position) + 1;
                    const std::size_t end = chain[side].frames.size();
                    double reach = 0.0;
                    if (next == end)
                        reach = sphere.centerInFrame.head<2>().norm();
                    else
                    {
                        reach = frames[static_cast<std::size_t>(chain[side].frames[next])]
                                    .offset.translation()
                                    .head<2>()
                                    .norm() +
                                sphere.centerInFrame.norm();
                        for (std::size_t k = next + 1; k < end; ++k)
                            reach +=
                                frames[static_cast<std::size_t>(chain[side].frames[k])].offset.translation().norm();
                    }
                    lipschitz[side][s * nDims + d] = reach;
                    dimWeight[d] = std::max(dimWeight[d], reach);
                }
            }
        }

        // candidates: every sphere pair; decided[] once some configuration brings it within the margin
        const std::size_t nA = sphereCount(0), nB = sphereCount(1);
        std::vector<char> reached(nA * nB, 0);
        Box root;
        root.centre.resize(nDims);
        root.half.resize(nDims);
        for (std::size_t d = 0; d < nDims; ++d)
        {
            root.centre[d] = 0.5 * (dims[d].lower + dims[d].upper);
            root.half[d] = 0.5 * (dims[d].upper - dims[d].lower);
        }
        root.pairs.resize(nA * nB);
        for (std::size_t k = 0; k < root.pairs.size(); ++k)
            root.pairs[k] = static_cast<int>(k);

        std::vector<Eigen::Vector3d> centres[2] = {std::vector<Eigen::Vector3d>(nA), std::vector<Eigen::Vector3d>(nB)};
        std::vector<double> slack[2] = {std::vector<double>(nA), std::vector<double>(nB)};
        // sphere centres at a box centre, in the common ancestor's frame, and their slack over the box
        const auto place = [&](const std::vector<double> &centre, const std::vector<double> &half)
        {
            for (int side = 0; side < 2; ++side)
            {
                Eigen::Isometry3d t = Eigen::Isometry3d::Identity();
                for (std::size_t k = 0; k < chain[side].frames.size(); ++k)
                {
                    const KinematicFrame &f = frames[static_cast<std::size_t>(chain[side].frames[k])];
                    t = t * f.offset;
                    if (f.motion == JointMotion::RotateZ)
                        for (std::size_t d = 0; d < nDims; ++d)
                            if (dims[d].side == side && dims[d].position == static_cast<int>(k))
                                t.rotate(Eigen::AngleAxisd(centre[d], Eigen::Vector3d::UnitZ()));
                }
                for (std::size_t s = 0; s < sphereCount(side); ++s)
                {
                    const CollisionSphere &sphere = spheres[static_cast<std::size_t>(chain[side].firstSphere) + s];
                    centres[side][s] = t * sphere.centerInFrame;
                    double l = 0.0;
                    for (std::size_t d = 0; d < nDims; ++d)
                        l += lipschitz[side][s * nDims + d] * half[d];
                    slack[side][s] = l;
                }
            }
        };
        /// candidate k's gap beyond contact plus the margin at the placed centres
        const auto gapAtCentre = [&](int k)
        {
            const std::size_t a = static_cast<std::size_t>(k) / nB, b = static_cast<std::size_t>(k) % nB;
            return (centres[0][a] - centres[1][b]).norm() -
                   spheres[static_cast<std::size_t>(la.firstSphere) + a].radius -
                   spheres[static_cast<std::size_t>(lb.firstSphere) + b].radius - options.margin;
        };
        // breadth first: the budget is spent level by level, so that a few hard pairs (a minimum distance just
        // above the margin) cannot keep the easy ones of unvisited boxes
        std::deque<Box> queue;
        queue.push_back(std::move(root));
        while (!queue.empty())
        {
            Box box = std::move(queue.front());
            queue.pop_front();
            // pairs found reachable in another box need no more work
            box.pairs.erase(std::remove_if(box.pairs.begin(), box.pairs.end(),
                                           [&](int k) { return reached[static_cast<std::size_t>(k)] != 0; }),
                            box.pairs.end());
            if (box.pairs.empty())
                continue;
            if (result.boxes >= static_cast<std::size_t>(options.boxBudget))
            {
                result.budgetExhausted = true;
                for (const int k : box.pairs)
                    reached[static_cast<std::size_t>(k)] = 1;
                continue;
            }
            ++result.boxes;
            place(box.centre, box.half);
            std::vector<int> open;
            for (const int k : box.pairs)
            {
                const double gap = gapAtCentre(k);
                if (gap <= 0.0)
                    reached[static_cast<std::size_t>(k)] = 1;
                else if (gap <= slack[0][static_cast<std::size_t>(k) / nB] + slack[1][static_cast<std::size_t>(k) % nB])
                    open.push_back(k);
            }
            if (open.empty())
                continue;
            // halve the box along its widest joint (weighted by how far the spheres sit from the joint axes)
            std::size_t split = 0;
            for (std::size_t d = 1; d < nDims; ++d)
                if (dimWeight[d] * box.half[d] > dimWeight[split] * box.half[split])
                    split = d;
            if (nDims == 0 || box.half[split] < 1e-12)
            {
                for (const int k : open)  // cannot split further: keep (never drop a pair that might touch)
                    reached[static_cast<std::size_t>(k)] = 1;
                continue;
            }
            Box lo{box.centre, box.half, open};
            Box hi{std::move(box.centre), std::move(box.half), std::move(open)};
            const double h = 0.5 * lo.half[split];
            lo.half[split] = hi.half[split] = h;
            lo.centre[split] -= h;
            hi.centre[split] += h;
            queue.push_back(std::move(lo));
            queue.push_back(std::move(hi));
        }
        std::vector<int> kept;
        for (std::size_t a = 0; a < nA; ++a)
            for (std::size_t b = 0; b < nB; ++b)
                if (reached[a * nB + b] != 0)
                {
                    result.pairs.emplace_back(la.firstSphere + static_cast<int>(a),
                                              lb.firstSphere + static_cast<int>(b));
                    kept.push_back(static_cast<int>(a * nB + b));
                }

        // the grid of free cells: every joint revolute with finite limits (continuous joints are not reduced to
        // one turn by the checkers, so their values can leave any finite grid)
        const int n = options.freeCellsPerJoint;
        const auto variableOf = [&](const Dim &d) {
            return frames[static_cast<std::size_t>(chain[d.side].frames[static_cast<std::size_t>(d.position)])]
                .variable;
        };
        bool gridable = n > 0 && nDims > 0 && !kept.empty();
        for (const Dim &d : dims)
            gridable = gridable && std::isfinite(d.lower) && std::isfinite(d.upper) && d.upper > d.lower &&
                       model.joints()[static_cast<std::size_t>(variableOf(d))].type == JointType::Revolute;
        if (!gridable)
            return result;
        SpherePairFreeCells &grid = result.freeCells;
        grid.cells = n;
        for (const Dim &d : dims)
        {
            grid.variables.push_back(variableOf(d));
            grid.lower.push_back(d.lower);
            grid.width.push_back((d.upper - d.lower) / n);
        }
        const std::size_t nCells = nDims == 1 ? static_cast<std::size_t>(n) : static_cast<std::size_t>(n) * n;
        grid.bits.assign((nCells + 31) / 32, 0u);
        constexpr double WIDEN = 1e-5;  // rad beyond each side of a cell
        std::vector<double> centre(nDims), half(nDims);
        for (std::size_t cell = 0; cell < nCells; ++cell)
        {
            const std::size_t index[2] = {nDims == 1 ? cell : cell / static_cast<std::size_t>(n),
                                          cell % static_cast<std::size_t>(n)};
            for (std::size_t d = 0; d < nDims; ++d)
            {
                centre[d] = grid.lower[d] + (static_cast<double>(index[d]) + 0.5) * grid.width[d];
                half[d] = 0.5 * grid.width[d] + WIDEN;
            }
            place(centre, half);
            const bool isFree = std::all_of(kept.begin(), kept.end(),
                                            [&](int k)
                                            {
                                                const std::size_t a = static_cast<std::size_t>(k) / nB,
                                                                  b = static_cast<std::size_t>(k) % nB;
                                                return gapAtCentre(k) > slack[0][a] + slack[1][b];
                                            });
            if (isFree)
                grid.bits[cell / 32] |= 1u << (cell % 32);
        }
        return result;
    }

    double SpherePairFreeCells::freeFraction() const noexcept
    {
        if (variables.empty() || cells <= 0)
            return 0.0;
        std::size_t set = 0;
        for (const std::uint32_t w : bits)
            set += static_cast<std::size_t>(__builtin_popcount(w));
        const double all = variables.size() == 1 ? cells : static_cast<double>(cells) * cells;
        return static_cast<double>(set) / all;
    }

    bool SpherePairFreeCells::isFree(const double *q) const noexcept
    {
        if (variables.empty() || cells <= 0)
            return false;
        std::size_t cell = 0;
        for (std::size_t d = 0; d < variables.size(); ++d)
        {
            const double x = (q[static_cast<std::size_t>(variables[d])] - lower[d]) / width[d];
            if (!(x >= 0.0 && x < cells))  // outside the limits (or NaN): no claim
                return false;
            cell = cell * static_cast<std::size_t>(cells) + static_cast<std::size_t>(x);
        }
        return ((bits[cell / 32] >> (cell % 32)) & 1u) != 0u;
    }
}  // namespace ropras::ompl_ext
