// The OMPL-backed reference policy on a 2-D point robot among boxes (PointRobotModel.h).
#include <gtest/gtest.h>

#include <ompl/util/Console.h>
#include <cmath>
#include <cstdio>
#include <limits>
#include <map>
#include <memory>
#include <string>
#include <vector>

#include "PointRobotModel.h"
#include "ropras/core/Error.h"
#include "ropras/ompl_ext/collision/CollisionChecker.h"
#include "ropras/pomdp/ModelRegistry.h"
#include "ropras/pomdp/OmplReferencePolicy.h"
#include "ropras/pomdp/SolverRunner.h"

namespace ropras::pomdp::test
{
    namespace
    {
        using Policy = OmplReferencePolicy<PointRobotModel, Point2>;
        using State = PointRobotModel::State;
        using Action = PointRobotModel::Action;

        /// a target space whose goal is \a goal and that has no informative targets
        class FixedTargetSpace final : public TargetSpace<State, Point2>
        {
        public:
            explicit FixedTargetSpace(Point2 goal) : goal_(goal) {}
            Point2 goal(const State &) const override { return goal_; }
            std::size_t numInformative(const State &) const override { return 0; }
            Point2 informative(const State &, std::size_t) const override { return goal_; }
            double distance(const State &, const Point2 &) const override { return 1.0; }
            std::uint64_t entropyBin(const State &p) const override { return p.door; }
            std::size_t numEntropyBins() const override { return 2; }

        private:
            Point2 goal_;
        };

        std::unique_ptr<Policy> makePolicy(Point2 goal, OmplPathPlannerSettings settings)
        {
            settings.resolution = POINT_RESOLUTION;
            auto space = std::make_shared<const FixedTargetSpace>(goal);
            return std::make_unique<Policy>(std::make_shared<const PointPlanningAdapter>(),
                                            std::make_unique<UniformHeuristic<State, Point2>>(space), pointRobot(),
                                            pointEnvironment(), settings);
        }

        State particle(std::uint8_t door, double x = PointRobotModel::START.x, double y = PointRobotModel::START.y)
        {
            State s;
            s.x = x;
            s.y = y;
            s.door = door;
            return s;
        }

        /// environment with the door where \a door says
        std::shared_ptr<ompl_ext::Environment> environmentFor(std::uint8_t door)
        {
            auto env = std::make_shared<ompl_ext::Environment>(*pointEnvironment());
            env->setObjectPose("door", Eigen::Isometry3d(Eigen::Translation3d(0.5, PointRobotModel::doorY(door), 0.0)));
            return env;
        }

        /// distance from (x, y) to the polyline \a path (row-major 2-D waypoints)
        double distanceToPath(const std::vector<double> &path, double x, double y)
        {
            double best = std::numeric_limits<double>::infinity();
            for (std::size_t i = 0; i + 3 < path.size(); i += 2)
            {
                const double ax = path[i], ay = path[i + 1], bx = path[i + 2], by = path[i + 3];
                const double dx = bx - ax, dy = by - ay, l2 = dx * dx + dy * dy;
                const double t = l2 > 0.0 ? std::clamp(((x - ax) * dx + (y - ay) * dy) / l2, 0.0, 1.0) : 0.0;
                best = std::min(best, std::hypot(ax + t * dx - x, ay + t * dy - y));
            }
            return best;
        }

        struct QuietOmpl : ::testing::Environment
        {
            void SetUp() override { ompl::msg::setLogLevel(ompl::msg::LOG_ERROR); }
        };
        const auto *const QUIET = ::testing::AddGlobalTestEnvironment(new QuietOmpl);
    }  // namespace

    TEST(OmplReferencePolicy, BadConfigurationThrowsAtConstruction)
    {
        OmplPathPlannerSettings settings;
        settings.planner = "NoSuchPlanner";
        EXPECT_THROW(makePolicy(PointRobotModel::GOAL, settings), Error);
        settings.planner = "RRTConnect";
        settings.plannerParams = {{"no_such_param", "1"}};
        EXPECT_THROW(makePolicy(PointRobotModel::GOAL, settings), Error);
        settings.plannerParams.clear();
        settings.timeLimit = 0.0;
        EXPECT_THROW(makePolicy(PointRobotModel::GOAL, settings), Error);
        settings.timeLimit = std::nan("");
        EXPECT_THROW(makePolicy(PointRobotModel::GOAL, settings), Error);
        settings.timeLimit = 0.05;
        EXPECT_NO_THROW(makePolicy(PointRobotModel::GOAL, settings));
        auto space = std::make_shared<const FixedTargetSpace>(PointRobotModel::GOAL);
        EXPECT_THROW(Policy(nullptr, std::make_unique<UniformHeuristic<State, Point2>>(space), pointRobot(),
                            pointEnvironment(), settings),
                     Error);
        EXPECT_THROW(Policy(std::make_shared<const PointPlanningAdapter>(),
                            std::make_unique<UniformHeuristic<State, Point2>>(space), pointRobot(), nullptr, settings),
                     Error);
    }

