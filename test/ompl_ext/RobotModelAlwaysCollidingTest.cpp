#include <gtest/gtest.h>

#include "ExpectError.h"
#include "RobotModelTestUtil.h"

#include <algorithm>
#include <cmath>
#include <functional>
#include <set>

#include "ropras/core/Error.h"
#include "ropras/ompl_ext/model/RobotModel.h"

// Link pairs in contact in (almost) every configuration: found, disabled and reported.
using namespace ropras::test;
using ropras::Error;
using ropras::ompl_ext::JointType;

namespace
{
    // Two links spinning about the same z axis with overlapping spheres (in contact in every configuration) and a
    // slider along x whose sphere touches both only near q = 0 (in contact at the default configuration only).
    const char *ALWAYS_URDF = R"(<?xml version="1.0"?>
<robot name="always">
  <link name="base"/>
  <link name="a"><collision><geometry><sphere radius="0.1"/></geometry></collision></link>
  <link name="b"><collision><origin xyz="0 0 0.15"/><geometry><sphere radius="0.1"/></geometry></collision></link>
  <link name="c"><collision><geometry><sphere radius="0.1"/></geometry></collision></link>
  <joint name="ja" type="revolute"><parent link="base"/><child link="a"/><axis xyz="0 0 1"/>
    <limit lower="-3" upper="3" effort="1" velocity="1"/></joint>
  <joint name="jb" type="continuous"><parent link="base"/><child link="b"/><axis xyz="0 0 1"/></joint>
  <joint name="jc" type="prismatic"><parent link="base"/><child link="c"/><axis xyz="1 0 0"/>
    <limit lower="-2" upper="2" effort="1" velocity="1"/></joint>
</robot>)";

    using NamePairs = std::vector<std::pair<std::string, std::string>>;

    /// link-name pairs of selfCollisionPairs(), each sorted, as a set
    std::set<std::pair<std::string, std::string>> namedSelfPairs(const RobotModel &m)
    {
        std::set<std::pair<std::string, std::string>> out;
        for (const auto &[a, b] : m.selfCollisionPairs())
        {
            out.insert(std::minmax(m.collisionLinks()[a].name, m.collisionLinks()[b].name));
        }
        return out;
    }

    std::set<std::pair<std::string, std::string>> sortedSet(const NamePairs &pairs)
    {
        std::set<std::pair<std::string, std::string>> out;
        for (const auto &[a, b] : pairs)
        {
            out.insert(std::minmax(a, b));
        }
        return out;
    }

    /// brute force over every sphere pair of every enabled self pair (reference centres, double)
    bool selfCollides(const RobotModel &m, const std::vector<double> &q)
    {
        const auto c = m.sphereCentersReference(q.data());
        const auto &s = m.spheres();
        for (const auto &[a, b] : m.selfCollisionPairs())
        {
            const auto &la = m.collisionLinks()[a], &lb = m.collisionLinks()[b];
            for (int i = la.firstSphere; i < la.firstSphere + la.sphereCount; ++i)
            {
                for (int j = lb.firstSphere; j < lb.firstSphere + lb.sphereCount; ++j)
                {
                    if ((c[i] - c[j]).norm() <= s[i].radius + s[j].radius)
                    {
                        return true;
                    }
                }
            }
        }
        return false;
    }

    /// how many of \a n random configurations (seed \a seed) are free of self-collision
    int selfFreeCount(const RobotModel &m, int n, unsigned seed)
    {
        std::mt19937 rng(seed);
        int free = 0;
        for (int k = 0; k < n; ++k)
        {
            free += selfCollides(m, randomQ(m, rng)) ? 0 : 1;
        }
        return free;
    }
}  // namespace

TEST(RobotModel, AlwaysCollidingPairsHandBuilt)
{
    const auto m = RobotModel::fromUrdfString(ALWAYS_URDF, ".", "always.urdf");
    EXPECT_EQ(sortedSet(m->alwaysCollidingPairs()), sortedSet({{"a", "b"}}));
    EXPECT_EQ(namedSelfPairs(*m), sortedSet({{"a", "c"}, {"b", "c"}}));
    // at q = 0 the slider's sphere sits on a's (distance 0) and 0.15 below b's (radii sum 0.2)
    EXPECT_EQ(m->defaultConfiguration(), std::vector<double>(3, 0.0));
    EXPECT_EQ(sortedSet(m->defaultCollidingPairs()), sortedSet({{"a", "c"}, {"b", "c"}}));

    RobotModel::Options off;
    off.disableAlwaysColliding = false;
    const auto all = RobotModel::fromUrdfString(ALWAYS_URDF, ".", "always.urdf", "", off);
    EXPECT_TRUE(all->alwaysCollidingPairs().empty());
    EXPECT_EQ(namedSelfPairs(*all), sortedSet({{"a", "b"}, {"a", "c"}, {"b", "c"}}));
    EXPECT_EQ(sortedSet(all->defaultCollidingPairs()), sortedSet({{"a", "b"}, {"a", "c"}, {"b", "c"}}));
    EXPECT_EQ(selfFreeCount(*all, 200, 3), 0);
    EXPECT_GT(selfFreeCount(*m, 200, 3), 100);  // free whenever |q_c| > 0.2 (a) and sqrt(q_c^2 + 0.0225) > 0.2

    // Options::disabledPairs acts like the SRDF
    RobotModel::Options extra;
    extra.disabledPairs = {{"c", "b"}};
    EXPECT_EQ(namedSelfPairs(*RobotModel::fromUrdfString(ALWAYS_URDF, ".", "always.urdf", "", extra)),
              sortedSet({{"a", "c"}}));
}

