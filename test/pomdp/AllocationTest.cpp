// The search loops do no heap allocation once a solver's pools are warmed up: the global operator new of
// this test executable counts allocations, and a planning call after a larger warm-up call may allocate only
// its result (the returned macro-action).
#include <gtest/gtest.h>

#include <atomic>
#include <cstdlib>
#include <new>
#include <vector>

#include "ropras/pomdp/ModelRegistry.h"
#include "ropras/pomdp/Tiger.h"

namespace
{
    std::atomic<std::size_t> allocations{0};
}

void *operator new(std::size_t size)
{
    allocations.fetch_add(1, std::memory_order_relaxed);
    if (void *p = std::malloc(size == 0 ? 1 : size))
    {
        return p;
    }
    throw std::bad_alloc();
}

void operator delete(void *p) noexcept
{
    std::free(p);
}

void operator delete(void *p, std::size_t) noexcept
{
    std::free(p);
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
