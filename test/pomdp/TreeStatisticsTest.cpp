// ROP-RAS3's observation handling and first evaluations (issue 14): macro observation keys (whole sequence vs the
// last non-empty observation), observation progressive widening bounding the branching, the bias of evaluating a
// new macro on the particle it was planned from (closed form), the belief fill of new nodes (closed form), and the
// tree snapshot's counts.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>
#include <memory>
#include <vector>

#include "TestModels.h"
#include "ropras/pomdp/MacroAction.h"
#include "ropras/pomdp/RopRas3Solver.h"
#include "ropras/pomdp/TreeSnapshot.h"

namespace ropras::pomdp::test
{
    namespace
    {
        /** \brief Observation = the action (0 = the empty observation, as a default-constructed int). */
        struct EchoModel
        {
            using State = int;
            using Action = int;
            using Observation = int;
            StepResult<State, Observation> step(State s, Action a, Rng &) const noexcept { return {s, a, 0.0, false}; }
            double observationProbability(Observation, State, Action) const noexcept { return 1.0; }
            State sampleInitialState(Rng &) const noexcept { return 0; }
            double discount() const noexcept { return 0.9; }
        };

        /** \brief A continuous observation (every step a new bin): x' = x, o = x + N(0, 1), key = o at 1e-9. */
        struct NoisyModel
        {
            using State = double;
            using Action = int;
            using Observation = double;
            StepResult<State, Observation> step(State s, Action, Rng &rng) const noexcept
            {
                return {s, s + rng.normal(0.0, 1.0), -1.0, false};
            }
            double observationProbability(Observation, State, Action) const noexcept { return 1.0; }
            State sampleInitialState(Rng &) const noexcept { return 0.0; }
            double discount() const noexcept { return 0.9; }
            std::uint64_t observationKey(Observation o) const noexcept
            {
                return static_cast<std::uint64_t>(static_cast<std::int64_t>(std::llround(o * 1e9)));
            }
            std::size_t numActions() const noexcept { return 1; }
            Action action(std::size_t) const noexcept { return 0; }
        };

        /** \brief Guess the side: s in {0, 1}; action a pays 1 when a == s, else 0, and ends the episode. */
        struct GuessModel
        {
            using State = int;
            using Action = int;
            using Observation = int;
            StepResult<State, Observation> step(State s, Action a, Rng &) const noexcept
            {
                return {s, 0, a == s ? 1.0 : 0.0, true};
            }
            double observationProbability(Observation, State, Action) const noexcept { return 1.0; }
            State sampleInitialState(Rng &rng) const noexcept { return static_cast<int>(rng.uniformIndex(2)); }
            double discount() const noexcept { return 0.9; }
            std::size_t numActions() const noexcept { return 2; }
            Action action(std::size_t i) const noexcept { return static_cast<Action>(i); }
        };

        /** \brief Wait, then guess the side: s = side + 2 t. At t = 0 action 2 waits (reward 0; its observation is
            the side + 1 when \a reveal, else empty); at t = 1 action a in {0, 1} pays 1 when a == side and ends. */
        template <bool Reveal>
        struct WaitGuessModel
        {
            using State = int;
            using Action = int;
            using Observation = int;
            StepResult<State, Observation> step(State s, Action a, Rng &) const noexcept
            {
                if (s < 2)
                    return {s + 2, Reveal ? s + 1 : 0, 0.0, false};
                return {s, 0, a == s % 2 ? 1.0 : 0.0, true};
            }
            double observationProbability(Observation, State, Action) const noexcept { return 1.0; }
            State sampleInitialState(Rng &rng) const noexcept { return static_cast<int>(rng.uniformIndex(2)); }
            double discount() const noexcept { return 0.9; }
            std::size_t numActions() const noexcept { return 3; }
            Action action(std::size_t i) const noexcept { return static_cast<Action>(i); }
        };

        /** \brief Wait at t = 0, then guess the side of the particle the macro is planned from. */
        template <class M>
        struct WaitThenGuessPolicy final : ReferencePolicy<M>
        {
            bool sample(const int &start, BeliefView<int>, Rng &, std::vector<int> &out) override
            {
                out.push_back(start < 2 ? 2 : start % 2);
                return true;
            }
            std::string name() const override { return "wait-then-guess"; }
        };

