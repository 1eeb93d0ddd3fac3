// ROP-RAS3's heuristic_leaf: the rollout below depth D ends with the model's heuristic value (default) or with 0,
// checked against the closed form on a deterministic chain; and the parameter's values.
#include <gtest/gtest.h>

#include <cmath>
#include <memory>
#include <string>
#include <vector>

#include "ropras/core/Error.h"
#include "ropras/pomdp/ParameterMap.h"
#include "ropras/pomdp/RandomMacroPolicy.h"
#include "ropras/pomdp/RopRas3Solver.h"

using namespace ropras::pomdp;

namespace
{
    /// one action, reward -1 per step, never terminal; every state is worth 100 by the heuristic
    struct HopefulChainModel
    {
        using State = int;
        using Action = int;
        using Observation = int;
        StepResult<State, Observation> step(State s, Action, Rng &) const noexcept { return {s + 1, 0, -1.0, false}; }
        double observationProbability(Observation, State, Action) const noexcept { return 1.0; }
        State sampleInitialState(Rng &) const noexcept { return 0; }
        double discount() const noexcept { return 0.9; }
        std::size_t numActions() const noexcept { return 1; }
        Action action(std::size_t) const noexcept { return 0; }
        double heuristicValue(State) const noexcept { return 100.0; }
    };

    /// Q of the root's children after 50 simulations with one macro level (D = 0) and rollouts of \a steps
    std::vector<double> rootQ(bool heuristicLeaf, unsigned steps)
    {
        auto model = std::make_shared<HopefulChainModel>();
        const ParameterMap params = ParameterMap::parse({"depth=0", "rollout_steps=" + std::to_string(steps),
                                                         heuristicLeaf ? "heuristic_leaf=1" : "heuristic_leaf=0"});
        RopRas3Solver<HopefulChainModel> solver(model,
                                                std::make_unique<RandomMacroPolicy<HopefulChainModel>>(model, 2, 2),
                                                RopRas3Settings::fromParameters(params));
        const int particle = 0;
        Rng rng(3);
        const auto result = solver.plan(BeliefView<int>{&particle, 1}, Budget::ofSimulations(50), rng);
        EXPECT_TRUE(result.valid);
        std::vector<double> q;
        for (const auto &child : solver.rootChildren())
            q.push_back(child.first);
        return q;
    }
}  // namespace

TEST(HeuristicLeafTest, TheLeafValueIsTheHeuristicOrZero)
{
    // a macro of 2 steps (-1 - 0.9), then a rollout of k steps (-sum 0.9^i), then 0.9^(2 + k) * 100 or nothing
    for (const unsigned k : {0u, 3u})
    {
        double rollout = 0.0;
        for (unsigned i = 0; i < k; ++i)
            rollout -= std::pow(0.9, 2 + i);
        const double macro = -1.0 - 0.9;
        const std::vector<double> with = rootQ(true, k), without = rootQ(false, k);
        ASSERT_FALSE(with.empty());
        ASSERT_FALSE(without.empty());
        for (const double q : with)
            EXPECT_NEAR(q, macro + rollout + std::pow(0.9, 2 + k) * 100.0, 1e-9) << "rollout steps " << k;
        for (const double q : without)
            EXPECT_NEAR(q, macro + rollout, 1e-9) << "rollout steps " << k;
    }
}

TEST(HeuristicLeafTest, BadValuesNameTheParameter)
{
    for (const char *bad : {"2", "-1", "0.5", "yes", "nan"})
    {
        try
        {
            (void)RopRas3Settings::fromParameters(ParameterMap::parse({std::string("heuristic_leaf=") + bad}));
            ADD_FAILURE() << "no error for heuristic_leaf=" << bad;
        }
        catch (const ropras::Error &e)
        {
            EXPECT_NE(std::string(e.what()).find("heuristic_leaf"), std::string::npos) << e.what();
        }
    }
}
