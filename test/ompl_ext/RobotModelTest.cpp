#include <gtest/gtest.h>

#include "ExpectError.h"
#include "RobotModelTestUtil.h"

#include <algorithm>
#include <cmath>
#include <functional>
#include <set>

#include "ropras/core/Error.h"
#include "ropras/ompl_ext/model/RobotModel.h"

// Loading robots: joints, limits, spheres, frames, self-collision pairs and held joints.
using namespace ropras::test;
using ropras::Error;
using ropras::ompl_ext::JointType;

TEST(RobotModel, PandaSpherizedJointsLimitsSpheres)
{
    REQUIRE_SHARED();
    auto m = RobotModel::fromUrdfFile(sharedFile("robots/panda/panda_spherized.urdf"),
                                      sharedFile("robots/panda/panda.srdf"));
    EXPECT_EQ(m->name(), "panda");
    ASSERT_EQ(m->dof(), 7u);
    for (int i = 0; i < 7; ++i)
    {
        EXPECT_EQ(m->joints()[i].name, "panda_joint" + std::to_string(i + 1));
        EXPECT_EQ(m->joints()[i].type, JointType::Revolute);
        EXPECT_EQ(m->jointIndex("panda_joint" + std::to_string(i + 1)), i);
    }
    EXPECT_DOUBLE_EQ(m->joints()[3].lower, -3.1416);
    EXPECT_DOUBLE_EQ(m->joints()[3].upper, 0.0873);
    EXPECT_DOUBLE_EQ(m->joints()[5].lower, -0.0873);
    EXPECT_DOUBLE_EQ(m->joints()[5].upper, 3.8223);
    EXPECT_EQ(m->spheres().size(), 59u);
    EXPECT_EQ(m->collisionGeometries().size(), 59u);
    EXPECT_EQ(m->frames().size(), 8u);  // root + 7 revolute joints
    EXPECT_EQ(m->links()[0].name, "panda_link0");
    EXPECT_EQ(m->links()[m->linkIndex("panda_link0")].frame, 0);
    EXPECT_THROW(m->linkIndex("nope"), Error);
    expectErrorMentions([&] { m->jointIndex("panda_finger_joint1"); }, {"panda_finger_joint1", "panda_joint7"});

    // spheres contiguous per collision link, bounding spheres enclose them
    int next = 0;
    for (std::size_t c = 0; c < m->collisionLinks().size(); ++c)
    {
        const auto &cl = m->collisionLinks()[c];
        EXPECT_EQ(cl.firstSphere, next);
        EXPECT_GT(cl.sphereCount, 0);
        EXPECT_EQ(cl.frame, m->links()[cl.link].frame);
        double tightest = 0.0;
        for (int i = cl.firstSphere; i < cl.firstSphere + cl.sphereCount; ++i)
        {
            const auto &s = m->spheres()[i];
            EXPECT_EQ(s.collisionLink, static_cast<int>(c));
            const double reach = (s.centerInFrame - cl.boundCenterInFrame).norm() + s.radius;
            EXPECT_LE(reach, cl.boundRadius);
            tightest = std::max(tightest, reach);
            // the bound is no bigger than the trivial one around the first sphere's centre
        }
        EXPECT_LE(cl.boundRadius, tightest + 1e-9);  // tight: touches the farthest sphere
        next += cl.sphereCount;
    }
    EXPECT_EQ(next, 59);
}

TEST(RobotModel, PandaLink8AtZero)
{
    REQUIRE_SHARED();
    auto m = RobotModel::fromUrdfFile(sharedFile("robots/panda/panda_spherized.urdf"));
    const std::vector<double> q(7, 0.0);
    const auto t = m->linkTransformsReference(q.data());
    // by hand: z = 0.333 + 0.316 + 0.384 - 0.107 (link7 points down), x = 0.0825 - 0.0825 + 0.088
    const Eigen::Vector3d p = t[m->linkIndex("panda_link8")].translation();
    EXPECT_NEAR(p.x(), 0.088, 1e-9);
    EXPECT_NEAR(p.y(), 0.0, 1e-9);
    EXPECT_NEAR(p.z(), 0.926, 1e-9);
}

