// Every registered solver runs on Tiger by name through the type-erased registry; bad names, parameters,
// budgets and beliefs are rejected with ropras::Error; same seed, same result.
#include <gtest/gtest.h>

#include <limits>
#include <memory>
#include <string>
#include <vector>

#include "ropras/core/Error.h"
#include "ropras/pomdp/BPlanSolver.h"
#include "ropras/pomdp/ModelRegistry.h"
#include "ropras/pomdp/PomcpSolver.h"
#include "ropras/pomdp/RopRas3Solver.h"
#include "ropras/pomdp/SolverRunner.h"
#include "ropras/pomdp/Tiger.h"

using namespace ropras::pomdp;

namespace
{
    /// fails its first \a failures requests (all of them by default), then plans the one-action macro "listen"
    class FailingPolicy final : public ReferencePolicy<TigerModel>
    {
    public:
        explicit FailingPolicy(std::size_t failures = std::numeric_limits<std::size_t>::max()) : failures_(failures) {}
        bool sample(const TigerModel::State &, BeliefView<TigerModel::State>, Rng &,
                    std::vector<TigerModel::Action> &macro) override
        {
            if (requests_++ < failures_)
            {
                return false;
            }
            macro.assign(1, TigerModel::LISTEN);
            return true;
        }
        std::string name() const override { return "failing"; }

    private:
        std::size_t failures_;
        std::size_t requests_{0};
    };

    std::string errorOf(const std::function<void()> &f)
    {
        try
        {
            f();
        }
        catch (const ropras::Error &e)
        {
            return e.what();
        }
        return "";
    }
}  // namespace

TEST(SolverRegistryTest, EverySolverRunsOnTigerByName)
{
    ASSERT_EQ(modelRegistry().names(), std::vector<std::string>{"tiger"});
    const std::vector<std::string> expected{"bplan", "pomcp", "refbasic", "ropras3", "rpomcp", "rbss"};
    auto names = solverNames<TigerModel>();
    std::sort(names.begin(), names.end());
    auto sortedExpected = expected;
    std::sort(sortedExpected.begin(), sortedExpected.end());
    EXPECT_EQ(names, sortedExpected);
    for (const auto &solver : expected)
    {
        ParameterMap params;
        params.set("particles", 100);
        auto runner = modelRegistry().create("tiger", solver, params);
        EXPECT_EQ(runner->modelName(), "tiger");
        EXPECT_EQ(runner->solverName(), solver);
        const auto stats = runner->planFromInitialBelief(Budget::ofSimulations(500), 1);
        if (solver == "ropras3" || solver == "refbasic" || solver == "pomcp" || solver == "rpomcp")
        {
            EXPECT_EQ(stats.simulations, 500u) << solver;
            EXPECT_GT(stats.beliefNodes, 1u) << solver;
            EXPECT_GT(stats.modelSteps, 0u) << solver;
        }
        EpisodeSettings episode;
        episode.maxSteps = 10;
        episode.budget = Budget::ofSimulations(200);
        const auto result = runner->runEpisode(episode, 3);
        EXPECT_EQ(result.steps, 10u) << solver;
        EXPECT_EQ(result.invalidPlans, 0u) << solver;
        EXPECT_GE(result.plans, 1u) << solver;
    }
}

TEST(SolverRegistryTest, SameSeedSameResult)
{
    for (const std::string solver : {"ropras3", "pomcp", "rpomcp"})
    {
        auto a = modelRegistry().create("tiger", solver, ParameterMap{});
        auto b = modelRegistry().create("tiger", solver, ParameterMap{});
        const auto sa = a->planFromInitialBelief(Budget::ofSimulations(2000), 17);
        const auto sb = b->planFromInitialBelief(Budget::ofSimulations(2000), 17);
        EXPECT_EQ(sa.rootValue, sb.rootValue) << solver;
        EXPECT_EQ(sa.beliefNodes, sb.beliefNodes) << solver;
        const auto sc = b->planFromInitialBelief(Budget::ofSimulations(2000), 18);
        EXPECT_NE(sa.rootValue, sc.rootValue) << solver;
        EpisodeSettings episode;
        episode.maxSteps = 20;
        episode.budget = Budget::ofSimulations(300);
        EXPECT_EQ(a->runEpisode(episode, 5).discountedReturn, b->runEpisode(episode, 5).discountedReturn) << solver;
    }
}

