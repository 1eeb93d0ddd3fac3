// Ray-Detect: the scene and its informative configurations, the model against the Bullet world (steps, rays,
// detections), observations and blocked steps, the reference policy in a particle's scene, episodes of every
// solver, and bad configuration values.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <memory>
#include <string>
#include <vector>

#include <ompl/util/Console.h>

#include "ArmScenarioTestUtil.h"
#include "ropras/core/Error.h"
#include "ropras/ompl_ext/scene/EnvironmentQueries.h"
#include "ropras/scenarios/manipulation/RayDetectPlanning.h"
#include "ropras/scenarios/manipulation/RayDetectScenario.h"
#include "ropras/scenarios/manipulation/RayDetectWorld.h"

namespace ropras::scenarios
{
    namespace
    {
        using State = RayDetectModel::State;

        struct QuietOmpl : ::testing::Environment
        {
            void SetUp() override { ompl::msg::setLogLevel(ompl::msg::LOG_ERROR); }
        };
        const auto *const QUIET = ::testing::AddGlobalTestEnvironment(new QuietOmpl);

        const ScenarioParts<RayDetectModel> &defaultParts()
        {
            static const ScenarioParts<RayDetectModel> parts = rayDetectParts();
            return parts;
        }

        /** \brief The smallest signed distance (m) from the arm's spheres to the scene (table, can, obstacles) and
            between spheres of self-collision link pairs at \a q (reference FK, exact double distances). */
        double clearance(const RayDetectModel &model, const ompl_ext::Environment &scene, const double *q)
        {
            const auto &robot = *model.arm().robot();
            const auto centers = robot.sphereCentersReference(q);
            const auto &spheres = robot.spheres();
            double best = 1e300;
            for (std::size_t i = 0; i < spheres.size(); ++i)
            {
                best = std::min(best, scene.signedDistance(centers[i], spheres[i].radius));
            }
            for (const auto &pair : robot.selfCollisionPairs())
            {
                const auto &a = robot.collisionLinks()[static_cast<std::size_t>(pair.first)];
                const auto &b = robot.collisionLinks()[static_cast<std::size_t>(pair.second)];
                for (int i = a.firstSphere; i < a.firstSphere + a.sphereCount; ++i)
                {
                    for (int j = b.firstSphere; j < b.firstSphere + b.sphereCount; ++j)
                    {
                        const auto ui = static_cast<std::size_t>(i), uj = static_cast<std::size_t>(j);
                        best = std::min(best,
                                        (centers[ui] - centers[uj]).norm() - spheres[ui].radius - spheres[uj].radius);
                    }
                }
            }
            return best;
        }

        /// the closest the segment a -> b comes to object \a id of \a scene (sampled every 0.5 mm)
        double segmentClearance(const ompl_ext::Environment &scene, int id, const Eigen::Vector3d &a,
                                const Eigen::Vector3d &b)
        {
            const std::size_t n = static_cast<std::size_t>(std::ceil((b - a).norm() / 5e-4)) + 1;
            double best = 1e300;
            for (std::size_t k = 0; k <= n; ++k)
            {
                const Eigen::Vector3d p = a + (static_cast<double>(k) / static_cast<double>(n)) * (b - a);
                best = std::min(best, std::abs(scene.objectSignedDistance(id, p, 0.0)));
            }
            return best;
        }

        /// the exact entry distance of the ray (origin, unit direction, length) into box k of \a s (slabs, double)
        double slabDistance(const RayDetectModel &model, const State &s, std::size_t k, const Eigen::Vector3d &origin,
                            const Eigen::Vector3d &direction, double length)
        {
            const Eigen::Isometry3d pose = rayDetectPose(s.poses[k]);
            const Eigen::Vector3d o = pose.inverse() * origin, d = pose.linear().transpose() * direction;
            const auto &e = model.config().obstacles[k].extents;
            double lo = 0.0, hi = length;
            for (int i = 0; i < 3; ++i)
            {
                const double h = 0.5 * e[static_cast<std::size_t>(i)];
                if (std::abs(d[i]) < 1e-12)
                {
                    if (std::abs(o[i]) > h)
                        return -1.0;
                    continue;
                }
                double t0 = (-h - o[i]) / d[i], t1 = (h - o[i]) / d[i];
                if (t0 > t1)
                    std::swap(t0, t1);
                lo = std::max(lo, t0);
                hi = std::min(hi, t1);
            }
            return lo <= hi ? lo : -1.0;
        }

