// stretch-crossing: the Stretch robot's spheres, the drive, rewards, model vs Bullet world, the lookahead
// tracker, bad configurations, and episodes of ropras3 / rpomcp / bplan through the Scenario interface.
#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <memory>
#include <string>
#include <vector>

#include <ompl/util/Console.h>

#include "ropras/core/Error.h"
#include "ropras/pomdp/OmplPathPlanner.h"
#include "ropras/pomdp/Rng.h"
#include "ropras/scenarios/SvgRenderer.h"
#include "ropras/scenarios/crossing/CrossingPlanning.h"
#include "ropras/scenarios/crossing/CrossingScenario.h"
#include "ropras/scenarios/crossing/CrossingWorld.h"

namespace ropras::scenarios
{
    namespace
    {
        struct QuietOmpl : ::testing::Environment
        {
            void SetUp() override { ompl::msg::setLogLevel(ompl::msg::LOG_ERROR); }
        };
        const auto *const QUIET = ::testing::AddGlobalTestEnvironment(new QuietOmpl);

        constexpr double PI = 3.14159265358979323846;

        ScenarioParts<CrossingModel> partsWith(const nlohmann::json &overrides)
        {
            ScenarioOptions options;
            options.overrides = overrides;
            return crossingParts(options);
        }

        void expectError(const nlohmann::json &overrides, const std::string &mustContain)
        {
            try
            {
                (void)partsWith(overrides);
                FAIL() << "no error for " << overrides.dump();
            }
            catch (const Error &e)
            {
                EXPECT_NE(std::string(e.what()).find(mustContain), std::string::npos)
                    << "message \"" << e.what() << "\" does not name " << mustContain;
            }
        }

        CrossingState stateAt(double x, double y, double theta, double px, double py)
        {
            CrossingState s;
            s.x = x;
            s.y = y;
            s.theta = theta;
            s.px = px;
            s.py = py;
            return s;
        }

        /// the smallest |distance - radius| of any robot sphere to any object (pedestrian, table, wall): how
        /// close the state is to a contact boundary
        double contactMargin(const CrossingModel &m, const CrossingState &s)
        {
            const auto &c = m.config();
            double best = std::numeric_limits<double>::infinity();
            for (std::size_t k = 0; k < m.spheres().size(); ++k)
            {
                double p[3];
                m.spherePosition(s, k, p);
                const double r = m.spheres()[k].radius;
                const double dp = std::sqrt((p[0] - s.px) * (p[0] - s.px) + (p[1] - s.py) * (p[1] - s.py) +
                                            (p[2] - c.pedestrianHeight) * (p[2] - c.pedestrianHeight));
                best = std::fmin(best, std::abs(dp - r - c.pedestrianRadius));
                for (const auto &t : c.tables)
                {
                    double d2 = 0.0;
                    for (int a = 0; a < 3; ++a)
                    {
                        const double e = std::abs(p[a] - t.center[static_cast<std::size_t>(a)]) -
                                         t.halfExtents[static_cast<std::size_t>(a)];
                        d2 += e > 0.0 ? e * e : 0.0;
                    }
                    best = std::fmin(best, std::abs(std::sqrt(d2) - r));
                }
                for (int a = 0; a < 2; ++a)
                {
                    best = std::fmin(best, std::abs(p[a] - c.labLo[static_cast<std::size_t>(a)] - r));
                    best = std::fmin(best, std::abs(c.labHi[static_cast<std::size_t>(a)] - p[a] - r));
                }
            }
            return best;
        }
    }  // namespace

