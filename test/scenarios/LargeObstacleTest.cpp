// Issue 17, item 12: a world of 100 000 obstacles is built and torn down in linear time.
#include <gtest/gtest.h>

#include <Eigen/Core>

#include "ropras/scenarios/BulletCollisionWorld.h"

namespace ropras::scenarios::test
{
    TEST(LargeObstacles, AHundredThousandObstaclesAreBuiltAndTornDownInLinearTime)
    {
        // Bullet finds an object to remove by a linear search: removing every obstacle one by one in the
        // destructor was quadratic (a scenario configuration of 100 000 obstacles took more than 90 s). The world
        // is now destroyed before its objects and releases them itself. (No time is asserted: a quadratic
        // teardown shows as this test's timeout.)
        for (int round = 0; round < 2; ++round)
        {
            BulletCollisionWorld world;
            for (int i = 0; i < 100000; ++i)
                world.addBox(Eigen::Vector3d(0.01 * (i % 300), 0.01 * (i / 300), 0.0),
                             Eigen::Vector3d(0.001, 0.001, 0.001));
            const std::size_t agent = world.addAgent(0.002, Eigen::Vector3d(-1.0, -1.0, 0.0));
            EXPECT_EQ(world.obstacleCount(), 100000u);
            EXPECT_FALSE(world.collides(agent, Eigen::Vector3d(-1.0, -1.0, 0.0)));
            EXPECT_TRUE(world.collides(agent, Eigen::Vector3d(0.5, 0.5, 0.0)));       // box 50 + 300 * 50
            EXPECT_FALSE(world.collides(agent, Eigen::Vector3d(0.505, 0.505, 0.0)));  // between boxes
        }
    }
}  // namespace ropras::scenarios::test
