// Theorem 1 / Theorem 2 checks on a small finite POMDP (Tiger): the exact reference-based value computed by
// exhaustive recursion over the belief tree is approached by RBSS as C_A, C_S grow and by ROP-RAS3's root
// estimate as the number of simulations grows.
#include <gtest/gtest.h>

#include <cmath>
#include <memory>
#include <vector>

#include "ropras/pomdp/RandomMacroPolicy.h"
#include "ropras/pomdp/RbssSolver.h"
#include "ropras/pomdp/RopRas3Solver.h"
#include "ropras/pomdp/Tiger.h"

using namespace ropras::pomdp;

namespace
{
    // Exact V_h(p) of the reference-based Tiger POMDP with pibar uniform over the 3 primitive actions;
    // p = P(tiger left), h = number of action levels left.
    double exactValue(const TigerModel &m, double p, int h, double eta)
    {
        if (h == 0)
        {
            return 0.0;
        }
        double q[3];
        // Listen.
        {
            const double pLeft = m.listenAccuracy * p + (1.0 - m.listenAccuracy) * (1.0 - p);
            const double postLeft = m.listenAccuracy * p / pLeft;
            const double postRight = (1.0 - m.listenAccuracy) * p / (1.0 - pLeft);
            q[0] = m.listenReward + m.gamma * (pLeft * exactValue(m, postLeft, h - 1, eta) +
                                               (1.0 - pLeft) * exactValue(m, postRight, h - 1, eta));
        }
        const double reset = m.gamma * exactValue(m, 0.5, h - 1, eta);
        q[1] = p * m.wrongReward + (1.0 - p) * m.correctReward + reset;  // open left
        q[2] = (1.0 - p) * m.wrongReward + p * m.correctReward + reset;  // open right
        double best = std::max(q[0], std::max(q[1], q[2]));
        double sum = 0.0;
        for (double qi : q)
        {
            sum += std::exp(eta * (qi - best)) / 3.0;
        }
        return best + std::log(sum) / eta;
    }

    std::vector<TigerModel::State> uniformBelief(std::size_t n)
    {
        std::vector<TigerModel::State> b(n);
        for (std::size_t i = 0; i < n; ++i)
        {
            b[i] = static_cast<TigerModel::State>(i % 2);
        }
        return b;
    }
}  // namespace

TEST(ReferenceValueTest, ExactRecursionSanity)
{
    const TigerModel m;
    // One level: (1/eta) log mean exp(eta R(b, a)) at p = 0.5: R = -1, -45, -45.
    const double eta = 0.2;
    const double expected = std::log((std::exp(-0.2) + 2.0 * std::exp(-9.0)) / 3.0) / eta;
    EXPECT_NEAR(exactValue(m, 0.5, 1, eta), expected, 1e-12);
    // Large eta approaches the optimal finite-horizon value (listen once: -1).
    EXPECT_NEAR(exactValue(m, 0.5, 1, 50.0), -1.0 - std::log(3.0) / 50.0, 1e-9);
}

TEST(ReferenceValueTest, RbssApproachesExactValueAsSamplesGrow)
{
    auto model = std::make_shared<const TigerModel>();
    const double eta = 0.2;
    const int depth = 2;
    const double exact = exactValue(*model, 0.5, depth, eta);
    const auto belief = uniformBelief(1000);
    std::vector<double> errors;
    for (const unsigned n : {2u, 6u, 16u})
    {
        double sumAbs = 0.0;
        const int seeds = 12;
        for (int seed = 0; seed < seeds; ++seed)
        {
            RbssSettings settings;
            settings.eta = eta;
            settings.actions = n;
            settings.particles = n;
            settings.depth = depth;
            RbssSolver<TigerModel> rbss(model, std::make_unique<RandomMacroPolicy<TigerModel>>(model, 1, 1), settings);
            Rng rng(1000 + seed);
            std::vector<TigerModel::State> particles(n);
            for (auto &p : particles)
            {
                p = belief[rng.uniformIndex(belief.size())];
            }
            const double v = rbss.estimateValue(particles, std::vector<double>(n, 1.0), rng);
            ASSERT_TRUE(std::isfinite(v));
            sumAbs += std::abs(v - exact);
        }
        errors.push_back(sumAbs / seeds);
    }
    EXPECT_GT(errors[0], errors[2]);
    EXPECT_GT(errors[1], errors[2]);
    // Soft value from C_A = 16 actions: SD about (1/eta) sqrt((1 - p) / (p C_A)) = 1.8 per seed, p = 1/3.
    EXPECT_LT(errors[2], 2.5) << "exact " << exact;
}

TEST(ReferenceValueTest, RopRas3RootEstimateApproachesExactValue)
{
    auto model = std::make_shared<const TigerModel>();
    const double eta = 0.2;
    // Two action levels, eta = 0.2. The running soft-value estimator of Algorithm 2 (value_backup 0) is biased
    // upwards while few visits have been made (early Q estimates of "open" can be +10 instead of about -45 and
    // enter exp(eta Q)); the bias decays as the visits grow. The backup over the current estimates
    // (value_backup 1) forgets them, but with few children it is biased downwards instead: a node whose sampled
    // children miss "listen" (whose exp(eta Q) outweighs the openings' by e^9) is valued as if it had none.
    // Measured mean |error| over 6 seeds at 1e3, 1e4 and 2e5 simulations: running 4.7, 3.6 and 1.6 (signed
    // errors mostly positive); current 21.3, 5.5 and 1.7 (three seeds at 1e3 near -40, on the same trees).
    const int levels = 2;
    const double exact = exactValue(*model, 0.5, levels, eta);
    const auto belief = uniformBelief(1000);
    for (const auto backup : {RopRas3Settings::ValueBackup::RUNNING, RopRas3Settings::ValueBackup::CURRENT,
                              RopRas3Settings::ValueBackup::FRESH})
    {
        std::vector<double> errors;
        for (const std::size_t sims : {std::size_t{1000}, std::size_t{10000}, std::size_t{200000}})
        {
            double sumAbs = 0.0;
            const int seeds = 6;
            for (int seed = 0; seed < seeds; ++seed)
            {
                RopRas3Settings settings;
                settings.eta = eta;
                settings.maxDepth = levels - 1;  // depths 0..D expand: D + 1 action levels
                settings.rolloutSteps = 0;
                // Children must keep growing for the empirical child distribution to approach pibar.
                settings.betaA = 1.0;
                settings.alphaA = 0.25;
                settings.valueBackup = backup;
                RopRas3Solver<TigerModel> solver(model, std::make_unique<RandomMacroPolicy<TigerModel>>(model, 1, 1),
                                                 settings);
                Rng rng(500 + seed);
                const auto result = solver.plan(BeliefView<TigerModel::State>{belief.data(), belief.size()},
                                                Budget::ofSimulations(sims), rng);
                ASSERT_TRUE(result.valid);
                EXPECT_EQ(result.statistics.simulations, sims);
                EXPECT_EQ(result.statistics.maxDepth, static_cast<std::size_t>(levels - 1));
                sumAbs += std::abs(result.statistics.rootValue - exact);
            }
            errors.push_back(sumAbs / seeds);
        }
        const int b = static_cast<int>(backup);
        EXPECT_GT(errors[0], errors[2]) << "value_backup " << b << ", exact " << exact;
        EXPECT_GT(errors[1], errors[2]) << "value_backup " << b << ", exact " << exact;
        EXPECT_LT(errors[2], 2.5) << "value_backup " << b << ", exact " << exact;
    }
}
