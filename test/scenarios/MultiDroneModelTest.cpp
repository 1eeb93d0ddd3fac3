// Multi-Drone Tag: the model's rules (flight, teleport, capture, observation), the Bullet world against the
// model's analytic blocking, and configuration errors.
#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <memory>
#include <nlohmann/json.hpp>
#include <string>

#include "ropras/core/Error.h"
#include "ropras/scenarios/multi-drone/MultiDroneModel.h"
#include "ropras/scenarios/multi-drone/MultiDroneScenario.h"
#include "ropras/scenarios/multi-drone/MultiDroneWorld.h"

namespace ropras::scenarios
{
    namespace
    {
        using State = MultiDroneModel::State;

        std::shared_ptr<const MultiDroneModel> defaultModel()
        {
            return multiDroneParts().model;
        }

        State makeState(const double drones[4][3], const double target[3])
        {
            State s{};
            for (int d = 0; d < 4; ++d)
            {
                for (int k = 0; k < 3; ++k)
                {
                    s.drone[d][k] = drones[d][k];
                }
            }
            for (int k = 0; k < 3; ++k)
            {
                s.target[k] = target[k];
            }
            return s;
        }

        /// far-apart drones in the corners; a blocked action: drone 1 (index 0) at x = -15 moving -x
        const double CORNERS[4][3] = {{-15, -15, 0}, {15, -15, 0}, {-15, 15, 0}, {15, 15, 0}};
        constexpr MultiDroneModel::Action DRONE1_MINUS_X = 1;
        /// drone 4 (index 3) -x: the tests keep drone 4 far away, so this action only lets time pass
        constexpr MultiDroneModel::Action DRONE4_MINUS_X = 19;

        void expectError(const nlohmann::json &overrides, const std::string &mustContain)
        {
            ScenarioOptions options;
            options.overrides = overrides;
            try
            {
                (void)multiDroneParts(options);
                FAIL() << "no error for " << overrides.dump();
            }
            catch (const Error &e)
            {
                EXPECT_NE(std::string(e.what()).find(mustContain), std::string::npos)
                    << "message \"" << e.what() << "\" does not name " << mustContain;
            }
        }
    }  // namespace

    TEST(MultiDroneModelTest, ActionsAreFourDronesTimesSixAxisMoves)
    {
        const auto model = defaultModel();
        ASSERT_EQ(model->numActions(), 24u);
        pomdp::Rng rng(3);
        const double drones[4][3] = {{-6, 0, 0}, {-2, 0, 0}, {2, 0, 0}, {6, 0, 0}};
        const double target[3] = {0, 12, 0};
        const State s = makeState(drones, target);
        const double expected[6][3] = {{0.5, 0, 0}, {-0.5, 0, 0}, {0, 0.5, 0}, {0, -0.5, 0}, {0, 0, 0.5}, {0, 0, -0.5}};
        for (std::size_t a = 0; a < 24; ++a)
        {
            const auto r = model->step(s, model->action(a), rng);
            for (std::size_t d = 0; d < 4; ++d)
            {
                for (int k = 0; k < 3; ++k)
                {
                    const double move = d == a / 6 ? expected[a % 6][k] : 0.0;
                    EXPECT_DOUBLE_EQ(r.next.drone[d][k], s.drone[d][k] + move) << "action " << a << " drone " << d;
                }
            }
            EXPECT_DOUBLE_EQ(r.reward, -0.1);
            EXPECT_FALSE(r.terminal);
        }
    }

    TEST(MultiDroneModelTest, DronesCannotLeaveTheBoxOrTouchEachOther)
    {
        const auto model = defaultModel();
        pomdp::Rng rng(4);
        const double target[3] = {0, 0, 0};
        const State corner = makeState(CORNERS, target);
        const auto r = model->step(corner, DRONE1_MINUS_X, rng);
        EXPECT_DOUBLE_EQ(r.next.drone[0][0], -15.0);
        const double close[4][3] = {{0, 5, 0}, {0.8, 5, 0}, {-8, 5, 0}, {8, 5, 0}};
        const State s = makeState(close, target);
        const auto blocked = model->step(s, 0 /* drone 1 +x: centres 0.3 apart < 0.6 */, rng);
        EXPECT_DOUBLE_EQ(blocked.next.drone[0][0], 0.0);
        const auto free = model->step(s, 1 /* drone 1 -x */, rng);
        EXPECT_DOUBLE_EQ(free.next.drone[0][0], -0.5);
    }