    // `--param planner.NAME=value` reaches the planner as plannerParams[NAME] (whole numbers without a decimal point,
    // which OMPL's bool and unsigned parsers need); a name the planner lacks fails when the policy is built, and
    // an empty name at once
    TEST(OmplReferencePolicy, PlannerParametersComeFromThePlannerPrefix)
    {
        const ParameterMap p = ParameterMap::parse(
            {"planner.range=0.3", "planner.dynamic_domain=-0", "planner.dd_radius=2.5", "planner.max_samples=1e6"});
        OmplPathPlannerSettings settings;
        settings.planner = "VectorizedRRTConnect";
        settings.readParameters(p);
        const std::map<std::string, std::string> expected = {{"range", "0.29999999999999999"},
                                                             {"dynamic_domain", "0"},
                                                             {"dd_radius", "2.5"},
                                                             {"max_samples", "1000000"}};
        EXPECT_EQ(settings.plannerParams, expected);
        EXPECT_NO_THROW(p.requireAllUsed("test"));
        EXPECT_NO_THROW(makePolicy(PointRobotModel::GOAL, settings));

        // the values reach the planner: the goal lies behind the wall, so a planner allowed no straight try and
        // one sample of a 0.05 step (the new node stays near its root, out of the other root's sight) finds no
        // path, while the same settings without the cap do
        OmplPathPlannerSettings capped;
        capped.planner = "VectorizedRRTConnect";
        capped.readParameters(ParameterMap::parse({"planner.direct=0", "planner.max_samples=1", "planner.range=0.05"}));
        auto cappedPolicy = makePolicy(PointRobotModel::GOAL, capped);
        OmplPathPlannerSettings uncapped;
        uncapped.planner = "VectorizedRRTConnect";
        // (a generous time limit: the uncapped plans must not fail on a loaded machine)
        uncapped.readParameters(ParameterMap::parse({"planner.direct=0", "planner.range=0.05", "plan_time=2"}));
        auto freePolicy = makePolicy(PointRobotModel::GOAL, uncapped);
        Rng rng(11);
        const State start = particle(0);
        std::vector<Action> macro;
        for (int i = 0; i < 5; ++i)
        {
            EXPECT_FALSE(cappedPolicy->sample(start, BeliefView<State>{&start, 1}, rng, macro));
            EXPECT_TRUE(freePolicy->sample(start, BeliefView<State>{&start, 1}, rng, macro));
        }
        EXPECT_EQ(cappedPolicy->plannerStatistics().notFound, 5u);

        OmplPathPlannerSettings unknown;
        unknown.planner = "VectorizedRRTConnect";
        unknown.readParameters(ParameterMap::parse({"planner.no_such=1"}));
        EXPECT_THROW(makePolicy(PointRobotModel::GOAL, unknown), Error);

        // a whole number past 1e15 keeps every digit (OMPL's integer parsers stop at an exponent), and the
        // registry refuses what the parameter's type cannot hold instead of wrapping it
        OmplPathPlannerSettings huge;
        huge.planner = "VectorizedRRTConnect";
        huge.readParameters(ParameterMap::parse({"planner.max_samples=1e17"}));
        EXPECT_EQ(huge.plannerParams.at("max_samples"), "100000000000000000");
        EXPECT_THROW(makePolicy(PointRobotModel::GOAL, huge), Error);

        OmplPathPlannerSettings empty;
        EXPECT_THROW(empty.readParameters(ParameterMap::parse({"planner.=1"})), Error);
    }