TEST(SolverRegistryTest, RopRas3StatisticsAndDefaults)
{
    const auto components = tigerComponents();
    RopRas3Settings defaults;
    EXPECT_EQ(defaults.eta, 0.2);
    EXPECT_EQ(defaults.betaA, 6.0);
    EXPECT_EQ(defaults.alphaA, 0.05);
    ParameterMap params;
    params.set("depth", 50);
    params.set("profile", 1);
    auto solver = makeSolver("ropras3", components, withDefaults(components, params));
    std::vector<TigerModel::State> belief{0, 1, 0, 1};
    Rng rng(2);
    const auto result =
        solver->plan(BeliefView<TigerModel::State>{belief.data(), belief.size()}, Budget::ofSimulations(1000), rng);
    ASSERT_TRUE(result.valid);
    const auto &s = result.statistics;
    EXPECT_EQ(s.simulations, 1000u);
    EXPECT_EQ(s.maxDepth, 50u);  // depth-first: the first simulation already reaches depth D
    EXPECT_GT(s.referenceRequested, 0u);
    EXPECT_EQ(s.referenceFailed, 0u);
    EXPECT_EQ(s.actionNodes, s.referenceRequested);
    EXPECT_GT(s.modelSeconds, 0.0);
    EXPECT_GT(s.referenceSeconds, 0.0);
    EXPECT_LT(s.modelSeconds + s.referenceSeconds, s.seconds);
    // The root's children obey the widening rule |C(b)| <= 6 N^0.05 + 1.
    auto *ropras3 = dynamic_cast<RopRas3Solver<TigerModel> *>(solver.get());
    ASSERT_NE(ropras3, nullptr);
    const auto children = ropras3->rootChildren();
    EXPECT_LE(static_cast<double>(children.size()), 6.0 * std::pow(1000.0, 0.05) + 1.0);
    EXPECT_GE(children.size(), 7u);
}

TEST(SolverRegistryTest, FailingReferencePolicyIsCountedNotFatal)
{
    auto model = std::make_shared<const TigerModel>();
    RopRas3Solver<TigerModel> solver(model, std::make_unique<FailingPolicy>(), RopRas3Settings{});
    std::vector<TigerModel::State> belief{0, 1};
    Rng rng(1);
    const auto result =
        solver.plan(BeliefView<TigerModel::State>{belief.data(), belief.size()}, Budget::ofSimulations(50), rng);
    EXPECT_FALSE(result.valid);
    EXPECT_TRUE(result.action.empty());
    EXPECT_EQ(result.statistics.referenceRequested, 50u);
    EXPECT_EQ(result.statistics.referenceFailed, 50u);
    EXPECT_EQ(result.statistics.simulations, 50u);
}

TEST(SolverRegistryTest, BadInputThrowsWithNames)
{
    EXPECT_NE(errorOf([] { modelRegistry().create("tigre", "pomcp", ParameterMap{}); }).find("tigre"),
              std::string::npos);
    EXPECT_NE(errorOf([] { modelRegistry().create("tiger", "mcts", ParameterMap{}); }).find("mcts"), std::string::npos);
    ParameterMap typo;
    typo.set("etaa", 0.3);
    EXPECT_NE(errorOf([&] { modelRegistry().create("tiger", "ropras3", typo); }).find("etaa"), std::string::npos);
    ParameterMap negative;
    negative.set("eta", -1.0);
    EXPECT_NE(errorOf([&] { modelRegistry().create("tiger", "ropras3", negative); }).find("eta"), std::string::npos);
    ParameterMap fraction;
    fraction.set("depth", 2.5);
    EXPECT_NE(errorOf([&] { modelRegistry().create("tiger", "pomcp", fraction); }).find("depth"), std::string::npos);
    ParameterMap heuristic;
    heuristic.set("heuristic", 7);
    EXPECT_NE(errorOf([&] { modelRegistry().create("tiger", "ropras3", heuristic); }).find("heuristic"),
              std::string::npos);
    ParameterMap reinvigorate;
    reinvigorate.set("reinvigorate", 1);
    EXPECT_NE(errorOf([&] { modelRegistry().create("tiger", "pomcp", reinvigorate); }).find("reinvigorate"),
              std::string::npos);
    ParameterMap huge;
    huge.set("c_a", 1000);
    huge.set("c_s", 1000);
    EXPECT_THROW(modelRegistry().create("tiger", "rbss", huge), ropras::Error);

    EXPECT_THROW(ParameterMap::parse({"eta"}), ropras::Error);
    EXPECT_THROW(ParameterMap::parse({"eta=abc"}), ropras::Error);
    EXPECT_THROW(ParameterMap::parse({"eta=nan"}), ropras::Error);
    EXPECT_THROW(ParameterMap::parse({"eta=inf"}), ropras::Error);
    EXPECT_THROW(ParameterMap::parse({"eta=0.1", "eta=0.2"}), ropras::Error);
    EXPECT_THROW(ParameterMap::parse({"=3"}), ropras::Error);
    EXPECT_EQ(ParameterMap::parse({"eta=0.5"}).get("eta", 0.0), 0.5);

    auto runner = modelRegistry().create("tiger", "ropras3", ParameterMap{});
    EXPECT_THROW(runner->planFromInitialBelief(Budget{}, 1), ropras::Error);
    EXPECT_THROW(runner->planFromInitialBelief(Budget{0, std::nan("")}, 1), ropras::Error);
    EXPECT_THROW(runner->planFromInitialBelief(Budget{0, -1.0}, 1), ropras::Error);

    auto model = std::make_shared<const TigerModel>();
    RopRas3Solver<TigerModel> solver(model, std::make_unique<FailingPolicy>(), RopRas3Settings{});
    Rng rng(1);
    EXPECT_THROW(solver.plan(BeliefView<TigerModel::State>{}, Budget::ofSimulations(10), rng), ropras::Error);
    EXPECT_THROW(RopRas3Solver<TigerModel>(model, nullptr, RopRas3Settings{}), ropras::Error);
}

