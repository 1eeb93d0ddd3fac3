// Multi-Drone Tag: the drones robot, the sampling heuristic, PathToMacroAction, and episodes through the
// Scenario interface.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <memory>
#include <set>
#include <string>
#include <vector>

#include <ompl/util/Console.h>

#include "ExpectError.h"
#include "ropras/core/Error.h"
#include "ropras/ompl_ext/scene/Environment.h"
#include "ropras/pomdp/OmplPathPlanner.h"
#include "ropras/scenarios/multi-drone/MultiDronePlanning.h"
#include "ropras/scenarios/multi-drone/MultiDroneScenario.h"

namespace ropras::scenarios
{
    namespace
    {
        using State = MultiDroneModel::State;

        /// applies a macro to the drones only (no blocking), returning the final positions
        State applyMoves(State s, const std::vector<MultiDroneModel::Action> &macro, double step)
        {
            for (const auto a : macro)
            {
                const std::size_t d = MultiDroneModel::droneOf(a);
                const int axis = (a % 6) / 2;
                s.drone[d][axis] += (a % 2 == 0 ? step : -step);
            }
            return s;
        }
    }  // namespace

    namespace
    {
        /// the reference planner's per-plan messages
        struct QuietOmpl : ::testing::Environment
        {
            void SetUp() override { ompl::msg::setLogLevel(ompl::msg::LOG_ERROR); }
        };
        const auto *const QUIET = ::testing::AddGlobalTestEnvironment(new QuietOmpl);
    }  // namespace

    TEST(MultiDroneScenarioTest, RobotHasTwelveJointsAndDroneDroneSelfCollision)
    {
        const auto parts = multiDroneParts();
        const auto robot = loadMultiDroneRobot(parts.model->config());
        ASSERT_EQ(robot->dof(), 12u);
        std::set<std::pair<std::string, std::string>> pairs;
        for (const auto &p : robot->selfCollisionPairs())
        {
            pairs.insert({robot->collisionLinks()[static_cast<std::size_t>(p.first)].name,
                          robot->collisionLinks()[static_cast<std::size_t>(p.second)].name});
        }
        EXPECT_EQ(pairs.size(), 6u);
        EXPECT_TRUE(pairs.count({"drone1", "drone4"}) == 1);
        EXPECT_TRUE(pairs.count({"drone2", "drone3"}) == 1);
        // The planner's collision checker agrees: two drones 0.5 m apart collide, 0.7 m apart do not.
        const ompl_ext::Environment empty;
        pomdp::OmplPathPlanner planner(robot, std::make_shared<const ompl_ext::Environment>());
        std::vector<double> q{-9, -13, 0, -3, -13, 0, 3, -13, 0, 9, -13, 0};
        EXPECT_TRUE(planner.checker().isValid(empty, q.data()));
        q[3] = -8.5;
        EXPECT_FALSE(planner.checker().isValid(empty, q.data()));
        q[3] = -8.3;
        EXPECT_TRUE(planner.checker().isValid(empty, q.data()));
    }

    TEST(MultiDroneScenarioTest, HeuristicSendsTheNearestDroneToABeliefTarget)
    {
        const auto parts = multiDroneParts();
        const auto &config = parts.model->config();
        pomdp::Rng rng(21);
        std::vector<State> belief(200);
        for (auto &p : belief)
        {
            p = parts.model->sampleInitialState(rng);
        }
        const pomdp::BeliefView<State> view{belief.data(), belief.size()};
        for (const auto spread : {MultiDroneHeuristic::Spread::Uniform, MultiDroneHeuristic::Spread::Belief})
        {
            MultiDroneHeuristic heuristic(config, spread, 0.0);
            int fromBelief = 0;
            for (int i = 0; i < 500; ++i)
            {
                MultiDroneTarget goal{};
                ASSERT_TRUE(heuristic.sample(belief[0], view, rng, goal));
                // Some drone's goal is a particle's target, and it is the drone nearest to that target.
                int chasers = 0;
                for (std::size_t d = 0; d < 4; ++d)
                {
                    for (const auto &p : belief)
                    {
                        if (goal.q[3 * d] == p.target[0] && goal.q[3 * d + 1] == p.target[1] &&
                            goal.q[3 * d + 2] == p.target[2])
                        {
                            double best = 1e300;
                            std::size_t nearest = 0;
                            for (std::size_t j = 0; j < 4; ++j)
                            {
                                const double dist = MultiDroneModel::squaredDistance(belief[0].drone[j], p.target);
                                if (dist < best)
                                {
                                    best = dist;
                                    nearest = j;
                                }
                            }
                            chasers += nearest == d ? 1 : 0;
                            fromBelief += nearest == d ? 0 : 1;
                            break;
                        }
                    }
                }
                ASSERT_GE(chasers, 1);
                ASSERT_LT(goal.chaser, 4u);
                for (std::size_t d = 0; d < 4; ++d)
                {
                    for (int k = 0; k < 3; ++k)
                    {
                        ASSERT_GE(goal.q[3 * d + k], config.lower[k]);
                        ASSERT_LE(goal.q[3 * d + k], config.upper[k]);
                    }
                    for (std::size_t j = 0; j < d; ++j)
                    {
                        ASSERT_GE(std::sqrt(MultiDroneModel::squaredDistance(&goal.q[3 * d], &goal.q[3 * j])),
                                  2 * config.droneRadius);
                    }
                }
            }
            if (spread == MultiDroneHeuristic::Spread::Belief)
            {
                EXPECT_GT(fromBelief, 1000);  // the other drones go to other particles' targets
            }
            else
            {
                EXPECT_LT(fromBelief, 10);  // uniform spread: almost never exactly a particle
            }
        }
        // epsilon = 1: every target is an exploration target, no chaser, four uniform goals.
        MultiDroneHeuristic explore(config, MultiDroneHeuristic::Spread::Belief, 1.0);
        EXPECT_EQ(explore.name(), "epsilon-greedy(chase+belief-spread)");
        for (int i = 0; i < 100; ++i)
        {
            MultiDroneTarget goal{};
            ASSERT_TRUE(explore.sample(belief[0], view, rng, goal));
            EXPECT_EQ(goal.chaser, 4u);
            for (const auto &p : belief)
            {
                ASSERT_FALSE(goal.q[0] == p.target[0] && goal.q[1] == p.target[1]);
            }
        }
        EXPECT_THROW(MultiDroneHeuristic::spreadFromName("greedy"), Error);
        EXPECT_THROW(MultiDroneHeuristic(config, MultiDroneHeuristic::Spread::Uniform, 1.5), Error);
    }

