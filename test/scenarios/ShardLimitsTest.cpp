// Issue 17: a shard's episodes are computed (never searched for among 10^12 indices) and the episode count has a
// maximum (--episodes 1000000000000 looped over every index or ended in std::bad_alloc).
#include <gtest/gtest.h>

#include "ExpectError.h"
#include "ropras/scenarios/ExperimentRunner.h"
#include "scenarios/ToyScenario.h"

namespace ropras::scenarios::test
{
    using ropras::test::expectErrorMentions;

    TEST(ShardLimits, ShardOwnedEpisodesAreComputedExactly)
    {
        for (std::size_t count : {1u, 2u, 3u, 7u, 10u})
            for (std::size_t index = 0; index < count; ++index)
                for (std::size_t episodes : {1u, 2u, 6u, 7u, 8u, 29u, 30u})
                {
                    const Shard shard{index, count};
                    std::size_t counted = 0;
                    for (std::size_t e = 0; e < episodes; ++e)
                        if (shard.owns(e))
                        {
                            EXPECT_EQ(shard.ownedEpisode(counted), e);
                            ++counted;
                        }
                    EXPECT_EQ(shard.ownedCount(episodes), counted) << shard.str() << " of " << episodes;
                }
        // huge numbers without a loop over every index
        EXPECT_EQ((Shard{3, 1000000000000}).ownedCount(1000000), 1u);
        EXPECT_EQ((Shard{999999, 1000000}).ownedCount(1000000), 1u);
        EXPECT_EQ((Shard{999999, 1000000}).ownedEpisode(0), 999999u);
    }

    TEST(ShardLimits, EpisodeCountHasAMaximum)
    {
        const auto toy = makeToyScenario();
        ExperimentSettings s;
        s.run.solver = "pomcp";
        s.run.budget = pomdp::Budget::ofSimulations(5);
        s.episodes = 1000000000000;
        expectErrorMentions([&] { runExperiment(*toy, s); }, {"episodes 1000000000000", "[1, 1000000]"});
        s.shard = Shard{5, 7};
        expectErrorMentions([&] { runExperiment(*toy, s); }, {"episodes 1000000000000"});
        // the last shard of a million episodes runs its one episode only
        s.episodes = MAX_EPISODES;
        s.shard = Shard{MAX_EPISODES - 1, MAX_EPISODES};
        const auto records = runExperiment(*toy, s);
        ASSERT_EQ(records.size(), 1u);
        EXPECT_EQ(records[0]["episode"], MAX_EPISODES - 1);
        EXPECT_EQ(records[0]["memory_capped_plans"], 0);
    }
}  // namespace ropras::scenarios::test
