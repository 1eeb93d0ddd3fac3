#include <algorithm>
#include <random>

#include "model/RobotModelBuilder.h"

namespace ropras::ompl_ext
{
    // Self-collision pairs: collision links on different compiled frames, minus SRDF disable_collisions,
    // minus adjacent links. Two links are adjacent when the tree path between them has at most one non-fixed
    // joint and every link strictly inside the path has no collision geometry (MoveIt's rule of
    // bridging geometry-less links).
    void RobotModelBuilder::buildSelfPairs()
    {
        const auto &links = model_->links_;
        std::vector<int> collisionOf(links.size(), -1);
        for (std::size_t i = 0; i < model_->collisionLinks_.size(); ++i)
        {
            collisionOf[model_->collisionLinks_[i].link] = static_cast<int>(i);
        }
        // pairs of link indices that are never checked: SRDF disable_collisions, Options::disabledPairs, and
        // adjacent links (hashed: the loop over all collision-link pairs below does O(1) work per pair)
        std::unordered_set<std::uint64_t> skipped;
        std::unordered_map<std::string, int> linkIndex;
        for (std::size_t i = 0; i < links.size(); ++i)
        {
            linkIndex.emplace(links[i].name, static_cast<int>(i));
        }
        skipSrdfPairs(linkIndex, skipped);
        for (const auto &[a, b] : options_.disabledPairs)
        {
            const auto ia = linkIndex.find(a), ib = linkIndex.find(b);
            if (ia == linkIndex.end() || ib == linkIndex.end())
            {
                fail("Options::disabledPairs names unknown link '" + (ia == linkIndex.end() ? a : b) + "'");
            }
            skipped.insert(pairKey(ia->second, ib->second));
        }
        std::vector<std::vector<int>> childJoints(links.size());
        for (std::size_t j = 0; j < model_->urdfJoints_.size(); ++j)
        {
            childJoints[static_cast<std::size_t>(model_->urdfJoints_[j].parentLink)].push_back(static_cast<int>(j));
        }
        for (std::size_t i = 0; i < model_->collisionLinks_.size(); ++i)
        {
            const int a = model_->collisionLinks_[i].link;
            for (const int b : adjacentLinks(a, collisionOf, childJoints))
            {
                skipped.insert(pairKey(a, b));
            }
        }
        const auto &cls = model_->collisionLinks_;
        for (std::size_t i = 0; i < cls.size(); ++i)
        {
            for (std::size_t k = i + 1; k < cls.size(); ++k)
            {
                if (cls[i].frame != cls[k].frame && skipped.count(pairKey(cls[i].link, cls[k].link)) == 0)
                {
                    model_->selfPairs_.emplace_back(static_cast<int>(i), static_cast<int>(k));
                }
            }
        }
    }

    std::uint64_t RobotModelBuilder::pairKey(int a, int b)
    {
        return (std::uint64_t(std::uint32_t(std::min(a, b))) << 32) | std::uint32_t(std::max(a, b));
    }

    void RobotModelBuilder::skipSrdfPairs(const std::unordered_map<std::string, int> &linkIndex,
                                          std::unordered_set<std::uint64_t> &skipped)
    {
        std::map<std::string, std::string> unknownLines;  // unknown link -> the lines naming it
        std::vector<std::string> unknownOrder;
        for (const SrdfDisabledPair &pair : srdf_.disabledPairs)
        {
            const auto ia = linkIndex.find(pair.link1), ib = linkIndex.find(pair.link2);
            if (ia != linkIndex.end() && ib != linkIndex.end())
            {
                skipped.insert(pairKey(ia->second, ib->second));
                continue;
            }
            const std::string &link = ia == linkIndex.end() ? pair.link1 : pair.link2;
            if (options_.strict)
                throw Error("SRDF '" + srdfName_ + "': <disable_collisions> on line " + std::to_string(pair.line) +
                            " names link '" + link + "', which the URDF does not define");
            std::string &lines = unknownLines[link];
            if (lines.empty())
                unknownOrder.push_back(link);
            lines += (lines.empty() ? "" : ", ") + std::to_string(pair.line);
        }
        // MoveIt warns and skips such entries: one SRDF often serves several variants of a robot
        for (const std::string &link : unknownOrder)
            model_->warnings_.push_back("SRDF '" + srdfName_ + "': <disable_collisions> on line" +
                                        (unknownLines[link].find(',') == std::string::npos ? " " : "s ") +
                                        unknownLines[link] + " names link '" + link +
                                        "', which the URDF does not define; skipped");
    }