    TEST(MultiDroneModelTest, TargetFleesTheClosestDrone)
    {
        const auto model = defaultModel();
        const double step = model->config().targetStep;
        pomdp::Rng rng(11);
        int checked = 0;
        for (int trial = 0; trial < 2000; ++trial)
        {
            State s{};
            for (int d = 0; d < 4; ++d)
            {
                s.drone[d][0] = rng.uniform(-14, 14);
                s.drone[d][1] = rng.uniform(-14, 14);
                s.drone[d][2] = rng.uniform(-1.5, 1.5);
            }
            // Target in the interior (no wrap, no clamp) and outside capture range.
            s.target[0] = rng.uniform(-13, 13);
            s.target[1] = rng.uniform(-13, 13);
            s.target[2] = rng.uniform(-1.0, 1.0);
            if (model->minTargetDistance(s) <= 1.5)
            {
                continue;
            }
            // Move drone 4 (index 3) by +z; the expected closest drone is computed after that move.
            const auto action = static_cast<MultiDroneModel::Action>(18 + 4);
            State moved = s;
            if (moved.drone[3][2] + 0.5 <= 2.0)
            {
                bool touches = false;
                for (int j = 0; j < 3; ++j)
                {
                    const double dx = moved.drone[j][0] - moved.drone[3][0], dy = moved.drone[j][1] - moved.drone[3][1],
                                 dz = moved.drone[j][2] - (moved.drone[3][2] + 0.5);
                    touches = touches || std::sqrt(dx * dx + dy * dy + dz * dz) < 0.6;
                }
                if (!touches)
                {
                    moved.drone[3][2] += 0.5;
                }
            }
            if (model->minTargetDistance(moved) <= 1.0)
            {
                continue;
            }
            int closest = 0;
            double best = std::numeric_limits<double>::infinity();
            for (int d = 0; d < 4; ++d)
            {
                const double dist = std::sqrt(MultiDroneModel::squaredDistance(moved.drone[d], s.target));
                if (dist < best)
                {
                    best = dist;
                    closest = d;
                }
            }
            const auto r = model->step(s, action, rng);
            if (r.terminal)
            {
                continue;  // captured after the flight: checked elsewhere
            }
            double away[3], delta[3];
            for (int k = 0; k < 3; ++k)
            {
                away[k] = (s.target[k] - moved.drone[closest][k]) / best;
                delta[k] = r.next.target[k] - s.target[k];
            }
            const double along = away[0] * delta[0] + away[1] * delta[1] + away[2] * delta[2];
            const double length = std::sqrt(delta[0] * delta[0] + delta[1] * delta[1] + delta[2] * delta[2]);
            if (std::abs(r.next.target[2]) >= 2.0 - 1e-12)
            {
                continue;  // z clamped
            }
            EXPECT_NEAR(length, step, 1e-9);
            EXPECT_NEAR(along, step, 1e-9) << "the target did not move straight away from drone " << closest + 1;
            // Moving away increases the distance to the closest drone by exactly the step.
            EXPECT_NEAR(std::sqrt(MultiDroneModel::squaredDistance(moved.drone[closest], r.next.target)), best + step,
                        1e-9);
            ++checked;
        }
        EXPECT_GT(checked, 1000);
    }

