// POMCP on Tiger (gamma 0.95, listen -1 at 0.85, +10/-100): the closed-loop discounted return approaches the
// optimal value 19.37, and the root estimate improves as the number of simulations grows.
#include <gtest/gtest.h>

#include <cmath>
#include <memory>
#include <vector>

#include "ropras/pomdp/Episode.h"
#include "ropras/pomdp/PomcpSolver.h"
#include "ropras/pomdp/Tiger.h"

using namespace ropras::pomdp;

namespace
{
    constexpr double TIGER_OPTIMAL_VALUE = 19.37;
}

TEST(PomcpTigerTest, ClosedLoopReturnWithinBandOfOptimalValue)
{
    auto model = std::make_shared<const TigerModel>();
    PomcpSettings settings;
    settings.explorationConstant = 30.0;
    settings.maxDepth = 50;
    settings.rolloutSteps = 0;
    PomcpSolver<TigerModel> solver(model, nullptr, settings, "pomcp");
    const int episodes = 60;
    EpisodeSettings episode;
    episode.maxSteps = 60;  // gamma^60 = 0.046: the truncated tail is worth about 0.05 * 19.37 < 1
    episode.budget = Budget::ofSimulations(1000);
    double sum = 0.0, sumSquares = 0.0;
    for (int e = 0; e < episodes; ++e)
    {
        Rng rng(9000 + e);
        ParticleFilterSettings filterSettings;
        filterSettings.numParticles = 200;
        ParticleFilter<TigerModel> filter(model, filterSettings);
        filter.initialize(rng);
        const auto result = runEpisode(*model, solver, filter, episode, rng);
        EXPECT_EQ(result.steps, episode.maxSteps);
        EXPECT_EQ(result.invalidPlans, 0u);
        sum += result.discountedReturn;
        sumSquares += result.discountedReturn * result.discountedReturn;
    }
    const double mean = sum / episodes;
    const double sd = std::sqrt(std::max(0.0, sumSquares / episodes - mean * mean));
    const double se = sd / std::sqrt(static_cast<double>(episodes));
    // Band: 3 standard errors plus 1 for the truncated tail. For scale: always listening gives about -19,
    // opening at random about -900, so the band only admits near-optimal behaviour.
    EXPECT_NEAR(mean, TIGER_OPTIMAL_VALUE, 3.0 * se + 1.0) << "se " << se;
    EXPECT_LT(se, 4.0);
}

TEST(PomcpTigerTest, RootEstimateImprovesWithSimulations)
{
    auto model = std::make_shared<const TigerModel>();
    PomcpSettings settings;
    settings.explorationConstant = 10.0;
    settings.rolloutSteps = 0;
    std::vector<TigerModel::State> belief(1000);
    for (std::size_t i = 0; i < belief.size(); ++i)
    {
        belief[i] = static_cast<TigerModel::State>(i % 2);
    }
    std::vector<double> errors;
    for (const std::size_t sims : {std::size_t{1000}, std::size_t{10000}, std::size_t{100000}})
    {
        double sumAbs = 0.0;
        for (int seed = 0; seed < 3; ++seed)
        {
            PomcpSolver<TigerModel> solver(model, nullptr, settings, "pomcp");
            Rng rng(seed);
            const auto result = solver.plan(BeliefView<TigerModel::State>{belief.data(), belief.size()},
                                            Budget::ofSimulations(sims), rng);
            ASSERT_TRUE(result.valid);
            EXPECT_EQ(result.action.size(), 1u);
            EXPECT_EQ(result.action.front(), TigerModel::LISTEN) << "sims " << sims;
            sumAbs += std::abs(result.statistics.rootValue - TIGER_OPTIMAL_VALUE);
        }
        errors.push_back(sumAbs / 3.0);
    }
    EXPECT_GT(errors[0], errors[1]);
    EXPECT_GT(errors[1], errors[2]);
}