TEST(RobotModel, BoundingSphereIsTight)
{
    REQUIRE_SHARED();
    auto m = RobotModel::fromUrdfFile(sharedFile("robots/panda/panda_spherized.urdf"));
    // panda_link1 has four spheres of radius 0.06 at (0,-0.08,0), (0,-0.03,0), (0,0,-0.12), (0,0,-0.17): the
    // minimal enclosing ball has the diameter from (0,-0.08,0) to (0,0,-0.17): radius |(0.08,0.17)|/2 + 0.06.
    const auto &cl = m->collisionLinks()[1];
    ASSERT_EQ(cl.name, "panda_link1");
    const double minimal = 0.5 * std::hypot(0.08, 0.17) + 0.06;
    EXPECT_GE(cl.boundRadius, minimal - 1e-9);
    EXPECT_LE(cl.boundRadius, minimal * 1.01);
}

TEST(RobotModel, Ur5JointOrderAndSpheres)
{
    REQUIRE_SHARED();
    auto m = RobotModel::fromUrdfFile(sharedFile("robots/ur5/ur5_spherized.urdf"), sharedFile("robots/ur5/ur5.srdf"));
    const std::vector<std::string> expected = {"shoulder_pan_joint", "shoulder_lift_joint", "elbow_joint",
                                               "wrist_1_joint",      "wrist_2_joint",       "wrist_3_joint"};
    ASSERT_EQ(m->dof(), expected.size());
    for (std::size_t i = 0; i < expected.size(); ++i)
    {
        EXPECT_EQ(m->joints()[i].name, expected[i]);
        EXPECT_NEAR(m->joints()[i].lower, -3.14159265, 1e-12);
        EXPECT_NEAR(m->joints()[i].upper, 3.14159265, 1e-12);
    }
    EXPECT_EQ(m->spheres().size(), 40u);
}

TEST(RobotModel, CompiledFramesMatchReferenceFk)
{
    REQUIRE_SHARED();
    Eigen::Isometry3d base = Eigen::Isometry3d::Identity();
    base.translate(Eigen::Vector3d(0.3, -0.2, 0.1))
        .rotate(Eigen::AngleAxisd(0.7, Eigen::Vector3d(1, 2, 3).normalized()));
    RobotModel::Options withBase;
    withBase.basePose = base;
    for (const auto &options : {RobotModel::Options(), withBase})
    {
        expectCompiledMatchesReference(
            *RobotModel::fromUrdfFile(sharedFile("robots/panda/panda_spherized.urdf"), "", options), 1000, 11);
        expectCompiledMatchesReference(
            *RobotModel::fromUrdfFile(sharedFile("robots/ur5/ur5_spherized.urdf"), "", options), 1000, 12);
    }
    // the base pose is applied
    auto m = RobotModel::fromUrdfFile(sharedFile("robots/panda/panda_spherized.urdf"), "", withBase);
    const std::vector<double> q(7, 0.0);
    EXPECT_TRUE(m->linkTransformsReference(q.data())[0].isApprox(base, 1e-12));
}

TEST(RobotModel, EveryJointTypeAndSkewAxes)
{
    auto m = RobotModel::fromUrdfString(testArmUrdf(), ".", "testarm.urdf");
    ASSERT_EQ(m->dof(), 4u);
    EXPECT_EQ(m->joints()[0].name, "z_last");  // document order, not name order
    EXPECT_EQ(m->joints()[0].type, JointType::Continuous);
    EXPECT_NEAR(m->joints()[0].lower, -M_PI, 1e-15);
    EXPECT_EQ(m->joints()[2].type, JointType::Prismatic);
    EXPECT_EQ(m->frames().size(), 5u);
    // the fixed joint folds "mount" into l2's frame
    EXPECT_EQ(m->links()[m->linkIndex("mount")].frame, m->links()[m->linkIndex("l2")].frame);
    expectCompiledMatchesReference(*m, 1000, 5);

    // continuous joints accept any finite value; others are bounded
    std::vector<double> q = {10.0, 0.0, 0.0, 0.0};
    EXPECT_TRUE(m->withinBounds(q.data()));
    q[2] = 0.25;
    EXPECT_FALSE(m->withinBounds(q.data()));
    q[2] = 0.0;
    q[0] = std::nan("");
    EXPECT_FALSE(m->withinBounds(q.data()));
    q[0] = std::numeric_limits<double>::infinity();
    EXPECT_FALSE(m->withinBounds(q.data()));
}