        /// a random configuration whose end effector is above the table's front half (where the obstacles are)
        bool randomWorkspaceConfiguration(const RayDetectModel &model, core::Rng &rng, double *q)
        {
            const auto &arm = model.arm();
            for (int attempt = 0; attempt < 1000; ++attempt)
            {
                for (std::size_t j = 0; j < ARM_DOF; ++j)
                {
                    q[j] = rng.uniform(arm.lower(j), arm.upper(j));
                }
                const Eigen::Vector3d ee = arm.endEffectorPosition(q);
                if (ee.x() > 0.25 && ee.x() < 1.0 && std::abs(ee.y()) < 0.5 && ee.z() > 0.25 && ee.z() < 0.9)
                {
                    return true;
                }
            }
            return false;
        }
    }  // namespace

    TEST(RayDetectTest, TheGoalAndEveryLookHaveCollisionFreeConfigurationsInTheNominalScene)
    {
        const auto &parts = defaultParts();
        const auto model = parts.model;
        const auto planning = rayDetectObstacleScene(
            model->config(), rayDetectStaticScene(model->config(), model->config().planningMargin),
            model->config().planningMargin);
        RayDetectTargetSpace space(model, planning);
        RayDetectGoalSampler sampler(model, planning, 7);
        const State nominal = model->nominalState();
        EXPECT_FALSE(model->reachedGoal(nominal));
        double q[ARM_DOF];
        ASSERT_TRUE(sampler.solve(nominal, space.goal(nominal), q));
        State reached = nominal;
        RayDetectModel::setJoints(reached, q);
        EXPECT_TRUE(model->reachedGoal(reached));
        EXPECT_TRUE(model->arm().checker()->isValid(model->scene(nominal), q));
        for (std::size_t k = 0; k < RAY_DETECT_OBSTACLES; ++k)
        {
            ASSERT_TRUE(sampler.solve(nominal, space.informative(nominal, k), q)) << "look at obstacle " << k;
            State look = nominal;
            RayDetectModel::setJoints(look, q);
            EXPECT_TRUE(model->arm().checker()->isValid(model->scene(look), q));
            const auto d = model->detect(look);
            EXPECT_EQ(d.object, static_cast<int>(k)) << "look at obstacle " << k;
            EXPECT_LT(d.distance, model->config().lookStandoff + 0.01);
        }
    }

