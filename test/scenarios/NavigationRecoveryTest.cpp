// NavigationRecovery: a depleted navigation belief is rebuilt from what the robot observed.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <vector>

#include "ExpectError.h"
#include "NavigationTestUtil.h"
#include "ropras/pomdp/ParticleFilter.h"
#include "ropras/scenarios/navigation/NavigationRecovery.h"

namespace ropras::scenarios::test
{
    namespace
    {
        std::shared_ptr<const NavigationModel> maze()
        {
            static const auto scenario = navScenario("maze2d");
            return asNav(*scenario).parts().model;
        }

        bool explains(const NavigationModel &m, const NavState &s, bool seen)
        {
            return m.observable(s.p) == seen && !m.blocked(s.p) && !m.inDanger(s.p) && !m.config().goal.contains(s.p);
        }

        double standardDeviation(const std::vector<NavState> &particles, int axis)
        {
            double m = 0.0, m2 = 0.0;
            for (const auto &s : particles)
            {
                m += s.p[axis];
                m2 += s.p[axis] * s.p[axis];
            }
            m /= static_cast<double>(particles.size());
            return std::sqrt(m2 / static_cast<double>(particles.size()) - m * m);
        }

        NavObservation seenAt(double x, double y)
        {
            NavObservation o;
            o.seen = true;
            o.p[0] = x;
            o.p[1] = y;
            return o;
        }
    }  // namespace

    TEST(NavigationRecovery, AnObservedPositionRedrawsTheBeliefAroundIt)
    {
        // maze2d: the robot sees itself at (-14.5, 15) in landmark L1 [[-16, 12], [-13, 18]]; every particle
        // believes it is at the mirror start B (-20, -15), which cannot have produced that observation
        const auto model = maze();
        const auto o = seenAt(-14.5, 15.0);
        std::vector<NavState> particles(400, at(-20.0, -15.0));
        std::vector<double> weights(particles.size(), 0.0);
        ASSERT_EQ(model->observationProbability(o, particles[0], 0), 0.0);
        NavigationRecovery recovery;
        pomdp::Rng rng(3);
        recovery.recover(*model, 0, o, particles, weights, rng);
        double mx = 0.0, my = 0.0;
        for (std::size_t i = 0; i < particles.size(); ++i)
        {
            ASSERT_EQ(weights[i], 1.0) << "particle " << i << " not redrawn";
            EXPECT_TRUE(explains(*model, particles[i], true)) << particles[i].p[0] << ", " << particles[i].p[1];
            EXPECT_GT(model->observationProbability(o, particles[i], 0), 0.0);
            mx += particles[i].p[0] / 400.0;
            my += particles[i].p[1] / 400.0;
        }
        // N(o, 0.5) cut to L1 (1.5 m each side in x, 3 m in y): the mean stays at o within a few standard errors
        EXPECT_NEAR(mx, -14.5, 0.1);
        EXPECT_NEAR(my, 15.0, 0.1);
        // and its spread: sigma 0.5 cut at +-1.5 m = 3 sigma in x (s.d. 0.493), at +-3 m in y (0.500); the s.e. of a
        // standard deviation of 400 draws is about 0.018
        EXPECT_NEAR(standardDeviation(particles, 0), 0.493, 0.06);
        EXPECT_NEAR(standardDeviation(particles, 1), 0.500, 0.06);
    }

    TEST(NavigationRecovery, AnObservationAtAZoneEdgeKeepsTheDrawsInsideTheZone)
    {
        // o at L3's left edge [[-10, -2], [-6, 2]]: draws left of x = -10 do not explain a seen position
        const auto model = maze();
        const auto o = seenAt(-10.1, 0.0);
        std::vector<NavState> particles(300, at(0.0, -20.0));
        std::vector<double> weights(particles.size(), 0.0);
        NavigationRecovery recovery;
        pomdp::Rng rng(8);
        recovery.recover(*model, 0, o, particles, weights, rng);
        for (std::size_t i = 0; i < particles.size(); ++i)
        {
            ASSERT_EQ(weights[i], 1.0);
            EXPECT_GE(particles[i].p[0], -10.0);
        }
    }

