// The navigation model (Light-Dark, Maze2D, Random3D) against its world and against its specification.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdlib>
#include <iostream>

#include "ExpectError.h"
#include "NavigationTestUtil.h"
#include "ropras/scenarios/navigation/NavigationPlanning.h"
#include "ropras/scenarios/navigation/NavigationWorld.h"

namespace ropras::scenarios::test
{
    using ropras::test::expectErrorMentions;

    namespace
    {
        /// exact distance from p to the nearest wall/obstacle box minus the radius (third computation)
        double signedClearance(const NavigationConfig &c, const double *p)
        {
            double best = 1e300;
            for (const auto *list : {&c.walls, &c.obstacles})
            {
                for (const auto &b : *list)
                {
                    double d2 = 0.0;
                    for (int k = 0; k < 3; ++k)
                    {
                        const double e = std::max({0.0, b.lo[k] - p[k], p[k] - b.hi[k]});
                        d2 += e * e;
                    }
                    best = std::min(best, std::sqrt(d2));
                }
            }
            return best - c.robotRadius;
        }

        /// Model (grid geometry) and world (Bullet) agree on every random move, except within 1e-3 m of contact.
        void expectModelAndWorldAgree(const std::string &name, int moves)
        {
            const auto scenario = navScenario(name);
            const auto model = asNav(*scenario).parts().model;
            const auto &c = model->config();
            NavigationWorld world(model);
            pomdp::Rng rng(11);
            int blockedCount = 0, compared = 0;
            NavState s = at(c.starts[0][0], c.starts[0][1], c.starts[0][2]);
            for (int i = 0; i < moves; ++i)
            {
                // restart every 20 moves at a random free position near a box (many moves end near contact)
                if (i % 20 == 0)
                {
                    const auto &boxes = c.obstacles.empty() ? c.walls : c.obstacles;
                    const auto &b = boxes[rng.uniformIndex(boxes.size())];
                    do
                    {
                        for (int k = 0; k < c.dims; ++k)
                        {
                            s.p[k] = rng.uniform(b.lo[k] - 1.0, b.hi[k] + 1.0);
                        }
                    } while (model->blocked(s.p));
                    world.reset(s);
                }
                const auto a = static_cast<NavigationModel::Action>(rng.uniformIndex(model->numActions()));
                const std::uint64_t seed = rng.split();
                pomdp::Rng r1(seed), r2(seed);
                const auto fromModel = model->step(s, a, r1);
                const auto fromWorld = world.step(a, r2);
                // the move both tried (the same slip draw from the same stream)
                pomdp::Rng r3(seed);
                const NavState tried = model->moved(s, model->executedAction(a, r3));
                if (std::abs(signedClearance(c, tried.p)) > 1e-3)
                {
                    ++compared;
                    const bool blocked =
                        fromModel.next.p[0] == s.p[0] && fromModel.next.p[1] == s.p[1] && fromModel.next.p[2] == s.p[2];
                    blockedCount += blocked;
                    for (int k = 0; k < 3; ++k)
                    {
                        ASSERT_EQ(fromModel.next.p[k], fromWorld.next.p[k]) << name << " move " << i << " axis " << k;
                    }
                    EXPECT_EQ(fromModel.reward, fromWorld.reward);
                    EXPECT_EQ(fromModel.terminal, fromWorld.terminal);
                    EXPECT_EQ(fromModel.observation.seen, fromWorld.observation.seen);
                }
                s = world.state();
                if (fromWorld.terminal)
                {
                    s = at(c.starts[0][0], c.starts[0][1], c.starts[0][2]);
                    world.reset(s);
                }
            }
            EXPECT_GT(compared, moves * 9 / 10) << name;
            EXPECT_GT(blockedCount, moves / 20) << name << ": too few blocked moves to test anything";
            EXPECT_LT(blockedCount, compared - moves / 20) << name;
        }
    }  // namespace

