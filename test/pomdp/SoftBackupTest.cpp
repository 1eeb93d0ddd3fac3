#include "ropras/pomdp/SoftBackup.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <memory>
#include <vector>

#include "TestModels.h"
#include "ropras/pomdp/ParameterMap.h"
#include "ropras/pomdp/RandomMacroPolicy.h"
#include "ropras/pomdp/RopRas3Solver.h"
#include "ropras/pomdp/TreeSnapshot.h"

using namespace ropras::pomdp;

TEST(SoftBackupTest, LogAddExpIsStable)
{
    EXPECT_NEAR(logAddExp(0.0, 0.0), std::log(2.0), 1e-15);
    EXPECT_NEAR(logAddExp(1000.0, 1000.0), 1000.0 + std::log(2.0), 1e-12);
    EXPECT_NEAR(logAddExp(-1000.0, -1001.0), -1000.0 + std::log1p(std::exp(-1.0)), 1e-12);
    EXPECT_EQ(logAddExp(-INFINITY, 3.0), 3.0);
}

// Running backup over a fixed visit sequence on a bandit with known Q values equals the batch formula
// (1/eta) log sum_t exp(eta Q_t) / N, and with uniform visits it is Theorem 1's value with uniform pibar.
TEST(SoftBackupTest, RunningEqualsBatchOnBandit)
{
    const double eta = 0.2;
    for (const double scale : {1.0, 800.0, 8000.0})
    {
        const double q[3] = {-1.0 * scale, 0.25 * scale, 1.0 * scale};
        ropras::pomdp::Rng rng(7);
        double v = 0.0;
        std::vector<double> visited;
        for (std::size_t n = 1; n <= 3000; ++n)
        {
            const auto a = rng.uniformIndex(3);
            visited.push_back(q[a]);
            v = softValueUpdate(v, q[a], n, eta);
            ASSERT_TRUE(std::isfinite(v)) << "scale " << scale << " n " << n;
        }
        const double batch = softValue(visited.data(), nullptr, visited.size(), eta);
        EXPECT_NEAR(v, batch, 1e-9 * scale) << "scale " << scale;
        // Theorem 1 with pibar uniform: (1/eta) log (1/3) sum_a exp(eta Q_a); visits are uniform only
        // approximately, so compare against the visit frequencies exactly and the uniform value loosely.
        const double exact = softValue(q, nullptr, 3, eta);
        EXPECT_LE(v, q[2] + 1e-9);
        EXPECT_GE(v, q[0] - 1e-9);
        if (scale == 1.0)
        {
            EXPECT_NEAR(v, exact, 0.1);  // visit frequencies are 1/3 +- 0.009
        }
        else
        {
            // Dominated by the best action: V = Q_max + (1/eta) log(freq_max) up to exp(-eta * gap) terms.
            EXPECT_NEAR(v, exact, 0.5);
        }
    }
}

TEST(SoftBackupTest, WeightedBatchMatchesClosedForm)
{
    const double q[2] = {1.0, 3.0};
    const double w[2] = {0.25, 0.75};
    const double eta = 0.5;
    const double expected = std::log(0.25 * std::exp(0.5) + 0.75 * std::exp(1.5)) / eta;
    EXPECT_NEAR(softValue(q, w, 2, eta), expected, 1e-12);
    const double zero[2] = {0.0, 0.0};
    EXPECT_EQ(softValue(q, zero, 2, eta), -INFINITY);
}

// The solver's root value on a one-step bandit is exactly the batch value over its children's visits.
TEST(SoftBackupTest, SolverRootValueIsBatchValueOverChildren)
{
    for (const double scale : {1.0, 800.0})
    {
        auto model = std::make_shared<test::BanditModel>();
        model->rewards[0] = -scale;
        model->rewards[1] = 0.5 * scale;
        model->rewards[2] = scale;
        RopRas3Settings settings;
        settings.maxDepth = 0;
        settings.rolloutSteps = 0;
        RopRas3Solver<test::BanditModel> solver(
            model, std::make_unique<RandomMacroPolicy<test::BanditModel>>(model, 1, 1), settings);
        const int particle = 0;
        ropras::pomdp::Rng rng(3);
        const auto result = solver.plan(BeliefView<int>{&particle, 1}, Budget::ofSimulations(2000), rng);
        ASSERT_TRUE(result.valid);
        const auto children = solver.rootChildren();
        ASSERT_GE(children.size(), 2u);
        std::vector<double> q, w;
        std::size_t total = 0;
        for (const auto &c : children)
        {
            q.push_back(c.first);
            w.push_back(c.second);
            total += c.second;
        }
        EXPECT_EQ(total, 2000u);
        EXPECT_NEAR(result.statistics.rootValue, softValue(q.data(), w.data(), q.size(), settings.eta), 1e-9 * scale);
        // argmax Q: the best action's macro is executed when it was sampled as a child.
        bool hasBest = false;
        for (const auto &c : children)
        {
            hasBest = hasBest || c.first == scale;
        }
        if (hasBest)
        {
            EXPECT_EQ(result.action.front(), 2);
        }
    }
}

