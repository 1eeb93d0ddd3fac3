// The navigation scenarios through the Scenario interface: configuration errors, episodes, determinism.
#include <gtest/gtest.h>

#include <cmath>
#include <limits>

#include "ExpectError.h"
#include "NavigationTestUtil.h"
#include "ReferencePolicyTestUtil.h"
#include "ropras/scenarios/navigation/NavigationPlanning.h"

namespace ropras::scenarios::test
{
    using ropras::test::expectErrorMentions;

    TEST(NavigationScenario, RegisteredWithSceneAndConfig)
    {
        for (const char *name : {"light-dark", "maze2d", "random3d-1", "random3d-2", "random3d-3", "random3d-4"})
        {
            const auto s = navScenario(name);
            EXPECT_EQ(s->name(), name);
            const auto scene = s->scene();
            for (const char *key : {"dims", "bounds", "walls", "obstacles", "danger_zones", "observation_zones", "goal",
                                    "starts", "robot_radius"})
            {
                EXPECT_TRUE(scene.contains(key)) << name << " scene lacks " << key;
            }
            EXPECT_EQ(s->config().at("horizon").get<std::size_t>(), s->horizon());
        }
        EXPECT_EQ(navScenario("light-dark")->horizon(), 60u);
        EXPECT_DOUBLE_EQ(navScenario("light-dark")->defaultPlanSeconds(), 0.01);
        EXPECT_EQ(navScenario("maze2d")->horizon(), 800u);
        EXPECT_DOUBLE_EQ(navScenario("maze2d")->defaultPlanSeconds(), 0.1);
    }