    TEST(NavigationModel, ModelAndBulletWorldAgreeMaze2D)
    {
        expectModelAndWorldAgree("maze2d", 6000);
    }
    TEST(NavigationModel, ModelAndBulletWorldAgreeRandom3D)
    {
        expectModelAndWorldAgree("random3d-4", 6000);
    }

    TEST(NavigationModel, ObservationsMatchTheirDensity)
    {
        const auto scenario = navScenario("light-dark");
        const auto &model = *asNav(*scenario).parts().model;
        pomdp::Rng rng(5);
        // In the light stripe (x in [2.5, 3.5]): a right step from x = 2.75 lands at 3.25.
        const NavState s = at(2.75, 0.3);
        const int n = 20000;
        double sum[2] = {0, 0}, sq[2] = {0, 0};
        for (int i = 0; i < n; ++i)
        {
            const auto r = model.step(s, 0, rng);
            ASSERT_TRUE(r.observation.seen);
            ASSERT_DOUBLE_EQ(r.next.p[0], 3.25);
            for (int k = 0; k < 2; ++k)
            {
                const double e = r.observation.p[k] - r.next.p[k];
                sum[k] += e;
                sq[k] += e * e;
            }
            EXPECT_GT(model.observationProbability(r.observation, r.next, 0), 0.0);
        }
        for (int k = 0; k < 2; ++k)
        {
            const double mean = sum[k] / n, var = sq[k] / n - mean * mean;
            EXPECT_LT(std::abs(mean), 5.0 * 0.1 / std::sqrt(n)) << "axis " << k;
            EXPECT_NEAR(var, 0.01, 0.01 * 0.06) << "axis " << k;  // 6% ~ 4 standard errors of a variance
        }
        // Density: the Gaussian product; None in the dark has probability 1, a position in the dark 0.
        NavObservation o;
        o.seen = true;
        o.p[0] = 3.35;
        o.p[1] = 0.1;
        const double expected = std::exp(-0.5 * (1.0 + 4.0)) / (2.0 * M_PI * 0.01);
        EXPECT_NEAR(model.observationProbability(o, at(3.25, 0.3), 0), expected, 1e-9 * expected);
        const NavState dark = at(0.0, 2.0);
        EXPECT_EQ(model.observationProbability(o, dark, 0), 0.0);
        EXPECT_EQ(model.observationProbability(NavObservation{}, dark, 0), 1.0);
        EXPECT_EQ(model.observationProbability(NavObservation{}, at(3.25, 0.3), 0), 0.0);
        // in the dark: always None
        const auto r = model.step(at(0.0, 2.0), 0, rng);
        EXPECT_FALSE(r.observation.seen);
        EXPECT_EQ(model.observationKey(r.observation), NavigationModel::NONE_KEY);
        // binning: nearby observations share a key, far ones do not
        NavObservation o2 = o;
        o2.p[0] = 3.45;
        NavObservation o3 = o;
        o3.p[0] = 1.0;
        EXPECT_EQ(model.observationKey(o), model.observationKey(o2));
        EXPECT_NE(model.observationKey(o), model.observationKey(o3));
    }

    TEST(NavigationModel, SlipFrequencyIsTwentyPercentUniformOverTheOthers)
    {
        const auto scenario = navScenario("maze2d");
        const auto &model = *asNav(*scenario).parts().model;
        pomdp::Rng rng(9);
        const NavState s = at(-20.0, 15.0);  // a free start, 1 m of room in every direction
        const int n = 20000;
        int counts[4] = {0, 0, 0, 0};
        for (int i = 0; i < n; ++i)
        {
            const auto r = model.step(s, 2, rng);  // +y
            const double dx = r.next.p[0] - s.p[0], dy = r.next.p[1] - s.p[1];
            const int executed = dx > 0 ? 0 : dx < 0 ? 1 : dy > 0 ? 2 : 3;
            ++counts[executed];
            ASSERT_NEAR(std::abs(dx) + std::abs(dy), 0.5, 1e-12);
        }
        // binomial(n, 0.2): sd = sqrt(n * 0.16) ~ 57; allow 5 sd
        EXPECT_NEAR(n - counts[2], 0.2 * n, 5 * std::sqrt(n * 0.16));
        for (int a : {0, 1, 3})
        {
            EXPECT_NEAR(counts[a], 0.2 * n / 3.0, 5 * std::sqrt(n * 0.2 / 3.0)) << "action " << a;
        }
        // Light-Dark is deterministic
        const auto ld = navScenario("light-dark");
        const auto &ldModel = *asNav(*ld).parts().model;
        for (int i = 0; i < 1000; ++i)
        {
            ASSERT_DOUBLE_EQ(ldModel.step(at(0.0, 2.0), 1, rng).next.p[0], -0.5);
        }
    }