// makeSolver itself rejects a misspelt parameter (the library API, not only the CLI's runner), with the error the
// CLI gives: it names the unknown parameter and lists the valid ones.
TEST(SolverRegistryTest, MakeSolverRejectsAMisspeltParameter)
{
    const auto components = tigerComponents();
    ParameterMap typo;
    typo.set("dpth", 5);
    const std::string direct = errorOf([&] { makeSolver("ropras3", components, withDefaults(components, typo)); });
    EXPECT_NE(direct.find("unknown parameter(s) for solver ropras3: dpth"), std::string::npos) << direct;
    for (const char *valid : {"depth", "eta", "beta_a", "particles"})
        EXPECT_NE(direct.find(valid), std::string::npos) << valid << " missing from: " << direct;
    const std::string viaRegistry = errorOf([&] { modelRegistry().create("tiger", "ropras3", typo); });
    EXPECT_EQ(viaRegistry, direct);
    for (const std::string &solver : solverNames<TigerModel>())
    {
        const std::string message = errorOf([&] { makeSolver(solver, components, withDefaults(components, typo)); });
        EXPECT_NE(message.find("dpth"), std::string::npos) << solver << ": " << message;
        // the correct names build: every solver accepts the particle filter's names and the model's defaults
        ParameterMap good;
        good.set("particles", 100);
        EXPECT_NO_THROW(makeSolver(solver, components, withDefaults(components, good))) << solver;
    }
}

TEST(SolverRegistryTest, TimeBudgetStopsTheSearch)
{
    auto runner = modelRegistry().create("tiger", "pomcp", ParameterMap{});
    const auto stats = runner->planFromInitialBelief(Budget::ofSeconds(0.02), 1);
    EXPECT_GT(stats.simulations, 0u);
    // No wall-clock assertion on the duration itself: only that a time-only budget terminates.
}