    TEST(NavigationScenario, BadOverridesNameTheKey)
    {
        expectErrorMentions([] { navScenario("light-dark", {{"lightness", 1.0}}); }, {"light-dark", "lightness"});
        expectErrorMentions(
            [] {
                navScenario("maze2d", {{"slip", std::numeric_limits<double>::quiet_NaN()}});
            },
            {"maze2d", "slip"});
        expectErrorMentions([] { navScenario("maze2d", {{"slip", 1.5}}); }, {"maze2d", "slip", "[0, 1]"});
        // a value that fails validation names where the overrides came from (e.g. the --config file)
        expectErrorMentions(
            []
            {
                ScenarioOptions options;
                options.overrides = {{"slip", 1.5}};
                options.source = "slippery.json";
                scenarioRegistry().create("maze2d", options);
            },
            {"slippery.json: ", "maze2d", "slip", "[0, 1]"});
        expectErrorMentions(
            [] {
                navScenario("light-dark", {{"robot_radius", -0.1}});
            },
            {"light-dark", "robot_radius", "> 0"});
        expectErrorMentions([] { navScenario("light-dark", {{"observation_sigma", 0}}); }, {"observation_sigma"});
        expectErrorMentions([] { navScenario("light-dark", {{"discount", 1.0}}); }, {"discount"});
        expectErrorMentions([] { navScenario("light-dark", {{"horizon", 2.5}}); }, {"horizon"});
        expectErrorMentions([] { navScenario("light-dark", {{"slip", "high"}}); }, {"slip"});
        expectErrorMentions([] { navScenario("maze2d", {{"danger_margin", -1.0}}); }, {"danger_margin", ">= 0"});
        expectErrorMentions([] { navScenario("maze2d", {{"obstacle_margin", -0.5}}); }, {"obstacle_margin", ">= 0"});
        expectErrorMentions([] { navScenario("maze2d", {{"obstacle_margin", "wide"}}); }, {"obstacle_margin"});
        expectErrorMentions(
            [] {
                navScenario("maze2d", {{"planner_dd_radius", -2.0}});
            },
            {"planner_dd_radius", ">= 0"});
        expectErrorMentions([] { navScenario("random3d-2", {{"planner_dd_radius", "wide"}}); }, {"planner_dd_radius"});
        expectErrorMentions(
            [] {
                navScenario("maze2d", {{"obstacle_margin", std::numeric_limits<double>::infinity()}});
            },
            {"obstacle_margin"});
        expectErrorMentions([] { navScenario("maze2d", {{"heuristic_value", 1}}); }, {"heuristic_value"});
        expectErrorMentions([] { navScenario("maze2d", {{"heuristic_decay", 0.0}}); }, {"heuristic_decay", "> 0"});
        expectErrorMentions(
            [] {
                navScenario("random3d-2", {{"heuristic_decay", 1.5}});
            },
            {"heuristic_decay", "(0, 1]"});
        expectErrorMentions([] { navScenario("maze2d", {{"heuristic_decay", -0.99}}); }, {"heuristic_decay"});
        expectErrorMentions([] { navScenario("maze2d", {{"heuristic_decay", "fast"}}); }, {"heuristic_decay"});
        // grids too large to build (std::bad_alloc, or gigabytes, before these checks)
        expectErrorMentions(
            [] {
                navScenario("maze2d", {{"bounds", {{-1e7, -1e7}, {1e7, 1e7}}}});
            },
            {"bounds", "collision grid", "cells", "more than 10000000"});
        expectErrorMentions(
            [] {
                navScenario("maze2d", {{"step", 1e-4}});
            },
            {"heuristic_value", "lattice points", "more than 50000000"});
        EXPECT_NO_THROW(navScenario("light-dark", {{"step", 1e-4}}));  // no distance field there
        expectErrorMentions([] { navScenario("maze2d", {{"heuristic_mdp", "yes"}}); }, {"heuristic_mdp", "boolean"});
        expectErrorMentions(
            [] {
                navScenario("light-dark", {{"heuristic_mdp", true}});
            },
            {"heuristic_mdp", "heuristic_value true"});
        expectErrorMentions(
            [] {
                navScenario("maze2d", {{"heuristic_mdp", true}, {"heuristic_decay", 0.99}});
            },
            {"heuristic_mdp", "heuristic_decay 1", "0.99"});
        expectErrorMentions(
            [] {
                navScenario("random3d-2", {{"heuristic_value", true}, {"heuristic_mdp", true}});
            },
            {"heuristic_mdp", "1030301", "250000"});
        // a start in collision with a wall
        expectErrorMentions(
            [] {
                navScenario("maze2d", {{"starts", {{-11.5, 10.0}}}});
            },
            {"maze2d", "starts[0]", "collision"});
        // a start in a danger zone, outside the bounds
        expectErrorMentions([] { navScenario("maze2d", {{"starts", {{-20, 23}}}}); }, {"starts[0]", "danger"});
        expectErrorMentions([] { navScenario("light-dark", {{"starts", {{-5, 0}}}}); }, {"starts[0]", "bounds"});
        // boxes: outside the bounds, inverted, wrong arity
        expectErrorMentions(
            [] {
                navScenario("light-dark", {{"obstacles", {{{3, 3}, {5, 5}}}}});
            },
            {"obstacles[0]", "outside the bounds"});
        expectErrorMentions(
            [] {
                navScenario("light-dark", {{"obstacles", {{{3, 3}, {2, 3.5}}}}});
            },
            {"obstacles[0]", "lo >= hi"});
        expectErrorMentions([] { navScenario("light-dark", {{"goal", {{0, 0, 0}, {1, 1, 1}}}}); }, {"goal"});
        // the URDF must match the configuration
        expectErrorMentions(
            [] {
                navScenario("light-dark", {{"robot_radius", 0.2}});
            },
            {"light-dark/robot.urdf", "robot_radius"});
        expectErrorMentions(
            [] {
                navScenario("light-dark", {{"bounds", {{-4, -4}, {4, 5}}}});
            },
            {"light-dark/robot.urdf", "bounds"});
        // Random3D generator
        expectErrorMentions(
            [] {
                navScenario("random3d-1", {{"generator", {{"obstacle_half_size", {2.0, 1.0}}}}});
            },
            {"random3d-1", "generator.obstacle_half_size"});
        expectErrorMentions(
            [] {
                navScenario("random3d-2", {{"generator", {{"seed", -1}}}});
            },
            {"random3d-2", "generator.seed"});
    }

    TEST(NavigationScenario, BadRunSettingsAreRejected)
    {
        const auto s = navScenario("light-dark");
        RunSettings settings;
        settings.params.set("macro_length", 0);
        expectErrorMentions([&] { s->validate(settings); }, {"macro_length"});
        RunSettings unknown;
        unknown.params.set("no_such_parameter", 1);
        EXPECT_THROW(s->validate(unknown), Error);
        RunSettings ok;
        EXPECT_NO_THROW(s->validate(ok));
    }