TEST(RobotModel, HeldJointsGiveTheSameSpheres)
{
    REQUIRE_SHARED();
    const std::string urdf = sharedFile("robots/panda/panda_spherized.urdf");
    const std::string srdf = sharedFile("robots/panda/panda.srdf");
    auto full = RobotModel::fromUrdfFile(urdf, srdf);
    RobotModel::Options o;
    o.planningJoints = {"panda_joint6", "panda_joint2", "panda_joint4"};  // the user's order
    o.heldJointValues = {{"panda_joint1", 0.4}, {"panda_joint3", -1.0}, {"panda_joint7", 2.0}};
    auto part = RobotModel::fromUrdfFile(urdf, srdf, o);
    ASSERT_EQ(part->dof(), 3u);
    EXPECT_EQ(part->joints()[0].name, "panda_joint6");
    EXPECT_EQ(part->frames().size(), 4u);
    ASSERT_EQ(part->spheres().size(), full->spheres().size());
    std::mt19937 rng(3);
    double worst = 0.0;
    for (int s = 0; s < 200; ++s)
    {
        const std::vector<double> qp = randomQ(*part, rng);
        std::vector<double> qf = {0.4, qp[1], -1.0, qp[2], 0.0, qp[0], 2.0};  // joint5 held at default 0
        const auto a = part->sphereCentersReference(qp.data());
        const auto b = full->sphereCentersReference(qf.data());
        const auto frames = compiledFrames(*part, qp);
        for (std::size_t i = 0; i < a.size(); ++i)
        {
            const auto &sp = part->spheres()[i];
            worst = std::max(worst, (a[i] - b[i]).norm());
            worst = std::max(worst,
                             (frames[part->collisionLinks()[sp.collisionLink].frame] * sp.centerInFrame - b[i]).norm());
        }
    }
    EXPECT_LT(worst, 1e-9);
    // fewer frames: the partial model's pairs are a subset (by name), strictly smaller without the SRDF
    auto names = [](const RobotModel &r)
    {
        std::set<std::pair<std::string, std::string>> out;
        for (const auto &[a, b] : r.selfCollisionPairs())
        {
            out.insert({r.collisionLinks()[a].name, r.collisionLinks()[b].name});
        }
        return out;
    };
    const auto fullPairs = names(*full);
    for (const auto &p : names(*part))
    {
        EXPECT_EQ(fullPairs.count(p), 1u) << p.first << " " << p.second;
    }
    EXPECT_LT(RobotModel::fromUrdfFile(urdf, "", o)->selfCollisionPairs().size(),
              RobotModel::fromUrdfFile(urdf)->selfCollisionPairs().size());

    // default held value is 0 clamped into the limits (panda_joint4 upper limit 0.0873 includes 0; joint6 too)
    RobotModel::Options o2;
    o2.planningJoints = {"panda_joint1"};
    auto one = RobotModel::fromUrdfFile(urdf, "", o2);
    for (const auto &j : one->urdfJoints())
    {
        if (j.name == "panda_joint4")
        {
            EXPECT_EQ(j.heldValue, 0.0);
            EXPECT_EQ(j.variable, -1);
        }
    }
}

TEST(RobotModel, SelfCollisionPairs)
{
    REQUIRE_SHARED();
    auto m = RobotModel::fromUrdfFile(sharedFile("robots/panda/panda_spherized.urdf"),
                                      sharedFile("robots/panda/panda.srdf"));
    auto noSrdf = RobotModel::fromUrdfFile(sharedFile("robots/panda/panda_spherized.urdf"));
    const auto &cls = m->collisionLinks();
    std::set<std::pair<std::string, std::string>> disabled;
    std::ifstream in(sharedFile("robots/panda/panda.srdf"));
    const std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
    for (std::size_t pos = text.find("<disable_collisions"); pos != std::string::npos;
         pos = text.find("<disable_collisions", pos + 1))
    {
        auto attr = [&](const std::string &key)
        {
            const std::size_t a = text.find(key + "=\"", pos) + key.size() + 2;
            return text.substr(a, text.find('"', a) - a);
        };
        disabled.insert({attr("link1"), attr("link2")});
        disabled.insert({attr("link2"), attr("link1")});
    }
    ASSERT_FALSE(disabled.empty());
    std::set<std::pair<int, int>> seen;
    for (const auto &[a, b] : m->selfCollisionPairs())
    {
        ASSERT_LT(a, b);
        EXPECT_TRUE(seen.insert({a, b}).second);
        EXPECT_NE(cls[a].frame, cls[b].frame);
        EXPECT_EQ(disabled.count({cls[a].name, cls[b].name}), 0u) << cls[a].name << " " << cls[b].name;
    }
    EXPECT_GT(m->selfCollisionPairs().size(), 5u);
    EXPECT_LT(m->selfCollisionPairs().size(), noSrdf->selfCollisionPairs().size());
    // adjacency: links joined by one joint never pair, with or without SRDF
    auto pairNamed = [](const RobotModel &r, const std::string &x, const std::string &y)
    {
        for (const auto &[a, b] : r.selfCollisionPairs())
        {
            const auto &na = r.collisionLinks()[a].name, &nb = r.collisionLinks()[b].name;
            if ((na == x && nb == y) || (na == y && nb == x))
            {
                return true;
            }
        }
        return false;
    };
    EXPECT_FALSE(pairNamed(*noSrdf, "panda_link1", "panda_link2"));
    EXPECT_FALSE(pairNamed(*noSrdf, "panda_link6", "panda_link7"));
    EXPECT_TRUE(pairNamed(*noSrdf, "panda_link1", "panda_link3"));
    EXPECT_TRUE(pairNamed(*m, "panda_link1", "panda_link5"));
    EXPECT_TRUE(pairNamed(*m, "panda_link2", "panda_hand"));
    EXPECT_FALSE(pairNamed(*m, "panda_link7", "panda_hand"));  // same frame (fixed joints)
}