    TEST(CrossingScenarioTest, StretchRobotHasThreeBaseJointsAndCoversItsBaseShell)
    {
        const auto parts = partsWith(nlohmann::json::object());
        const auto robot = loadStretchRobot(parts.model->config());
        ASSERT_EQ(robot->dof(), 3u);
        EXPECT_EQ(robot->joints()[0].name, "base_x");
        EXPECT_EQ(robot->joints()[2].name, "base_theta");
        EXPECT_EQ(robot->spheres().size(), 102u);
        // Every point of the base shell's surface (0.34 x 0.33 x 0.16 m box, centre (0, 0, 0.09): the template's
        // numbers, stated here independently of the spherizer) lies inside a sphere of the model.
        const auto &spheres = parts.model->spheres();
        pomdp::Rng rng(3);
        const double h[3] = {0.17, 0.165, 0.08};
        for (int i = 0; i < 20000; ++i)
        {
            double p[3] = {rng.uniform(-h[0], h[0]), rng.uniform(-h[1], h[1]), rng.uniform(-h[2], h[2])};
            const int face = static_cast<int>(rng.uniformIndex(3));
            p[face] = rng.bernoulli(0.5) ? h[face] : -h[face];
            p[2] += 0.09;
            bool covered = false;
            for (const auto &s : spheres)
            {
                const double dx = p[0] - s.x, dy = p[1] - s.y, dz = p[2] - s.z;
                covered = covered || dx * dx + dy * dy + dz * dz <= s.radius * s.radius + 1e-12;
            }
            ASSERT_TRUE(covered) << "surface point (" << p[0] << ", " << p[1] << ", " << p[2] << ") not covered";
        }
        // The held lift puts the arm at 0.17 + 0.2 + 0.5 = 0.87 m: some sphere is centred there.
        double highest = 0.0;
        for (const auto &s : spheres)
        {
            if (std::abs(s.z - 0.87) < 0.03)
            {
                highest = s.z;
            }
        }
        EXPECT_GT(highest, 0.0);
        EXPECT_NEAR(parts.model->boundingRadius(), std::hypot(0.17, 0.26), 0.06);
    }

    TEST(CrossingScenarioTest, FortyFiveTwistsAndTheDriveFollowsClosedForms)
    {
        const auto parts = partsWith({{"speed_noise", {0.0, 0.0}}});
        const CrossingModel &m = *parts.model;
        ASSERT_EQ(m.numActions(), 45u);
        EXPECT_DOUBLE_EQ(m.twists()[44].v, 0.3);
        EXPECT_DOUBLE_EQ(m.twists()[12].v, -0.1);  // backward, w flipped
        EXPECT_DOUBLE_EQ(m.twists()[12].w, 0.4);
        // Already at the target twist (0.2, 0.3): one exact arc of 0.7 s.
        std::size_t arc = 0;
        for (std::size_t a = 0; a < m.numActions(); ++a)
        {
            if (std::abs(m.twists()[a].v - 0.2) < 1e-12 && std::abs(m.twists()[a].w - 0.3) < 1e-12)
            {
                arc = a;
            }
        }
        CrossingState s = stateAt(0.0, 0.0, 0.4, 10.0, 10.0);
        s.v = 0.2;
        s.w = 0.3;
        m.predict(s, static_cast<CrossingModel::Action>(arc));
        const double r = 0.2 / 0.3, th = 0.4 + 0.3 * 0.7;
        EXPECT_NEAR(s.x, r * (std::sin(th) - std::sin(0.4)), 1e-12);
        EXPECT_NEAR(s.y, -r * (std::cos(th) - std::cos(0.4)), 1e-12);
        EXPECT_NEAR(s.theta, th, 1e-12);
        // From rest, the wheels ramp at 0.12 m/s^2: after 0.7 s the speed is 0.084 m/s (< 0.3), the distance
        // between the continuous ramp's 0.5 a T^2 and a T^2.
        CrossingState rest = stateAt(0.0, 0.0, 0.0, 10.0, 10.0);
        m.predict(rest, 44);
        EXPECT_NEAR(rest.v, 0.084, 1e-12);
        EXPECT_GT(rest.x, 0.5 * 0.12 * 0.49);
        EXPECT_LT(rest.x, 0.12 * 0.49);
        // Wheel speed limit: a fast turn from full speed keeps both wheels within 0.3 m/s.
        for (int i = 0; i < 5; ++i)
        {
            m.predict(rest, 44);
        }
        EXPECT_NEAR(rest.v, 0.3, 1e-12);
        m.predict(rest, 32);  // (0.2, 0.5): wheels 0.2 -/+ 0.08
        EXPECT_LE(std::abs(rest.v - 0.5 * rest.w * 0.31966), 0.3 + 1e-12);
        EXPECT_LE(std::abs(rest.v + 0.5 * rest.w * 0.31966), 0.3 + 1e-12);
    }