TEST(RopRas3SelectionTest, UcbConcentratesVisitsOnTheBestChildrenUniformSpreadsThem)
{
    // a bandit whose three arms pay -1, 0.5 and 1; random one-step macros, so the root's ~9 children repeat the
    // arms. Uniform choice (Algorithm 2) gives every child about N / |C| visits; UCB1 gives the arms paying 1
    // nearly all of them, and both read the same best action off the root.
    auto model = std::make_shared<test::BanditModel>();
    model->rewards[0] = -1.0;
    model->rewards[1] = 0.5;
    model->rewards[2] = 1.0;
    struct Spread
    {
        double bestShare;       ///< share of the visits that went to children of the best arm
        double bestChildShare;  ///< share of the children that are the best arm
        std::size_t children;
        std::uint32_t fewest;  ///< visits of the least visited child
    };
    const auto spread = [&](bool ucb)
    {
        RopRas3Settings settings;
        settings.maxDepth = 0;
        settings.rolloutSteps = 0;
        settings.ucbSelection = ucb;
        settings.ucbC = 0.5;
        RopRas3Solver<test::BanditModel> solver(
            model, std::make_unique<RandomMacroPolicy<test::BanditModel>>(model, 1, 1), settings);
        const int particle = 0;
        ropras::pomdp::Rng rng(17);
        const auto result = solver.plan(BeliefView<int>{&particle, 1}, Budget::ofSimulations(4000), rng);
        EXPECT_TRUE(result.valid);
        EXPECT_EQ(result.action.front(), 2);
        Spread out{0.0, 0.0, solver.rootChildren().size(), 4000};
        for (const auto &c : solver.rootChildren())
        {
            out.bestShare += c.first == 1.0 ? c.second / 4000.0 : 0.0;
            out.bestChildShare += c.first == 1.0 ? 1.0 / static_cast<double>(out.children) : 0.0;
            out.fewest = std::min(out.fewest, c.second);
        }
        return out;
    };
    const Spread uniform = spread(false);
    const Spread ucb = spread(true);
    ASSERT_GE(uniform.children, 6u);
    ASSERT_GE(ucb.children, 6u);
    ASSERT_GT(uniform.bestChildShare, 0.0);
    ASSERT_LT(uniform.bestChildShare, 0.7);
    // uniform: the visits follow the children (the later children, admitted by the widening, have fewer)
    EXPECT_NEAR(uniform.bestShare, uniform.bestChildShare, 0.2);
    EXPECT_GT(ucb.bestShare, 0.9) << "UCB1 concentrates the visits on the best arm";
    EXPECT_LT(ucb.fewest, 4000u / ucb.children / 4) << "UCB1 starves the worst children";

    ParameterMap bad;
    bad.set("ucb_select", 1);
    bad.set("ucb_c", -1.0);
    EXPECT_THROW(RopRas3Settings::fromParameters(bad), ropras::Error);
    ParameterMap good;
    good.set("ucb_select", 1);
    good.set("ucb_c", 1000.0);
    const auto parsed = RopRas3Settings::fromParameters(good);
    EXPECT_TRUE(parsed.ucbSelection);
    EXPECT_DOUBLE_EQ(parsed.ucbC, 1000.0);
}

namespace
{
    // Four steps: action 0 gambles (+800 or -2000 with equal probability, either ends the episode: Q = -600),
    // action 1 (when there are two actions) pays -1 and goes on. With two actions, a deep tree whose children's Q
    // estimates move as their returns come in.
    struct GambleChainModel
    {
        using State = int;
        using Action = int;
        using Observation = int;
        std::size_t actions{2};