    TEST(MultiDroneScenarioTest, MacroConversionReproducesThePathEnd)
    {
        const auto parts = multiDroneParts();
        pomdp::Rng rng(31);
        State start = parts.model->sampleInitialState(rng);
        MultiDronePlanningAdapter adapter(0.5, 10000, 0.75);
        for (int trial = 0; trial < 200; ++trial)
        {
            // A random 3-waypoint path from the start configuration.
            std::vector<double> path(36);
            adapter.configuration(start, path.data());
            for (std::size_t i = 12; i < 36; ++i)
            {
                const std::size_t k = i % 3;
                path[i] = k == 2 ? rng.uniform(-2, 2) : rng.uniform(-15, 15);
            }
            const std::size_t chaser = static_cast<std::size_t>(trial % 5);  // 4 = no chaser
            adapter.setChaser(chaser);
            std::vector<MultiDroneModel::Action> macro;
            ASSERT_TRUE(adapter.pathToMacroAction(start, path.data(), 3, macro));
            const State end = applyMoves(start, macro, 0.5);
            for (std::size_t d = 0; d < 4; ++d)
            {
                const double error = std::sqrt(MultiDroneModel::squaredDistance(end.drone[d], &path[24 + 3 * d]));
                ASSERT_LT(error, 0.5) << "trial " << trial << " drone " << d;
            }
            // Truncated: exactly macro_length actions, a prefix of the full conversion.
            MultiDronePlanningAdapter shortAdapter(0.5, 20, 0.75);
            shortAdapter.setChaser(chaser);
            std::vector<MultiDroneModel::Action> prefix;
            ASSERT_TRUE(shortAdapter.pathToMacroAction(start, path.data(), 3, prefix));
            ASSERT_EQ(prefix.size(), 20u);
            ASSERT_TRUE(std::equal(prefix.begin(), prefix.end(), macro.begin()));
            // The chaser's share of the truncated macro (when it has enough moves of its own).
            const auto movesOf = [](const std::vector<MultiDroneModel::Action> &m, std::size_t d)
            { return std::count_if(m.begin(), m.end(), [d](auto a) { return MultiDroneModel::droneOf(a) == d; }); };
            if (chaser < 4 && movesOf(macro, chaser) >= 20)
            {
                EXPECT_EQ(movesOf(prefix, chaser), 15);
            }
            if (chaser == 4)
            {
                for (std::size_t d = 0; d < 4; ++d)
                {
                    if (movesOf(macro, d) >= 5)
                    {
                        EXPECT_EQ(movesOf(prefix, d), 5);  // turns
                    }
                }
            }
            for (const auto a : macro)
            {
                ASSERT_LT(a, 24);
            }
        }
        EXPECT_THROW(MultiDronePlanningAdapter(0.5, 0, 0.75), Error);
        EXPECT_THROW(MultiDronePlanningAdapter(0.5, 10, 0.0), Error);
        EXPECT_THROW(MultiDronePlanningAdapter(0.5, 10, 1.5), Error);
    }