    TEST(NavigationRecovery, NoneObservedMovesParticlesJustOutOfTheZones)
    {
        // every particle is inside landmark L1 (x in [-16, -13], y in [12, 18]) but the robot saw nothing
        const auto model = maze();
        pomdp::Rng rng(5);
        std::vector<NavState> particles;
        for (int i = 0; i < 300; ++i)
        {
            particles.push_back(at(rng.uniform(-15.9, -13.1), rng.uniform(12.1, 17.9)));
        }
        const auto before = particles;
        std::vector<double> weights(particles.size(), 0.0);
        NavigationRecovery recovery;
        recovery.recover(*model, 0, NavObservation{}, particles, weights, rng);
        std::vector<double> moves;
        for (std::size_t i = 0; i < particles.size(); ++i)
        {
            ASSERT_EQ(weights[i], 1.0) << "particle " << i;
            EXPECT_TRUE(explains(*model, particles[i], false)) << particles[i].p[0] << ", " << particles[i].p[1];
            moves.push_back(std::hypot(particles[i].p[0] - before[i].p[0], particles[i].p[1] - before[i].p[1]));
        }
        std::sort(moves.begin(), moves.end());
        // the farthest point of L1 from its border is 1.5 m away: moves stay of that order, not across the maze
        EXPECT_LT(moves[moves.size() / 2], 2.5);
        EXPECT_LT(moves.back(), 8.0);
    }

    TEST(NavigationRecovery, NoneObservedNeverMovesAParticleThroughAWall)
    {
        // a zone right of wall [[-12, 2.5], [-11, 25]]; particles at its left edge (x in [-10.75, -10.5]): the
        // shortest way out is 1.5 m left, through the 1 m wall (x < -12.25); the free ways are 2.5 m right or 7 m
        // up or down. Without the move check, the jitters of 1 m s.d. would take many particles through the wall.
        const auto scenario = navScenario("maze2d", {{"observation_zones", {{{-11.0, 3.0}, {-8.0, 20.0}}}}});
        const auto model = asNav(*scenario).parts().model;
        pomdp::Rng rng(17);
        std::vector<NavState> particles;
        for (int i = 0; i < 200; ++i)
        {
            particles.push_back(at(rng.uniform(-10.75, -10.5), rng.uniform(10.0, 13.0)));
        }
        std::vector<double> weights(particles.size(), 0.0);
        NavigationRecovery recovery;
        recovery.recover(*model, 0, NavObservation{}, particles, weights, rng);
        std::size_t moved = 0;
        for (std::size_t i = 0; i < particles.size(); ++i)
        {
            EXPECT_GT(particles[i].p[0], -11.0) << "particle " << i << " went through the wall";
            if (weights[i] > 0.0)
            {
                ++moved;
                EXPECT_TRUE(explains(*model, particles[i], false));
            }
        }
        EXPECT_GE(moved, 150u) << "most find the free way out within 16 sigma";
    }

    TEST(NavigationRecovery, ADepletedFilterLocalisesAtTheObservation)
    {
        // through the filter: the belief holds only the wrong mode; one landmark observation moves it to the robot
        const auto model = maze();
        pomdp::ParticleFilterSettings settings;
        settings.numParticles = 200;
        settings.continuation = true;
        pomdp::ParticleFilter<NavigationModel> filter(model, settings, std::make_unique<NavigationRecovery>());
        filter.setParticles(std::vector<NavState>(200, at(-15.0, -21.0)));
        pomdp::Rng rng(13);
        const auto o = seenAt(-14.0, 14.0);
        EXPECT_FALSE(filter.update(0, o, rng)) << "the update depletes";
        EXPECT_EQ(filter.depletions(), 1u);
        double mx = 0.0, my = 0.0, w = 0.0;
        for (std::size_t i = 0; i < filter.particles().size(); ++i)
        {
            mx += filter.weights()[i] * filter.particles()[i].p[0];
            my += filter.weights()[i] * filter.particles()[i].p[1];
            w += filter.weights()[i];
        }
        EXPECT_NEAR(mx / w, -14.0, 0.25);
        EXPECT_NEAR(my / w, 14.0, 0.25);
        // the default (ignore the observation) leaves the belief where it was
        pomdp::ParticleFilter<NavigationModel> ignoring(model, settings);
        ignoring.setParticles(std::vector<NavState>(200, at(-15.0, -21.0)));
        ignoring.update(0, o, rng);
        double iy = 0.0;
        for (const auto &s : ignoring.particles())
        {
            iy += s.p[1] / 200.0;
        }
        EXPECT_LT(iy, -15.0);
    }