        StepResult<State, Observation> step(State s, Action a, Rng &rng) const noexcept
        {
            if (a == 0)
            {
                return {s + 1, 0, rng.uniform01() < 0.5 ? 800.0 : -2000.0, true};
            }
            return {s + 1, static_cast<int>(rng.uniformIndex(2)), -1.0, s + 1 >= 4};
        }
        double observationProbability(Observation, State, Action) const noexcept { return 1.0; }
        State sampleInitialState(Rng &) const noexcept { return 0; }
        double discount() const noexcept { return 0.95; }
        std::size_t numActions() const noexcept { return actions; }
        Action action(std::size_t i) const noexcept { return static_cast<Action>(i); }
    };

    /// ROP-RAS3 over the gamble chain: macros of one random primitive, leaves worth 0 below depth \a maxDepth
    std::unique_ptr<RopRas3Solver<GambleChainModel>> gambleSolver(const std::shared_ptr<GambleChainModel> &model,
                                                                  unsigned maxDepth,
                                                                  RopRas3Settings::ValueBackup backup)
    {
        RopRas3Settings settings;
        settings.maxDepth = maxDepth;
        settings.rolloutSteps = 0;
        settings.valueBackup = backup;
        return std::make_unique<RopRas3Solver<GambleChainModel>>(
            model, std::make_unique<RandomMacroPolicy<GambleChainModel>>(model, 1, 1), settings);
    }

    struct NodeCheck
    {
        std::size_t checked{0};  ///< belief nodes with at least two visited children
        std::size_t deep{0};     ///< of them at depth >= 2
    };

    /// every belief node of \a tree with two or more visited children has V = Theorem 1 over them, each Q shrunk by
    /// \a qPrior pseudo-visits towards the children's visit-weighted mean (qPrior 0: the plain estimates)
    NodeCheck expectTheorem1AtEveryNode(const TreeSnapshot &tree, double eta, double qPrior, double tolerance)
    {
        NodeCheck out;
        for (const auto &belief : tree.beliefs)
        {
            std::vector<double> q, w;
            double mean = 0.0, visits = 0.0;
            for (const std::uint32_t a : belief.children)
            {
                mean += tree.actions[a].visits * tree.actions[a].q;
                visits += tree.actions[a].visits;
            }
            for (const std::uint32_t a : belief.children)
            {
                const double n = tree.actions[a].visits;
                if (n > 0.0)
                {
                    q.push_back(qPrior > 0.0 ? (n * tree.actions[a].q + qPrior * mean / visits) / (n + qPrior)
                                             : tree.actions[a].q);
                    w.push_back(n);
                }
            }
            if (q.size() < 2)
            {
                continue;
            }
            ++out.checked;
            out.deep += belief.depth >= 2 ? 1 : 0;
            EXPECT_NEAR(belief.value, softValue(q.data(), w.data(), q.size(), eta), tolerance)
                << "belief at depth " << belief.depth << " with " << belief.visits << " visits";
        }
        return out;
    }
}  // namespace

// With noisy returns, Algorithm 2's running backup keeps every early Q estimate in its mean of exp(eta Q): one
// child whose first return was +800 holds V near 800 - (1/eta) log N long after its Q fell to about -600. The
// backup over the current estimates (value_backup=1) is Theorem 1's value of the children as they stand.
TEST(SoftBackupTest, CurrentBackupForgetsStaleEstimatesRunningBackupDoesNot)
{
    auto model = std::make_shared<GambleChainModel>();
    model->actions = 1;  // the gamble alone: every child of the root is the same gamble
    const auto rootValue = [&](RopRas3Settings::ValueBackup backup, std::vector<std::pair<double, std::uint32_t>> &kids)
    {
        const auto solver = gambleSolver(model, 0, backup);
        const int particle = 0;
        ropras::pomdp::Rng rng(5);
        const auto result = solver->plan(BeliefView<int>{&particle, 1}, Budget::ofSimulations(4000), rng);
        EXPECT_TRUE(result.valid);
        kids = solver->rootChildren();
        return result.statistics.rootValue;
    };
    std::vector<std::pair<double, std::uint32_t>> running, current;
    const double vRunning = rootValue(RopRas3Settings::ValueBackup::RUNNING, running);
    const double vCurrent = rootValue(RopRas3Settings::ValueBackup::CURRENT, current);
    ASSERT_GE(current.size(), 6u);
    std::vector<double> q, w;
    double maxQ = -INFINITY;
    for (const auto &c : current)
    {
        ASSERT_GT(c.second, 20u);
        q.push_back(c.first);
        w.push_back(c.second);
        maxQ = std::max(maxQ, c.first);
        EXPECT_NEAR(c.first, -600.0, 5.0 * 1400.0 / std::sqrt(static_cast<double>(c.second)));
    }
    EXPECT_NEAR(vCurrent, softValue(q.data(), w.data(), q.size(), 0.2), 1e-9 * 2000.0);
    EXPECT_LE(vCurrent, maxQ + 1e-9);
    EXPECT_LT(vCurrent, 0.0) << "the current backup is a soft maximum of Q estimates near -600 (seed 5: -362)";
    // the running backup: bounded by the best return, far above every child's Q
    EXPECT_GT(vRunning, 700.0) << "Algorithm 2's running backup remembers the first lucky returns (seed 5: 770)";
    EXPECT_LE(vRunning, 800.0);

    ParameterMap p;
    p.set("value_backup", 1);
    EXPECT_EQ(RopRas3Settings::fromParameters(p).valueBackup, RopRas3Settings::ValueBackup::CURRENT);
    p.set("value_backup", 2);
    EXPECT_EQ(RopRas3Settings::fromParameters(p).valueBackup, RopRas3Settings::ValueBackup::FRESH);
    p.set("value_backup", 3);
    EXPECT_THROW(RopRas3Settings::fromParameters(p), ropras::Error);
}