    // For every planner: the macro executed in the particle's world reaches the goal without collision, every
    // visited configuration and motion is valid per a CollisionChecker of the true (unpadded) disc in that
    // particle's environment, the points lie on the planned path one step apart, and the path uses the gap that
    // particle believes open. The planner plans with the padded disc (PLANNING_RADIUS), so its sample-wise motion
    // checks imply these continuous ones: the test holds for every path, not just for most.
    TEST(OmplReferencePolicy, MacrosAreCollisionFreeAndFollowThePath)
    {
        const PointRobotModel model;
        const ompl_ext::CollisionChecker exact(pointRobot(PointRobotModel::RADIUS));
        for (const char *planner : {"VectorizedRRTConnect", "RRTConnect", "BiTRRT", "RRTstar"})
        {
            SCOPED_TRACE(planner);
            OmplPathPlannerSettings settings;
            settings.planner = planner;
            settings.timeLimit = std::string(planner) == "RRTstar" ? 0.02 : 0.5;
            auto policy = makePolicy(PointRobotModel::GOAL, settings);
            Rng rng(3);
            for (int trial = 0; trial < 6; ++trial)
            {
                const std::uint8_t door = static_cast<std::uint8_t>(trial % 2);
                const State start = particle(door);
                std::vector<Action> macro;
                ASSERT_TRUE(policy->sample(start, BeliefView<State>{&start, 1}, rng, macro));
                ASSERT_FALSE(macro.empty());
                ASSERT_LE(macro.size(), 40u);
                const auto env = environmentFor(door);
                const auto &checker = policy->planner().checker();
                const double resolution = policy->planner().settings().resolution;
                const std::vector<double> path = policy->planner().path();
                ASSERT_GE(path.size(), 4u);
                EXPECT_EQ(path[0], start.x);
                EXPECT_EQ(path[1], start.y);
                bool crossedAboveWall = false;
                for (std::size_t i = 0; i + 3 < path.size(); i += 2)
                {
                    ASSERT_TRUE(checker.isMotionValid(*env, &path[i], &path[i + 2], resolution, nullptr, true));
                    if ((path[i] - 0.5) * (path[i + 2] - 0.5) <= 0.0 && path[i] != path[i + 2])
                    {
                        const double t = (0.5 - path[i]) / (path[i + 2] - path[i]);
                        crossedAboveWall = path[i + 1] + t * (path[i + 3] - path[i + 1]) > 0.5;
                    }
                }
                EXPECT_EQ(crossedAboveWall, door == 0) << "door " << int(door);
                State s = start;
                double q[2] = {s.x, s.y};
                bool terminal = false;
                for (std::size_t k = 0; k < macro.size(); ++k)
                {
                    const Action &a = macro[k];
                    EXPECT_LE(std::hypot(a.dx, a.dy), PointRobotModel::STEP + 1e-9);
                    const double next[2] = {s.x + a.dx, s.y + a.dy};
                    EXPECT_LT(distanceToPath(path, next[0], next[1]), 1e-9);
                    EXPECT_TRUE(exact.isMotionValid(*env, q, next, resolution, nullptr, true)) << "step " << k;
                    const auto r = model.step(s, a, rng);
                    s = r.next;
                    q[0] = s.x;
                    q[1] = s.y;
                    ASSERT_GT(r.reward, -100.0) << "collision at step " << k;
                    if (r.terminal)
                    {
                        terminal = true;
                        EXPECT_EQ(r.reward, 100.0);
                        break;
                    }
                }
                EXPECT_TRUE(terminal) << "macro of " << macro.size() << " steps did not reach the goal";
            }
            EXPECT_EQ(policy->statistics().requested, 6u);
            EXPECT_EQ(policy->statistics().succeeded, 6u);
            EXPECT_EQ(policy->plannerStatistics().solved, 6u);
            EXPECT_GT(policy->statistics().seconds, 0.0);
            std::printf("[ info ] %s: %.1f us per reference plan (wall clock, incl. shortcut and conversion)\n",
                        planner, 1e6 * policy->statistics().seconds / 6.0);
        }
    }

