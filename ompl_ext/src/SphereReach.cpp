#include "ropras/ompl_ext/SphereReach.h"

#include <Eigen/Geometry>
#include <algorithm>
#include <cmath>
#include <deque>
#include <string>

#include "ropras/core/Error.h"
#include "ropras/ompl_ext/RobotModel.h"

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
            options.maxVariables < 0)
            throw Error("reachableSpherePairs: invalid options (margin " + std::to_string(options.margin) +
                        " must be finite and >= 0, boxBudget " + std::to_string(options.boxBudget) +
                        " >= 1, maxVariables " + std::to_string(options.maxVariables) + " >= 0)");

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
            // sphere centres at the box centre, in the common ancestor's frame; their slack over the box
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
                                t.rotate(Eigen::AngleAxisd(box.centre[d], Eigen::Vector3d::UnitZ()));
                }
                for (std::size_t s = 0; s < sphereCount(side); ++s)
                {
                    const CollisionSphere &sphere = spheres[static_cast<std::size_t>(chain[side].firstSphere) + s];
                    centres[side][s] = t * sphere.centerInFrame;
                    double l = 0.0;
                    for (std::size_t d = 0; d < nDims; ++d)
                        l += lipschitz[side][s * nDims + d] * box.half[d];
                    slack[side][s] = l;
                }
            }
            std::vector<int> open;
            for (const int k : box.pairs)
            {
                const std::size_t a = static_cast<std::size_t>(k) / nB, b = static_cast<std::size_t>(k) % nB;
                const double gap = (centres[0][a] - centres[1][b]).norm() -
                                   spheres[static_cast<std::size_t>(la.firstSphere) + a].radius -
                                   spheres[static_cast<std::size_t>(lb.firstSphere) + b].radius - options.margin;
                if (gap <= 0.0)
                    reached[static_cast<std::size_t>(k)] = 1;
                else if (gap <= slack[0][a] + slack[1][b])
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
        for (std::size_t a = 0; a < nA; ++a)
            for (std::size_t b = 0; b < nB; ++b)
                if (reached[a * nB + b] != 0)
                    result.pairs.emplace_back(la.firstSphere + static_cast<int>(a),
                                              lb.firstSphere + static_cast<int>(b));
        return result;
    }
}  // namespace ropras::ompl_ext
