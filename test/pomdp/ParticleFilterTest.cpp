#include "ropras/pomdp/ParticleFilter.h"

#include <gtest/gtest.h>

#include <cmath>
#include <memory>
#include <string>
#include <vector>

#include "TestModels.h"

using namespace ropras::pomdp;
using test::LinearGaussianModel;

namespace
{
    void weightedMoments(const ParticleFilter<LinearGaussianModel> &f, double &mean, double &variance)
    {
        mean = 0.0;
        double total = 0.0;
        for (std::size_t i = 0; i < f.particles().size(); ++i)
        {
            mean += f.weights()[i] * f.particles()[i];
            total += f.weights()[i];
        }
        mean /= total;
        variance = 0.0;
        for (std::size_t i = 0; i < f.particles().size(); ++i)
        {
            const double d = f.particles()[i] - mean;
            variance += f.weights()[i] * d * d;
        }
        variance /= total;
    }
}  // namespace

// Posterior mean and variance of the particle filter on a 1-D linear Gaussian model match the Kalman filter.
TEST(ParticleFilterTest, MatchesKalmanFilterOnLinearGaussianModel)
{
    for (const double threshold : {1.0, 0.5})
    {
        auto model = std::make_shared<LinearGaussianModel>();
        ParticleFilterSettings settings;
        settings.numParticles = 40000;
        settings.resampleThreshold = threshold;
        ParticleFilter<LinearGaussianModel> filter(model, settings);
        Rng rng(42);
        filter.initialize(rng);
        double m = model->m0, p = model->p0;
        Rng world(7);
        double x = model->sampleInitialState(world);
        const double controls[] = {0.5, -1.0, 0.0, 2.0, 0.3, -0.7};
        for (const double u : controls)
        {
            const auto step = model->step(x, u, world);
            x = step.next;
            ASSERT_TRUE(filter.update(u, step.observation, rng));
            // Kalman filter.
            m += u;
            p += model->q;
            const double k = p / (p + model->r);
            m += k * (step.observation - m);
            p *= 1.0 - k;
            double mean, variance;
            weightedMoments(filter, mean, variance);
            EXPECT_NEAR(mean, m, 0.05 * std::sqrt(p)) << "threshold " << threshold;
            EXPECT_NEAR(variance, p, 0.08 * p) << "threshold " << threshold;
        }
        EXPECT_EQ(filter.depletions(), 0u);
    }
}

TEST(ParticleFilterTest, SystematicResamplingKeepsProportions)
{
    auto model = std::make_shared<LinearGaussianModel>();
    ParticleFilterSettings settings;
    settings.numParticles = 4;
    ParticleFilter<LinearGaussianModel> filter(model, settings);
    filter.setParticles({0.0, 1.0, 2.0, 3.0});
    Rng rng(1);
    // Weighted sampling to 1000 particles: counts are within 1 of n * w for systematic resampling.
    const auto drawn = filter.sampleUnweighted(1000, rng);
    int counts[4] = {0, 0, 0, 0};
    for (double v : drawn)
    {
        ++counts[static_cast<int>(v)];
    }
    for (int c : counts)
    {
        EXPECT_NEAR(c, 250, 1);
    }
}

TEST(ParticleFilterTest, DepletionIsRecoveredAndLogged)
{
    auto model = std::make_shared<LinearGaussianModel>();
    model->bounded = true;
    ParticleFilterSettings settings;
    settings.numParticles = 500;
    std::vector<std::string> log;
    ParticleFilter<LinearGaussianModel> filter(model, settings, nullptr,
                                               [&log](const std::string &message) { log.push_back(message); });
    Rng rng(5);
    filter.initialize(rng);
    EXPECT_FALSE(filter.update(0.0, 1000.0, rng));  // impossible observation
    EXPECT_EQ(filter.depletions(), 1u);
    ASSERT_EQ(log.size(), 1u);
    EXPECT_NE(log[0].find("ignore-observation"), std::string::npos);
    EXPECT_FALSE(filter.update(0.0, std::nan(""), rng));  // NaN likelihoods count as zero
    EXPECT_EQ(filter.depletions(), 2u);
    double total = 0.0;
    for (std::size_t i = 0; i < filter.particles().size(); ++i)
    {
        EXPECT_TRUE(std::isfinite(filter.particles()[i]));
        total += filter.weights()[i];
    }
    EXPECT_NEAR(total, 1.0, 1e-9);
    // A normal observation afterwards works again.
    EXPECT_TRUE(filter.update(0.0, filter.particles()[0], rng));
}