    // The first form of per-particle obstacles: the adapter hands out a whole Environment per particle.
    TEST(OmplReferencePolicy, ParticleEnvironmentsAreSwappedIn)
    {
        class SceneAdapter final : public OmplPlanningAdapter<State, Action, Point2>
        {
        public:
            void configuration(const State &s, double *q) const override { inner_.configuration(s, q); }
            bool targetConfiguration(const State &s, const Point2 &t, double *q) const override
            {
                return inner_.targetConfiguration(s, t, q);
            }
            bool pathToMacroAction(const State &s, const double *w, std::size_t n,
                                   std::vector<Action> &out) const override
            {
                return inner_.pathToMacroAction(s, w, n, out);
            }
            std::shared_ptr<const ompl_ext::Environment> environment(const State &particle) const override
            {
                return scenes_[particle.door];
            }

        private:
            PointPlanningAdapter inner_;
            std::shared_ptr<const ompl_ext::Environment> scenes_[2]{environmentFor(0), environmentFor(1)};
        };
        auto space = std::make_shared<const FixedTargetSpace>(PointRobotModel::GOAL);
        OmplPathPlannerSettings settings;
        settings.resolution = POINT_RESOLUTION;
        // the base environment has no door at all: only the particle's scene can block a gap
        auto open = std::make_shared<ompl_ext::Environment>();
        open->addBox("wall", Eigen::Isometry3d(Eigen::Translation3d(0.5, 0.5, 0.0)), Eigen::Vector3d(0.06, 0.5, 0.2));
        Policy policy(std::make_shared<const SceneAdapter>(), std::make_unique<UniformHeuristic<State, Point2>>(space),
                      pointRobot(), open, settings);
        Rng rng(2);
        for (std::uint8_t door : {0, 1, 1, 0})
        {
            const State start = particle(door);
            std::vector<Action> macro;
            ASSERT_TRUE(policy.sample(start, BeliefView<State>{&start, 1}, rng, macro));
            const auto &used = *policy.planner().environment();
            ASSERT_TRUE(used.hasObject("door"));
            EXPECT_EQ(used.objectPose(used.objectId("door")).translation().y(), PointRobotModel::doorY(door));
            const auto env = environmentFor(door);
            const auto &path = policy.planner().path();
            for (std::size_t i = 0; i + 3 < path.size(); i += 2)
                ASSERT_TRUE(policy.planner().checker().isMotionValid(*env, &path[i], &path[i + 2], POINT_RESOLUTION,
                                                                     nullptr, true));
            // the macro never enters the blocked gap of this particle
            for (std::size_t i = 0; i + 1 < path.size(); i += 2)
                EXPECT_FALSE(PointRobotModel::collides(path[i], path[i + 1], door));
        }
        EXPECT_EQ(policy.plannerStatistics().solved, 4u);
    }

    TEST(OmplReferencePolicy, TruncatedMacroStopsShortOnThePath)
    {
        auto space = std::make_shared<const FixedTargetSpace>(PointRobotModel::GOAL);
        Policy policy(std::make_shared<const PointPlanningAdapter>(5),
                      std::make_unique<UniformHeuristic<State, Point2>>(space), pointRobot(), pointEnvironment());
        Rng rng(1);
        const State start = particle(1);
        std::vector<Action> macro;
        ASSERT_TRUE(policy.sample(start, BeliefView<State>{&start, 1}, rng, macro));
        ASSERT_EQ(macro.size(), 5u);
        double x = start.x, y = start.y;
        for (const Action &a : macro)
        {
            EXPECT_LE(std::hypot(a.dx, a.dy), PointRobotModel::STEP + 1e-9);
            x += a.dx;
            y += a.dy;
        }
        EXPECT_LT(distanceToPath(policy.planner().path(), x, y), 1e-9);
    }