TEST(RobotModel, AdjacencyBridgesGeometrylessLinks)
{
    // base -(revolute)- l1 ; l2 joined to l1 by a prismatic joint; mount (no geometry) is fixed to l2 and l3 hangs
    // off mount by a revolute joint: l2-l3 are adjacent (one movable joint, geometry-less link between)
    auto m = RobotModel::fromUrdfString(testArmUrdf(), ".", "testarm.urdf");
    auto has = [&](const std::string &x, const std::string &y)
    {
        for (const auto &[a, b] : m->selfCollisionPairs())
        {
            const auto &na = m->collisionLinks()[a].name, &nb = m->collisionLinks()[b].name;
            if ((na == x && nb == y) || (na == y && nb == x))
            {
                return true;
            }
        }
        return false;
    };
    EXPECT_FALSE(has("base", "l1"));
    EXPECT_FALSE(has("l1", "l2"));
    EXPECT_FALSE(has("l2", "l3"));
    EXPECT_FALSE(has("l3", "l4"));
    EXPECT_TRUE(has("base", "l2"));
    EXPECT_TRUE(has("l1", "l3"));
    EXPECT_TRUE(has("base", "l4"));
    EXPECT_EQ(m->selfCollisionPairs().size(), 6u);  // 5 links: 10 pairs minus 4 adjacent
}

TEST(RobotModel, ShippedRoprasArm)
{
    const std::string dir = std::string(ROPRAS_SOURCE_DIR) + "/robots/ropras_arm/";
    auto m = RobotModel::fromUrdfFile(dir + "ropras_arm.urdf", dir + "ropras_arm.srdf");
    auto noSrdf = RobotModel::fromUrdfFile(dir + "ropras_arm.urdf");
    EXPECT_EQ(m->name(), "ropras_arm");
    const std::vector<std::string> names = {"shoulder_pan_joint", "shoulder_lift_joint", "elbow_joint",
                                            "wrist_1_joint",      "wrist_2_joint",       "wrist_3_joint"};
    ASSERT_EQ(m->dof(), names.size());
    for (std::size_t i = 0; i < names.size(); ++i)
    {
        EXPECT_EQ(m->joints()[i].name, names[i]);
        EXPECT_EQ(m->joints()[i].type, JointType::Revolute);
        EXPECT_LT(m->joints()[i].lower, 0.0);
        EXPECT_GT(m->joints()[i].upper, 0.0);
    }
    // a skewed joint axis, and every kind of collision geometry
    bool skewed = false;
    for (const auto &j : m->urdfJoints())
    {
        skewed = skewed || (j.type != JointType::Fixed && j.axis.cwiseAbs().maxCoeff() < 0.99);
    }
    EXPECT_TRUE(skewed);
    std::set<int> types;
    for (const auto &g : m->collisionGeometries())
    {
        types.insert(static_cast<int>(g.type));
        EXPECT_LE(g.coverProtrusion, 0.035) << m->links()[g.link].name;
    }
    EXPECT_EQ(types.size(), 4u);
    // the SRDF lists only adjacent pairs, which the adjacency rule already skips
    EXPECT_EQ(m->selfCollisionPairs(), noSrdf->selfCollisionPairs());
    EXPECT_GT(m->selfCollisionPairs().size(), 10u);
    expectCompiledMatchesReference(*m, 1000, 21);

    // q = 0: upright, free of self-collision and above a floor whose top is at z = -0.04
    const std::vector<double> q(6, 0.0);
    const auto c = m->sphereCentersReference(q.data());
    double lowest = 1e9, highest = -1e9;
    for (std::size_t i = 0; i < c.size(); ++i)
    {
        lowest = std::min(lowest, c[i].z() - m->spheres()[i].radius);
        highest = std::max(highest, c[i].z() + m->spheres()[i].radius);
    }
    EXPECT_GT(lowest, -0.04);
    EXPECT_GT(highest, 1.0);  // reach: about 1.4 m tall when upright
    double closest = 1e9;
    for (const auto &[a, b] : m->selfCollisionPairs())
    {
        const auto &la = m->collisionLinks()[a], &lb = m->collisionLinks()[b];
        for (int i = la.firstSphere; i < la.firstSphere + la.sphereCount; ++i)
        {
            for (int k = lb.firstSphere; k < lb.firstSphere + lb.sphereCount; ++k)
            {
                closest = std::min(closest, (c[i] - c[k]).norm() - m->spheres()[i].radius - m->spheres()[k].radius);
            }
        }
    }
    EXPECT_GT(closest, 0.02);
    // some random configurations do collide with themselves (the self pairs are not vacuous)
    std::mt19937 rng(8);
    int colliding = 0;
    for (int s = 0; s < 2000; ++s)
    {
        const std::vector<double> qr = randomQ(*m, rng);
        const auto f = m->sphereCentersReference(qr.data());
        bool hit = false;
        for (const auto &[a, b] : m->selfCollisionPairs())
        {
            const auto &la = m->collisionLinks()[a], &lb = m->collisionLinks()[b];
            for (int i = la.firstSphere; i < la.firstSphere + la.sphereCount; ++i)
            {
                for (int k = lb.firstSphere; k < lb.firstSphere + lb.sphereCount; ++k)
                {
                    hit = hit || (f[i] - f[k]).norm() < m->spheres()[i].radius + m->spheres()[k].radius;
                }
            }
        }
        colliding += hit ? 1 : 0;
    }
    EXPECT_GT(colliding, 0);
    EXPECT_LT(colliding, 400);
}