TEST(RobotModel, AlwaysCollidingOptionErrors)
{
    RobotModel::Options zero;
    zero.alwaysCollidingSamples = 0;
    try
    {
        RobotModel::fromUrdfString(ALWAYS_URDF, ".", "always.urdf", "", zero);
        FAIL() << "no error";
    }
    catch (const Error &e)
    {
        EXPECT_NE(std::string(e.what()).find("always.urdf"), std::string::npos) << e.what();
        EXPECT_NE(std::string(e.what()).find("alwaysCollidingSamples"), std::string::npos) << e.what();
    }
    zero.disableAlwaysColliding = false;  // then the count is unused
    EXPECT_NO_THROW(RobotModel::fromUrdfString(ALWAYS_URDF, ".", "always.urdf", "", zero));
    RobotModel::Options unknown;
    unknown.disabledPairs = {{"a", "nolink"}};
    try
    {
        RobotModel::fromUrdfString(ALWAYS_URDF, ".", "always.urdf", "", unknown);
        FAIL() << "no error";
    }
    catch (const Error &e)
    {
        EXPECT_NE(std::string(e.what()).find("'nolink'"), std::string::npos) << e.what();
    }
}

TEST(RobotModel, Ur5AlwaysCollidingSensorPairIsDisabled)
{
    REQUIRE_SHARED();
    const std::string urdf = sharedFile("robots/ur5/ur5_spherized.urdf"), srdf = sharedFile("robots/ur5/ur5.srdf");
    const auto m = RobotModel::fromUrdfFile(urdf, srdf);
    RobotModel::Options off;
    off.disableAlwaysColliding = false;
    const auto old = RobotModel::fromUrdfFile(urdf, srdf, off);

    const auto always = sortedSet(m->alwaysCollidingPairs());
    EXPECT_EQ(always.count(std::minmax(std::string("fts_robotside"), std::string("wrist_2_link"))), 1u);
    // ON = OFF minus exactly the always pairs
    auto expected = namedSelfPairs(*old);
    for (const auto &p : always)
    {
        EXPECT_EQ(expected.erase(p), 1u) << p.first << " / " << p.second;
    }
    EXPECT_EQ(namedSelfPairs(*m), expected);
    EXPECT_TRUE(old->alwaysCollidingPairs().empty());

    // the rule is reproducible: another seed and more samples disable the same pairs
    RobotModel::Options other;
    other.alwaysCollidingSeed = 99;
    other.alwaysCollidingSamples = 3000;
    EXPECT_EQ(sortedSet(RobotModel::fromUrdfFile(urdf, srdf, other)->alwaysCollidingPairs()), always);

    // before: every configuration self-collides; after: most random configurations are free
    EXPECT_EQ(selfFreeCount(*old, 300, 7), 0);
    EXPECT_GT(selfFreeCount(*m, 300, 7), 150);
    // the default configuration is reported consistently with the brute force
    EXPECT_EQ(m->defaultCollidingPairs().empty(), !selfCollides(*m, m->defaultConfiguration()));
}

TEST(RobotModel, PandaHasNoAlwaysCollidingPairs)
{
    REQUIRE_SHARED();
    const std::string urdf = sharedFile("robots/panda/panda_spherized.urdf"),
                      srdf = sharedFile("robots/panda/panda.srdf");
    const auto m = RobotModel::fromUrdfFile(urdf, srdf);
    RobotModel::Options off;
    off.disableAlwaysColliding = false;
    EXPECT_TRUE(m->alwaysCollidingPairs().empty());
    EXPECT_EQ(m->selfCollisionPairs(), RobotModel::fromUrdfFile(urdf, srdf, off)->selfCollisionPairs());
    EXPECT_EQ(m->defaultCollidingPairs().empty(), !selfCollides(*m, m->defaultConfiguration()));
}
