// GCC 12 reports a false -Wmaybe-uninitialized inside Eigen's AVX-512 4x4 products (-march=native builds).
#if defined(__GNUC__) && !defined(__clang__)
#pragma GCC diagnostic ignored "-Wmaybe-uninitialized"
#endif

#include "collision/simd/ProgramCompiler.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>
#include <string>
#include <vector>

#include "collision/simd/SelfPairProgram.h"
#include "model/EnclosingSphere.h"
#include "ropras/core/Error.h"

namespace ropras::ompl_ext::simd
{
    namespace
    {
        /// offset rotation entries within this of 0 or +-1 make a signed permutation (folded in the batch path)
        constexpr double PERMUTATION_TOLERANCE = 1e-9;

        /// collision links with more than WIDTH spheres become program links of at most this many spheres
        constexpr std::size_t SUB_LINK_SPHERES = 6;

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

        /// the variables: their count and limit tests (compileFrames marks the rotational ones)
        void compileLimits(const RobotModel &model, KinematicProgram &p)
        {
            p.model = &model;
            p.dof = static_cast<int>(model.dof());

            p.rotational.assign(model.dof(), 0);
            // the limit test as one pair of comparisons (NaN fails both, infinities one; continuous joints: any
            // finite)
            const double big = std::numeric_limits<double>::max();
            for (const PlanningJoint &joint : model.joints())
            {
                const bool unbounded = joint.type == JointType::Continuous;
                p.lowerCheck.push_back(unbounded ? -big : std::max(joint.lower, -big));
                p.upperCheck.push_back(unbounded ? big : std::min(joint.upper, big));
            }
        }

        /// op's offset folded for the batch path: a signed-permutation rotation (permId, flipColumns) and the
        /// zero translation components (translationMask)
        void foldOffset(const KinematicFrame &frame, FrameOp &op)
        {
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

        /// the frames in topological order, their offsets in the forms the single and batch paths use
        void compileFrames(const RobotModel &model, KinematicProgram &p)
        {
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
                                "' refers to variable " + std::to_string(frame.variable) + " of " +
                                std::to_string(p.dof));
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
                foldOffset(frame, op);
            }
        }

        /// the spheres (model indices) of each program link of collision link \a cl: all of them when they fit in
        /// one vector, else groups of at most SUB_LINK_SPHERES neighbours along the axis of largest extent
        std::vector<std::vector<int>> sphereGroups(const CollisionLink &cl, const std::vector<CollisionSphere> &spheres)
        {
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
            return groups;
        }

        /// a program link of collision link \a c with the spheres \a group (its own bound when \a split), appended
        /// to p.links with its block of spheres
        void addProgramLink(const CollisionLink &cl, std::size_t c, const std::vector<int> &group, bool split,
                            const std::vector<CollisionSphere> &spheres, KinematicProgram &p)
        {
            simd::LinkOp op;
            op.frame = cl.frame;
            op.collisionLink = static_cast<int>(c);
            Eigen::Vector3d centre = cl.boundCenterInFrame;
            double bound = cl.boundRadius;
            if (split)
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
            p.links.push_back(op);
        }

        /** \brief Spheres in program order, collision link by collision link: a link with more than WIDTH spheres
            is split into groups of at most SUB_LINK_SPHERES neighbouring spheres, each with its own bound (tighter
            culling, fewer fine tests). Returns the program links of each collision link. */
        std::vector<std::vector<int>> compileLinks(const RobotModel &model, KinematicProgram &p)
        {
            const auto &frames = model.frames();
            const auto &collisionLinks = model.collisionLinks();
            const auto &spheres = model.spheres();
            p.programIndexOfSphere.assign(spheres.size(), -1);
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
                const std::vector<std::vector<int>> groups = sphereGroups(cl, spheres);
                for (const std::vector<int> &group : groups)
                {
                    linkIndex[c].push_back(static_cast<int>(p.links.size()));
                    addProgramLink(cl, c, group, groups.size() > 1, spheres, p);
                }
            }
            return linkIndex;
        }

        /// links grouped by frame, the link bounds in the forms the two paths read
        void compileLinkBounds(const RobotModel &model, KinematicProgram &p)
        {
            const auto &spheres = model.spheres();
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
            p.linkFrame.assign(static_cast<std::size_t>(p.linkPadded), -1.0f);
            p.linkBoundPairs.assign(16 * p.links.size(), 1.0f);
            for (std::size_t l = 0; l < p.links.size(); ++l)
            {
                p.linkRadius[l] = p.links[l].br;
                p.linkFrame[l] = static_cast<float>(p.links[l].frame);
                for (int i = 0; i < 4; ++i)
                {
                    p.linkBoundPairs[16 * l + static_cast<std::size_t>(i)] = p.links[l].bx;
                    p.linkBoundPairs[16 * l + 4 + static_cast<std::size_t>(i)] = p.links[l].by;
                    p.linkBoundPairs[16 * l + 8 + static_cast<std::size_t>(i)] = p.links[l].bz;
                }
            }
            // the sphere at each program slot (RobotModel order; -1 in the padding)
            p.sphereOfSlot.assign(p.sx.size(), -1);
            for (std::size_t s = 0; s < spheres.size(); ++s)
                p.sphereOfSlot[static_cast<std::size_t>(p.programIndexOfSphere[s])] = static_cast<int>(s);
        }

        /// scratch layouts, and the angles a batch must look at for the double reduction
        void compileLayouts(const RobotModel &model, KinematicProgram &p)
        {
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
            // the angles a batch must look at for the double reduction: rotational joints whose limits reach past
            // 64
            for (int j = 0; j < p.dof; ++j)
                if (p.rotational[static_cast<std::size_t>(j)] && (p.lowerCheck[static_cast<std::size_t>(j)] < -64.0 ||
                                                                  p.upperCheck[static_cast<std::size_t>(j)] > 64.0))
                    p.reduceCheck.push_back(j);
        }
    }  // namespace

    KinematicProgram compileProgram(const RobotModel &model)
    {
        KinematicProgram p;
        compileLimits(model, p);
        compileFrames(model, p);
        const std::vector<std::vector<int>> linkIndex = compileLinks(model, p);
        compileLinkBounds(model, p);
        compileSelfPairProgram(model, linkIndex, p);
        compileLayouts(model, p);
        return p;
    }
}  // namespace ropras::ompl_ext::simd