    TEST(NavigationRecovery, ACutoffMakesABeliefFarFromWhatWasSeenDepleteAndRelocalise)
    {
        // seed-502 episode 12 of scenario-maze2d.md: the robot, stopped by the wall below gap 2, sees itself in
        // landmark L4 at (-3, 16) while every particle went through the gap and sits in L5 around (9, 16), 12 m
        // (24 sigma) away. A plain Gaussian gives those particles a tiny, non-zero likelihood: no depletion, and
        // the belief stays confidently wrong. With observation_cutoff 4 it depletes and is redrawn at L4.
        const auto o = seenAt(-3.0, 16.0);
        pomdp::ParticleFilterSettings settings;
        settings.numParticles = 200;
        settings.continuation = true;
        pomdp::Rng rng(21);
        std::vector<NavState> lost;
        for (int i = 0; i < 200; ++i)
        {
            lost.push_back(at(rng.uniform(9.5, 12.5), rng.uniform(13.5, 17.5)));
        }
        const auto meanX = [](const pomdp::ParticleFilter<NavigationModel> &f)
        {
            double m = 0.0, w = 0.0;
            for (std::size_t i = 0; i < f.particles().size(); ++i)
            {
                m += f.weights()[i] * f.particles()[i].p[0];
                w += f.weights()[i];
            }
            return m / w;
        };
        const auto plain = maze();
        ASSERT_GT(plain->observationProbability(o, lost[0], 1), 0.0);
        pomdp::ParticleFilter<NavigationModel> gaussian(plain, settings, std::make_unique<NavigationRecovery>());
        gaussian.setParticles(lost);
        EXPECT_TRUE(gaussian.update(1, o, rng)) << "no depletion without the cutoff";
        EXPECT_GT(meanX(gaussian), 8.0) << "the belief stays in L5";

        const auto scenario =
            navScenario("maze2d", {{"observation_cutoff", 4.0}, {"depletion_recovery", "observation"}});
        const auto cut = asNav(*scenario).parts().model;
        // the likelihood is the Gaussian within 4 sigma on every axis and 0 beyond
        // z = (1, -2): (2 pi sigma^2)^-1 exp(-(1 + 4) / 2) with sigma 0.5
        const double closedForm = 1.0 / (2.0 * M_PI * 0.25) * std::exp(-2.5);
        EXPECT_NEAR(cut->observationProbability(o, at(-3.5, 17.0), 1), closedForm, 1e-12);
        EXPECT_NEAR(plain->observationProbability(o, at(-3.5, 17.0), 1), closedForm, 1e-12);
        EXPECT_GT(cut->observationProbability(o, at(-3.0, 17.99), 1), 0.0) << "3.98 sigma: inside";
        EXPECT_EQ(cut->observationProbability(o, at(-3.0, 18.1), 1), 0.0);
        EXPECT_EQ(cut->observationProbability(o, lost[0], 1), 0.0);
        pomdp::ParticleFilter<NavigationModel> filter(cut, settings, asNav(*scenario).parts().recovery());
        filter.setParticles(lost);
        EXPECT_FALSE(filter.update(1, o, rng)) << "the cutoff makes it a depletion";
        EXPECT_NEAR(meanX(filter), -3.0, 0.3) << "redrawn at what was seen";
        for (std::size_t i = 0; i < filter.particles().size(); ++i)
        {
            if (filter.weights()[i] > 0.0)
            {
                EXPECT_GT(cut->observationProbability(o, filter.particles()[i], 1), 0.0);
            }
        }
        ropras::test::expectErrorMentions(
            [] {
                navScenario("maze2d", {{"observation_cutoff", -1.0}});
            },
            {"observation_cutoff", ">= 0"});
        ropras::test::expectErrorMentions(
            [] {
                navScenario("maze2d", {{"observation_cutoff", 2.0}});
            },
            {"observation_cutoff", "= 2", ">= 3"});
        ropras::test::expectErrorMentions(
            [] {
                navScenario("maze2d", {{"observation_cutoff", "far"}});
            },
            {"observation_cutoff"});
        NavObservation bad = o;
        bad.p[0] = std::numeric_limits<double>::quiet_NaN();
        EXPECT_EQ(cut->observationProbability(bad, at(-3.0, 16.0), 1), 0.0) << "NaN: 0, not NaN";
        EXPECT_EQ(plain->observationProbability(bad, at(-3.0, 16.0), 1), 0.0);
    }

    TEST(NavigationRecovery, TheScenarioKeyChoosesTheRecovery)
    {
        EXPECT_FALSE(asNav(*navScenario("maze2d")).parts().recovery) << "default: ignore the observation";
        const auto s = navScenario("maze2d", {{"depletion_recovery", "observation"}});
        ASSERT_TRUE(asNav(*s).parts().recovery);
        EXPECT_EQ(asNav(*s).parts().recovery()->name(), "observation");
        ropras::test::expectErrorMentions(
            [] {
                navScenario("maze2d", {{"depletion_recovery", "forget"}});
            },
            {"depletion_recovery", "forget"});
        ropras::test::expectErrorMentions(
            [] {
                navScenario("light-dark", {{"depletion_recovery", 1}});
            },
            {"depletion_recovery"});
    }
}  // namespace ropras::scenarios::test
