// heuristic_mdp's leaf value (NavigationSlipValue.cpp) against three other computations: the shortest path without
// slip, Bellman's equation through the model's own moves, and the returns of its greedy policy in the model.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <iostream>

#include "NavigationTestUtil.h"

namespace ropras::scenarios::test
{
    namespace
    {
        /// one step of the fully observed problem from \a s with action \a a, every outcome enumerated through the
        /// model's own moves (not the policy iteration's tables): sum_b P(b | a) (r + gamma V(next))
        double slipBackup(const NavigationModel &model, const NavState &s, int a)
        {
            const auto &c = model.config();
            const int m = 2 * c.dims;
            double q = 0.0;
            for (int b = 0; b < m; ++b)
            {
                const double pb = b == a ? 1.0 - c.slip : c.slip / (m - 1);
                NavState next = model.moved(s, static_cast<NavigationModel::Action>(b));
                if (model.blocked(next.p))
                    next = s;
                double r = c.stepReward;
                if (model.inDanger(next.p))
                    r += c.dangerReward;
                else if (model.reachedGoal(next))
                    r += c.goalReward;
                else
                    r += model.discount() * model.heuristicValue(next);
                q += pb * r;
            }
            return q;
        }
    }  // namespace

    TEST(NavigationModel, SlipValueIsTheFullyObservedOptimum)
    {
        // Without the slip the fully observed optimum is the shortest path's value, with the goal reward arriving
        // with the d-th step (discounted d - 1 times; the distance field's value discounts it d times).
        const auto still = navScenario("maze2d", {{"slip", 0.0}, {"heuristic_mdp", true}});
        const auto &exact = *asNav(*still).parts().model;
        const auto walked = [](const NavigationModel &m, const NavState &s)
        {
            const double g = m.discount();
            const auto d = static_cast<double>(m.goalDistance(s.p));
            return 800.0 * std::pow(g, d - 1.0) - 0.1 * (1.0 - std::pow(g, d)) / (1.0 - g);
        };
        for (const auto &start : exact.config().starts)
        {
            const NavState s = at(start[0], start[1]);
            ASSERT_GT(exact.goalDistance(s.p), 100);
            EXPECT_NEAR(exact.heuristicValue(s), walked(exact, s), 1e-3);
            EXPECT_NEAR(exact.heuristicValue(s) * exact.discount(),
                        fieldValue(exact.discount(), static_cast<std::size_t>(exact.goalDistance(s.p))), 0.11);
        }

        const auto scenario = navScenario("maze2d", {{"heuristic_mdp", true}});
        const auto plain = navScenario("maze2d");
        const auto &model = *asNav(*scenario).parts().model;
        const auto &field = *asNav(*plain).parts().model;
        std::cout << "maze2d slip value: " << model.slipValueIterations() << " policy iterations\n";
        EXPECT_GT(model.slipValueIterations(), 1u);
        EXPECT_LT(model.slipValueIterations(), 1000u);
        // At random free lattice points: Bellman's equation holds (to the sweeps' tolerance) when every outcome is
        // enumerated from the model's moves, and the value is below the shortest path's (slips only cost).
        pomdp::Rng rng(5);
        const auto &c = model.config();
        int checked = 0, lower = 0;
        for (int i = 0; i < 20000 && checked < 400; ++i)
        {
            const NavState s = at(c.bounds.lo[0] + 0.5 * static_cast<double>(rng.uniformIndex(101)),
                                  c.bounds.lo[1] + 0.5 * static_cast<double>(rng.uniformIndex(101)));
            if (!model.continuesAt(s.p) || model.goalDistance(s.p) < 0)
                continue;
            ++checked;
            double best = -1e300;
            for (int a = 0; a < 4; ++a)
                best = std::max(best, slipBackup(model, s, a));
            EXPECT_NEAR(model.heuristicValue(s), best, 1e-2) << s.p[0] << ", " << s.p[1];
            EXPECT_LE(model.heuristicValue(s), walked(field, s) + 1e-9);
            lower += model.heuristicValue(s) < walked(field, s) - 1.0;
        }
        EXPECT_EQ(checked, 400);
        EXPECT_GT(lower, 300);
        // Off the lattice and terminal: the nearest lattice point's value; 0 in a wall, a danger zone, the goal.
        EXPECT_EQ(model.heuristicValue(model.moved(at(-20, 15), 0)), model.heuristicValue(at(-19.5, 15.04)));
        EXPECT_EQ(model.heuristicValue(at(-11.5, 10)), 0.0);
        EXPECT_EQ(model.heuristicValue(at(-20, 24)), 0.0);
        EXPECT_EQ(model.heuristicValue(at(21.5, 0)), 0.0);
    }

    TEST(NavigationModel, SlipValueIsWhatItsGreedyPolicyEarnsInTheModel)
    {
        // Acting greedily on the value (one-step lookahead) from a start earns it on average: a Monte-Carlo check
        // with the model's own sampled steps, 1 500 episodes, the mean within 3 standard errors.
        const auto scenario = navScenario("maze2d", {{"heuristic_mdp", true}});
        const auto &model = *asNav(*scenario).parts().model;
        const NavState start = at(-20, -15);
        pomdp::Rng rng(17);
        const int episodes = 1500;
        double sum = 0.0, sum2 = 0.0;
        int reached = 0;
        for (int e = 0; e < episodes; ++e)
        {
            NavState s = start;
            double ret = 0.0, discount = 1.0;
            for (std::size_t t = 0; t < model.config().horizon; ++t)
            {
                int best = 0;
                for (int a = 1; a < 4; ++a)
                    if (slipBackup(model, s, a) > slipBackup(model, s, best))
                        best = a;
                const auto step = model.step(s, static_cast<NavigationModel::Action>(best), rng);
                ret += discount * step.reward;
                discount *= model.discount();
                s = step.next;
                if (step.terminal)
                {
                    reached += model.reachedGoal(s);
                    break;
                }
            }
            sum += ret;
            sum2 += ret * ret;
        }
        const double mean = sum / episodes;
        const double se = std::sqrt((sum2 / episodes - mean * mean) / episodes);
        const double value = model.heuristicValue(start);
        std::cout << "maze2d from (-20, -15): slip value " << value << ", greedy return " << mean << " (" << se
                  << "), goal in " << reached << " of " << episodes << "\n";
        EXPECT_NEAR(mean, value, 3.0 * se + 1.0);
        EXPECT_GT(reached, episodes * 8 / 10);
    }

}  // namespace ropras::scenarios::test