TEST(ParticleFilterTest, PriorRecoveryReweightsFreshParticles)
{
    auto model = std::make_shared<LinearGaussianModel>();
    model->bounded = true;
    model->m0 = 50.0;
    model->p0 = 1.0;
    ParticleFilterSettings settings;
    settings.numParticles = 2000;
    ParticleFilter<LinearGaussianModel> filter(model, settings, std::make_unique<PriorRecovery<LinearGaussianModel>>());
    Rng rng(11);
    filter.setParticles(std::vector<double>(2000, -50.0));  // belief far from the truth
    EXPECT_FALSE(filter.update(0.0, 50.0, rng));
    double mean = 0.0;
    for (double v : filter.particles())
    {
        mean += v;
    }
    mean /= 2000.0;
    EXPECT_NEAR(mean, 50.0, 1.0);
}

TEST(ParticleFilterTest, ReinvigorationAddsModelNoise)
{
    auto model = std::make_shared<LinearGaussianModel>();
    model->reinvigorationStd = 0.0;
    ParticleFilterSettings settings;
    settings.numParticles = 20000;
    settings.reinvigorate = true;
    Rng rngA(3), rngB(3);
    ParticleFilter<LinearGaussianModel> plain(model, settings);
    plain.initialize(rngA);
    plain.update(0.0, 1.0, rngA);
    auto noisy = std::make_shared<LinearGaussianModel>();
    noisy->reinvigorationStd = 1.0;
    ParticleFilter<LinearGaussianModel> jittered(noisy, settings);
    jittered.initialize(rngB);
    jittered.update(0.0, 1.0, rngB);
    auto variance = [](const std::vector<double> &v)
    {
        double m = 0.0, s = 0.0;
        for (double x : v)
        {
            m += x;
        }
        m /= static_cast<double>(v.size());
        for (double x : v)
        {
            s += (x - m) * (x - m);
        }
        return s / static_cast<double>(v.size());
    };
    // Reinvigoration with N(0, 1) noise adds about 1 to the posterior variance.
    EXPECT_NEAR(variance(jittered.particles()) - variance(plain.particles()), 1.0, 0.1);
}

TEST(ParticleFilterTest, BadSettingsThrow)
{
    auto model = std::make_shared<LinearGaussianModel>();
    ParticleFilterSettings settings;
    settings.numParticles = 0;
    EXPECT_THROW((ParticleFilter<LinearGaussianModel>(model, settings)), ropras::Error);
    settings.numParticles = 10;
    ParticleFilter<LinearGaussianModel> filter(model, settings);
    EXPECT_THROW(filter.setParticles({}), ropras::Error);
    ParameterMap p;
    p.set("resample_threshold", 2.0);
    EXPECT_THROW(ParticleFilterSettings::fromParameters(p), ropras::Error);
}

TEST(ParticleFilterTest, ContinuationRemovesParticlesThatWouldHaveEnded)
{
    // CounterModel: s' = s + 1, terminal once s' >= terminalAt = 3; the observation says nothing (probability 1)
    const auto model = std::make_shared<const ropras::pomdp::test::CounterModel>(ropras::pomdp::test::CounterModel{3});
    for (const bool continuation : {false, true})
    {
        ropras::pomdp::ParticleFilterSettings s;
        s.numParticles = 300;
        s.continuation = continuation;
        ropras::pomdp::ParticleFilter<ropras::pomdp::test::CounterModel> filter(model, s);
        std::vector<int> start;
        for (int i = 0; i < 300; ++i)
            start.push_back(i % 3);  // 0, 1, 2 in equal parts
        filter.setParticles(start);
        ropras::pomdp::Rng rng(5);
        EXPECT_TRUE(filter.update(1, 1, rng));
        std::size_t ended = 0;
        for (const int p : filter.particles())
            ended += p >= 3 ? 1 : 0;
        if (continuation)
        {
            EXPECT_EQ(ended, 0u) << "the episode went on: no particle may be in a terminal state";
            EXPECT_EQ(filter.particles().size(), 300u);
        }
        else
        {
            EXPECT_GT(ended, 60u) << "without the condition a third of the particles are terminal (100 expected)";
            EXPECT_LT(ended, 140u);
        }
    }
    ropras::pomdp::ParameterMap p;
    p.set("continuation", 2.0);
    EXPECT_THROW(ropras::pomdp::ParticleFilterSettings::fromParameters(p), ropras::Error);
}
