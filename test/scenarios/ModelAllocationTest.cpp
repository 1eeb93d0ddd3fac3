// The scenario models are hot paths (every simulated step of every search): step(), observationProbability(),
// observationKey() and heuristicValue() must not allocate. The global operator new of this test executable
// counts allocations.
#include <gtest/gtest.h>

#include <cmath>

#include "AllocationCounter.h"
#include "NavigationTestUtil.h"
#include "ropras/pomdp/Model.h"
#include "ropras/scenarios/multi-drone/MultiDroneScenario.h"

namespace
{
    const auto &allocations = ropras::test::allocationCount;
}

namespace ropras::scenarios::test
{
    namespace
    {
        /** \brief Allocations during \a steps random-walk steps of \a model (with the observation functions and
            the rollout heuristic). */
        template <class M>
        std::size_t allocationsPerWalk(const M &model, std::size_t steps)
        {
            pomdp::Rng rng(7);
            auto s = model.sampleInitialState(rng);
            double sink = 0.0;
            const std::size_t before = allocations.load();
            for (std::size_t i = 0; i < steps; ++i)
            {
                const auto a = model.action(static_cast<std::size_t>(rng.uniformIndex(model.numActions())));
                const auto r = model.step(s, a, rng);
                sink += r.reward + model.observationProbability(r.observation, r.next, a) +
                        static_cast<double>(pomdp::observationKeyOf(model, r.observation) & 1u) +
                        pomdp::heuristicValueOf(model, r.next);
                s = r.terminal ? model.sampleInitialState(rng) : r.next;
            }
            const std::size_t during = allocations.load() - before;
            EXPECT_TRUE(std::isfinite(sink));
            return during;
        }
    }  // namespace

    TEST(ModelAllocation, ScenarioModelsDoNotAllocatePerStep)
    {
        const std::size_t before = allocations.load();
        for (const char *name : {"light-dark", "maze2d", "random3d-4"})
        {
            const auto scenario = navScenario(name);
            EXPECT_EQ(allocationsPerWalk(*asNav(*scenario).parts().model, 20000), 0u) << name;
        }
        const auto drones = makeMultiDroneScenario();
        EXPECT_EQ(allocationsPerWalk(*drones->parts().model, 20000), 0u) << "multi-drone";
        EXPECT_GT(allocations.load(), before) << "the allocation counter is not live (building scenarios allocates)";
    }
}  // namespace ropras::scenarios::test