    // The planning margin's fallback: the policy plans in obstacles grown by 5 cm; a particle that noise put inside
    // that margin (valid in the true obstacles, invalid in the grown ones) is planned for in its true obstacles,
    // posed like the grown ones (the door where the particle believes it), instead of failing as an invalid start.
    TEST(OmplReferencePolicy, StartsInsideThePlanningMarginPlanInTheTrueObstacles)
    {
        constexpr double MARGIN = 0.05;
        auto grown = std::make_shared<ompl_ext::Environment>();
        grown->addBox("wall", Eigen::Isometry3d(Eigen::Translation3d(0.5, 0.5, 0.0)),
                      Eigen::Vector3d(0.06 + 2 * MARGIN, 0.5 + 2 * MARGIN, 0.2));
        grown->addBox("door", Eigen::Isometry3d(Eigen::Translation3d(0.5, PointRobotModel::doorY(0), 0.0)),
                      Eigen::Vector3d(0.06 + 2 * MARGIN, 0.25 + 2 * MARGIN, 0.2));
        auto space = std::make_shared<const FixedTargetSpace>(PointRobotModel::GOAL);
        OmplPathPlannerSettings settings;
        settings.resolution = POINT_RESOLUTION;
        Policy policy(std::make_shared<const PointPlanningAdapter>(),
                      std::make_unique<UniformHeuristic<State, Point2>>(space), pointRobot(), grown, settings);
        const auto &checker = policy.planner().checker();
        // 2 cm from the wall's face: clear of the true wall, 3 cm deep in the grown one
        const State marginal = particle(1, 0.47 - PLANNING_RADIUS - 0.02, 0.5);
        const double q[2]{marginal.x, marginal.y};
        ASSERT_TRUE(checker.isValid(*pointEnvironment(), q));
        ASSERT_FALSE(checker.isValid(*grown, q));
        Rng rng(5);
        std::vector<Action> macro;
        EXPECT_FALSE(policy.sample(marginal, BeliefView<State>{&marginal, 1}, rng, macro)) << "no fallback yet";
        EXPECT_EQ(policy.lastStatus(), PathPlanStatus::InvalidStart);

        policy.setTrueEnvironment(pointEnvironment());
        ASSERT_TRUE(policy.sample(marginal, BeliefView<State>{&marginal, 1}, rng, macro));
        EXPECT_EQ(policy.statistics().marginStarts, 1u);
        const auto &used = *policy.planner().environment();
        EXPECT_TRUE(checker.isValid(used, q)) << "planned in the true obstacles";
        EXPECT_EQ(used.objectPose(used.objectId("door")).translation().y(), PointRobotModel::doorY(1))
            << "posed as the particle believes";
        const auto truth = environmentFor(1);
        const auto &path = policy.planner().path();
        for (std::size_t i = 0; i + 3 < path.size(); i += 2)
            ASSERT_TRUE(checker.isMotionValid(*truth, &path[i], &path[i + 2], POINT_RESOLUTION, nullptr, true));

        // a start clear of the margin keeps the grown obstacles
        const State clear = particle(1);
        ASSERT_TRUE(policy.sample(clear, BeliefView<State>{&clear, 1}, rng, macro));
        EXPECT_FALSE(checker.isValid(*policy.planner().environment(), q)) << "planned in the grown obstacles";
        // a start in collision in the true obstacles too stays an invalid start
        const State inside = particle(1, 0.5, 0.5);
        EXPECT_FALSE(policy.sample(inside, BeliefView<State>{&inside, 1}, rng, macro));
        EXPECT_EQ(policy.lastStatus(), PathPlanStatus::InvalidStart);
        EXPECT_EQ(policy.statistics().marginStarts, 1u);
    }

    TEST(OmplReferencePolicy, FailuresAreCountedNotThrown)
    {
        OmplPathPlannerSettings settings;
        // target inside the wall
        auto policy = makePolicy(Point2{0.5, 0.5}, settings);
        Rng rng(5);
        const State start = particle(0);
        std::vector<Action> macro;
        EXPECT_FALSE(policy->sample(start, BeliefView<State>{&start, 1}, rng, macro));
        EXPECT_TRUE(macro.empty());
        EXPECT_EQ(policy->lastStatus(), PathPlanStatus::InvalidTarget);
        // target inside the door of this particle only: fine for the other particle
        auto doorPolicy = makePolicy(Point2{0.5, 0.1}, settings);
        EXPECT_FALSE(doorPolicy->sample(start, BeliefView<State>{&start, 1}, rng, macro));
        EXPECT_EQ(doorPolicy->plannerStatistics().invalidTarget, 1u);
        const State other = particle(1);
        EXPECT_TRUE(doorPolicy->sample(other, BeliefView<State>{&other, 1}, rng, macro));
        EXPECT_FALSE(macro.empty());
        // start in collision, NaN target
        macro.clear();
        const State inWall = particle(0, 0.5, 0.5);
        EXPECT_FALSE(policy->sample(inWall, BeliefView<State>{&inWall, 1}, rng, macro));
        EXPECT_EQ(policy->plannerStatistics().invalidStart, 1u);
        auto nanPolicy = makePolicy(Point2{std::nan(""), 0.5}, settings);
        EXPECT_FALSE(nanPolicy->sample(start, BeliefView<State>{&start, 1}, rng, macro));
        EXPECT_EQ(nanPolicy->statistics().noTarget, 1u);
        // out-of-bounds target
        auto outside = makePolicy(Point2{1.5, 0.5}, settings);
        EXPECT_FALSE(outside->sample(start, BeliefView<State>{&start, 1}, rng, macro));
        EXPECT_EQ(outside->plannerStatistics().invalidTarget, 1u);
        // impossible time budget, for our planner and an OMPL one
        for (const char *planner : {"VectorizedRRTConnect", "RRTConnect"})
        {
            settings.planner = planner;
            settings.timeLimit = 1e-12;
            auto hurried = makePolicy(PointRobotModel::GOAL, settings);
            for (int i = 0; i < 3; ++i)
                EXPECT_FALSE(hurried->sample(start, BeliefView<State>{&start, 1}, rng, macro));
            EXPECT_TRUE(macro.empty());
            EXPECT_EQ(hurried->plannerStatistics().requested, 3u);
            EXPECT_EQ(hurried->plannerStatistics().notFound, 3u);
            EXPECT_EQ(hurried->statistics().failed(), 3u);
        }
        EXPECT_EQ(policy->statistics().requested, 2u);
        EXPECT_EQ(policy->statistics().failed(), 2u);
    }