    TEST(MultiDroneModelTest, TargetTeleportsAcrossXAndYAndIsClampedInZ)
    {
        const auto model = defaultModel();
        pomdp::Rng rng(5);
        {
            // Closest drone at x = 10 on the target's line: the target flies +x over x = 15 and reappears at -15.
            const double drones[4][3] = {{10, 0, 0}, {-10, 10, 0}, {-10, -10, 0}, {0, -14, 0}};
            const double target[3] = {14.9, 0, 0};
            const auto r = model->step(makeState(drones, target), DRONE4_MINUS_X, rng);
            EXPECT_NEAR(r.next.target[0], 14.9 + 0.3 - 30.0, 1e-12);
            EXPECT_NEAR(r.next.target[1], 0.0, 1e-12);
        }
        {
            // -y flight over y = -15 reappears at +15.
            const double drones[4][3] = {{0, -10, 0}, {10, 10, 0}, {-10, 10, 0}, {14, 0, 0}};
            const double target[3] = {0, -14.8, 0};
            const auto r = model->step(makeState(drones, target), DRONE4_MINUS_X, rng);
            EXPECT_NEAR(r.next.target[1], -14.8 - 0.3 + 30.0, 1e-12);
        }
        {
            // Straight up against the ceiling: z is clamped at 2, no teleport.
            const double drones[4][3] = {{3, 3, -2}, {10, 10, 0}, {-10, 10, 0}, {-10, -10, 0}};
            const double target[3] = {3, 3, 1.9};
            const auto r = model->step(makeState(drones, target), DRONE4_MINUS_X, rng);
            EXPECT_DOUBLE_EQ(r.next.target[2], 2.0);
            EXPECT_NEAR(r.next.target[0], 3.0, 1e-12);
        }
    }

    TEST(MultiDroneModelTest, CaptureGivesTheRewardAndEndsTheEpisode)
    {
        const auto model = defaultModel();
        pomdp::Rng rng(6);
        // Drone 1 at 1.4 m behind the target moves +x to 0.9 m: captured before the target can flee.
        const double drones[4][3] = {{0, 0, 0}, {10, 10, 0}, {-10, 10, 0}, {-10, -10, 0}};
        const double target[3] = {1.4, 0, 0};
        const State s = makeState(drones, target);
        EXPECT_FALSE(model->reachedGoal(s));
        const auto r = model->step(s, 0, rng);
        EXPECT_TRUE(r.terminal);
        EXPECT_DOUBLE_EQ(r.reward, 600.0 - 0.1);
        EXPECT_TRUE(model->reachedGoal(r.next));
        EXPECT_DOUBLE_EQ(r.next.target[0], 1.4);  // caught where it was
        // Fleeing from drone 1 into drone 2: captured after the target's own move.
        const double sandwich[4][3] = {{0, 0, 0}, {2.45, 0, 0}, {-10, 10, 0}, {-10, -10, 0}};
        const double between[3] = {1.2, 0, 0};
        const auto r2 = model->step(makeState(sandwich, between), DRONE4_MINUS_X, rng);
        EXPECT_TRUE(r2.terminal);
        EXPECT_NEAR(r2.next.target[0], 1.5, 1e-12);
        EXPECT_DOUBLE_EQ(r2.reward, 600.0 - 0.1);
        // Far away: a plain step.
        const double far[3] = {5, 5, 0};
        const auto r3 = model->step(makeState(drones, far), 0, rng);
        EXPECT_FALSE(r3.terminal);
        EXPECT_DOUBLE_EQ(r3.reward, -0.1);
    }