    TEST(NavigationModel, GoalDangerAndStepRewards)
    {
        const auto scenario = navScenario("maze2d", {{"slip", 0.0}});
        const auto &model = *asNav(*scenario).parts().model;
        pomdp::Rng rng(1);
        // goal x in [19, 24]: from 18.75 a +x step enters
        auto r = model.step(at(18.75, 0.0), 0, rng);
        EXPECT_TRUE(r.terminal);
        EXPECT_DOUBLE_EQ(r.reward, 800.0 - 0.1);
        EXPECT_TRUE(model.reachedGoal(r.next));
        // danger zone [[14, 6], [24, 10]]: from y = 5.75 a +y step enters
        r = model.step(at(16.0, 5.75), 2, rng);
        EXPECT_TRUE(r.terminal);
        EXPECT_DOUBLE_EQ(r.reward, -2000.0 - 0.1);
        EXPECT_FALSE(model.reachedGoal(r.next));
        // an ordinary step
        r = model.step(at(-20.0, 15.0), 0, rng);
        EXPECT_FALSE(r.terminal);
        EXPECT_DOUBLE_EQ(r.reward, -0.1);
        // a blocked step stays: wall [[-12, 2.5], [-11, 25]], radius 0.25; from x = -12.5 a +x step would touch
        r = model.step(at(-12.5, 10.0), 0, rng);
        EXPECT_DOUBLE_EQ(r.next.p[0], -12.5);
        EXPECT_DOUBLE_EQ(r.reward, -0.1);
        // the bounds block too
        r = model.step(at(-24.9, -10.0), 1, rng);
        EXPECT_DOUBLE_EQ(r.next.p[0], -24.9);
    }

    TEST(NavigationModel, TerminationEvidenceRulesOutGoalAndDangerParticles)
    {
        for (const bool evidence : {false, true})
        {
            const auto scenario = navScenario("maze2d", {{"slip", 0.0}, {"termination_evidence", evidence}});
            const auto &model = *asNav(*scenario).parts().model;
            pomdp::Rng rng(1);
            const auto ended = model.step(at(18.75, 0.0), 0, rng);  // enters the goal
            const auto wentOn = model.step(at(-20.0, 15.0), 0, rng);
            ASSERT_TRUE(ended.terminal);
            ASSERT_FALSE(wentOn.terminal);
            EXPECT_EQ(ended.observation.ended, evidence);
            EXPECT_FALSE(wentOn.observation.ended);
            // "the episode went on" from a goal particle and a danger particle: impossible only with the evidence
            const double inGoal = model.observationProbability(wentOn.observation, at(21.0, 0.0), 0);
            const double inDanger = model.observationProbability(wentOn.observation, at(16.0, 8.0), 0);
            const double free = model.observationProbability(wentOn.observation, at(-20.0, 0.0), 0);
            EXPECT_EQ(inGoal, evidence ? 0.0 : 1.0);
            EXPECT_EQ(inDanger, evidence ? 0.0 : 1.0);
            EXPECT_EQ(free, 1.0);
            EXPECT_EQ(model.observationProbability(ended.observation, at(21.0, 0.0), 0), 1.0);
            EXPECT_EQ(model.observationKey(ended.observation) != model.observationKey(wentOn.observation), evidence);
        }
    }

