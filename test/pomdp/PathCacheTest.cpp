// PathCache (experience reuse of the OMPL reference policy): a kept path is continued only toward the same target,
// from a start within the radius, after the target has its quota of paths, and never when the joined path collides;
// through OmplReferencePolicy a second query from the same start runs no plan.
#include <gtest/gtest.h>

#include <ompl/util/Console.h>
#include <cmath>
#include <memory>
#include <vector>

#include "PointRobotModel.h"
#include "ropras/core/Error.h"
#include "ropras/ompl_ext/collision/CollisionChecker.h"
#include "ropras/pomdp/OmplPathPlanner.h"
#include "ropras/pomdp/OmplReferencePolicy.h"
#include "ropras/pomdp/PathCache.h"

namespace ropras::pomdp::test
{
    namespace
    {
        const double START[2] = {PointRobotModel::START.x, PointRobotModel::START.y};
        const double GOAL[2] = {PointRobotModel::GOAL.x, PointRobotModel::GOAL.y};

        /// a planned (collision-free) path START -> GOAL
        std::vector<double> plannedPath()
        {
            ompl::msg::setLogLevel(ompl::msg::LOG_ERROR);
            OmplPathPlannerSettings settings;
            settings.resolution = POINT_RESOLUTION;
            settings.timeLimit = 1.0;
            settings.plannerParams = {{"seed", "3"}};
            OmplPathPlanner planner(pointRobot(), pointEnvironment(), settings);
            EXPECT_EQ(planner.plan(START, GOAL), PathPlanStatus::Solved);
            return planner.path();
        }

        /// the goal, no informative state: every reference query targets the goal
        class GoalOnlyTargetSpace final : public TargetSpace<PointRobotModel::State, Point2>
        {
        public:
            Point2 goal(const PointRobotModel::State &) const override { return PointRobotModel::GOAL; }
            std::size_t numInformative(const PointRobotModel::State &) const override { return 0; }
            Point2 informative(const PointRobotModel::State &, std::size_t) const override
            {
                return PointRobotModel::GOAL;
            }
            double distance(const PointRobotModel::State &, const Point2 &) const override { return 1.0; }
            std::uint64_t entropyBin(const PointRobotModel::State &p) const override { return p.door; }
            std::size_t numEntropyBins() const override { return 2; }
        };

        bool everySegmentValid(const ompl_ext::CollisionChecker &checker, const std::vector<double> &path)
        {
            for (std::size_t i = 0; i + 3 < path.size(); i += 2)
            {
                if (!checker.isMotionValid(*pointEnvironment(), &path[i], &path[i + 2], POINT_RESOLUTION))
                    return false;
            }
            return true;
        }
    }  // namespace

    TEST(PathCache, ContinuesAKeptPathOnlyWhenNearValidAndWarm)
    {
        const ompl_ext::CollisionChecker checker(pointRobot());
        const auto env = pointEnvironment();
        const std::vector<double> path = plannedPath();
        ASSERT_GE(path.size(), 4u);
        PathCache::Settings settings;
        settings.radius = 0.05;
        settings.pathsPerTarget = 2;
        PathCache cache(2, settings);
        Rng rng(1);
        std::vector<double> out;
        const double near[2] = {START[0] + 0.02, START[1] - 0.02};
        EXPECT_FALSE(cache.find(checker, *env, POINT_RESOLUTION, near, GOAL, rng, out)) << "nothing kept";
        cache.store(GOAL, path.data(), path.size() / 2);
        EXPECT_FALSE(cache.find(checker, *env, POINT_RESOLUTION, near, GOAL, rng, out)) << "1 of 2 paths: warming";
        EXPECT_EQ(cache.statistics().warming, 2u);
        cache.store(GOAL, path.data(), path.size() / 2);
        ASSERT_TRUE(cache.find(checker, *env, POINT_RESOLUTION, near, GOAL, rng, out));
        ASSERT_GE(out.size(), 4u);
        EXPECT_EQ(out[0], near[0]);
        EXPECT_EQ(out[1], near[1]);
        EXPECT_EQ(out[out.size() - 2], GOAL[0]);
        EXPECT_EQ(out[out.size() - 1], GOAL[1]);
        EXPECT_TRUE(everySegmentValid(checker, out));
        // the joined point lies within the radius of the start
        EXPECT_LE(std::hypot(out[2] - near[0], out[3] - near[1]), settings.radius + 1e-12);
        EXPECT_EQ(cache.statistics().hits, 1u);

        const double far[2] = {START[0], START[1] + 0.3};
        EXPECT_FALSE(cache.find(checker, *env, POINT_RESOLUTION, far, GOAL, rng, out)) << "too far from the paths";
        const double otherTarget[2] = {GOAL[0], GOAL[1] + 0.1};
        EXPECT_FALSE(cache.find(checker, *env, POINT_RESOLUTION, near, otherTarget, rng, out)) << "another target";
    }