    TEST(RayDetectTest, ModelAndBulletWorldAgreeOnRandomStepsAndRays)
    {
        const auto model = defaultParts().model;
        RayDetectWorld world(model);
        const auto &arm = model->arm();
        core::Rng rng(20251202);
        pomdp::Rng beliefRng(99);
        const double tolerance = 1e-3;  // m: disagreements only this close to contact
        const double resolution = model->config().resolution;
        std::size_t steps = 0, collided = 0, stepDisagreements = 0, rays = 0, hits = 0, rayDisagreements = 0;
        double worstStep = 0.0, worstRay = 0.0, worstDistance = 0.0;
        State s = model->sampleInitialState(beliefRng);
        world.reset(s);
        while (steps < 2000)
        {
            if (steps % 100 == 0)
            {
                // a fresh draw of the obstacle poses (b0), in both
                s = model->sampleInitialState(beliefRng);
                world.reset(s);
            }
            double q0[ARM_DOF], q1[ARM_DOF];
            if (!randomWorkspaceConfiguration(*model, rng, q0) || !arm.checker()->isValid(model->scene(s), q0))
            {
                continue;
            }
            double norm = 0.0, dq[ARM_DOF];
            for (double &d : dq)
            {
                d = rng.normal();
                norm += d * d;
            }
            const double length = rng.uniform(0.05, 0.5) / std::sqrt(norm);
            for (std::size_t j = 0; j < ARM_DOF; ++j)
            {
                q1[j] = q0[j] + length * dq[j];
            }
            arm.clamp(q1);
            ++steps;
            const ompl_ext::Environment &scene = model->scene(s);
            const bool modelValid = arm.checker()->isMotionValid(scene, q0, q1, resolution);
            const bool worldValid = world.bullet().motionValid(q0, q1, resolution);
            collided += worldValid ? 0 : 1;
            if (modelValid != worldValid)
            {
                ++stepDisagreements;
                const std::size_t n = PandaArm::motionSamples(q0, q1, resolution);
                double nearest = 1e300;
                for (std::size_t k = 1; k <= n; ++k)
                {
                    const double t = static_cast<double>(k) / static_cast<double>(n);
                    double q[ARM_DOF];
                    for (std::size_t j = 0; j < ARM_DOF; ++j)
                    {
                        q[j] = q0[j] + t * (q1[j] - q0[j]);
                    }
                    const double c = clearance(*model, scene, q);
                    nearest = std::abs(c) < std::abs(nearest) ? c : nearest;
                }
                worstStep = std::max(worstStep, std::abs(nearest));
                EXPECT_LT(std::abs(nearest), tolerance) << "step disagreement at step " << steps;
            }
            // the detector at q0: the same object first, at the same distance
            State at = s;
            RayDetectModel::setJoints(at, q0);
            const auto m = model->detect(at);
            const auto w = world.detect(q0);
            ++rays;
            hits += m.object >= 0 ? 1 : 0;
            if (m.object != w.object)
            {
                ++rayDisagreements;
                // the ray grazes the object only one of them saw
                const int id = m.object >= 0 ? m.object : w.object;
                const double graze =
                    segmentClearance(model->scene(at), id, m.origin,
                                     m.origin + (m.end - m.origin).normalized() * model->config().rayLength);
                worstRay = std::max(worstRay, graze);
                EXPECT_LT(graze, tolerance) << "ray disagreement at step " << steps;
            }
            else if (m.object >= 0)
            {
                worstDistance = std::max(worstDistance, std::abs(m.distance - w.distance));
                EXPECT_NEAR(m.distance, w.distance, tolerance)
                    << "exact slab distance "
                    << slabDistance(*model, at, static_cast<std::size_t>(m.object), m.origin,
                                    (m.end - m.origin).normalized(), model->config().rayLength);
            }
        }
        const double stepRate = 1.0 - static_cast<double>(stepDisagreements) / static_cast<double>(steps);
        const double rayRate = 1.0 - static_cast<double>(rayDisagreements) / static_cast<double>(rays);
        ::testing::Test::RecordProperty("step_agreement_rate", std::to_string(stepRate));
        ::testing::Test::RecordProperty("ray_agreement_rate", std::to_string(rayRate));
        std::printf(
            "model vs Bullet world: %zu random steps, %zu collide (world), %zu disagree (agreement %.4f, worst "
            "%.2e m from contact); %zu rays, %zu hit an obstacle, %zu disagree (agreement %.4f, worst graze "
            "%.2e m), worst hit-distance difference %.2e m\n",
            steps, collided, stepDisagreements, stepRate, worstStep, rays, hits, rayDisagreements, rayRate, worstRay,
            worstDistance);
        EXPECT_GT(collided, steps / 10);  // many collisions, not only free space
        EXPECT_GT(hits, rays / 20);       // many detections, not only misses
        EXPECT_GE(stepRate, 0.99);
        EXPECT_GE(rayRate, 0.99);
    }