    TEST(NavigationModel, InitialBelief)
    {
        const auto maze = navScenario("maze2d");
        const auto &mazeModel = *asNav(*maze).parts().model;
        pomdp::Rng rng(2);
        int upper = 0;
        for (int i = 0; i < 2000; ++i)
        {
            const auto s = mazeModel.sampleInitialState(rng);
            ASSERT_EQ(s.p[0], -20.0);
            ASSERT_TRUE(s.p[1] == 15.0 || s.p[1] == -15.0);
            upper += s.p[1] > 0;
        }
        EXPECT_NEAR(upper, 1000, 5 * std::sqrt(500.0));  // bimodal Dirac, 50/50
        // Light-Dark: the start plus N(0, initial_sigma) per axis (0.4 here: samples never leave the bounds)
        const auto ld = navScenario("light-dark", {{"initial_sigma", 0.4}});
        const auto &ldModel = *asNav(*ld).parts().model;
        double sum = 0, sq = 0;
        for (int i = 0; i < 4000; ++i)
        {
            const double x = ldModel.sampleInitialState(rng).p[0] + 2.5;
            sum += x;
            sq += x * x;
        }
        EXPECT_NEAR(sum / 4000, 0.0, 5 * 0.4 / std::sqrt(4000.0));
        EXPECT_NEAR(sq / 4000, 0.16, 0.16 * 0.12);
    }

    TEST(NavigationModel, Maze2DNeedsAHundredStepsAndHasADangerFreePath)
    {
        const auto scenario = navScenario("maze2d", {{"slip", 0.0}});
        const auto &model = *asNav(*scenario).parts().model;
        for (const auto &start : model.config().starts)
        {
            const std::size_t safe = shortestGoalSteps(model, at(start[0], start[1]), true);
            const std::size_t any = shortestGoalSteps(model, at(start[0], start[1]), false);
            std::cout << "maze2d H_min from (" << start[0] << ", " << start[1] << "): " << safe
                      << " steps avoiding danger, " << any << " through danger\n";
            EXPECT_GE(safe, 100u) << "H_min from (" << start[0] << ", " << start[1] << ")";
            EXPECT_GE(any, 100u);
            EXPECT_LE(any, safe);
            EXPECT_LE(safe, 400u);
            // the heuristic value's distance field (a multi-source BFS from the goal) agrees with the forward BFS
            EXPECT_EQ(model.goalDistance(start.data()), static_cast<long>(safe));
            EXPECT_NEAR(model.heuristicValue(at(start[0], start[1])), fieldValue(model.discount(), safe), 1e-9);
        }
        // off in Light-Dark: no leaf value
        const auto ld = navScenario("light-dark");
        EXPECT_EQ(asNav(*ld).parts().model->heuristicValue(at(-2.5, 2.5)), 0.0);
        // a wall closing the first gap makes the goal unreachable: the BFS can fail
        const auto closed = navScenario("maze2d", {{"walls", {{{-12, -25}, {-11, 25}}}}});
        EXPECT_EQ(shortestGoalSteps(*asNav(*closed).parts().model, at(-20, 15), true), 0u);
    }

    TEST(NavigationModel, Random3DLeavesAreWorthZeroUnlessTheFieldIsOn)
    {
        // off by default (issue 14: the field's leaf value made the search put off risky passages); switched on, the
        // field is the discounted shortest danger-free lattice path
        for (const char *name : {"random3d-1", "random3d-2", "random3d-3", "random3d-4"})
        {
            const auto r3 = navScenario(name);
            const auto &off = *asNav(*r3).parts().model;
            const double *p = off.config().starts.front().data();
            const NavState start = at(p[0], p[1], p[2]);
            EXPECT_EQ(off.goalDistance(p), -1) << name;
            EXPECT_EQ(off.heuristicValue(start), 0.0) << name;
            const auto on = navScenario(name, {{"heuristic_value", true}});
            const auto &field = *asNav(*on).parts().model;
            const long d = field.goalDistance(p);
            // the field (a grid anchored at the bounds, the start rounded to its nearest cell: at most half a step
            // per axis) agrees with the forward BFS from the start that avoids danger zones (H_min, 45-47 steps)
            const auto hMin = static_cast<long>(shortestGoalSteps(field, start, true));
            EXPECT_GE(hMin, 40) << name;
            EXPECT_LE(std::abs(d - hMin), 3) << name << ": field " << d << ", forward BFS " << hMin;
            ASSERT_GE(d, 0) << name;
            EXPECT_NEAR(field.heuristicValue(start), fieldValue(field.discount(), static_cast<std::size_t>(d)), 1e-9)
                << name;
        }
    }

