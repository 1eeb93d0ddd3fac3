// Sphere-Search: the embedded Panda, the model against the Bullet world, light and goal, the reference policy,
// episodes of every solver, and bad configuration values.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <memory>
#include <string>
#include <vector>

#include <ompl/util/Console.h>

#include "ArmScenarioTestUtil.h"
#include "ReferencePolicyTestUtil.h"
#include "ropras/core/Error.h"
#include "ropras/pomdp/OmplPathPlanner.h"
#include "ropras/pomdp/ParticleFilter.h"
#include "ropras/scenarios/SvgRenderer.h"
#include "ropras/scenarios/manipulation/ArmPlanning.h"
#include "ropras/scenarios/manipulation/SphereSearchScenario.h"
#include "ropras/scenarios/manipulation/SphereSearchWorld.h"

namespace ropras::scenarios
{
    namespace
    {
        using State = SphereSearchModel::State;

        struct QuietOmpl : ::testing::Environment
        {
            void SetUp() override { ompl::msg::setLogLevel(ompl::msg::LOG_ERROR); }
        };
        const auto *const QUIET = ::testing::AddGlobalTestEnvironment(new QuietOmpl);

        const ScenarioParts<SphereSearchModel> &defaultParts()
        {
            static const ScenarioParts<SphereSearchModel> parts = sphereSearchParts();
            return parts;
        }

        State startState(const SphereSearchModel &model, int goal = 0)
        {
            State s;
            SphereSearchModel::setJoints(s, model.config().start.data());
            s.goal = goal;
            return s;
        }