        /** \brief The one-step macro {start} (guess the side of the particle it is planned from) / {0}. */
        template <class M>
        struct EchoStartPolicy final : ReferencePolicy<M>
        {
            bool sample(const typename M::State &start, BeliefView<typename M::State>, Rng &,
                        std::vector<typename M::Action> &out) override
            {
                out.push_back(static_cast<typename M::Action>(start));
                return true;
            }
            std::string name() const override { return "echo-start"; }
        };

        template <class M>
        std::unique_ptr<RopRas3Solver<M>> solverOf(const RopRas3Settings &s)
        {
            return std::make_unique<RopRas3Solver<M>>(std::make_shared<const M>(),
                                                      std::make_unique<EchoStartPolicy<M>>(), s);
        }
    }  // namespace

    TEST(MacroObservationKey, SequenceSeparatesWhatTheLastNonEmptyObservationMerges)
    {
        const EchoModel model;
        Rng rng(1);
        const std::vector<int> a{1, 0, 2, 0}, b{3, 0, 2, 0}, c{3, 0, 2}, empty{0, 0};
        const auto ra = executeMacro(model, 0, MacroView<int>{a.data(), a.size()}, rng);
        const auto rb = executeMacro(model, 0, MacroView<int>{b.data(), b.size()}, rng);
        const auto rc = executeMacro(model, 0, MacroView<int>{c.data(), c.size()}, rng);
        const auto re = executeMacro(model, 0, MacroView<int>{empty.data(), empty.size()}, rng);
        EXPECT_NE(ra.observationKey, rb.observationKey) << "the sequences differ in their first observation";
        EXPECT_NE(rb.observationKey, rc.observationKey) << "the sequences differ in length";
        EXPECT_EQ(ra.lastObservationKey, 2u) << "the last non-empty observation, 2";
        EXPECT_EQ(rb.lastObservationKey, ra.lastObservationKey);
        EXPECT_EQ(rc.lastObservationKey, ra.lastObservationKey);
        EXPECT_EQ(re.lastObservationKey, 0u) << "no non-empty observation: the empty key";
    }

    TEST(ObservationWidening, BoundsTheObservationChildrenOfAnAction)
    {
        // one action (beta_a tiny: a single child); every macro observation is new
        RopRas3Settings s;
        s.betaA = 1e-9;
        s.alphaA = 0.0;
        s.maxDepth = 3;
        s.rolloutSteps = 0;
        const std::vector<double> particles(50, 0.0);
        const BeliefView<double> belief{particles.data(), particles.size()};
        for (const double betaO : {0.0, 1.0, 2.0})
        {
            s.betaO = betaO;
            s.alphaO = 0.5;
            auto solver = solverOf<NoisyModel>(s);
            Rng rng(7);
            solver->plan(belief, Budget::ofSimulations(400), rng);
            TreeSnapshot tree;
            ASSERT_TRUE(solver->treeSnapshot(tree));
            ASSERT_EQ(tree.beliefs[0].children.size(), 1u);
            const auto &root = tree.actions[tree.beliefs[0].children[0]];
            EXPECT_EQ(root.visits, 400u);
            if (betaO == 0.0)
            {
                EXPECT_EQ(root.children.size(), 400u) << "binning alone: every simulation opens a new branch";
            }
            else
            {
                // a child is admitted only while |C| <= beta_o N^alpha_o, checked before the N-th backup
                EXPECT_LE(root.children.size(), static_cast<std::size_t>(betaO * std::sqrt(400.0)) + 1);
                EXPECT_GE(root.children.size(), static_cast<std::size_t>(betaO * std::sqrt(399.0)) - 1);
                std::uint32_t particlesBelow = 0;
                for (const auto c : root.children)
                    particlesBelow += tree.beliefs[c].particles;
                EXPECT_EQ(particlesBelow, 400u) << "every simulation's s' joined one of the children";
            }
        }
    }

