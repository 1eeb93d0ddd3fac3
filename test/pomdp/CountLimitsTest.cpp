// Issue 17: a count read into an `unsigned` setting is never truncated, and a particle count asks for its memory
// before it is allocated (std::bad_alloc was the only message for --param particles=100000000000 and
// --planning-particles 1000000000000).
#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>
#include <string>

#include "ExpectError.h"
#include "ropras/core/MemoryLimit.h"
#include "ropras/pomdp/ModelRegistry.h"
#include "ropras/pomdp/ParameterMap.h"

using namespace ropras::pomdp;

TEST(CountLimits, CountsAreNeverTruncatedToUnsigned)
{
    ParameterMap params;
    params.set("depth", 4294967296.0);  // 2^32: static_cast<unsigned> made it 0
    ropras::test::expectErrorMentions([&] { modelRegistry().create("tiger", "ropras3", params); },
                                      {"parameter \"depth\" = 4294967296 exceeds the maximum 4294967295"});
    ParameterMap ok;
    ok.set("depth", 4294967295.0);
    EXPECT_EQ(ok.getCount("depth", 0, ParameterMap::MAX_UNSIGNED), 4294967295u);
}

TEST(CountLimits, ParticleCountsAskForTheirMemoryFirst)
{
    const std::uint64_t saved = ropras::memoryLimit();
    ropras::setMemoryLimit(std::uint64_t(1) << 30);
    ParameterMap params;
    params.set("particles", 1e11);
    auto runner = modelRegistry().create("tiger", "ropras3", params);
    EpisodeSettings episode;
    episode.maxSteps = 1;
    episode.budget = Budget::ofSimulations(10);
    ropras::test::expectErrorMentions([&] { runner->runEpisode(episode, 1); },
                                      {"parameter particles = 100000000000", "more than the memory limit 1.0 GiB"});

    auto small = modelRegistry().create("tiger", "ropras3", ParameterMap{});
    episode.planningParticles = 1000000000000;
    ropras::test::expectErrorMentions([&] { small->runEpisode(episode, 1); },
                                      {"planning particles (--planning-particles) 1000000000000", "asks for"});
    ropras::setMemoryLimit(saved);
}

TEST(CountLimits, FillParticlesAreBounded)
{
    // each filled particle costs a macro execution per new node: a count past 100 000 is refused by name, a
    // fraction or NaN is no count
    for (const double bad : {100001.0, 2.5, -1.0, std::nan("")})
    {
        ropras::test::expectErrorMentions(
            [&]
            {
                ParameterMap params;
                params.set("fill_particles", bad);  // NaN is refused here already
                modelRegistry().create("tiger", "ropras3", params);
            },
            {"fill_particles"});
    }
    ParameterMap ok;
    ok.set("fill_particles", 100000.0);
    EXPECT_NO_THROW(modelRegistry().create("tiger", "ropras3", ok));
}