// value_backup=1 keeps Theorem 1's value over the current children at every belief node of a deep tree, not only
// at the root, while the children's estimates move.
TEST(SoftBackupTest, CurrentBackupHoldsAtEveryNodeOfADeepTree)
{
    auto model = std::make_shared<GambleChainModel>();
    const auto solver = gambleSolver(model, 3, RopRas3Settings::ValueBackup::CURRENT);
    const int particle = 0;
    ropras::pomdp::Rng rng(11);
    const auto result = solver->plan(BeliefView<int>{&particle, 1}, Budget::ofSimulations(20000), rng);
    ASSERT_TRUE(result.valid);
    TreeSnapshot tree;
    ASSERT_TRUE(solver->treeSnapshot(tree));
    const NodeCheck nodes = expectTheorem1AtEveryNode(tree, solver->settings().eta, 0.0, 1e-9 * 2000.0);
    EXPECT_GT(nodes.checked, 20u);
    EXPECT_GT(nodes.deep, 5u);
}

// value_backup=2 also makes Q(b, a) of the children as they stand: for a walk (reward -1, discount 0.95, never
// terminal before depth 4) whose children are all backed-up nodes, Q(b, a) = -1 + 0.95 sum_o N(bao)/N(ba) V(bao)
// exactly. The running mean of past returns (value_backup 0 and 1) does not satisfy it.
TEST(SoftBackupTest, FreshBackupMakesEveryQOfTheChildrenAsTheyStand)
{
    auto model = std::make_shared<GambleChainModel>();
    for (const auto backup : {RopRas3Settings::ValueBackup::FRESH, RopRas3Settings::ValueBackup::CURRENT})
    {
        const auto solver = gambleSolver(model, 3, backup);
        const int particle = 0;
        ropras::pomdp::Rng rng(13);
        ASSERT_TRUE(solver->plan(BeliefView<int>{&particle, 1}, Budget::ofSimulations(20000), rng).valid);
        TreeSnapshot tree;
        ASSERT_TRUE(solver->treeSnapshot(tree));
        std::size_t checked = 0, off = 0;
        for (const auto &belief : tree.beliefs)
        {
            for (const std::uint32_t a : belief.children)
            {
                const auto &action = tree.actions[a];
                if (action.children.empty() || action.visits < 2)
                {
                    continue;  // the gamble (terminal) or too few visits to tell
                }
                double sum = 0.0;
                std::uint32_t entered = 0;
                bool leaves = false;
                for (const std::uint32_t c : action.children)
                {
                    sum += tree.beliefs[c].visits * tree.beliefs[c].value;
                    entered += tree.beliefs[c].visits;
                    leaves = leaves || tree.beliefs[c].depth > solver->settings().maxDepth;
                }
                if (leaves || entered != action.visits)
                {
                    continue;  // rollouts below depth D: their samples are not in the snapshot
                }
                ++checked;
                const double expected = -1.0 + 0.95 * sum / action.visits;
                if (backup == RopRas3Settings::ValueBackup::FRESH)
                {
                    EXPECT_NEAR(action.q, expected, 1e-9 * 2000.0) << "visits " << action.visits;
                }
                off += std::abs(action.q - expected) > 1.0;
            }
        }
        EXPECT_GT(checked, 20u);
        if (backup == RopRas3Settings::ValueBackup::CURRENT)
        {
            EXPECT_GT(off, checked / 4) << "the running mean of returns remembers past child values";
        }
    }
}