    TEST(IndependentEvaluation, FirstReturnsEstimateTheBeliefsQ)
    {
        // Every simulation creates a new macro (beta_a huge, alpha_a 0), so each child holds exactly one return.
        // A macro guessing the side of the particle it was planned from is worth 1/2 under the belief; returned
        // from that same particle it always pays 1.
        RopRas3Settings s;
        s.betaA = 1e9;
        s.alphaA = 0.0;
        s.eta = 1.0;
        std::vector<int> particles;
        for (int i = 0; i < 1000; ++i)
            particles.push_back(i % 2);
        const BeliefView<int> belief{particles.data(), particles.size()};
        const std::size_t n = 4000;
        for (const bool independent : {false, true})
        {
            s.independentEvaluation = independent;
            auto solver = solverOf<GuessModel>(s);
            Rng rng(11);
            const auto result = solver->plan(belief, Budget::ofSimulations(n), rng);
            const auto children = solver->rootChildren();
            ASSERT_EQ(children.size(), n);
            double mean = 0.0;
            for (const auto &qn : children)
            {
                EXPECT_EQ(qn.second, 1u);
                mean += qn.first / static_cast<double>(n);
            }
            if (!independent)
            {
                EXPECT_NEAR(mean, 1.0, 1e-9) << "evaluated on the particle it was planned from: always right";
                EXPECT_NEAR(result.statistics.rootValue, 1.0, 1e-9);
            }
            else
            {
                const double se = std::sqrt(0.25 / static_cast<double>(n));
                EXPECT_NEAR(mean, 0.5, 4.0 * se);
                // V = (1/eta) log mean exp(eta Q) over Bernoulli(1/2) returns
                const double v = std::log(0.5 + 0.5 * std::exp(1.0));
                EXPECT_NEAR(result.statistics.rootValue, v, 4.0 * se * std::exp(1.0) / (1.0 + std::exp(1.0)) * 2.0);
            }
        }
    }

    TEST(BeliefFill, DeepNodesHoldTheBeliefNotTheOneParticleThatArrived)
    {
        // Every simulation creates a new wait macro at the root (beta_a huge, alpha_a 0), so each depth-1 node is
        // new and gets one guess, evaluated on a particle drawn from the node independently of the one it was
        // planned from (independent_eval). Without the fill that node holds the single particle that arrived: the
        // guess is always right, the search believes the side known. With the fill it holds the root's belief
        // moved through the wait: about half the guesses are wrong. When the wait reveals the side, the fill keeps only
        // the particles of the observed side, and every guess is right again.
        RopRas3Settings s;
        s.betaA = 1e9;
        s.alphaA = 0.0;
        s.maxDepth = 1;
        s.rolloutSteps = 0;
        s.independentEvaluation = true;
        std::vector<int> particles;
        for (int i = 0; i < 200; ++i)
            particles.push_back(i % 2);
        const BeliefView<int> belief{particles.data(), particles.size()};
        const std::size_t n = 2000;
        const auto run = [&](auto model, unsigned fill, double &meanQ, TreeSnapshot &tree)
        {
            using M = decltype(model);
            s.fillParticles = fill;
            RopRas3Solver<M> solver(std::make_shared<const M>(), std::make_unique<WaitThenGuessPolicy<M>>(), s);
            Rng rng(5);
            const auto result = solver.plan(belief, Budget::ofSimulations(n), rng);
            ASSERT_TRUE(solver.treeSnapshot(tree));
            const auto children = solver.rootChildren();
            ASSERT_EQ(children.size(), n);
            meanQ = 0.0;
            for (const auto &qn : children)
                meanQ += qn.first / static_cast<double>(n);
            // every simulation creates one depth-1 node, filled only when it is expanded (D >= 1)
            EXPECT_EQ(result.statistics.fillTried, s.maxDepth > 0 ? static_cast<std::size_t>(fill) * n : 0u)
                << "fill " << fill << ", D " << s.maxDepth;
        };
        const double se = 0.9 * std::sqrt(0.25 / static_cast<double>(n));
        double q = 0.0;
        TreeSnapshot tree;
        run(WaitGuessModel<false>{}, 0, q, tree);
        EXPECT_NEAR(q, 0.9, 1e-9) << "one particle per node: the guess is planned and valued on it";
        for (std::size_t i = 1; i < tree.beliefs.size(); ++i)
        {
            if (tree.beliefs[i].depth == 1)
            {
                EXPECT_EQ(tree.beliefs[i].particles, 1u);
            }
        }
        run(WaitGuessModel<false>{}, 30, q, tree);
        // planned from one of the node's 31 particles, valued on an independent draw from them: right w.p.
        // E[p^2 + (1 - p)^2] with 31 p ~ Binomial(31, 1/2) arrivals and fills, i.e. 16/31
        EXPECT_NEAR(q, 0.9 * 16.0 / 31.0, 4.0 * se) << "the node holds both sides: half the guesses miss";
        for (std::size_t i = 1; i < tree.beliefs.size(); ++i)
        {
            if (tree.beliefs[i].depth == 1)
            {
                EXPECT_EQ(tree.beliefs[i].particles, 31u) << "a wait never ends and never tells: all 30 kept";
            }
        }
        run(WaitGuessModel<true>{}, 30, q, tree);
        EXPECT_NEAR(q, 0.9, 1e-9) << "the fill keeps only the particles of the observed side";
        std::uint32_t kept = 0, nodes = 0;
        for (std::size_t i = 1; i < tree.beliefs.size(); ++i)
            if (tree.beliefs[i].depth == 1)
            {
                kept += tree.beliefs[i].particles - 1;
                ++nodes;
            }
        ASSERT_EQ(nodes, n);
        EXPECT_NEAR(static_cast<double>(kept) / (30.0 * n), 0.5, 0.02) << "about half the drawn particles match";
        // Algorithm 2's first evaluation (independent_eval 0) values a new macro on the particle it was planned
        // from, filled node or not: the fill changes what later visits and the reference policy draw, not that
        s.independentEvaluation = false;
        run(WaitGuessModel<false>{}, 30, q, tree);
        EXPECT_NEAR(q, 0.9, 1e-9);
        s.independentEvaluation = true;
        // with D = 0 the depth-1 nodes are leaves (a rollout from one particle): none is filled
        s.maxDepth = 0;
        run(WaitGuessModel<false>{}, 30, q, tree);
    }