    TEST(RayDetectTest, DetectionsCarryTheHitObjectWithBoundedNoiseAndBinByDistance)
    {
        const auto &parts = defaultParts();
        const auto model = parts.model;
        const auto &c = model->config();
        const auto planning = rayDetectObstacleScene(c, rayDetectStaticScene(c, c.planningMargin), c.planningMargin);
        RayDetectTargetSpace space(model, planning);
        RayDetectGoalSampler sampler(model, planning, 3);
        const State nominal = model->nominalState();
        double q[ARM_DOF];
        ASSERT_TRUE(sampler.solve(nominal, space.informative(nominal, 1), q));
        State look = nominal;
        RayDetectModel::setJoints(look, q);
        pomdp::Rng rng(11);
        RayDetectModel::Action stay;
        std::uint64_t key = 0;
        for (int i = 0; i < 200; ++i)
        {
            pomdp::StepResult<State, RayDetectModel::Observation> out;
            out.next = look;
            model->finishStep(out, model->detect(look), rng);
            ASSERT_EQ(out.observation.object, 1);
            for (std::size_t k = 0; k < 6; ++k)
            {
                const double a = k < 3 ? c.positionNoise : c.angleNoise;
                EXPECT_LE(std::abs(out.observation.pose[k] - look.poses[1][k]), a);
            }
            // the true state explains the observation better than a state with obstacle 1 moved by 5 cm
            State moved = look;
            moved.poses[1][0] += 0.05;
            EXPECT_GT(model->observationProbability(out.observation, look, stay),
                      model->observationProbability(out.observation, moved, stay));
            const std::uint64_t k = model->observationKey(out.observation);
            EXPECT_NE(k, 0u);
            key = key == 0 ? k : key;
        }
        // no detection: key 0; another object: another key
        RayDetectModel::Observation none;
        EXPECT_EQ(model->observationKey(none), 0u);
        RayDetectModel::Observation other;
        std::copy(q, q + ARM_DOF, other.q);
        other.object = 2;
        std::copy(look.poses[1], look.poses[1] + 6, other.pose);
        EXPECT_NE(model->observationKey(other), key);
        // a particle that predicts another object than observed keeps only the mismatch weight
        pomdp::StepResult<State, RayDetectModel::Observation> out;
        out.next = look;
        model->finishStep(out, model->detect(look), rng);
        State elsewhere = look;
        elsewhere.poses[1][1] += 0.5;  // obstacle 1 out of the ray
        ASSERT_NE(model->detect(elsewhere).object, 1);
        double chi2 = 0.0;
        for (std::size_t j = 0; j < ARM_DOF; ++j)
        {
            const double d = (out.observation.q[j] - elsewhere.q[j]) / c.observationSigma;
            chi2 += d * d;
        }
        const double joints = std::exp(-0.5 * chi2) / std::pow(std::sqrt(2.0 * M_PI) * c.observationSigma, 7.0);
        EXPECT_NEAR(model->observationProbability(out.observation, elsewhere, stay) / (joints * c.mismatchLikelihood),
                    1.0, 1e-9);
    }

    TEST(RayDetectTest, ACollidingStepIsBlockedNotTerminal)
    {
        const auto &parts = defaultParts();
        const auto model = parts.model;
        RayDetectWorld world(model);
        const State nominal = model->nominalState();
        world.reset(nominal);
        // straight down from the start: the hand meets the table or an obstacle
        pomdp::Rng rng(5);
        std::size_t blocked = 0;
        State s = nominal;
        for (int i = 0; i < 80; ++i)
        {
            RayDetectModel::Action a;
            a.dq[1] = 0.05;  // shoulder forward
            a.dq[3] = 0.05;  // elbow opens
            const auto m = model->step(s, a, rng);
            EXPECT_FALSE(m.terminal);
            EXPECT_DOUBLE_EQ(m.reward, model->config().stepReward);
            EXPECT_TRUE(model->arm().checker()->isValid(model->scene(m.next), m.next.q));
            double moved = 0.0;
            for (std::size_t j = 0; j < ARM_DOF; ++j)
            {
                moved += std::abs(m.next.q[j] - s.q[j]);
            }
            blocked += moved < 0.05 ? 1 : 0;
            s = m.next;
        }
        EXPECT_GT(blocked, 10u);
        // the world blocks the same way
        world.reset(nominal);
        std::size_t worldBlocked = 0;
        for (int i = 0; i < 80; ++i)
        {
            RayDetectModel::Action a;
            a.dq[1] = 0.05;
            a.dq[3] = 0.05;
            const State before = world.state();
            const auto w = world.step(a, rng);
            EXPECT_FALSE(w.terminal);
            double moved = 0.0;
            for (std::size_t j = 0; j < ARM_DOF; ++j)
            {
                moved += std::abs(w.next.q[j] - before.q[j]);
            }
            worldBlocked += moved < 0.05 ? 1 : 0;
        }
        EXPECT_GT(worldBlocked, 10u);
    }