    TEST(CrossingScenarioTest, RewardsAreThePapers)
    {
        const auto parts = partsWith({{"speed_noise", {0.0, 0.0}}});
        const CrossingModel &m = *parts.model;
        pomdp::Rng rng(1);
        // Driving into a pedestrian standing 0.5 m ahead: terminal, -800 - 1.
        CrossingState s = stateAt(-0.9, -0.4, PI / 2, -0.9, 0.05);
        s.v = 0.3;
        auto out = m.step(s, 44, rng);
        EXPECT_TRUE(out.terminal);
        EXPECT_EQ(out.next.event, CrossingEvent::Pedestrian);
        EXPECT_DOUBLE_EQ(out.reward, -801.0);
        // Passing 0.1 m beside it (clearance < 0.3 m): -20 - 1.
        s = stateAt(-0.9, -1.0, PI / 2, -0.9 + m.boundingRadius() + 0.2 + 0.1, -0.9);
        out = m.step(s, 44, rng);
        EXPECT_FALSE(out.terminal);
        EXPECT_EQ(out.next.event, CrossingEvent::TooClose);
        EXPECT_DOUBLE_EQ(out.reward, -21.0);
        // Far from everything: -1.
        s = stateAt(-0.9, -1.0, PI / 2, 1.5, 0.1);
        out = m.step(s, 44, rng);
        EXPECT_EQ(out.next.event, CrossingEvent::None);
        EXPECT_DOUBLE_EQ(out.reward, -1.0);
        // Reaching the goal: +800 - 1, terminal, success.
        s = stateAt(-0.9, 1.2, PI / 2, 1.5, 0.1);
        s.v = 0.2;
        out = m.step(s, 44, rng);
        EXPECT_TRUE(out.terminal);
        EXPECT_TRUE(m.reachedGoal(out.next));
        EXPECT_DOUBLE_EQ(out.reward, 799.0);
        // Into the table: terminal, collision reward.
        s = stateAt(-0.1, -1.4, 0.0, -1.5, 0.1);
        s.v = 0.3;
        out = m.step(s, 44, rng);
        EXPECT_EQ(out.next.event, CrossingEvent::Obstacle);
        EXPECT_DOUBLE_EQ(out.reward, -801.0);
        EXPECT_DOUBLE_EQ(out.next.v, 0.0);
    }

    TEST(CrossingScenarioTest, ModelAndBulletWorldAgreeOnContacts)
    {
        const auto parts = partsWith(nlohmann::json::object());
        auto model = parts.model;
        CrossingWorld world(model);
        const auto &c = model->config();
        pomdp::Rng rng(17);
        std::size_t pedestrian = 0, obstacle = 0, free = 0, nearBoundary = 0;
        for (int i = 0; i < 5000; ++i)
        {
            CrossingState s = stateAt(rng.uniform(c.labLo[0], c.labHi[0]), rng.uniform(c.labLo[1], c.labHi[1]),
                                      rng.uniform(-PI, PI), 0.0, 0.0);
            // the pedestrian near the robot half of the time
            if (rng.bernoulli(0.5))
            {
                s.px = s.x + rng.uniform(-0.7, 0.7);
                s.py = s.y + rng.uniform(-0.7, 0.7);
            }
            else
            {
                s.px = rng.uniform(c.labLo[0], c.labHi[0]);
                s.py = rng.uniform(c.labLo[1], c.labHi[1]);
            }
            const CrossingEvent a = model->contact(s);
            const CrossingEvent b = world.contact(s);
            if (a != b)
            {
                ++nearBoundary;
                ASSERT_LT(contactMargin(*model, s), 1e-3)
                    << "model " << static_cast<int>(a) << " vs Bullet " << static_cast<int>(b) << " at (" << s.x << ", "
                    << s.y << ", " << s.theta << "), pedestrian (" << s.px << ", " << s.py << ")";
                continue;
            }
            pedestrian += a == CrossingEvent::Pedestrian;
            obstacle += a == CrossingEvent::Obstacle;
            free += a == CrossingEvent::None;
        }
        EXPECT_GT(pedestrian, 250u);
        EXPECT_GT(obstacle, 250u);
        EXPECT_GT(free, 250u);
        EXPECT_LT(nearBoundary, 5u);
    }