    TEST(NavigationScenario, LightDarkEpisodeWithSimulationBudgetIsDeterministic)
    {
        const auto s = navScenario("light-dark");
        RunSettings settings;
        settings.solver = "ropras3";
        settings.budget = pomdp::Budget::ofSimulations(40);
        settings.params.set("plan_iterations", 200);  // the reference planner stops by iterations, not time
        settings.params.set("plan_time", 1.0);
        nlohmann::json recording;
        const auto a = s->runEpisode(settings, 17, &recording);
        const auto b = s->runEpisode(settings, 17);
        EXPECT_TRUE(std::isfinite(a.discountedReturn));
        EXPECT_LE(a.steps, 60u);
        EXPECT_GT(a.steps, 0u);
        EXPECT_GT(a.plans, 0u);
        EXPECT_EQ(a.steps, b.steps);
        EXPECT_EQ(a.success, b.success);
        EXPECT_EQ(a.discountedReturn, b.discountedReturn);
        EXPECT_EQ(a.undiscountedReturn, b.undiscountedReturn);
        EXPECT_EQ(a.search.simulations, b.search.simulations);
        EXPECT_EQ(recording.at("trajectory").size(), a.steps + 1);
        if (a.success)
        {
            EXPECT_GT(a.undiscountedReturn, 90.0);
        }
        // another solver runs too (POMCP over primitive actions)
        settings.solver = "pomcp";
        settings.params = pomdp::ParameterMap();
        const auto c = s->runEpisode(settings, 3);
        EXPECT_LE(c.steps, 60u);
        EXPECT_TRUE(std::isfinite(c.discountedReturn));
    }

    TEST(NavigationScenario, ShortMaze2DAndRandom3DEpisodesRun)
    {
        for (const char *name : {"maze2d", "random3d-3"})
        {
            const auto s = navScenario(name, {{"horizon", 40}});
            RunSettings settings;
            settings.budget = pomdp::Budget::ofSimulations(20);
            settings.params.set("plan_iterations", 300);
            settings.params.set("plan_time", 1.0);
            const auto a = s->runEpisode(settings, 5);
            EXPECT_LE(a.steps, 40u) << name;
            EXPECT_GT(a.steps, 0u) << name;
            EXPECT_TRUE(std::isfinite(a.discountedReturn)) << name;
            EXPECT_GT(a.search.simulations, 0u) << name;
        }
    }
}  // namespace ropras::scenarios::test

namespace ropras::scenarios::test
{
    TEST(NavigationScenario, ParticlesInsideTheDangerMarginStillPlan)
    {
        // maze2d: danger zone [[-10, -10], [-2, -5]] grown by danger_margin 1.5 for the planner; (-6, -4) lies
        // 1 m above the zone: invalid for the grown obstacles, so the adapter hands the planner the true zones
        const auto scenario = navScenario("maze2d");
        const auto &parts = asNav(*scenario).parts();
        const auto policy = omplReferencePolicy<NavTarget>(parts, "uniform", 3);
        auto *ompl = policy.ompl;
        ASSERT_NE(ompl, nullptr);
        const NavState nearDanger = at(-6.0, -4.0);
        const NavState farAway = at(-20.0, 15.0);
        pomdp::Rng rng(5);
        std::size_t solved = 0;
        for (int i = 0; i < 10; ++i)
        {
            std::vector<std::uint8_t> macro;
            const bool ok = ompl->sample(nearDanger, pomdp::BeliefView<NavState>{&nearDanger, 1}, rng, macro);
            EXPECT_NE(ompl->lastStatus(), pomdp::PathPlanStatus::InvalidStart);
            solved += ok ? 1 : 0;
        }
        EXPECT_GE(solved, 5u);
        EXPECT_EQ(ompl->statistics().marginStarts, 10u) << "every plan from inside the margin used the true zones";
        // the base (grown) obstacles reject that start: the fallback is what makes it plan
        const auto grown = navigationEnvironment(asNav(*scenario).parts().model->config());
        const auto tight = navigationEnvironment(asNav(*scenario).parts().model->config(), 0.0);
        EXPECT_LT(grown->signedDistance(Eigen::Vector3d(-6.0, -4.0, 0.0), 0.25), 0.0);
        EXPECT_GT(tight->signedDistance(Eigen::Vector3d(-6.0, -4.0, 0.0), 0.25), 0.0);
        // far from every danger zone the base obstacles are kept
        std::vector<std::uint8_t> macro;
        ompl->sample(farAway, pomdp::BeliefView<NavState>{&farAway, 1}, rng, macro);
        EXPECT_EQ(ompl->statistics().marginStarts, 10u);
        EXPECT_LT(ompl->planner().environment()->signedDistance(Eigen::Vector3d(-6.0, -4.0, 0.0), 0.25), 0.0);
    }
}  // namespace ropras::scenarios::test