    // The model's arm moves as the world's: the same action and noise draw give the same next joints, in free
    // space (the whole step) and when blocked (within the resolution of the last valid sample).
    TEST(RayDetectTest, ModelAndWorldMoveTheArmAlike)
    {
        const auto model = defaultParts().model;
        RayDetectWorld world(model);
        State s = model->nominalState();
        world.reset(s);
        std::size_t moved = 0, blocked = 0;
        for (int i = 0; i < 60; ++i)
        {
            RayDetectModel::Action a;
            a.dq[0] = i < 30 ? 0.02 : -0.02;
            a.dq[1] = 0.03;
            a.dq[3] = 0.02;
            pomdp::Rng modelRng(100 + i), worldRng(100 + i);
            const auto m = model->step(s, a, modelRng);
            const auto w = world.step(a, worldRng);
            double gap = 0.0, step = 0.0;
            for (std::size_t j = 0; j < ARM_DOF; ++j)
            {
                gap = std::max(gap, std::abs(m.next.q[j] - w.next.q[j]));
                step = std::max(step, std::abs(m.next.q[j] - s.q[j]));
            }
            EXPECT_LT(gap, 2.0 * model->config().resolution) << "step " << i;
            moved += step > 0.5 * model->config().step ? 1 : 0;
            blocked += step < 1e-9 ? 1 : 0;
            s = m.next;
            world.reset(s);
        }
        EXPECT_GT(moved, 20u);  // free-space steps move by about the commanded step
        std::printf("model vs world, 60 steps from the start: %zu moved, %zu blocked at once\n", moved, blocked);
    }

    TEST(RayDetectTest, ReferenceMacrosAreCollisionFreeInTheSampledParticlesScene)
    {
        const auto &parts = defaultParts();
        const auto &model = *parts.model;
        const auto &c = model.config();
        const auto planning = rayDetectObstacleScene(c, rayDetectStaticScene(c, c.planningMargin), c.planningMargin);
        for (const std::string planner : {"VectorizedRRTConnect", "RRTConnect"})
        {
            RunSettings settings;
            settings.planner = planner;
            settings.heuristic = "uniform";
            pomdp::ParameterMap params;
            params.set("plan_time", 0.05);
            auto policy = parts.referencePolicy(settings, params, 17);
            pomdp::Rng rng(5);
            std::vector<State> belief;
            for (int i = 0; i < 10; ++i)
            {
                belief.push_back(model.sampleInitialState(rng));
            }
            int macros = 0;
            for (std::size_t i = 0; i < 20; ++i)
            {
                std::vector<ArmAction> macro;
                const State &particle = belief[i % belief.size()];
                if (!policy->sample(particle, {belief.data(), belief.size()}, rng, macro))
                {
                    continue;
                }
                ++macros;
                EXPECT_LE(macro.size(), 10u);
                auto scene = std::make_shared<ompl_ext::Environment>(*planning);
                poseRayDetectObstacles(particle, *scene);
                State s = particle;
                for (const auto &a : macro)
                {
                    double norm = 0.0, next[ARM_DOF];
                    for (std::size_t j = 0; j < ARM_DOF; ++j)
                    {
                        norm += a.dq[j] * a.dq[j];
                        next[j] = s.q[j] + a.dq[j];
                    }
                    EXPECT_LE(std::sqrt(norm), c.step + 1e-9);
                    EXPECT_TRUE(model.arm().checker()->isMotionValid(*scene, s.q, next, c.resolution)) << planner;
                    RayDetectModel::setJoints(s, next);
                }
            }
            EXPECT_GE(macros, 10) << planner;
        }
    }

    TEST(RayDetectTest, TheDynamicHeuristicsEntropyFallsAsTheObstaclesAreLocalised)
    {
        const auto &parts = defaultParts();
        const auto model = parts.model;
        RayDetectTargetSpace space(model, model->nominalScene());
        pomdp::Rng rng(8);
        std::vector<State> belief;
        for (int i = 0; i < 100; ++i)
        {
            belief.push_back(model->sampleInitialState(rng));
        }
        const double spread = space.beliefEntropy({belief.data(), belief.size()});
        EXPECT_GT(spread, 0.8);
        // obstacles 0 and 1 known exactly: their entropy is 0, the mean halves
        for (auto &s : belief)
        {
            for (std::size_t k = 0; k < 2; ++k)
            {
                std::copy(model->config().obstacles[k].pose.begin(), model->config().obstacles[k].pose.end(),
                          s.poses[k]);
            }
        }
        const double half = space.beliefEntropy({belief.data(), belief.size()});
        EXPECT_NEAR(half, 0.5 * spread, 0.05);
        std::vector<State> collapsed(100, model->nominalState());
        EXPECT_DOUBLE_EQ(space.beliefEntropy({collapsed.data(), collapsed.size()}), 0.0);
    }