namespace
{
    // Every action is the same lottery: +800 with probability 0.1, else 0, never terminal. Every Q(b, a) of a
    // belief with h action levels left is therefore 80 (1 + 0.95 + ... + 0.95^(h-1)), and so is Theorem 1's value,
    // whatever eta: the soft maximum of equal Q is their common value.
    struct LotteryModel
    {
        using State = int;
        using Action = int;
        using Observation = int;

        StepResult<State, Observation> step(State s, Action, Rng &rng) const noexcept
        {
            return {s + 1, 0, rng.uniform01() < 0.1 ? 800.0 : 0.0, false};
        }
        double observationProbability(Observation, State, Action) const noexcept { return 1.0; }
        State sampleInitialState(Rng &) const noexcept { return 0; }
        double discount() const noexcept { return 0.95; }
        std::size_t numActions() const noexcept { return 3; }
        Action action(std::size_t i) const noexcept { return static_cast<Action>(i); }
    };
}  // namespace

// With eta = 0.01 and rewards of +800, a node whose children each hold a few returns is valued near the luckiest of
// them: the plug-in soft maximum over noisy Q estimates is biased upwards, and the bias climbs the tree. q_prior
// shrinks each Q towards the node's mean before the soft maximum; the root value then stays near the exact one.
TEST(SoftBackupTest, QPriorShrinksFewVisitEstimatesTowardsTheNodeMean)
{
    auto model = std::make_shared<LotteryModel>();
    const unsigned maxDepth = 3;  // four action levels
    const double exact = 80.0 * (1.0 + 0.95 + 0.95 * 0.95 + 0.95 * 0.95 * 0.95);
    const auto meanError = [&](double qPrior, RopRas3Settings::ValueBackup backup)
    {
        double sum = 0.0;
        for (int seed = 0; seed < 4; ++seed)
        {
            RopRas3Settings settings;
            settings.eta = 0.01;
            settings.maxDepth = maxDepth;
            settings.rolloutSteps = 0;
            settings.valueBackup = backup;
            settings.qPrior = qPrior;
            RopRas3Solver<LotteryModel> solver(model, std::make_unique<RandomMacroPolicy<LotteryModel>>(model, 1, 1),
                                               settings);
            const int particle = 0;
            ropras::pomdp::Rng rng(300 + seed);
            const auto result = solver.plan(BeliefView<int>{&particle, 1}, Budget::ofSimulations(20000), rng);
            EXPECT_TRUE(result.valid);
            sum += result.statistics.rootValue - exact;
            if (seed == 0 && qPrior > 0.0)
            {
                // every node's value is Theorem 1 over its children's shrunk estimates
                TreeSnapshot tree;
                EXPECT_TRUE(solver.treeSnapshot(tree));
                EXPECT_GT(expectTheorem1AtEveryNode(tree, 0.01, qPrior, 1e-9 * 1000.0).checked, 100u);
            }
        }
        return sum / 4.0;
    };
    const double plain = meanError(0.0, RopRas3Settings::ValueBackup::CURRENT);
    const double shrunk = meanError(4.0, RopRas3Settings::ValueBackup::CURRENT);
    // value_backup 2 makes Q of the children's current (shrunk) values too
    const double plainFresh = meanError(0.0, RopRas3Settings::ValueBackup::FRESH);
    const double shrunkFresh = meanError(4.0, RopRas3Settings::ValueBackup::FRESH);
    std::printf("root value - exact (%.1f): q_prior 0 %+.1f, q_prior 4 %+.1f; value_backup 2: %+.1f, %+.1f\n", exact,
                plain, shrunk, plainFresh, shrunkFresh);
    EXPECT_GT(plain, 100.0) << "the plug-in soft maximum over few-return children is biased upwards";
    EXPECT_LT(std::abs(shrunk), plain / 3.0);
    EXPECT_GT(plainFresh, 100.0);
    EXPECT_LT(std::abs(shrunkFresh), plainFresh / 3.0);

    ParameterMap p;
    p.set("q_prior", 2.5);
    EXPECT_THROW(RopRas3Settings::fromParameters(p), ropras::Error) << "the running backup does not read q_prior";
    p.set("value_backup", 1);
    EXPECT_DOUBLE_EQ(RopRas3Settings::fromParameters(p).qPrior, 2.5);
    p.set("q_prior", -1.0);
    EXPECT_THROW(RopRas3Settings::fromParameters(p), ropras::Error);
    EXPECT_THROW(p.set("q_prior", std::nan("")), ropras::Error);
}