    TEST(NavigationModel, HeuristicDecayDiscountsOnlyTheGoalRewardPerStepOfTheField)
    {
        // heuristic_decay rho: goal_reward (gamma rho)^d + the step rewards of the d steps, d the field's distance
        const double rho = 0.98;
        const auto plain = navScenario("random3d-2", {{"heuristic_value", true}});
        const auto decayed = navScenario("random3d-2", {{"heuristic_value", true}, {"heuristic_decay", rho}});
        const auto &a = *asNav(*plain).parts().model;
        const auto &b = *asNav(*decayed).parts().model;
        const double *p = a.config().starts.front().data();
        const NavState start = at(p[0], p[1], p[2]);
        const long d = b.goalDistance(p);
        ASSERT_GT(d, 40);
        EXPECT_EQ(a.goalDistance(p), d);
        const double g = b.discount();
        const auto steps = static_cast<std::size_t>(d);
        EXPECT_NEAR(b.heuristicValue(start), fieldValue(g, steps, rho), 1e-9);
        // the same steps, a smaller goal term: the difference is the goal reward's share rho^d takes away
        const double gd = std::pow(g, static_cast<double>(d));
        EXPECT_NEAR(a.heuristicValue(start) - b.heuristicValue(start),
                    800.0 * gd * (1.0 - std::pow(rho, static_cast<double>(d))), 1e-9);
        // a cell next to the goal (d = 1) keeps the share rho of it: walk out of the goal box along each axis
        const auto &goal = b.config().goal;
        const auto centre = goal.center();
        bool found = false;
        for (int k = 0; k < 3 && !found; ++k)
            for (const double dir : {1.0, -1.0})
            {
                double q[3] = {centre[0], centre[1], centre[2]};
                while (!found && goal.contains(q))
                    q[k] += 0.5 * dir;
                if (!found && b.goalDistance(q) == 1)
                {
                    EXPECT_NEAR(b.heuristicValue(at(q[0], q[1], q[2])), fieldValue(g, 1, rho), 1e-9);
                    found = true;
                }
            }
        ASSERT_TRUE(found);
        // off: no leaf value whatever the decay
        const auto off = navScenario("random3d-2", {{"heuristic_decay", rho}});
        EXPECT_EQ(asNav(*off).parts().model->heuristicValue(start), 0.0);
    }

    TEST(NavigationModel, LightDarkHMinIsEight)
    {
        const auto scenario = navScenario("light-dark");
        const auto &model = *asNav(*scenario).parts().model;
        EXPECT_EQ(shortestGoalSteps(model, at(-2.5, 2.5), true), 8u);
    }

