#include "ropras/scenarios/BulletCollisionWorld.h"

#include <gtest/gtest.h>

#include <cmath>

#include "ExpectError.h"
#include "ropras/core/Error.h"
#include "ropras/pomdp/Rng.h"

namespace ropras::scenarios
{
    namespace
    {
        double boxDistance(const Eigen::Vector3d &c, const Eigen::Vector3d &h, const Eigen::Vector3d &p)
        {
            return (((p - c).cwiseAbs() - h).cwiseMax(0.0)).norm();
        }
    }  // namespace

    TEST(BulletCollisionWorld, SphereAgainstBoxMatchesExactDistance)
    {
        BulletCollisionWorld world;
        const Eigen::Vector3d c(1.0, -2.0, 0.5), h(1.5, 0.5, 2.0);
        EXPECT_EQ(world.addBox(c, h), 0u);
        const double r = 0.3;
        const std::size_t agent = world.addAgent(r, Eigen::Vector3d(10, 10, 10));
        pomdp::Rng rng(3);
        int hits = 0, checked = 0;
        for (int i = 0; i < 4000; ++i)
        {
            const Eigen::Vector3d p(rng.uniform(-2, 4), rng.uniform(-4, 0), rng.uniform(-3, 4));
            const double d = boxDistance(c, h, p) - r;
            if (std::abs(d) < 1e-3)
            {
                continue;  // within float precision of contact
            }
            ++checked;
            const bool expected = d < 0.0;
            hits += expected;
            EXPECT_EQ(world.collides(agent, p), expected) << p.transpose() << " signed distance " << d;
        }
        EXPECT_GT(hits, 300);
        EXPECT_GT(checked - hits, 300);
        // collides() leaves the stored position alone
        EXPECT_TRUE(world.agentPosition(agent).isApprox(Eigen::Vector3d(10, 10, 10)));
    }

    TEST(BulletCollisionWorld, AgentsAndSpheresCollide)
    {
        BulletCollisionWorld world;
        world.addSphere(Eigen::Vector3d(0, 0, 0), 1.0);
        const auto a = world.addAgent(0.5, Eigen::Vector3d(5, 0, 0));
        const auto b = world.addAgent(0.5, Eigen::Vector3d(8, 0, 0));
        EXPECT_EQ(world.agentCount(), 2u);
        EXPECT_EQ(world.obstacleCount(), 1u);
        EXPECT_TRUE(world.collides(a, Eigen::Vector3d(1.4, 0, 0)));
        EXPECT_FALSE(world.collides(a, Eigen::Vector3d(1.6, 0, 0)));
        EXPECT_TRUE(world.collides(a, Eigen::Vector3d(7.2, 0, 0)));  // agent b at 8
        EXPECT_FALSE(world.collides(a, Eigen::Vector3d(6.8, 0, 0)));
        world.setAgentPosition(b, Eigen::Vector3d(-8, 0, 0));
        EXPECT_FALSE(world.collides(a, Eigen::Vector3d(7.2, 0, 0)));
        EXPECT_TRUE(world.collides(b, Eigen::Vector3d(-1.2, 0, 0)));
    }

    TEST(BulletCollisionWorld, BadInputThrows)
    {
        BulletCollisionWorld world;
        ropras::test::expectErrorMentions([&] { world.addBox(Eigen::Vector3d(0, 0, 0), Eigen::Vector3d(1, -1, 1)); },
                                          {"addBox", "half extents"});
        ropras::test::expectErrorMentions(
            [&] { world.addBox(Eigen::Vector3d(std::nan(""), 0, 0), Eigen::Vector3d(1, 1, 1)); }, {"addBox"});
        ropras::test::expectErrorMentions([&] { world.addAgent(0.0, Eigen::Vector3d(0, 0, 0)); }, {"addAgent"});
        ropras::test::expectErrorMentions([&] { world.collides(3, Eigen::Vector3d(0, 0, 0)); }, {"agent 3"});
        ropras::test::expectErrorMentions([] { BulletCollisionWorld w(-1.0); }, {"contact margin"});
    }

    TEST(BulletCollisionWorld, RigidAgentOfSpheresTurnsWithItsPoseAndNamesWhatItTouches)
    {
        BulletCollisionWorld world;
        world.addBox(Eigen::Vector3d(0, 3, 0), Eigen::Vector3d(5, 0.5, 1));  // y in [2.5, 3.5]
        // a dumbbell along its x axis: spheres at x = +-1, radius 0.3
        const auto bar = world.addRigidAgent({{Eigen::Vector3d(1, 0, 0), 0.3}, {Eigen::Vector3d(-1, 0, 0), 0.3}},
                                             Eigen::Isometry3d::Identity());
        const auto ball = world.addAgent(0.2, Eigen::Vector3d(0, -3, 0));
        Eigen::Isometry3d pose = Eigen::Isometry3d::Identity();
        pose.translation() = Eigen::Vector3d(0, 1.5, 0);
        EXPECT_FALSE(world.touching(bar, pose).any());  // lying along x: reaches y = 1.8
        pose.linear() = Eigen::AngleAxisd(1.5707963267948966, Eigen::Vector3d::UnitZ()).toRotationMatrix();
        auto t = world.touching(bar, pose);  // turned along y: reaches y = 2.8 > 2.5
        EXPECT_TRUE(t.obstacle);
        EXPECT_EQ(t.agents, 0u);
        pose.translation() = Eigen::Vector3d(0, -1.5, 0);  // the lower sphere at y = -2.5, the ball at -3
        t = world.touching(bar, pose);
        EXPECT_FALSE(t.obstacle);
        EXPECT_EQ(t.agents, std::uint64_t{1} << ball);
        world.setAgentPose(bar, pose);
        EXPECT_TRUE(world.collides(ball, Eigen::Vector3d(0, -3, 0)));  // the ball sees the moved bar
        ropras::test::expectErrorMentions([&] { world.addRigidAgent({}, Eigen::Isometry3d::Identity()); },
                                          {"addRigidAgent", "no spheres"});
        ropras::test::expectErrorMentions(
            [&] {
                world.addRigidAgent({{Eigen::Vector3d(0, 0, 0), -1.0}}, Eigen::Isometry3d::Identity());
            },
            {"addRigidAgent", "radius"});
        ropras::test::expectErrorMentions([&] { world.touching(7, pose); }, {"touching", "agent 7"});
    }
}  // namespace ropras::scenarios