    TEST(TreeSnapshot, CountsAgreeWithTheSearch)
    {
        RopRas3Settings s;
        s.maxDepth = 4;
        s.rolloutSteps = 0;
        s.betaO = 1.0;
        s.alphaO = 0.5;
        const std::vector<double> particles(20, 0.0);
        auto solver = solverOf<NoisyModel>(s);
        Rng rng(3);
        const auto result =
            solver->plan(BeliefView<double>{particles.data(), particles.size()}, Budget::ofSimulations(300), rng);
        TreeSnapshot tree;
        ASSERT_TRUE(solver->treeSnapshot(tree));
        EXPECT_EQ(tree.beliefs.size(), result.statistics.beliefNodes);
        EXPECT_EQ(tree.actions.size(), result.statistics.actionNodes);
        EXPECT_EQ(tree.simulations, 300u);
        EXPECT_EQ(tree.beliefs[0].visits, 300u);
        EXPECT_EQ(tree.beliefs[0].particles, 20u);
        for (std::size_t i = 0; i < tree.beliefs.size(); ++i)
        {
            const auto &b = tree.beliefs[i];
            std::uint32_t visits = 0;
            double pi = 0.0;
            for (const auto a : b.children)
            {
                EXPECT_EQ(tree.actions[a].parent, i);
                visits += tree.actions[a].visits;
                pi += tree.actions[a].piStar;
            }
            EXPECT_EQ(visits, b.visits) << "N(b) = sum of N(ba), belief " << i;
            if (!b.children.empty())
            {
                EXPECT_NEAR(pi, 1.0, 1e-9) << "pi* sums to 1 at belief " << i;
            }
            if (i > 0)
            {
                const auto &parentAction = tree.actions[b.parent];
                const auto &parent = tree.beliefs[parentAction.parent];
                EXPECT_EQ(b.depth, parent.depth + 1);
                EXPECT_EQ(b.steps, parent.steps + parentAction.length);
                // one particle per simulation that reached the node; a node within depth D backs every one up,
                // a leaf below D none
                EXPECT_GE(b.particles, 1u);
                EXPECT_EQ(b.visits, b.depth <= s.maxDepth ? b.particles : 0u) << "belief " << i;
            }
        }
        const auto levels = treeLevelStatistics(tree);
        ASSERT_EQ(levels.size(), s.maxDepth + 2u) << "levels 0..D expand, level D+1 holds the leaves";
        std::size_t total = 0;
        for (const auto &l : levels)
            total += l.beliefs;
        EXPECT_EQ(total, tree.beliefs.size());
        EXPECT_EQ(levels[0].beliefs, 1u);
        EXPECT_EQ(levels.back().visitedOnce, levels.back().beliefs) << "leaves are never backed up";
    }
}  // namespace ropras::pomdp::test