    TEST(RayDetectTest, EverySolverRunsAnEpisodeToTheEnd)
    {
        ScenarioOptions options;
        options.overrides["horizon"] = 12;
        test::expectEverySolverRunsAnEpisode(
            *makeRayDetectScenario(options),
            [](const std::string &solver, const pomdp::EpisodeResult &result, const nlohmann::json &recording)
            {
                ASSERT_TRUE(recording.contains("rays")) << solver;
                EXPECT_EQ(recording["rays"].size(), result.steps + 1) << solver;
                EXPECT_EQ(recording["rays"][0]["segments"].size(), 1u) << solver;
            });
    }

    TEST(RayDetectTest, BadConfigurationValuesNameTheKey)
    {
        const auto expectError = [](const nlohmann::json &overrides, const std::string &key)
        {
            ScenarioOptions options;
            options.overrides = overrides;
            try
            {
                (void)rayDetectParts(options);
                ADD_FAILURE() << "no error for " << overrides.dump();
            }
            catch (const Error &e)
            {
                EXPECT_NE(std::string(e.what()).find(key), std::string::npos) << e.what();
            }
        };
        expectError({{"no_such_key", 1}}, "no_such_key");
        expectError({{"step", -0.05}}, "\"step\"");
        expectError({{"step", "big"}}, "step");
        expectError({{"step", std::nan("")}}, "\"step\"");
        expectError({{"goal_radius", 0}}, "\"goal_radius\"");
        expectError({{"ray_length", 1e9}}, "\"ray_length\"");
        expectError({{"horizon", 1e12}}, "\"horizon\"");
        expectError({{"horizon", 1.5}}, "\"horizon\"");
        expectError({{"discount", 1.5}}, "\"discount\"");
        expectError({{"start", {0, 0, 0}}}, "\"start\"");
        expectError({{"start", {0, 5, 0, -2.356, 0, 1.571, 0.785}}}, "\"start\"");
        expectError({{"obstacles", nlohmann::json::array()}}, "\"obstacles\"");
        expectError({{"initial_sigma_pose", {0.05, 0.05, 0, 0, 0, -1}}}, "\"initial_sigma_pose\"");
        expectError({{"table", {{"center", {0.75, 0, 0.198}}, {"extents", {0.9, 0, 0.04}}}}}, "\"table.extents\"");
        expectError({{"goal_point", {0.75, 0, 0.278}}}, "\"goal_point\"");  // inside the can
        expectError({{"planning", {{"margin", -1}}}}, "\"planning.margin\"");
        expectError({{"planning", {{"ik_restarts", 1e9}}}}, "\"planning.ik_restarts\"");
        expectError({{"end_effector", "panda_nose"}}, "panda_nose");
        expectError({{"transition_sigma", -0.02}}, "\"transition_sigma\"");
        expectError({{"reachable_goal", 3}}, "\"reachable_goal\"");
        expectError({{"goal_point", {1.6, 0, 0.4}}},
                    "\"goal_point\" (1.600000, 0.000000, 0.400000) has no collision-free");
        // two obstacles at the same place
        nlohmann::json stacked = nlohmann::json::parse(R"([
            {"pose": [0.55, 0.12, 0.368, 0, 0, 0], "extents": [0.2, 0.02, 0.3]},
            {"pose": [0.55, 0.12, 0.368, 0, 0, 0], "extents": [0.02, 0.2, 0.3]},
            {"pose": [0.75, 0.25, 0.368, 0, 0, 0.3], "extents": [0.2, 0.05, 0.3]},
            {"pose": [0.75, -0.25, 0.368, 0, 0, -0.3], "extents": [0.2, 0.05, 0.3]}])");
        expectError({{"obstacles", stacked}}, "\"obstacles\" at their nominal poses: obstacle 1 overlaps obstacle 0");
    }
}  // namespace ropras::scenarios