        /** \brief The smallest signed distance (m) between the arm's spheres and the obstacle spheres or
            between spheres of self-collision link pairs, at \a q (double-precision reference FK). */
        double clearance(const SphereSearchModel &model, const double *q)
        {
            const auto &robot = *model.arm().robot();
            const auto centers = robot.sphereCentersReference(q);
            const auto &spheres = robot.spheres();
            double best = 1e300;
            for (std::size_t i = 0; i < spheres.size(); ++i)
            {
                for (const auto &o : model.config().obstacles)
                {
                    best = std::min(best,
                                    (centers[i] - Eigen::Vector3d(o[0], o[1], o[2])).norm() - o[3] - spheres[i].radius);
                }
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
    }  // namespace

    TEST(SphereSearchTest, EmbeddedPandaStartsWhereTheSpecificationSays)
    {
        const auto &model = *defaultParts().model;
        EXPECT_EQ(model.arm().robot()->dof(), ARM_DOF);
        EXPECT_EQ(model.arm().endEffector(), "panda_grasptarget");
        // manipulation-scenarios.md 0.4: FK of the VAMP start puts the grasp target at (0.307, 0, 0.485)
        const Eigen::Vector3d ee = model.endEffector(startState(model));
        EXPECT_NEAR(ee.x(), 0.307, 1e-3);
        EXPECT_NEAR(ee.y(), 0.0, 1e-3);
        EXPECT_NEAR(ee.z(), 0.485, 1e-3);
        EXPECT_FALSE(model.inLight(startState(model)));
        EXPECT_FALSE(model.reachedGoal(startState(model)));
    }

    TEST(SphereSearchTest, ModelAndBulletWorldAgreeOnRandomSteps)
    {
        const auto model = defaultParts().model;
        SphereSearchWorld world(model);
        const auto &arm = model->arm();
        core::Rng rng(424242);
        const double tolerance = 1e-3;  // m: disagreements only this close to contact
        std::size_t steps = 0, collided = 0, disagreements = 0;
        double worstClearance = 0.0;
        while (steps < 2000)
        {
            double q0[ARM_DOF], q1[ARM_DOF];
            for (std::size_t j = 0; j < ARM_DOF; ++j)
            {
                q0[j] = rng.uniform(arm.lower(j), arm.upper(j));
            }
            if (!arm.checker()->isValid(*model->environment(), q0))
            {
                continue;
            }
            // a primitive-sized step (0.1 .. 0.5 rad L2) in a random direction
            double norm = 0.0, dq[ARM_DOF];
            for (double &d : dq)
            {
                d = rng.normal();
                norm += d * d;
            }
            const double length = rng.uniform(0.1, 0.5) / std::sqrt(norm);
            for (std::size_t j = 0; j < ARM_DOF; ++j)
            {
                q1[j] = q0[j] + length * dq[j];
            }
            arm.clamp(q1);
            ++steps;
            const double resolution = model->config().resolution;
            const bool modelValid = arm.checker()->isMotionValid(*model->environment(), q0, q1, resolution);
            const bool worldValid = world.bullet().motionValid(q0, q1, resolution);
            collided += worldValid ? 0 : 1;
            if (modelValid != worldValid)
            {
                ++disagreements;
                // the configurations both checked: the closest one to contact decides the disagreement
                const std::size_t n = PandaArm::motionSamples(q0, q1, resolution);
                double nearest = 1e300;
                for (std::size_t k = 1; k <= n; ++k)
                {
                    double q[ARM_DOF];
                    SphereSearchModel::moveAlong(q0, q1, static_cast<double>(k) / static_cast<double>(n), q);
                    const double c = clearance(*model, q);
                    nearest = std::abs(c) < std::abs(nearest) ? c : nearest;
                }
                worstClearance = std::max(worstClearance, std::abs(nearest));
                EXPECT_LT(std::abs(nearest), tolerance) << "disagreement " << disagreements << " at step " << steps;
            }
        }
        const double rate = 1.0 - static_cast<double>(disagreements) / static_cast<double>(steps);
        ::testing::Test::RecordProperty("agreement_rate", std::to_string(rate));
        std::printf(
            "model vs Bullet world: %zu random steps, %zu collide (world), %zu disagree (agreement %.4f), "
            "worst disagreement %.2e m from contact\n",
            steps, collided, disagreements, rate, worstClearance);
        EXPECT_GT(collided, steps / 10);  // the test sees many collisions, not only free space
        EXPECT_GE(rate, 0.995);
    }

    TEST(SphereSearchTest, TheLightRevealsTheGoalAndTheGoalBallEndsTheEpisode)
    {
        const auto &model = *defaultParts().model;
        const auto &config = model.config();
        auto env = sphereSearchEnvironment(config, 0.0);
        ArmGoalSampler sampler(model.armPtr(), env, ArmGoalSampler::Settings(), 11);
        const State start = startState(model, 1);
        State lit = start;
        ASSERT_TRUE(sampler.solve(start.q, config.light, config.lightRadius, lit.q));
        ASSERT_TRUE(model.inLight(lit));
        State atGoal = start;
        ASSERT_TRUE(sampler.solve(start.q, config.goals[1], config.goalRadius, atGoal.q));
        ASSERT_TRUE(model.reachedGoal(atGoal));
        atGoal.goal = 0;  // the other goal: not reached there
        EXPECT_FALSE(model.reachedGoal(atGoal));

        pomdp::Rng rng(3);
        pomdp::StepResult<State, SphereSearchModel::Observation> out;
        out.next = lit;
        model.finishStep(out, false, rng);
        EXPECT_EQ(out.observation.goal, 1);
        EXPECT_FALSE(out.terminal);
        EXPECT_DOUBLE_EQ(out.reward, config.stepReward);
        State other = lit;
        other.goal = 0;
        const SphereSearchModel::Action none;
        EXPECT_GT(model.observationProbability(out.observation, lit, none), 0.0);
        EXPECT_EQ(model.observationProbability(out.observation, other, none), 0.0);  // the light rules it out
        EXPECT_EQ(model.observationKey(out.observation), 2u);

        out = {};
        out.next = start;
        model.finishStep(out, false, rng);
        EXPECT_EQ(out.observation.goal, -1);  // None outside the light
        EXPECT_EQ(model.observationKey(out.observation), 0u);
        out = {};
        out.next = startState(model, 1);
        SphereSearchModel::setJoints(out.next, atGoal.q);
        model.finishStep(out, false, rng);
        EXPECT_TRUE(out.terminal);
        EXPECT_DOUBLE_EQ(out.reward, config.stepReward + config.goalReward);
        out = {};
        out.next = start;
        model.finishStep(out, true, rng);  // a collision: terminal failure
        EXPECT_TRUE(out.terminal);
        EXPECT_DOUBLE_EQ(out.reward, config.stepReward + config.failReward);
    }

    // A full pool of IK solutions answers with the one nearest to the particle's configuration (planning.ik_choice
    // "nearest"): checked against every pooled solution from random seeds; "uniform" answers with others too.
    TEST(SphereSearchTest, AFullIkPoolAnswersWithTheSolutionNearestToTheParticle)
    {
        const auto &model = *defaultParts().model;
        const auto &config = model.config();
        const auto env = sphereSearchEnvironment(config, 0.0);
        for (const bool nearest : {true, false})
        {
            ArmGoalSampler::Settings settings;
            settings.nearest = nearest;
            ArmGoalSampler sampler(model.armPtr(), env, settings, 21);
            const State start = startState(model, 2);
            double q[ARM_DOF];
            for (std::size_t i = 0; i < 200 && sampler.pooled(config.light).size() < settings.poolSize; ++i)
                ASSERT_TRUE(sampler.solve(start.q, config.light, config.lightRadius, q));
            const auto pool = sampler.pooled(config.light);
            ASSERT_EQ(pool.size(), settings.poolSize);
            core::Rng rng(5);
            std::size_t notNearest = 0;
            for (int trial = 0; trial < 50; ++trial)
            {
                double seed[ARM_DOF];
                for (std::size_t j = 0; j < ARM_DOF; ++j)
                    seed[j] = rng.uniform(model.arm().lower(j), model.arm().upper(j));
                ASSERT_TRUE(sampler.solve(seed, config.light, config.lightRadius, q));
                std::vector<double> d2(pool.size(), 0.0);
                std::size_t answered = pool.size();
                for (std::size_t k = 0; k < pool.size(); ++k)
                {
                    for (std::size_t j = 0; j < ARM_DOF; ++j)
                        d2[k] += (pool[k][j] - seed[j]) * (pool[k][j] - seed[j]);
                    if (std::equal(q, q + ARM_DOF, pool[k].begin()))
                        answered = k;
                }
                ASSERT_LT(answered, pool.size()) << "the answer is one of the pooled solutions";
                const double best = *std::min_element(d2.begin(), d2.end());
                if (d2[answered] > best)
                    ++notNearest;
            }
            if (nearest)
                EXPECT_EQ(notNearest, 0u);
            else
                EXPECT_GT(notNearest, 10u);
            EXPECT_EQ(sampler.pooled(config.goals[0]).size(), 0u) << "another ball has its own pool";
        }
    }

    // The goal marginal of the execution filter: before the light no observation depends on the goal, so it must
    // stay near 1/2; resampling on the sharp joint likelihood alone fixes it at random within a few steps (the cause of
    // the wrong-goal failures), the Gibbs move of reinvigorate() keeps it; a particle that has seen the light keeps
    // its goal.
    TEST(SphereSearchTest, TheFilterKeepsTheGoalOpenUntilTheLight)
    {
        const auto &parts = defaultParts();
        const auto &model = *parts.model;
        const auto goalShareDrift = [&](bool reinvigorate)
        {
            double drift = 0.0;
            for (std::uint64_t seed = 1; seed <= 10; ++seed)
            {
                pomdp::ParticleFilterSettings settings;
                settings.numParticles = 100;
                settings.reinvigorate = reinvigorate;
                pomdp::ParticleFilter<SphereSearchModel> filter(parts.model, settings);
                pomdp::Rng rng(seed);
                filter.initialize(rng);
                SphereSearchWorld world(parts.model);
                world.reset(startState(model, 0));
                const SphereSearchModel::Action stay;  // dq = 0: the start is far from the light
                for (int step = 0; step < 8; ++step)
                {
                    const auto out = world.step(stay, rng);
                    EXPECT_EQ(out.observation.goal, -1);
                    filter.update(stay, out.observation, rng);
                }
                const auto &particles = filter.particles();
                const double share = static_cast<double>(std::count_if(particles.begin(), particles.end(),
                                                                       [](const State &s) { return s.goal == 0; })) /
                                     static_cast<double>(particles.size());
                drift += std::abs(share - 0.5) / 10.0;
            }
            return drift;
        };
        EXPECT_LT(goalShareDrift(true), 0.1);
        EXPECT_GT(goalShareDrift(false), 0.3);

        pomdp::Rng rng(5);
        State lit = startState(model, 1);
        lit.seen = true;
        for (int i = 0; i < 200; ++i)
        {
            model.reinvigorate(lit, rng);
            ASSERT_EQ(lit.goal, 1);
        }
        State dark = startState(model, 1);
        int ones = 0;
        for (int i = 0; i < 2000; ++i)
        {
            model.reinvigorate(dark, rng);
            ones += dark.goal;
        }
        EXPECT_NEAR(ones / 2000.0, 0.5, 0.05);
        // the step marks the particle that enters the light
        ArmGoalSampler sampler(model.armPtr(), sphereSearchEnvironment(model.config(), 0.0), ArmGoalSampler::Settings(),
                               11);
        pomdp::StepResult<State, SphereSearchModel::Observation> out;
        out.next = startState(model, 0);
        ASSERT_TRUE(sampler.solve(out.next.q, model.config().light, model.config().lightRadius, out.next.q));
        model.finishStep(out, false, rng);
        EXPECT_TRUE(out.next.seen);
    }

    // The reference planner shares the arm's checker (building one costs far more than a plan) and plans with it;
    // a checker of another robot object is refused, naming both robots.
    TEST(SphereSearchTest, TheReferencePlannerSharesTheArmsChecker)
    {
        const auto &model = *defaultParts().model;
        pomdp::OmplPathPlannerSettings settings;
        settings.checker = model.arm().checker();
        settings.timeLimit = 0.5;
        pomdp::OmplPathPlanner planner(model.arm().robot(), model.environment(), settings);
        EXPECT_EQ(&planner.checker(), model.arm().checker().get());
        State start = startState(model, 0), goal = start;
        ArmGoalSampler sampler(model.armPtr(), model.environment(), ArmGoalSampler::Settings(), 11);
        ASSERT_TRUE(sampler.solve(start.q, model.config().light, model.config().lightRadius, goal.q));
        ASSERT_EQ(planner.plan(start.q, goal.q), pomdp::PathPlanStatus::Solved);
        const auto &path = planner.path();
        for (std::size_t i = 0; i + 1 < planner.waypointCount(); ++i)
        {
            EXPECT_TRUE(model.arm().checker()->isMotionValid(*model.environment(), &path[i * ARM_DOF],
                                                             &path[(i + 1) * ARM_DOF], model.config().resolution));
        }
        const auto copy = std::make_shared<const ompl_ext::RobotModel>(*model.arm().robot());
        EXPECT_THROW(pomdp::OmplPathPlanner(copy, model.environment(), settings), Error);
    }

    TEST(SphereSearchTest, ReferenceMacrosFollowCollisionFreePathsInSteps)
    {
        // the dq reading, whose actions are the path's steps (the default waypoint actions are its points)
        ScenarioOptions options;
        options.overrides["action_mode"] = "delta";
        const auto parts = sphereSearchParts(options);
        const auto &model = *parts.model;
        for (const std::string planner : {"VectorizedRRTConnect", "RRTConnect"})
        {
            RunSettings settings;
            settings.planner = planner;
            settings.heuristic = "uniform";
            pomdp::ParameterMap params;
            params.set("plan_time", 0.05);
            auto policy = parts.referencePolicy(settings, params, 17);
            pomdp::Rng rng(5);
            std::vector<State> belief{startState(model, 0), startState(model, 1)};
            int macros = 0;
            for (int i = 0; i < 10; ++i)
            {
                std::vector<ArmAction> macro;
                if (!policy->sample(belief[static_cast<std::size_t>(i % 2)], {belief.data(), belief.size()}, rng,
                                    macro))
                {
                    continue;
                }
                ++macros;
                EXPECT_LE(macro.size(), 10u);  // macro_length
                State s = belief[static_cast<std::size_t>(i % 2)];
                for (const auto &a : macro)
                {
                    double norm = 0.0, next[ARM_DOF];
                    for (std::size_t j = 0; j < ARM_DOF; ++j)
                    {
                        norm += a.dq[j] * a.dq[j];
                        next[j] = s.q[j] + a.dq[j];
                    }
                    EXPECT_LE(std::sqrt(norm), model.config().step + 1e-9);
                    EXPECT_TRUE(model.arm().checker()->isMotionValid(*model.environment(), s.q, next,
                                                                     model.config().resolution))
                        << planner;
                    SphereSearchModel::setJoints(s, next);
                }
            }
            EXPECT_GE(macros, 5) << planner;
        }
    }

    TEST(SphereSearchTest, EverySolverRunsAnEpisodeToTheEnd)
    {
        ScenarioOptions options;
        options.overrides["horizon"] = 12;
        test::expectEverySolverRunsAnEpisode(*makeSphereSearchScenario(options));
    }

    std::size_t occurrences(const std::string &text, const std::string &what)
    {
        std::size_t n = 0;
        for (auto at = text.find(what); at != std::string::npos; at = text.find(what, at + what.size()))
            ++n;
        return n;
    }

    // `ropras render` of an arm episode: the recording carries the Panda and its joints per step; the picture poses
    // every collision sphere of the embedded URDF at each chosen step in the top and the side view, and draws every
    // recorded ray segment in both.
    TEST(SphereSearchTest, RenderedEpisodeShowsTheArmAtChosenStepsAndTheRays)
    {
        ScenarioOptions options;
        options.overrides["horizon"] = 6;
        const auto scenario = makeSphereSearchScenario(options);
        RunSettings settings;
        settings.solver = "bplan";
        settings.params.set("particles", 20);
        scenario->validate(settings);
        nlohmann::json recording;
        const auto result = scenario->runEpisode(settings, 3, &recording, RecordSettings());
        ASSERT_TRUE(recording.contains("robot"));
        ASSERT_EQ(recording["robot"]["configurations"].size(), result.steps + 1);
        const auto &first = recording["robot"]["configurations"][0];
        ASSERT_EQ(first.size(), ARM_DOF);
        const std::size_t spheres = defaultParts().model->arm().robot()->spheres().size();
        ASSERT_GT(spheres, 50u);

        SvgOptions svgOptions;
        svgOptions.armSteps = {0, result.steps};
        std::string svg = renderSvg(recording, svgOptions);
        EXPECT_EQ(occurrences(svg, "class=\"arm-sphere\""), 2 * 2 * spheres) << "2 steps x 2 views";
        EXPECT_EQ(occurrences(svg, "<g class=\"arm-pose\" data-step=\"0\""), 2u);
        EXPECT_EQ(occurrences(svg, "class=\"ray\""), 0u) << "no rays recorded";
        EXPECT_NE(svg.find("data-label=\"end_effector\""), std::string::npos);

        // default: up to 6 steps spread over the episode
        svg = renderSvg(recording, SvgOptions());
        EXPECT_EQ(occurrences(svg, "class=\"arm-sphere\""), 2 * std::min<std::size_t>(6, result.steps + 1) * spheres);

        recording["rays"] = {{{"step", 0}, {"segments", {{{0.3, 0.0, 0.5}, {0.3, 0.0, 0.0}}}}},
                             {{"step", 1}, {"segments", {{{0.3, 0.0, 0.5}, {0.8, 0.0, 0.5}}, {{0, 0, 0}, {0, 1, 0}}}}}};
        svg = renderSvg(recording, svgOptions);
        EXPECT_EQ(occurrences(svg, "class=\"ray\""), 2u * 3u) << "3 segments x 2 views";

        svgOptions.armSteps = {result.steps + 1};
        try
        {
            renderSvg(recording, svgOptions, "ep.json");
            ADD_FAILURE() << "an arm step past the end must throw";
        }
        catch (const Error &e)
        {
            EXPECT_NE(std::string(e.what()).find("arm step " + std::to_string(result.steps + 1)), std::string::npos)
                << e.what();
        }
        recording["robot"]["configurations"][0] = {0.0, 1.0};
        EXPECT_THROW(renderSvg(recording, SvgOptions(), "ep.json"), Error);
    }

    // A particle that noise pushed inside the planning margin (valid in the true cage, invalid in the grown one) is
    // planned for in the true cage by the scenario's reference policy; any other particle in the grown cage.
    TEST(SphereSearchTest, ParticlesInsideThePlanningMarginPlanInTheTrueWorld)
    {
        const auto &parts = defaultParts();
        const SphereSearchModel &model = *parts.model;
        const auto &arm = model.arm();
        const auto grown = sphereSearchEnvironment(model.config(), model.config().planningMargin);
        const auto policy = test::omplReferencePolicy<ArmTarget>(parts, "uniform", 3);
        auto *ompl = policy.ompl;
        ASSERT_NE(ompl, nullptr);
        core::Rng rng(11);
        std::size_t inside = 0, clear = 0, planned = 0;
        for (int attempt = 0; attempt < 20000 && (inside < 5 || clear < 5); ++attempt)
        {
            State s = startState(model);
            for (std::size_t j = 0; j < ARM_DOF; ++j)
                s.q[j] = rng.uniform(arm.lower(j), arm.upper(j));
            const bool trueValid = arm.checker()->isValid(*model.environment(), s.q);
            const bool grownValid = arm.checker()->isValid(*grown, s.q);
            if (!trueValid || (grownValid && clear >= 5))
                continue;
            const std::size_t before = ompl->statistics().marginStarts, noTarget = ompl->statistics().noTarget;
            std::vector<ArmAction> macro;
            const bool ok = ompl->sample(s, pomdp::BeliefView<State>{&s, 1}, rng, macro);
            if (ompl->statistics().noTarget > noTarget)
                continue;  // no plan ran: the target had no IK solution
            if (!grownValid)
            {
                ++inside;
                EXPECT_EQ(ompl->statistics().marginStarts, before + 1);
                EXPECT_NE(ompl->lastStatus(), pomdp::PathPlanStatus::InvalidStart);
                planned += ok ? 1 : 0;
                if (ok)
                {
                    EXPECT_EQ(ompl->planner().environment(), model.environment()) << "planned in the true cage";
                }
            }
            else
            {
                ++clear;
                EXPECT_EQ(ompl->statistics().marginStarts, before);
                EXPECT_NE(ompl->planner().environment(), model.environment()) << "planned in the grown cage";
            }
        }
        EXPECT_EQ(inside, 5u) << "random configurations inside the margin were found";
        EXPECT_EQ(clear, 5u);
        EXPECT_GE(planned, 1u) << "some of them reached a plan";
    }

    TEST(SphereSearchTest, BadConfigurationValuesNameTheKey)
    {
        const auto expectError = [](const nlohmann::json &overrides, const std::string &key)
        {
            ScenarioOptions options;
            options.overrides = overrides;
            try
            {
                (void)sphereSearchParts(options);
                ADD_FAILURE() << "no error for " << overrides.dump();
            }
            catch (const Error &e)
            {
                EXPECT_NE(std::string(e.what()).find(key), std::string::npos) << e.what();
            }
        };
        expectError({{"step", -0.1}}, "\"step\"");
        expectError({{"step", "big"}}, "step");
        expectError({{"goal_radius", 0}}, "\"goal_radius\"");
        expectError({{"goals", {{0.5, 0.76, 0.4}}}}, "\"goals\"");
        expectError({{"start", {0, 0, 0}}}, "\"start\"");
        expectError({{"start", {0, 5, 0, -2.356, 0, 1.571, 0.785}}}, "\"start\"");   // joint 2 outside its limits
        expectError({{"obstacles", {{0.307, 0.0, 0.485, 0.05}}}}, "\"start\"");      // the start in collision
        expectError({{"obstacles", {{0.55, 0.0, 0.8, 0.12}}}}, "\"light_center\"");  // the light inside
        expectError({{"horizon", 1.5}}, "\"horizon\"");
        expectError({{"discount", 1.5}}, "\"discount\"");
        expectError({{"planning", {{"margin", -1}}}}, "\"planning.margin\"");
        expectError({{"planning", {{"ik_points", 0}}}}, "\"planning.ik_points\"");
        expectError({{"end_effector", "panda_nose"}}, "panda_nose");
        expectError({{"transition_sigma", -0.02}}, "\"transition_sigma\"");
        expectError({{"action_mode", "teleport"}}, "\"action_mode\"");
        expectError({{"planning", {{"ik_choice", "closest"}}}},
                    "\"planning.ik_choice\" must be \"nearest\" or \"uniform\"");
        expectError({{"color", 1}}, "color");  // unknown key
    }
}  // namespace ropras::scenarios