    TEST(MultiDroneModelTest, ObservationOnlyWithinDetectionRangeWithGaussianNoise)
    {
        const auto model = defaultModel();
        const double sigma = model->config().observationSigma;
        pomdp::Rng rng(7);
        const double drones[4][3] = {{0, 0, 0}, {10, 10, 0}, {-10, 10, 0}, {-10, -10, 0}};
        const double near[3] = {2.0, 0, 0};  // 2.3 m after fleeing: within 3 m
        const double far[3] = {6.0, 0, 0};
        const State sNear = makeState(drones, near), sFar = makeState(drones, far);
        double sum[3] = {0, 0, 0}, sumSquares[3] = {0, 0, 0};
        const int n = 20000;
        for (int i = 0; i < n; ++i)
        {
            const auto r = model->step(sNear, DRONE4_MINUS_X, rng);
            ASSERT_TRUE(r.observation.seen);
            for (int k = 0; k < 3; ++k)
            {
                const double e = r.observation.position[k] - r.next.target[k];
                sum[k] += e;
                sumSquares[k] += e * e;
            }
            if (i < 50)
            {
                // The density is the product of three independent 1-D normal densities.
                double expected = 1.0;
                for (int k = 0; k < 3; ++k)
                {
                    const double z = (r.observation.position[k] - r.next.target[k]) / sigma;
                    expected *= std::exp(-0.5 * z * z) / (sigma * std::sqrt(2.0 * M_PI));
                }
                EXPECT_NEAR(model->observationProbability(r.observation, r.next, DRONE4_MINUS_X), expected,
                            1e-12 * expected);
                MultiDroneModel::Observation none;
                EXPECT_EQ(model->observationProbability(none, r.next, DRONE4_MINUS_X), 0.0);
                EXPECT_NE(model->observationKey(r.observation), model->observationKey(none));
            }
            const auto rf = model->step(sFar, DRONE4_MINUS_X, rng);
            ASSERT_FALSE(rf.observation.seen);
            EXPECT_EQ(model->observationProbability(rf.observation, rf.next, DRONE4_MINUS_X), 1.0);
        }
        for (int k = 0; k < 3; ++k)
        {
            const double mean = sum[k] / n;
            const double variance = sumSquares[k] / n - mean * mean;
            EXPECT_NEAR(mean, 0.0, 4.0 * sigma / std::sqrt(n));  // 4 standard errors
            EXPECT_NEAR(variance, sigma * sigma, 4.0 * sigma * sigma * std::sqrt(2.0 / n));
        }
        MultiDroneModel::Observation seen;
        seen.seen = true;
        EXPECT_EQ(model->observationProbability(seen, sFar, DRONE4_MINUS_X), 0.0);
    }

    TEST(MultiDroneModelTest, InitialBeliefHasDronesAtTheStartsAndAUniformTarget)
    {
        const auto model = defaultModel();
        pomdp::Rng rng(8);
        double mean[3] = {0, 0, 0};
        const int n = 20000;
        for (int i = 0; i < n; ++i)
        {
            const State s = model->sampleInitialState(rng);
            for (int d = 0; d < 4; ++d)
            {
                for (int k = 0; k < 3; ++k)
                {
                    ASSERT_EQ(s.drone[d][k], model->config().starts[d][k]);
                }
            }
            ASSERT_FALSE(model->reachedGoal(s));
            for (int k = 0; k < 3; ++k)
            {
                ASSERT_GE(s.target[k], model->config().lower[k]);
                ASSERT_LE(s.target[k], model->config().upper[k]);
                mean[k] += s.target[k] / n;
            }
        }
        // Uniform over [-15, 15]: standard deviation 8.66, standard error 0.061.
        EXPECT_NEAR(mean[0], 0.0, 0.3);
        EXPECT_NEAR(mean[1], 0.0, 0.3);
        EXPECT_NEAR(mean[2], 0.0, 0.05);
    }

    TEST(MultiDroneModelTest, WorldAndModelAgreeOnBlocking)
    {
        const auto model = defaultModel();
        MultiDroneWorld world(model);
        pomdp::Rng rng(9);
        const double r = model->config().droneRadius;
        int blocked = 0, free = 0;
        for (int trial = 0; trial < 4000; ++trial)
        {
            // Drones packed in a small region so that blocking is frequent.
            State s{};
            for (int d = 0; d < 4; ++d)
            {
                s.drone[d][0] = rng.uniform(-1.5, 1.5);
                s.drone[d][1] = rng.uniform(-1.5, 1.5);
                s.drone[d][2] = rng.uniform(-1.0, 1.0);
            }
            s.target[0] = 10.0;
            world.reset(s);
            const auto action = static_cast<MultiDroneModel::Action>(rng.uniformIndex(24));
            const std::size_t d = MultiDroneModel::droneOf(action);
            double p[3];
            ASSERT_TRUE(model->proposeMove(s, action, p));
            // Skip configurations within a tiny tolerance of contact (float Bullet vs double).
            bool nearContact = false;
            for (std::size_t j = 0; j < 4; ++j)
            {
                if (j != d)
                {
                    nearContact = nearContact ||
                                  std::abs(std::sqrt(MultiDroneModel::squaredDistance(s.drone[j], p)) - 2.0 * r) < 1e-4;
                }
            }
            if (nearContact)
            {
                continue;
            }
            const bool analytic = model->dronesOverlap(s, d, p);
            ASSERT_EQ(world.blocked(d, p), analytic) << "trial " << trial;
            // The world's step moves the drone exactly when neither check blocks.
            pomdp::Rng stepRng(trial);
            const auto result = world.step(action, stepRng);
            const auto expected = model->step(s, action, stepRng);
            for (int k = 0; k < 3; ++k)
            {
                ASSERT_EQ(result.next.drone[d][k], expected.next.drone[d][k]);
            }
            (analytic ? blocked : free)++;
        }
        EXPECT_GT(blocked, 300);
        EXPECT_GT(free, 300);
    }