namespace ropras::scenarios::test
{
    TEST(NavigationScenario, TheObstacleMarginKeepsPathsOffWallsAndStillPlansFromInsideIt)
    {
        // maze2d with obstacle_margin 1: the planner sees obstacle [[8, 8], [10.5, 11]] grown to [[7, 7], [11.5, 12]]
        const auto scenario = navScenario("maze2d", {{"obstacle_margin", 1.0}});
        const auto &config = asNav(*scenario).parts().model->config();
        const auto grown = navigationEnvironment(config);
        const auto tight = navigationEnvironment(config, 0.0, 0.0);
        const Eigen::Vector3d besideObstacle(11.25, 9.5, 0.0);  // 0.5 m right of the obstacle: free, inside the margin
        EXPECT_LT(grown->signedDistance(besideObstacle, 0.25), 0.0);
        EXPECT_GT(tight->signedDistance(besideObstacle, 0.25), 0.0);
        EXPECT_NEAR(grown->signedDistance(Eigen::Vector3d(11.5, 9.5, 0.0), 0.0), 0.0, 1e-9)
            << "walls and obstacles grow by the margin per side, danger zones by danger_margin";
        const Eigen::Vector3d besideWall(-10.5, 10.0, 0.0);  // 0.5 m right of wall [[-12, 2.5], [-11, 25]]
        EXPECT_LT(grown->signedDistance(besideWall, 0.25), 0.0);
        EXPECT_GT(tight->signedDistance(besideWall, 0.25), 0.0);
        // the default keeps the true walls and obstacles
        const auto plain = navigationEnvironment(asNav(*navScenario("maze2d")).parts().model->config());
        EXPECT_GT(plain->signedDistance(besideObstacle, 0.25), 0.0);

        // plans bounded by iterations, with time to spare: the counts below do not depend on the machine's load
        pomdp::ParameterMap params;
        params.set("plan_iterations", 20000);
        params.set("plan_time", 2.0);
        const auto policy = omplReferencePolicy<NavTarget>(asNav(*scenario).parts(), "uniform", 7, params);
        auto *ompl = policy.ompl;
        ASSERT_NE(ompl, nullptr);
        pomdp::Rng rng(11);
        // a particle inside the margin plans in the true obstacles instead of failing with an invalid start
        const NavState inside = at(besideObstacle.x(), besideObstacle.y());
        std::size_t solved = 0;
        for (int i = 0; i < 10; ++i)
        {
            std::vector<std::uint8_t> macro;
            solved += ompl->sample(inside, pomdp::BeliefView<NavState>{&inside, 1}, rng, macro) ? 1 : 0;
            EXPECT_NE(ompl->lastStatus(), pomdp::PathPlanStatus::InvalidStart);
        }
        EXPECT_GE(solved, 5u);
        EXPECT_EQ(ompl->statistics().marginStarts, 10u);
        // from a start clear of the margin, every macro's lattice points stay at least the margin less half a step
        // (the staircase's deviation from the path) away from every wall and obstacle
        const NavState clear = at(11.0, 15.5);
        const double slack = 0.5 * config.stepLength + 1e-9;
        std::size_t macros = 0;
        for (int i = 0; i < 40; ++i)
        {
            std::vector<std::uint8_t> macro;
            if (!ompl->sample(clear, pomdp::BeliefView<NavState>{&clear, 1}, rng, macro))
            {
                continue;
            }
            ++macros;
            NavState s = clear;
            for (const auto a : macro)
            {
                s = asNav(*scenario).parts().model->moved(s, a);
                EXPECT_GT(tight->signedDistance(Eigen::Vector3d(s.p[0], s.p[1], 0.0), config.robotRadius),
                          config.obstacleMargin - slack)
                    << "macro point (" << s.p[0] << ", " << s.p[1] << ")";
            }
        }
        EXPECT_GE(macros, 20u);
    }
}  // namespace ropras::scenarios::test