    std::vector<int> RobotModelBuilder::adjacentLinks(int from, const std::vector<int> &collisionOf,
                                                      const std::vector<std::vector<int>> &childJoints) const
    {
        const auto &links = model_->links_;
        const auto &joints = model_->urdfJoints_;
        std::vector<int> out;
        struct Step
        {
            int link, previous, movable;
        };
        std::vector<Step> stack{{from, -1, 0}};
        while (!stack.empty())
        {
            const Step step = stack.back();
            stack.pop_back();
            if (step.link != from && collisionOf[static_cast<std::size_t>(step.link)] >= 0)
            {
                out.push_back(step.link);  // an end point: the path does not continue through geometry
                continue;
            }
            const auto visit = [&](int next, const UrdfJoint &joint)
            {
                const int movable = step.movable + (joint.type != JointType::Fixed ? 1 : 0);
                if (next != step.previous && movable <= 1)
                {
                    stack.push_back({next, step.link, movable});
                }
            };
            const Link &link = links[static_cast<std::size_t>(step.link)];
            if (link.parentJoint >= 0)
            {
                const UrdfJoint &up = joints[static_cast<std::size_t>(link.parentJoint)];
                visit(up.parentLink, up);
            }
            for (const int j : childJoints[static_cast<std::size_t>(step.link)])
            {
                visit(joints[static_cast<std::size_t>(j)].childLink, joints[static_cast<std::size_t>(j)]);
            }
        }
        return out;
    }

    bool RobotModelBuilder::inContact(const std::vector<Eigen::Vector3d> &centers, int a, int b) const
    {
        const auto &spheres = model_->spheres_;
        const CollisionLink &la = model_->collisionLinks_[static_cast<std::size_t>(a)];
        const CollisionLink &lb = model_->collisionLinks_[static_cast<std::size_t>(b)];
        for (int i = la.firstSphere; i < la.firstSphere + la.sphereCount; ++i)
        {
            for (int j = lb.firstSphere; j < lb.firstSphere + lb.sphereCount; ++j)
            {
                const auto si = static_cast<std::size_t>(i), sj = static_cast<std::size_t>(j);
                if ((centers[si] - centers[sj]).norm() <= spheres[si].radius + spheres[sj].radius)
                {
                    return true;
                }
            }
        }
        return false;
    }

    std::pair<std::string, std::string> RobotModelBuilder::pairNames(const std::pair<int, int> &p) const
    {
        return {model_->collisionLinks_[static_cast<std::size_t>(p.first)].name,
                model_->collisionLinks_[static_cast<std::size_t>(p.second)].name};
    }

    // MoveIt Setup Assistant's "Always" rule (disable pairs in contact in every sampled configuration) and
    // "Default" rule (report, but keep, pairs in contact at the default configuration). Samples are uniform
    // within the limits from a fixed-seed mt19937_64 with a portable [0, 1) mapping, so the result is the same
    // on every platform. A pair leaves the candidates at its first contact-free sample; sampling stops early
    // when none is left, which does not change the result.
    void RobotModelBuilder::findAlwaysAndDefaultPairs()
    {
        std::vector<std::pair<int, int>> &pairs = model_->selfPairs_;
        if (options_.disableAlwaysColliding)
        {
            if (options_.alwaysCollidingSamples == 0)
            {
                fail("Options::alwaysCollidingSamples must be > 0 when disableAlwaysColliding is on");
            }
            std::vector<std::pair<int, int>> always = pairs;
            std::mt19937_64 rng(options_.alwaysCollidingSeed);
            std::vector<double> q(model_->joints_.size());
            for (std::size_t k = 0; k < options_.alwaysCollidingSamples && !always.empty(); ++k)
            {
                for (std::size_t i = 0; i < q.size(); ++i)
                {
                    const PlanningJoint &j = model_->joints_[i];
                    const double u = static_cast<double>(rng() >> 11) * 0x1.0p-53;
                    q[i] = std::min(j.upper, j.lower + u * (j.upper - j.lower));
                }
                const std::vector<Eigen::Vector3d> centers = model_->sphereCentersReference(q.data());
                always.erase(std::remove_if(always.begin(), always.end(),
                                            [&](const std::pair<int, int> &p)
                                            { return !inContact(centers, p.first, p.second); }),
                             always.end());
            }
            for (const std::pair<int, int> &p : always)
            {
                model_->alwaysPairs_.push_back(pairNames(p));
            }
            std::unordered_set<std::uint64_t> alwaysKeys;  // hashed: O(1) per pair, not O(|always|)
            for (const std::pair<int, int> &p : always)
            {
                alwaysKeys.insert((std::uint64_t(std::uint32_t(p.first)) << 32) | std::uint32_t(p.second));
            }
            pairs.erase(std::remove_if(pairs.begin(), pairs.end(),
                                       [&](const std::pair<int, int> &p) {
                                           return alwaysKeys.count((std::uint64_t(std::uint32_t(p.first)) << 32) |
                                                                   std::uint32_t(p.second)) != 0;
                                       }),
                        pairs.end());
        }
        const std::vector<double> q = model_->defaultConfiguration();
        const std::vector<Eigen::Vector3d> centers = model_->sphereCentersReference(q.data());
        for (const std::pair<int, int> &p : pairs)
        {
            if (inContact(centers, p.first, p.second))
            {
                model_->defaultPairs_.push_back(pairNames(p));
            }
        }
    }
}  // namespace ropras::ompl_ext
