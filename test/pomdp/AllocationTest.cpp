// The search loops do no heap allocation once a solver's pools are warmed up: the global operator new of
// this test executable counts allocations, and a planning call after a larger warm-up call may allocate only
// its result (the returned macro-action).
#include <gtest/gtest.h>

#include <vector>

#include "AllocationCounter.h"
#include "ropras/pomdp/ModelRegistry.h"
#include "ropras/pomdp/Tiger.h"

namespace
{
    const auto &allocations = ropras::test::allocationCount;
}

using namespace ropras::pomdp;

TEST(AllocationTest, WarmSolversDoNotAllocatePerSimulation)
{
    const auto components = tigerComponents();
    std::vector<TigerModel::State> belief(500);
    for (std::size_t i = 0; i < belief.size(); ++i)
    {
        belief[i] = static_cast<TigerModel::State>(i % 2);
    }
    for (const char *name : {"ropras3", "refbasic", "pomcp", "rpomcp"})
    {
        auto solver = makeSolver(name, components, withDefaults(components, ParameterMap{}));
        Rng rng(1);
        const BeliefView<TigerModel::State> view{belief.data(), belief.size()};
        const std::size_t beforeWarmUp = allocations.load();
        solver->plan(view, Budget::ofSimulations(20000), rng);  // warm-up: pools grow here
        EXPECT_GT(allocations.load() - beforeWarmUp, 0u) << "the allocation counter is not live";
        const std::size_t before = allocations.load();
        const auto result = solver->plan(view, Budget::ofSimulations(5000), rng);
        const std::size_t during = allocations.load() - before;
        ASSERT_TRUE(result.valid) << name;
        EXPECT_EQ(result.statistics.simulations, 5000u) << name;
        // Only the returned macro-action may allocate (5000 simulations of depth up to 50 run in between).
        EXPECT_LE(during, 1u) << name;
    }
}
