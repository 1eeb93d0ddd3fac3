// Issue 17: budgets have a maximum, and the tree solvers stop at a memory cap and say so (a --plan-time of 1e300
// used to search until the machine ran out of memory).
#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "ExpectError.h"
#include "ropras/pomdp/ModelRegistry.h"
#include "ropras/pomdp/ParameterMap.h"

using namespace ropras::pomdp;

TEST(BudgetLimits, TimesAndSimulationsAboveTheMaximumAreRefused)
{
    ropras::test::expectErrorMentions([] { Budget::ofSeconds(1e300).validate(); },
                                      {"seconds = 1e+300", "exceeds the maximum 86400"});
    ropras::test::expectErrorMentions([] { Budget::ofSimulations(Budget::MAX_SIMULATIONS + 1).validate(); },
                                      {"simulations = 1000000001", "exceeds the maximum 1000000000"});
    EXPECT_NO_THROW(Budget::ofSeconds(Budget::MAX_SECONDS).validate());
    EXPECT_NO_THROW(Budget::ofSimulations(Budget::MAX_SIMULATIONS).validate());
}

TEST(BudgetLimits, EveryTreeSolverStopsAtItsMemoryCapAndSaysSo)
{
    for (const std::string solver : {"ropras3", "refbasic", "pomcp", "rpomcp"})
    {
        ParameterMap params;
        params.set("max_tree_mb", 1);
        auto runner = modelRegistry().create("tiger", solver, params);
        // the longest budget there is: only the cap ends the search
        const SearchStatistics stats = runner->planFromInitialBelief(Budget::ofSeconds(Budget::MAX_SECONDS), 5);
        EXPECT_EQ(stats.memoryCapped, 1u) << solver;
        EXPECT_GT(stats.simulations, 0u) << solver;
        EXPECT_GE(stats.treeBytes, std::size_t(1) << 20) << solver;
        // pools grow by doubling: the tree holds less than twice the cap (plus the last simulation's growth)
        EXPECT_LT(stats.treeBytes, std::size_t(3) << 20) << solver;
        EXPECT_LT(stats.seconds, 60.0) << solver;  // generous: about 0.1 s here; a hang would never return

        // a budget that ends first: no cap reported
        const SearchStatistics small = runner->planFromInitialBelief(Budget::ofSimulations(100), 5);
        EXPECT_EQ(small.memoryCapped, 0u) << solver;
        EXPECT_EQ(small.simulations, 100u) << solver;
    }
}

TEST(BudgetLimits, TreeCapOutOfRangeIsRefused)
{
    for (const double mb : {0.0, 0.5, 2e6})
    {
        ParameterMap params;
        params.set("max_tree_mb", mb);
        ropras::test::expectErrorMentions([&] { modelRegistry().create("tiger", "ropras3", params); },
                                          {"max_tree_mb", "must be in [1, 1048576]"});
    }
    ParameterMap bplan;
    bplan.set("max_tree_mb", 10);  // B-plan builds no tree: an unknown parameter
    ropras::test::expectErrorMentions([&] { modelRegistry().create("tiger", "bplan", bplan); }, {"max_tree_mb"});
}