    TEST(MultiDroneModelTest, WorldFollowsTheModelOverAnEpisode)
    {
        const auto model = defaultModel();
        MultiDroneWorld world(model);
        pomdp::Rng rng(10);
        State s = model->sampleInitialState(rng);
        world.reset(s);
        for (int i = 0; i < 400; ++i)
        {
            const auto a = static_cast<MultiDroneModel::Action>(rng.uniformIndex(24));
            pomdp::Rng a1(i), a2(i);
            const auto w = world.step(a, a1);
            const auto m = model->step(s, a, a2);
            for (int d = 0; d < 4; ++d)
            {
                for (int k = 0; k < 3; ++k)
                {
                    ASSERT_EQ(w.next.drone[d][k], m.next.drone[d][k]) << "step " << i << " drone " << d;
                }
            }
            for (int k = 0; k < 3; ++k)
            {
                // 1e-9: the world is compiled in the library (FMA contraction may differ from this file's)
                ASSERT_NEAR(w.next.target[k], m.next.target[k], 1e-9) << "step " << i;
            }
            ASSERT_EQ(w.reward, m.reward);
            ASSERT_EQ(w.observation.seen, m.observation.seen);
            s = w.next;
            if (m.terminal)
            {
                break;
            }
        }
    }

    TEST(MultiDroneModelTest, BadConfigurationsAreErrorsNamingTheKey)
    {
        expectError({{"colour", 1}}, "colour");
        expectError({{"capture_radius", 3.0}}, "capture_radius");
        expectError({{"capture_radius", 5.0}}, "capture_radius");
        expectError({{"drone_radius", -0.3}}, "drone_radius");
        expectError({{"target_step", 0.0}}, "target_step");
        expectError({{"detection_range", std::numeric_limits<double>::quiet_NaN()}}, "detection_range");
        expectError({{"discount", 1.5}}, "discount");
        expectError({{"horizon", 0}}, "horizon");
        expectError({{"starts", {{0, 0, 0}, {0.5, 0, 0}, {5, 0, 0}, {8, 0, 0}}}}, "starts");
        expectError({{"starts", {{0, 0, 0}, {16, 0, 0}, {5, 0, 0}, {8, 0, 0}}}}, "starts");
        expectError({{"starts", {{0, 0, 0}, {5, 0, 0}}}}, "starts");
        expectError({{"bounds", {{-15, -15, -2}, {-20, 15, 2}}}}, "bounds");
        expectError({{"bounds", {{-10, -10, -2}, {10, 10, 2}}}}, "bounds");  // the URDF fixes the box
        expectError({{"drone_radius", 0.4}}, "drone_radius");                // and the radius
        expectError({{"planning", {{"resolution", -1.0}}}}, "planning.resolution");
        expectError({{"defaults", {{"depth", "deep"}}}}, "depth");
        expectError({{"observation_sigma", "wide"}}, "observation_sigma");
        // A valid override goes through.
        ScenarioOptions ok;
        ok.overrides = {{"target_step", 0.4}, {"detection_range", 4.0}};
        const auto parts = multiDroneParts(ok);
        EXPECT_DOUBLE_EQ(parts.model->config().targetStep, 0.4);
        EXPECT_DOUBLE_EQ(parts.config.at("detection_range").get<double>(), 4.0);
    }
}  // namespace ropras::scenarios