TEST(SolverRegistryTest, RPomcpAndBPlanUseTheReferencePolicy)
{
    auto model = std::make_shared<const TigerModel>();
    const auto components = tigerComponents();
    std::vector<TigerModel::State> belief{0, 1, 0, 1};
    const BeliefView<TigerModel::State> view{belief.data(), belief.size()};
    PomcpSettings settings;
    settings.macroActionsPerNode = 5;
    PomcpSolver<TigerModel> rpomcp(model, components.referencePolicy(ParameterMap{}), settings, "rpomcp");
    Rng rng(4);
    const auto planned = rpomcp.plan(view, Budget::ofSimulations(300), rng);
    ASSERT_TRUE(planned.valid);
    EXPECT_EQ(rpomcp.rootChildren().size(), 5u);  // K macros at the root
    EXPECT_EQ(planned.statistics.referenceRequested, 5u * planned.statistics.beliefNodes);

    // A root whose K plans all failed asks again on the next simulation (a transient failure does not spend the
    // call on a root without actions); below the root a node without actions is a leaf.
    PomcpSolver<TigerModel> failingRpomcp(model, std::make_unique<FailingPolicy>(), settings, "rpomcp");
    const auto failed = failingRpomcp.plan(view, Budget::ofSimulations(20), rng);
    EXPECT_FALSE(failed.valid);
    EXPECT_EQ(failed.statistics.referenceRequested, 5u * 20u);
    EXPECT_EQ(failed.statistics.referenceFailed, 5u * 20u);
    PomcpSolver<TigerModel> recovering(model, std::make_unique<FailingPolicy>(12), settings, "rpomcp");
    const auto recovered = recovering.plan(view, Budget::ofSimulations(20), rng);
    ASSERT_TRUE(recovered.valid);
    EXPECT_EQ(recovered.action, std::vector<TigerModel::Action>{TigerModel::LISTEN});
    EXPECT_EQ(recovering.rootChildren().size(), 3u);  // the third round of 5: 2 failed, 3 planned
    EXPECT_EQ(recovered.statistics.referenceFailed, 12u);

    BPlanSolver<TigerModel> bplan(model, std::make_unique<FailingPolicy>(), 3);
    const auto fallback = bplan.plan(view, Budget::ofSimulations(1), rng);
    EXPECT_TRUE(fallback.valid);  // the model's rollout action
    EXPECT_EQ(fallback.action.size(), 1u);
    EXPECT_EQ(fallback.statistics.referenceRequested, 3u);
    EXPECT_EQ(fallback.statistics.referenceFailed, 3u);

    // Certain belief (tiger left): the Dynamic heuristic's B-plan opens the right door.
    BPlanSolver<TigerModel> informed(model, components.referencePolicy(ParameterMap{}), 3);
    const std::vector<TigerModel::State> left(20, 0);
    const auto open =
        informed.plan(BeliefView<TigerModel::State>{left.data(), left.size()}, Budget::ofSimulations(1), rng);
    ASSERT_TRUE(open.valid);
    EXPECT_EQ(open.action, std::vector<TigerModel::Action>{TigerModel::OPEN_RIGHT});
}

TEST(SolverRegistryTest, SolverDefaultsApplyToTheirSolverOnlyAndYieldToTheUser)
{
    auto components = tigerComponents();
    components.defaults["depth"] = 7;
    components.solverDefaults["ropras3"] = {{"depth", 0}, {"beta_a", 8}, {"alpha_a", 0}};
    components.solverDefaults["bplan"] = {{"depth", 3}};  // B-plan reads no depth: no unknown-parameter error
    const auto ropras3 = makeSolver("ropras3", components, withDefaults(components, ParameterMap{}, "ropras3"));
    const auto &own = dynamic_cast<const RopRas3Solver<TigerModel> &>(*ropras3).settings();
    EXPECT_EQ(own.maxDepth, 0u);
    EXPECT_EQ(own.betaA, 8.0);
    EXPECT_EQ(own.alphaA, 0.0);
    // Ref-Basic shares ROP-RAS3's settings but not its solver defaults: the shared depth, the solver's widening
    const auto refbasic = makeSolver("refbasic", components, withDefaults(components, ParameterMap{}, "refbasic"));
    const auto &shared = dynamic_cast<const RopRas3Solver<TigerModel> &>(*refbasic).settings();
    EXPECT_EQ(shared.maxDepth, 7u);
    EXPECT_EQ(shared.betaA, RopRas3Settings{}.betaA);
    // the user's parameters override both
    ParameterMap user;
    user.set("depth", 2);
    const auto mine = makeSolver("ropras3", components, withDefaults(components, user, "ropras3"));
    EXPECT_EQ(dynamic_cast<const RopRas3Solver<TigerModel> &>(*mine).settings().maxDepth, 2u);
    EXPECT_NO_THROW(makeSolver("bplan", components, withDefaults(components, ParameterMap{}, "bplan")));
    // the names exempt from the unread-parameter check: every default the user did not set, shared and own
    const auto exempt = unreadDefaultsAllowed(components, user, "ropras3");
    EXPECT_EQ(exempt.count("depth"), 0u);
    EXPECT_EQ(exempt.count("beta_a"), 1u);
    EXPECT_EQ(exempt.count("ucb_c"), 1u);
    // the runner (ropras pomdp-run) merges the same way: B-plan's own unread default is no error there either
    EXPECT_NO_THROW(ModelSolverRunner<TigerModel>("tiger", components, "bplan", ParameterMap{}));
    EXPECT_NO_THROW(ModelSolverRunner<TigerModel>("tiger", components, "ropras3", user));
}