    TEST(OmplReferencePolicy, SameSeedSameMacros)
    {
        OmplPathPlannerSettings settings;
        settings.resolution = POINT_RESOLUTION;
        settings.timeLimit = 10.0;  // never reached: the iteration bound decides
        settings.maxIterations = 100000;
        settings.plannerParams = {{"seed", "7"}, {"max_samples", "20000"}};
        const auto run = [&](const OmplPathPlannerSettings &s)
        {
            auto space = std::make_shared<const PointTargetSpace>();
            Policy policy(std::make_shared<const PointPlanningAdapter>(),
                          std::make_unique<EpsilonGreedyHeuristic<State, Point2>>(
                              space, std::make_unique<UniformHeuristic<State, Point2>>(space), 0.5),
                          pointRobot(), pointEnvironment(), s);
            Rng rng(11);
            std::vector<double> trace;
            for (int i = 0; i < 12; ++i)
            {
                const State start = particle(static_cast<std::uint8_t>(i % 2), 0.1 + 0.02 * i, 0.3 + 0.03 * i);
                std::vector<Action> macro;
                trace.push_back(policy.sample(start, BeliefView<State>{&start, 1}, rng, macro) ? 1.0 : 0.0);
                for (const Action &a : macro)
                {
                    trace.push_back(a.dx);
                    trace.push_back(a.dy);
                }
            }
            return trace;
        };
        const auto a = run(settings);
        const auto b = run(settings);
        EXPECT_EQ(a, b);
        EXPECT_GT(a.size(), 100u);
        settings.plannerParams["seed"] = "8";
        EXPECT_NE(a, run(settings));
    }

    // ROP-RAS3 (and the other informed solvers, unchanged) through the runner on the toy model.
    TEST(OmplReferencePolicy, RopRas3EpisodesThroughTheRunner)
    {
        ParameterMap params;
        params.set("particles", 200);
        params.set("plan_time", 0.05);
        params.set("planner_seed", 3);
        ModelSolverRunner<PointRobotModel> runner("point2d", pointComponents(), "ropras3", params);
        EpisodeSettings settings;
        settings.maxSteps = 80;
        settings.budget = Budget::ofSimulations(100);
        int reached = 0;
        std::size_t requested = 0, failed = 0;
        double total = 0.0;
        const int episodes = 8;
        for (int e = 0; e < episodes; ++e)
        {
            const EpisodeResult r = runner.runEpisode(settings, 100 + e);
            requested += r.search.referenceRequested;
            failed += r.search.referenceFailed;
            total += r.undiscountedReturn;
            reached += r.terminal && r.undiscountedReturn > 0.0 ? 1 : 0;
        }
        EXPECT_GT(requested, 0u);
        std::printf(
            "[ info ] ropras3 on point2d: %d/%d episodes reached the goal, mean return %.1f, %zu reference "
            "plans (%zu failed)\n",
            reached, episodes, total / episodes, requested, failed);
        EXPECT_GE(reached, 7) << "mean return " << total / episodes;
        for (const char *solver : {"bplan", "rpomcp"})
        {
            ModelSolverRunner<PointRobotModel> other("point2d", pointComponents(), solver, params);
            settings.budget = Budget::ofSimulations(20);
            const EpisodeResult r = other.runEpisode(settings, 7);
            EXPECT_GT(r.steps, 0u) << solver;
            EXPECT_GT(r.search.referenceRequested, 0u) << solver;
        }
    }
}  // namespace ropras::pomdp::test