    TEST(CrossingScenarioTest, WorldFollowsTheModelWithoutPedestrianNoise)
    {
        const auto parts = partsWith({{"world_pedestrian_speed_noise", 0.0}});
        auto model = parts.model;
        pomdp::Rng actions(5);
        std::size_t terminalRuns = 0;
        for (int run = 0; run < 100; ++run)
        {
            CrossingWorld world(model);
            pomdp::Rng init(100 + static_cast<std::uint64_t>(run));
            CrossingState s = model->sampleInitialState(init);
            world.reset(s);
            pomdp::Rng a(1000 + static_cast<std::uint64_t>(run)), b(1000 + static_cast<std::uint64_t>(run));
            for (int t = 0; t < 30; ++t)
            {
                const auto action = model->action(actions.uniformIndex(model->numActions()));
                const auto m = model->step(s, action, a);
                const auto w = world.step(action, b);
                ASSERT_EQ(m.terminal, w.terminal) << "run " << run << " step " << t;
                ASSERT_DOUBLE_EQ(m.reward, w.reward);
                ASSERT_EQ(m.next.event, w.next.event);
                // the same code in two instantiations: equal up to floating-point contraction (FMA)
                ASSERT_NEAR(m.next.x, w.next.x, 1e-9);
                ASSERT_NEAR(m.next.y, w.next.y, 1e-9);
                ASSERT_NEAR(m.next.theta, w.next.theta, 1e-9);
                ASSERT_NEAR(m.next.px, w.next.px, 1e-9);
                ASSERT_NEAR(m.observation.theta, w.observation.theta, 1e-9);
                s = w.next;
                if (m.terminal)
                {
                    ++terminalRuns;
                    break;
                }
            }
        }
        EXPECT_GT(terminalRuns, 10u);  // random driving hits things: the comparison covers collisions
    }

    TEST(CrossingScenarioTest, WorldPedestrianSpeedVariesWithinItsNoise)
    {
        const auto parts = partsWith(nlohmann::json::object());
        CrossingWorld world(parts.model);
        CrossingState s = stateAt(-0.9, -1.4, PI / 2, -1.6, 1.0);
        world.reset(s);
        pomdp::Rng rng(9);
        double lo = 1.0, hi = 0.0;
        for (int t = 0; t < 20; ++t)
        {
            const double before = world.state().px;
            world.step(0, rng);  // slow forward, far from the pedestrian's line
            const double dx = world.state().px - before;
            lo = std::fmin(lo, dx);
            hi = std::fmax(hi, dx);
        }
        EXPECT_GE(lo, 0.08 - 1e-12);
        EXPECT_LE(hi, 0.12 + 1e-12);
        EXPECT_GT(hi - lo, 0.01);
    }

    TEST(CrossingScenarioTest, TrackerDrivesAlongThePath)
    {
        const auto parts = partsWith({{"speed_noise", {0.0, 0.0}}});
        auto model = parts.model;
        const CrossingPlanningAdapter adapter(model, 8, 0);
        // Straight ahead 1 m: the tracker goes forward without turning much and ends near the line x = -0.9.
        const CrossingState s = stateAt(-0.9, -1.4, PI / 2, 1.5, 0.0);
        const double straight[] = {-0.9, -1.4, PI / 2, -0.9, -0.9, PI / 2, -0.9, -0.4, PI / 2};
        std::vector<CrossingModel::Action> macro;
        ASSERT_TRUE(adapter.pathToMacroAction(s, straight, 3, macro));
        ASSERT_EQ(macro.size(), 8u);
        CrossingState p = s;
        for (const auto a : macro)
        {
            EXPECT_GT(model->twists()[a].v, 0.0);
            model->predict(p, a);
        }
        EXPECT_NEAR(p.x, -0.9, 0.05);
        EXPECT_GT(p.y, -1.4 + 0.5);
        // A path to the left (-x): the first twists turn left (w > 0 when facing +y).
        const double left[] = {-0.9, -1.4, PI / 2, -1.4, -0.9, PI / 2};
        macro.clear();
        ASSERT_TRUE(adapter.pathToMacroAction(s, left, 2, macro));
        EXPECT_GT(model->twists()[macro.front()].w, 0.0);
        p = s;
        for (const auto a : macro)
        {
            model->predict(p, a);
        }
        EXPECT_LT(p.x, -1.0);
        // A degenerate path is a failed conversion.
        const double point[] = {-0.9, -1.4, 0.0, -0.9, -1.4, 0.0};
        macro.clear();
        EXPECT_FALSE(adapter.pathToMacroAction(s, point, 2, macro));
    }