namespace ropras::scenarios::test
{
    TEST(NavigationScenario, UniformTargetsAreGoalsThePlannerAccepts)
    {
        // maze2d grows its danger zones by danger_margin 1.5 for the planner; a uniform target inside that margin
        // would only make the plan fail at an invalid goal. Cross-check every draw against the planner's own
        // obstacles (ompl_ext::Environment, an independent distance computation).
        const auto margins = navScenario("maze2d", {{"obstacle_margin", 0.5}});
        const auto none = navScenario("maze2d", {{"danger_margin", 0.0}});
        const auto &config = asNav(*margins).parts().model->config();
        const auto planner = navigationEnvironment(config);
        const NavigationTargetSpace withMargins(asNav(*margins).parts().model);
        const NavigationTargetSpace withoutMargins(asNav(*none).parts().model);
        pomdp::Rng rng(23);
        std::size_t insideMargin = 0;
        for (int i = 0; i < 3000; ++i)
        {
            NavTarget t{};
            ASSERT_TRUE(withMargins.sampleFree(rng, t));
            EXPECT_GE(planner->signedDistance(Eigen::Vector3d(t[0], t[1], 0.0), config.robotRadius), 0.0)
                << "target (" << t[0] << ", " << t[1] << ") lies inside a planner margin";
            ASSERT_TRUE(withoutMargins.sampleFree(rng, t));
            insideMargin += planner->signedDistance(Eigen::Vector3d(t[0], t[1], 0.0), config.robotRadius) < 0.0;
        }
        // without margins a share of the draws falls where the margins are (about a tenth of the free area)
        EXPECT_GT(insideMargin, 100u);
    }
}  // namespace ropras::scenarios::test

namespace ropras::scenarios::test
{
    TEST(NavigationScenario, ThePlannerScaleGoesToVectorizedRRTConnectUnlessOverridden)
    {
        // a scenario's step and dynamic-domain radius reach our planner; planner.NAME wins over them; an OMPL
        // planner, which has neither parameter, gets none; 0 keeps the planner's own value
        RunSettings settings;
        const PlannerScale scale{5.0, 20.0};
        auto s = referencePlannerSettings(settings, pomdp::ParameterMap(), 0.003, 0.25, 7, scale);
        EXPECT_EQ(s.plannerParams.at("range"), std::to_string(5.0));
        EXPECT_EQ(s.plannerParams.at("dd_radius"), std::to_string(20.0));
        EXPECT_EQ(s.plannerParams.at("seed"), "8");
        s = referencePlannerSettings(settings, pomdp::ParameterMap::parse({"planner.dd_radius=7"}), 0.003, 0.25, 7,
                                     scale);
        EXPECT_EQ(s.plannerParams.at("dd_radius"), "7");
        EXPECT_EQ(s.plannerParams.at("range"), std::to_string(5.0));
        s = referencePlannerSettings(settings, pomdp::ParameterMap(), 0.003, 0.25, 7, PlannerScale{5.0, 0.0});
        EXPECT_EQ(s.plannerParams.count("dd_radius"), 0u);
        settings.planner = "RRTConnect";
        s = referencePlannerSettings(settings, pomdp::ParameterMap(), 0.003, 0.25, 7, scale);
        EXPECT_TRUE(s.plannerParams.empty());
        expectErrorMentions(
            [&] { referencePlannerSettings(settings, pomdp::ParameterMap::parse({"planner.seed=3"}), 0.003, 0.25, 7); },
            {"planner.seed", "--seed"});
    }