    TEST(NavigationModel, Random3DVariantsAreSolvableAndFar)
    {
        for (const char *name : {"random3d-1", "random3d-2", "random3d-3", "random3d-4"})
        {
            const auto scenario = navScenario(name);
            const auto &model = *asNav(*scenario).parts().model;
            const auto &c = model.config();
            EXPECT_EQ(c.dims, 3);
            const std::size_t steps = shortestGoalSteps(model, at(c.starts[0][0], c.starts[0][1], c.starts[0][2]));
            std::cout << name << " H_min: " << steps << " steps\n";
            EXPECT_GE(steps, 40u) << name;
            EXPECT_LT(steps, 200u) << name;
            EXPECT_FALSE(model.blocked(c.starts[0].data()));
            const std::string n(name);
            const std::size_t obstacles = n == "random3d-1"   ? 100
                                          : n == "random3d-2" ? 200
                                          : n == "random3d-3" ? 300
                                                              : 400;
            const std::size_t danger = n == "random3d-1" ? 15 : n == "random3d-4" ? 5 : 10;
            EXPECT_EQ(c.obstacles.size(), obstacles) << name;
            EXPECT_EQ(c.dangerZones.size(), danger) << name;
            // deterministic from the seed
            const auto again = navScenario(name);
            EXPECT_EQ(again->scene(), scenario->scene()) << name;
        }
        // another seed, another layout
        EXPECT_NE(navScenario("random3d-1", {{"generator", {{"seed", 77}}}})->scene(),
                  navScenario("random3d-1")->scene());
    }

    TEST(NavigationModel, Random3DCorridorPlacesBoxesAlongTheStartGoalLine)
    {
        // distance (max norm) from a point to the segment start + t (goal - start), t in [0.1, 0.9]
        const auto corridorDistance = [](const std::array<double, 3> &p, const NavigationConfig &c)
        {
            const auto &a = c.starts[0];
            const auto g = c.goal.center();
            double best = 1e300;
            for (int i = 0; i <= 800; ++i)
            {
                const double t = 0.1 + 0.8 * i / 800.0;
                double d = 0.0;
                for (int k = 0; k < 3; ++k)
                    d = std::max(d, std::abs(p[k] - (a[k] + t * (g[k] - a[k]))));
                best = std::min(best, d);
            }
            return best;
        };
        const auto countNear = [&](double fraction)
        {
            const auto scenario =
                navScenario("random3d-2", {{"generator", {{"corridor_fraction", fraction}, {"corridor_radius", 3.0}}}});
            const auto &c = asNav(*scenario).parts().model->config();
            std::size_t near = 0;
            for (const auto &b : c.obstacles)
                near += corridorDistance(b.center(), c) <= 3.0 + 2.5 ? 1 : 0;  // + clamping into the bounds
            return std::make_pair(near, c.obstacles.size());
        };
        const auto all = countNear(1.0);
        EXPECT_EQ(all.first, all.second);  // every obstacle centred in the corridor
        const auto none = countNear(0.0);
        EXPECT_LT(none.first, none.second / 5);  // uniform placement: few near the line
        expectErrorMentions(
            [] {
                navScenario("random3d-1", {{"generator", {{"corridor_fraction", 1.5}}}});
            },
            {"random3d-1", "corridor_fraction"});
    }

    TEST(NavigationModel, StaircaseMacroFollowsThePath)
    {
        const auto scenario = navScenario("light-dark");
        const auto model = asNav(*scenario).parts().model;
        NavigationPlanningAdapter adapter(model, 10);
        const double path[] = {0.0, 0.0, 1.0, 0.5, 1.0, -1.0};
        std::vector<std::uint8_t> out;
        ASSERT_TRUE(adapter.pathToMacroAction(at(0.0, 0.0), path, 3, out));
        // replay: ends at (1, -1) on the lattice, each action one axis step
        double x = 0.0, y = 0.0;
        for (auto a : out)
        {
            x += a == 0 ? 0.5 : a == 1 ? -0.5 : 0.0;
            y += a == 2 ? 0.5 : a == 3 ? -0.5 : 0.0;
        }
        EXPECT_DOUBLE_EQ(x, 1.0);
        EXPECT_DOUBLE_EQ(y, -1.0);
        EXPECT_EQ(out.size(), 6u);  // |dx| + |dy| = 1 + 0.5 + 1.5 = 3 m = 6 steps
        NavigationPlanningAdapter shortAdapter(model, 2);
        out.clear();
        ASSERT_TRUE(shortAdapter.pathToMacroAction(at(0.0, 0.0), path, 3, out));
        EXPECT_EQ(out.size(), 2u);
    }
}  // namespace ropras::scenarios::test