    TEST(MultiDroneScenarioTest, ReferencePolicyProducesMacrosFromOmplPlans)
    {
        const auto parts = multiDroneParts();
        RunSettings settings;
        pomdp::ParameterMap params;
        for (const auto &entry : parts.defaults)
        {
            params.set(entry.first, entry.second);
        }
        params.set("plan_time", 0.5);
        params.set("plan_iterations", 2000);
        auto policy = parts.referencePolicy(settings, params, 77);
        pomdp::Rng rng(41);
        std::vector<State> belief(100);
        for (auto &p : belief)
        {
            p = parts.model->sampleInitialState(rng);
        }
        int ok = 0;
        for (int i = 0; i < 20; ++i)
        {
            std::vector<MultiDroneModel::Action> macro;
            if (policy->sample(belief[0], {belief.data(), belief.size()}, rng, macro))
            {
                ++ok;
                EXPECT_GE(macro.size(), 1u);
                EXPECT_LE(macro.size(), 16u);  // macro_length
            }
        }
        EXPECT_GE(ok, 18);
        settings.heuristic = "nearest";
        EXPECT_THROW(parts.referencePolicy(settings, params, 77), Error);
    }

    TEST(MultiDroneScenarioTest, ShortEpisodeWithASimulationBudgetIsFiniteAndDeterministic)
    {
        const auto owned = makeMultiDroneScenario();
        const Scenario *scenario = owned.get();  // the type-erased interface (default arguments)
        EXPECT_EQ(scenario->horizon(), 400u);
        EXPECT_DOUBLE_EQ(scenario->defaultPlanSeconds(), 0.1);
        EXPECT_EQ(scenario->scene().at("dims").get<int>(), 3);
        RunSettings settings;
        settings.budget = pomdp::Budget::ofSimulations(30);
        settings.params.set("plan_iterations", 300);
        settings.params.set("plan_time", 1.0);
        settings.params.set("particles", 300);
        scenario->validate(settings);
        nlohmann::json recording;
        const auto a = scenario->runEpisode(settings, 5, &recording);
        const auto b = scenario->runEpisode(settings, 5);
        EXPECT_TRUE(std::isfinite(a.discountedReturn));
        EXPECT_TRUE(std::isfinite(a.undiscountedReturn));
        EXPECT_GE(a.steps, 1u);
        EXPECT_LE(a.steps, 400u);
        EXPECT_GE(a.plans, 1u);
        EXPECT_EQ(a.success, a.terminal);  // the only terminal outcome is a capture
        if (a.success)
        {
            EXPECT_GT(a.undiscountedReturn, 500.0);
        }
        EXPECT_EQ(a.steps, b.steps);
        EXPECT_EQ(a.discountedReturn, b.discountedReturn);
        EXPECT_EQ(a.success, b.success);
        EXPECT_EQ(a.plans, b.plans);
        EXPECT_EQ(recording.at("labels").size(), 5u);
        EXPECT_EQ(recording.at("trajectory").size(), a.steps + 1);
        // Another solver on the same scenario (Ref-Basic: random macros; it reads no planner parameters).
        settings.solver = "refbasic";
        settings.params = pomdp::ParameterMap();
        settings.params.set("particles", 300);
        const auto c = scenario->runEpisode(settings, 6);
        EXPECT_LE(c.steps, 400u);
        EXPECT_TRUE(std::isfinite(c.discountedReturn));
        // Unknown parameters are rejected.
        settings.params.set("macro_lenght", 3);
        EXPECT_THROW(scenario->validate(settings), Error);
    }
}  // namespace ropras::scenarios

namespace ropras::scenarios
{
    TEST(MultiDroneScenarioTest, RopRas3HasItsOwnDefaults)
    {
        // ROP-RAS3 compares nine candidate macro-actions over one macro level; R-POMCP keeps depth 3
        const auto parts = multiDroneParts();
        EXPECT_EQ(parts.solverDefaults.at("ropras3").at("depth"), 0.0);
        EXPECT_EQ(parts.solverDefaults.at("ropras3").at("beta_a"), 8.0);
        EXPECT_EQ(parts.solverDefaults.at("ropras3").at("alpha_a"), 0.0);
        EXPECT_EQ(parts.defaults.at("depth"), 3.0);
        EXPECT_EQ(parts.solverDefaults.count("rpomcp"), 0u);
        ScenarioOptions deeper;
        deeper.overrides = {{"solver_defaults", {{"ropras3", {{"depth", 2}}}}}};
        EXPECT_EQ(multiDroneParts(deeper).solverDefaults.at("ropras3").at("depth"), 2.0);
        ScenarioOptions bad;
        bad.overrides = {{"solver_defaults", {{"ropras3", {{"depth", "deep"}}}}}};
        ropras::test::expectErrorMentions([&] { multiDroneParts(bad); }, {"solver_defaults.ropras3.depth"});
    }
}  // namespace ropras::scenarios