    TEST(CrossingScenarioTest, PlannerPedestrianCoversItsNextSteps)
    {
        // pedestrian_sweep 3 (default) and step (0.1, 0): a capsule from the pedestrian to 0.3 m ahead in +x
        const auto parts = partsWith(nlohmann::json::object());
        const auto &c = parts.model->config();
        ASSERT_DOUBLE_EQ(c.planning.pedestrianSweep, 3.0);
        const Eigen::Isometry3d pose = crossingPedestrianPose(c, -1.0, 0.2);
        EXPECT_NEAR(pose.translation().x(), -1.0 + 0.15, 1e-12);
        EXPECT_NEAR(pose.translation().y(), 0.2, 1e-12);
        EXPECT_NEAR((pose.linear() * Eigen::Vector3d::UnitZ() - Eigen::Vector3d::UnitX()).norm(), 0.0, 1e-12);
        // the scene's pedestrian blocks the robot 0.4 m ahead of the pedestrian, not 0.8 m ahead; with sweep 0 it
        // blocks only around the pedestrian itself
        const auto robot = loadStretchRobot(c);
        for (const double sweep : {3.0, 0.0})
        {
            const auto p = partsWith({{"planning", {{"pedestrian_sweep", sweep}}}});
            int id = -1;
            auto scene = crossingPlanningScene(p.model->config(), crossingLab(p.model->config()), id);
            pomdp::OmplPathPlanner planner(robot, scene);
            const auto px = p.model->config().pedestrianStart[0], py = p.model->config().pedestrianStart[1];
            const double near[3] = {px + 0.4, py - 0.4, PI / 2};  // base front into the capsule, 0.31 m from the sphere
            const double far[3] = {px + 0.8, py - 0.4, PI / 2};
            EXPECT_EQ(planner.checker().isValid(*scene, near), sweep == 0.0) << "sweep " << sweep;
            EXPECT_TRUE(planner.checker().isValid(*scene, far)) << "sweep " << sweep;
        }
    }

    TEST(CrossingScenarioTest, BadConfigurationsAreErrorsNamingTheKey)
    {
        expectError({{"colour", 1}}, "colour");
        expectError({{"lab", {{-1.9, -2.0}, {-2.0, 2.0}}}}, "lab");
        expectError({{"lab", {{-3.0, -2.0}, {3.0, 2.0}}}}, "lab");  // the robot's base joints span the lab
        expectError({{"wheel_acceleration", 0.0}}, "wheel_acceleration");
        expectError({{"wheel_base", -0.3}}, "wheel_base");
        expectError({{"speed_noise", {0.03}}}, "speed_noise");
        expectError({{"speed_noise", {0.03, -1.0}}}, "speed_noise");
        expectError({{"linear_speeds", nlohmann::json::array()}}, "linear_speeds");
        expectError({{"linear_speeds", {0.1, -0.2}}}, "linear_speeds");
        expectError({{"observation_sigma", {0.1, 0.0, 0.1}}}, "observation_sigma");
        expectError({{"discount", 1.0}}, "discount");
        expectError({{"horizon", 7.5}}, "horizon");
        expectError({{"close_distance", std::numeric_limits<double>::quiet_NaN()}}, "close_distance");
        expectError({{"start", {1.0, -1.4, 0.0}}}, "start");    // in a table
        expectError({{"start", {-1.85, -1.4, 0.0}}}, "start");  // against the wall
        expectError({{"goal", {5.0, 0.0}}}, "goal");
        expectError({{"landmarks", {{1.3, 1.25}}}}, "landmarks");
        expectError({{"pedestrian_start", {1.85, 0.1}}}, "pedestrian_start");
        expectError({{"tables", {{{"center", {0, 0, 0}}, {"half_extents", {0.1, -0.1, 0.1}}}}}}, "tables");
        expectError({{"lift", 2.0}}, "lift");
        expectError({{"arm", -0.1}}, "arm");
        expectError({{"substep", 0.0}}, "substep");
        expectError({{"world_pedestrian_speed_noise", 1.5}}, "world_pedestrian_speed_noise");
        expectError({{"heuristic_value", 1}}, "heuristic_value");
        expectError({{"planning", {{"lookahead", -0.5}}}}, "planning.lookahead");
        expectError({{"planning", {{"path_nodes", 1}}}}, "planning.path_nodes");
        expectError({{"planning", {{"pedestrian_sweep", -1}}}}, "planning.pedestrian_sweep");
        expectError({{"planning", {{"speed", 1}}}}, "planning.speed");
        expectError({{"defaults", {{"depth", "deep"}}}}, "depth");
        // A valid override goes through.
        const auto parts = partsWith({{"goal_tolerance", 0.2}, {"planning", {{"lookahead", 0.4}}}});
        EXPECT_DOUBLE_EQ(parts.model->config().goalTolerance, 0.2);
        EXPECT_DOUBLE_EQ(parts.model->config().planning.lookahead, 0.4);
        EXPECT_DOUBLE_EQ(parts.model->config().planning.headingWeight, 0.5);
    }