    TEST(NavigationScenario, SolverDefaultsAreCheckedAndApplyToTheirSolver)
    {
        // maze2d's ROP-RAS3 searches one macro level with nine candidate macros; the other solvers keep the
        // shared defaults (depth 4, beta_a 2)
        const auto maze = navScenario("maze2d");  // parts() refers into the scenario: keep it alive
        const auto &parts = asNav(*maze).parts();
        EXPECT_EQ(parts.model->config().plannerDdRadius, 0.0);  // the planner's own default
        EXPECT_EQ(parts.solverDefaults.at("ropras3").at("depth"), 0.0);
        EXPECT_EQ(parts.solverDefaults.at("ropras3").at("beta_a"), 8.0);
        EXPECT_EQ(parts.solverDefaults.at("ropras3").at("alpha_a"), 0.0);
        EXPECT_EQ(parts.defaults.at("depth"), 4.0);
        EXPECT_EQ(parts.solverDefaults.count("rpomcp"), 0u);
        // Random3D's ROP-RAS3 backs V up from the current Q estimates (value_backup 1), fills new nodes with 16
        // particles of their parent, softens the backup (eta 0.01) and shrinks few-return Q estimates towards their
        // node's mean in it (q_prior 4; doc/scenario-random3d.md)
        for (const char *variant : {"random3d-1", "random3d-4"})
        {
            const auto random3d = navScenario(variant);
            const auto &defaults = asNav(*random3d).parts().solverDefaults;
            EXPECT_EQ(defaults.at("ropras3").at("value_backup"), 1.0) << variant;
            EXPECT_EQ(defaults.at("ropras3").at("fill_particles"), 16.0) << variant;
            EXPECT_EQ(defaults.at("ropras3").at("eta"), 0.01) << variant;
            EXPECT_EQ(defaults.at("ropras3").at("q_prior"), 4.0) << variant;
            // Ref-Basic keeps the paper's running backup (its Random3D rows fail every episode with either)
            EXPECT_EQ(defaults.count("refbasic"), 0u) << variant;
            // every solver's reference planner takes a dynamic-domain radius for metres, not radians
            EXPECT_EQ(asNav(*random3d).parts().model->config().plannerDdRadius, 20.0) << variant;
        }
        // --config overrides a solver default like any other key; --param still overrides both at run time
        const auto deeper = navScenario("maze2d", {{"solver_defaults", {{"ropras3", {{"depth", 2}}}}}});
        EXPECT_EQ(asNav(*deeper).parts().solverDefaults.at("ropras3").at("depth"), 2.0);
        RunSettings settings;
        settings.solver = "ropras3";
        settings.params.set("depth", 1);
        EXPECT_NO_THROW(deeper->validate(settings));
        settings.solver = "bplan";  // reads no depth, beta_a nor alpha_a: not an unknown-parameter error
        settings.params = pomdp::ParameterMap{};
        EXPECT_NO_THROW(deeper->validate(settings));

        // bad solver_defaults in a scenario file: the key and the problem are named
        const nlohmann::json base = navScenario("maze2d")->config();
        const auto withSolverDefaults = [&](const nlohmann::json &value)
        {
            nlohmann::json config = base;
            config["solver_defaults"] = value;
            return [config] { makeNavigationScenario("maze2d", "test", "navigation/maze2d", config); };
        };
        expectErrorMentions(withSolverDefaults({{"nosuch", {{"depth", 0}}}}),
                            {"solver_defaults.nosuch", "names no solver", "ropras3"});
        expectErrorMentions(withSolverDefaults(5), {"solver_defaults", "must be an object"});
        expectErrorMentions(withSolverDefaults({{"ropras3", 3}}), {"solver_defaults.ropras3", "must be an object"});
        expectErrorMentions(withSolverDefaults({{"ropras3", {{"depth", "deep"}}}}), {"solver_defaults.ropras3.depth"});
        expectErrorMentions(
            [] {
                navScenario("maze2d", {{"solver_defaults", {{"nosuch", {{"depth", 0}}}}}});
            },
            {"solver_defaults.nosuch"});
        // absent (Light-Dark has none): no solver defaults
        EXPECT_TRUE(asNav(*navScenario("light-dark")).parts().solverDefaults.empty());
    }
}  // namespace ropras::scenarios::test