    TEST(PathCache, NeverReturnsAPathThatCollidesInTheQuerysWorld)
    {
        const ompl_ext::CollisionChecker checker(pointRobot());
        const auto env = pointEnvironment();
        // the straight line START -> GOAL crosses the wall at x = 0.5
        const std::vector<double> straight = {START[0], START[1], GOAL[0], GOAL[1]};
        ASSERT_FALSE(checker.isMotionValid(*env, START, GOAL, POINT_RESOLUTION));
        PathCache::Settings settings;
        settings.radius = 0.05;
        settings.pathsPerTarget = 1;
        PathCache cache(2, settings);
        cache.store(GOAL, straight.data(), 2);
        Rng rng(2);
        std::vector<double> out = {7.0};
        EXPECT_FALSE(cache.find(checker, *env, POINT_RESOLUTION, START, GOAL, rng, out));
        EXPECT_EQ(cache.statistics().rejected, 1u);
        EXPECT_EQ(out, std::vector<double>{7.0}) << "out unchanged on a miss";
        // in an empty world the same kept path is returned
        ompl_ext::Environment empty;
        EXPECT_TRUE(cache.find(checker, empty, POINT_RESOLUTION, START, GOAL, rng, out));
    }

    // With a prefix (the caller cuts at most prefixSteps points of prefixStep), a kept path that collides only beyond
    // the cut is continued: only the segments the cut reads are checked and returned, and the macro-action cut from
    // them equals the one cut from the whole path; a collision inside the cut still rejects it.
    TEST(PathCache, APrefixIsCheckedAndReturnedOnlyAsFarAsTheCallersCut)
    {
        const ompl_ext::CollisionChecker checker(pointRobot());
        const auto env = pointEnvironment();
        // free up to x = 0.35, then straight through the wall at x = 0.5
        const std::vector<double> kept = {START[0], START[1], 0.30, 0.5, 0.35, 0.5, GOAL[0], GOAL[1]};
        ASSERT_FALSE(checker.isMotionValid(*env, &kept[4], GOAL, POINT_RESOLUTION));
        const double near[2] = {START[0] + 0.01, START[1] + 0.01};
        const auto cacheWith = [&](std::size_t steps)
        {
            PathCache::Settings settings;
            settings.radius = 0.05;
            settings.pathsPerTarget = 1;
            settings.prefixStep = 0.05;
            settings.prefixSteps = steps;
            auto cache = std::make_unique<PathCache>(2, settings);
            cache->store(GOAL, kept.data(), kept.size() / 2);
            return cache;
        };
        Rng rng(6);
        std::vector<double> whole, out;
        ompl_ext::Environment empty;
        ASSERT_TRUE(cacheWith(0)->find(checker, empty, POINT_RESOLUTION, near, GOAL, rng, whole));
        ASSERT_EQ(whole.size(), 10u) << "near, its foot on the first segment, then the rest of the kept path";
        EXPECT_FALSE(cacheWith(0)->find(checker, *env, POINT_RESOLUTION, near, GOAL, rng, out)) << "whole path checked";

        // near -> foot (1 piece), foot -> (0.30, 0.5) (3 pieces): a cut of 4 steps reads 3 waypoints
        auto cache = cacheWith(4);
        ASSERT_TRUE(cache->find(checker, *env, POINT_RESOLUTION, near, GOAL, rng, out));
        ASSERT_EQ(out.size(), 6u);
        EXPECT_EQ(std::vector<double>(out.begin(), out.end()), std::vector<double>(whole.begin(), whole.begin() + 6));
        EXPECT_EQ(cache->statistics().truncated, 1u);
        EXPECT_TRUE(everySegmentValid(checker, out));
        std::vector<double> fromPrefix, fromWhole;
        ASSERT_EQ(discretizeJointPath(out.data(), out.size() / 2, 2, 0.05, 4, fromPrefix), 4u);
        ASSERT_EQ(discretizeJointPath(whole.data(), whole.size() / 2, 2, 0.05, 4, fromWhole), 4u);
        EXPECT_EQ(fromPrefix, fromWhole);

        // a cut of 60 steps reaches the wall: rejected
        EXPECT_FALSE(cacheWith(60)->find(checker, *env, POINT_RESOLUTION, near, GOAL, rng, out));
        PathCache::Settings bad;
        bad.radius = 0.1;
        bad.prefixSteps = 3;  // without a step
        EXPECT_THROW(PathCache(2, bad), Error);
    }