    TEST(CrossingScenarioTest, EpisodesCompleteForRopras3RpomcpAndBplan)
    {
        const std::unique_ptr<Scenario> scenario = makeCrossingScenario();
        for (const char *solver : {"ropras3", "rpomcp", "bplan"})
        {
            RunSettings settings;
            settings.solver = solver;
            settings.heuristic = "uniform";
            settings.budget = pomdp::Budget::ofSimulations(20);
            // reference plans limited by iterations, not (load-dependent) time: reproducible
            settings.params.set("plan_time", 1.0);
            settings.params.set("plan_iterations", 3000);
            nlohmann::json recording;
            const auto a = scenario->runEpisode(settings, 7, &recording);
            EXPECT_GE(a.steps, 1u) << solver;
            EXPECT_LE(a.steps, 75u) << solver;
            EXPECT_GE(a.plans, 1u) << solver;
            EXPECT_TRUE(std::isfinite(a.undiscountedReturn));
            // the reference planner was used and succeeded most of the time
            EXPECT_GT(a.search.referenceRequested, 0u) << solver;
            EXPECT_LT(a.search.referenceFailed, a.search.referenceRequested) << solver;
            // a seeded planner and a simulation budget: the same seed gives the same episode
            const auto b = scenario->runEpisode(settings, 7);
            EXPECT_EQ(a.steps, b.steps) << solver;
            EXPECT_DOUBLE_EQ(a.undiscountedReturn, b.undiscountedReturn) << solver;
            // the recording has one footprint and one pedestrian disc per state, and the events
            ASSERT_EQ(recording["trajectory"].size(), a.steps + 1);
            ASSERT_TRUE(recording.contains("events"));
            if (a.success)
            {
                EXPECT_EQ(recording["events"].back()["event"], "goal");
            }
            const std::string svg = renderSvg(recording);
            // the footprints are the polygons of the "footprint" group (path arrows are polygons too)
            const std::size_t begin = svg.find("<g id=\"footprint\">");
            ASSERT_NE(begin, std::string::npos) << solver;
            const std::size_t end = svg.find("</g>", begin);
            std::size_t polygons = 0;
            for (std::size_t at = svg.find("<polygon", begin); at < end; at = svg.find("<polygon", at + 1))
            {
                ++polygons;
            }
            EXPECT_EQ(polygons, a.steps + 1) << solver;
            EXPECT_NE(svg.find("id=\"discs\""), std::string::npos);
        }
    }

    TEST(CrossingScenarioTest, EveryRegistryPlannerCanBeTheReferencePlanner)
    {
        const std::unique_ptr<Scenario> scenario = makeCrossingScenario();
        for (const char *planner : {"RRTConnect", "PRM", "BITstar", "VectorizedRRTConnect"})
        {
            RunSettings settings;
            settings.solver = "ropras3";
            settings.heuristic = "uniform";
            settings.planner = planner;
            settings.budget = pomdp::Budget::ofSimulations(5);
            const auto r = scenario->runEpisode(settings, 3);
            EXPECT_GE(r.steps, 1u) << planner;
            EXPECT_GT(r.search.referenceRequested, 0u) << planner;
            EXPECT_LT(r.search.referenceFailed, r.search.referenceRequested) << planner;
        }
    }
}  // namespace ropras::scenarios