TEST(RobotModel, MimicJointsAreHeld)
{
    const std::string urdf = R"(<robot name="grip">
  <link name="palm"><collision><geometry><box size="0.1 0.04 0.04"/></geometry></collision></link>
  <link name="left"><collision><origin xyz="0 0 0.05"/><geometry><sphere radius="0.01"/></geometry></collision></link>
  <link name="right"><collision><origin xyz="0 0 0.05"/><geometry><sphere radius="0.01"/></geometry></collision></link>
  <joint name="finger" type="prismatic"><parent link="palm"/><child link="left"/><origin xyz="0.03 0 0"/>
    <axis xyz="1 0 0"/><limit lower="0" upper="0.04" effort="1" velocity="1"/></joint>
  <joint name="finger_mimic" type="prismatic"><parent link="palm"/><child link="right"/><origin xyz="-0.03 0 0"/>
    <axis xyz="-1 0 0"/><limit lower="0" upper="0.04" effort="1" velocity="1"/><mimic joint="finger"/></joint>
</robot>)";
    auto m = RobotModel::fromUrdfString(urdf, ".", "grip.urdf");
    ASSERT_EQ(m->dof(), 1u);
    EXPECT_EQ(m->joints()[0].name, "finger");
    RobotModel::Options held;
    held.heldJointValues = {{"finger_mimic", 0.02}};
    auto h = RobotModel::fromUrdfString(urdf, ".", "grip.urdf", "", held);
    const double q = 0.01;
    const auto t = h->linkTransformsReference(&q);
    EXPECT_NEAR(t[h->linkIndex("right")].translation().x(), -0.05, 1e-12);
    EXPECT_NEAR(t[h->linkIndex("left")].translation().x(), 0.04, 1e-12);
    expectCompiledMatchesReference(*h, 100, 4);
    RobotModel::Options planMimic;
    planMimic.planningJoints = {"finger_mimic"};
    expectErrorMentions([&] { RobotModel::fromUrdfString(urdf, ".", "grip.urdf", "", planMimic); },
                        {"grip.urdf", "finger_mimic", "mimic"});
    // SRDF from memory: named after the source, missing attributes rejected
    expectErrorMentions(
        [&]
        { RobotModel::fromUrdfString(urdf, ".", "grip.urdf", "<robot><disable_collisions link1=\"left\"/></robot>"); },
        {"grip.urdf (SRDF)", "link2"});
    expectErrorMentions([&] { RobotModel::fromUrdfString(urdf, ".", "grip.urdf", "<srdf/>"); },
                        {"grip.urdf (SRDF)", "<robot>"});
}