    TEST(PathCache, BadSettingsThrow)
    {
        PathCache::Settings settings;
        settings.radius = -1.0;
        EXPECT_THROW(PathCache(2, settings), Error);
        settings.radius = std::nan("");
        EXPECT_THROW(PathCache(2, settings), Error);
        settings.radius = 0.1;
        settings.pathsPerTarget = 0;
        EXPECT_THROW(PathCache(2, settings), Error);
        settings.pathsPerTarget = 1;
        EXPECT_THROW(PathCache(0, settings), Error);
        EXPECT_NO_THROW(PathCache(2, settings));
    }

    TEST(PathCache, ReferencePolicyReusesAPlanForTheSameTarget)
    {
        ompl::msg::setLogLevel(ompl::msg::LOG_ERROR);
        OmplPathPlannerSettings settings;
        settings.resolution = POINT_RESOLUTION;
        settings.timeLimit = 1.0;
        using Policy = OmplReferencePolicy<PointRobotModel, Point2>;
        // the goal heuristic with no informative state: always the goal
        Policy policy(std::make_shared<const PointPlanningAdapter>(),
                      std::make_unique<UniformHeuristic<PointRobotModel::State, Point2>>(
                          std::make_shared<const GoalOnlyTargetSpace>()),
                      pointRobot(), pointEnvironment(), settings);
        PathCache::Settings reuse;
        reuse.radius = 0.05;
        reuse.pathsPerTarget = 1;
        policy.setPathCache(reuse);
        ASSERT_NE(policy.pathCache(), nullptr);
        PointRobotModel::State s;
        s.x = PointRobotModel::START.x;
        s.y = PointRobotModel::START.y;
        Rng rng(4);
        std::vector<PointRobotModel::Action> first, second;
        ASSERT_TRUE(policy.sample(s, BeliefView<PointRobotModel::State>{&s, 1}, rng, first));
        ASSERT_TRUE(policy.sample(s, BeliefView<PointRobotModel::State>{&s, 1}, rng, second));
        EXPECT_EQ(policy.plannerStatistics().requested, 1u) << "the second macro comes from the kept path";
        EXPECT_EQ(policy.statistics().reused, 1u);
        ASSERT_EQ(first.size(), second.size());
        reuse.radius = -0.1;
        EXPECT_THROW(policy.setPathCache(reuse), Error);
    }
}  // namespace ropras::pomdp::test
