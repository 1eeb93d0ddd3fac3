// Shelf-Move's model: the configuration's geometry is reachable, grasp and place events, the held can follows the
// hand, blocked steps, observations, and reinvigoration that never makes cans interpenetrate or float.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <memory>
#include <nlohmann/json.hpp>
#include <vector>

#include "ReferencePolicyTestUtil.h"
#include "ShelfMoveTestUtil.h"
#include "ropras/core/Error.h"
#include "ropras/pomdp/OmplPathPlanner.h"
#include "ropras/scenarios/ScenarioRegistry.h"
#include "ropras/scenarios/manipulation/ShelfMovePlanning.h"
#include "ropras/scenarios/manipulation/ShelfMoveScenario.h"

namespace ropras::scenarios
{
    namespace
    {
        using State = ShelfMoveModel::State;

        nlohmann::json defaultJson()
        {
            return test::shelfMoveJson();
        }

        std::shared_ptr<const ShelfMoveModel> makeModel(const nlohmann::json &json = defaultJson())
        {
            return test::makeShelfMoveModel(json);
        }

        const std::shared_ptr<const ShelfMoveModel> &model()
        {
            return test::shelfMoveModel();
        }

        /// a configuration for \a target in the true initial scene (or \a s), solved by the planner's IK
        bool solveTarget(const State &s, const ShelfTarget &target, double *q, std::uint64_t seed = 7)
        {
            ShelfMoveIk ik(model(), 30, seed);
            const auto scene = model()->makeScene(s, false);
            return ik.solve(s, target, *scene, q);
        }

        struct Outcome
        {
            State state;
            double reward{0.0};
            bool terminal{false};
            std::size_t blocked{0};  ///< primitives that moved less than commanded
            std::string failure;     ///< the stage that failed: "ik", "plan" or "conversion"
        };

        /** \brief What the reference policy does for \a target: IK in the particle's planning scene, a
            VectorizedRRTConnect plan there, PathToMacroAction (ShelfMoveAdapter); then the macro run through
            the model. False when there is no target configuration or no plan. */
        bool execute(const State &s, const ShelfTarget &target, pomdp::Rng &rng, Outcome &out, std::uint64_t seed = 7)
        {
            ShelfMoveAdapter adapter(model(), std::make_unique<ShelfMoveIk>(model(), 30, seed));
            double goal[ARM_DOF];
            out = Outcome();
            if (!adapter.targetConfiguration(s, target, goal))
            {
                out.failure = "ik";
                return false;
            }
            pomdp::OmplPathPlannerSettings settings;
            settings.timeLimit = 2.0;
            settings.resolution = model()->config().resolution;
            settings.plannerParams["seed"] = std::to_string(seed);
            auto scene = adapter.environment(s);
            if (!model()->arm().checker()->isValid(*scene, s.q))
                scene = adapter.trueEnvironment(s);  // inside the planning margin: as OmplReferencePolicy plans it
            pomdp::OmplPathPlanner planner(model()->arm().robot(), scene, settings);
            if (planner.plan(s.q, goal) != pomdp::PathPlanStatus::Solved)
            {
                out.failure = "plan";
                return false;
            }
            std::vector<ShelfMoveAction> macro;
            if (!adapter.pathToMacroAction(s, planner.path().data(), planner.waypointCount(), macro))
            {
                out.failure = "conversion";
                return false;
            }
            out.state = s;
            for (const auto &a : macro)
            {
                const auto r = model()->step(out.state, a, rng);
                double moved = 0.0, commanded = 0.0;
                for (std::size_t j = 0; j < ARM_DOF; ++j)
                {
                    moved += std::abs(r.next.q[j] - out.state.q[j]);
                    commanded += std::abs(a.waypoint ? a.dq[j] - out.state.q[j] : a.dq[j]);
                }
                out.blocked += moved < 0.5 * commanded;
                out.state = r.next;
                out.reward += r.reward;
                out.terminal = out.terminal || r.terminal;
            }
            return true;
        }
    }  // namespace

    TEST(ShelfMoveModel, TheFrontCansBlockTheTargetWhoseGraspIsFreeOnceTheyAreMoved)
    {
        const auto &m = *model();
        const State s0 = m.trueInitialState();
        EXPECT_TRUE(m.validState(s0));
        const ShelfMoveTargetSpace space(model());
        const int target = static_cast<int>(m.config().targetCan);
        for (int k = 0; k < static_cast<int>(SHELF_CANS); ++k)
        {
            double q[ARM_DOF];
            if (k == target)
            {
                EXPECT_FALSE(solveTarget(s0, space.grasp(s0, k), q)) << "the target is not packed in";
                continue;
            }
            ASSERT_TRUE(solveTarget(s0, space.grasp(s0, k), q)) << "can " << k;
            State at = s0;
            ShelfMoveModel::setJoints(at, q);
            EXPECT_TRUE(m.validState(at)) << "can " << k;
            EXPECT_EQ(m.graspableCan(at), k);
            EXPECT_LT((m.graspPoint(at) - Eigen::Vector3d(s0.can[k][0], s0.can[k][1], s0.can[k][2])).norm(), 1e-3);
        }
        // the front cans on the lower free spots (slots 3, 4) and a top slot (0): the target's grasp is free
        State cleared = s0;
        const std::size_t moves[3][2] = {{1, 3}, {2, 0}, {3, 4}};
        for (const auto &move : moves)
        {
            for (int a = 0; a < 3; ++a)
            {
                cleared.can[move[0]][a] = m.config().slots[move[1]][static_cast<std::size_t>(a)];
            }
        }
        ASSERT_TRUE(m.validState(cleared));
        double q[ARM_DOF];
        EXPECT_TRUE(solveTarget(cleared, space.grasp(cleared, target), q));
        // every can can be sensed from somewhere collision-free
        for (int k = 0; k < static_cast<int>(SHELF_CANS); ++k)
        {
            ASSERT_TRUE(solveTarget(s0, space.sense(s0, k), q)) << "sense can " << k;
            State at = s0;
            ShelfMoveModel::setJoints(at, q);
            EXPECT_LE((m.endEffector(at) - Eigen::Vector3d(s0.can[k][0], s0.can[k][1], s0.can[k][2])).norm(),
                      m.config().senseDistance);
        }
    }

    // A can moved out of the way (parked at a slot other than the reserved one) is neither grasped nor sensed again:
    // right after its release the hand is at it, and 1/distance weights would pick it again and again (an episode
    // grasped and released can 1 nine times in a row). A can on the reserved slot stays graspable (to clear it).
    TEST(ShelfMoveModel, ParkedCansAreNoLongerInformative)
    {
        const auto &m = *model();
        const ShelfMoveTargetSpace space(model());
        const auto targets = [&](const State &s)
        {
            std::vector<std::pair<ShelfTarget::Kind, int>> out;
            for (std::size_t i = 0; i < space.numInformative(s); ++i)
                out.emplace_back(space.informative(s, i).kind, space.informative(s, i).can);
            return out;
        };
        const auto has = [](const std::vector<std::pair<ShelfTarget::Kind, int>> &t, ShelfTarget::Kind kind, int can)
        { return std::find(t.begin(), t.end(), std::make_pair(kind, can)) != t.end(); };
        const State s0 = m.trueInitialState();
        const auto initial = targets(s0);
        EXPECT_EQ(initial.size(), 3u + 4u) << "grasp the 3 obstacles, sense the 4 cans";
        State parked = s0;
        for (int a = 0; a < 3; ++a)
        {
            parked.can[1][a] = m.config().slots[3][static_cast<std::size_t>(a)];
            parked.can[2][a] = m.config().slots[m.config().reservedSlot][static_cast<std::size_t>(a)];
        }
        EXPECT_TRUE(space.parked(parked, 1));
        EXPECT_FALSE(space.parked(parked, 2)) << "the reserved slot is not a parking place";
        EXPECT_FALSE(space.parked(parked, 3));
        const auto after = targets(parked);
        EXPECT_EQ(after.size(), 2u + 3u);
        EXPECT_FALSE(has(after, ShelfTarget::Kind::Grasp, 1));
        EXPECT_FALSE(has(after, ShelfTarget::Kind::Sense, 1));
        EXPECT_TRUE(has(after, ShelfTarget::Kind::Grasp, 2));
        EXPECT_TRUE(has(after, ShelfTarget::Kind::Grasp, 3));
        EXPECT_TRUE(has(after, ShelfTarget::Kind::Sense, 0));
        EXPECT_FALSE(has(after, ShelfTarget::Kind::Grasp, 0)) << "the target's grasp is the goal, not informative";
        // a parked can that is held is not parked: holding it, the slots are offered again
        State holding = parked;
        holding.held = 1;
        EXPECT_FALSE(space.parked(holding, 1));
        EXPECT_EQ(space.numInformative(holding), m.config().slots.size() - 1 + 4u);
        for (std::size_t i = 0; i < space.numInformative(holding); ++i)
            if (space.informative(holding, i).kind == ShelfTarget::Kind::Place)
            {
                EXPECT_NE(space.informative(holding, i).slot, static_cast<int>(m.config().reservedSlot))
                    << "an obstacle is never offered the target's slot";
            }
    }

    // The goal chain: while a can blocks the target's grasp, the goal is grasping that can. "Blocks" is a geometric
    // test (in front, within planning.blocking_halfwidth sideways); it agrees with the IK: the target's grasp has no
    // solution exactly when a blocker is reported, and the goal grasp has one in every case.
    TEST(ShelfMoveModel, TheGoalGraspsTheCanThatBlocksTheTargetUntilNoneDoes)
    {
        // the default approaches (straight and turned by +-15 and +-30 degrees), then the straight one alone
        auto straightJson = defaultJson();
        straightJson["planning"]["grasp_yaws"] = {0};
        for (const bool straight : {false, true})
        {
            const auto m = straight ? makeModel(straightJson) : model();
            const ShelfMoveTargetSpace space(m);
            const State s0 = m->trueInitialState();
            const int target = static_cast<int>(m->config().targetCan);
            const auto moved = [&](const std::vector<std::pair<std::size_t, std::size_t>> &moves)
            {
                State s = s0;
                for (const auto &[can, slot] : moves)
                    for (int a = 0; a < 3; ++a)
                        s.can[can][a] = m->config().slots[slot][static_cast<std::size_t>(a)];
                return s;
            };
            struct Case
            {
                State state;
                std::vector<int> blockers;  ///< the cans the goal may grasp first
            };
            // the rule reads the straight approach: with one front can moved, a turned approach may pass beside
            // the other (can 2 moved: it does; can 1 moved: can 3 stands in the way), so with turned approaches the
            // rule is conservative and the target's grasp is asserted impossible only while both front cans stand
            const std::vector<Case> cases{{s0, {1, 2}},
                                          {moved({{1, 3}}), {2}},
                                          {moved({{2, 4}}), {1}},
                                          {moved({{1, 3}, {2, 4}}), {}},
                                          {moved({{1, 3}, {2, 0}, {3, 4}}), {}}};
            for (std::size_t i = 0; i < cases.size(); ++i)
            {
                SCOPED_TRACE(std::string(straight ? "straight" : "turned") + " approaches, case " + std::to_string(i));
                const State &s = cases[i].state;
                ASSERT_TRUE(m->validState(s));
                const int blocker = space.blockingCan(s);
                const ShelfTarget goal = space.goal(s);
                EXPECT_EQ(goal.kind, ShelfTarget::Kind::Grasp);
                ShelfMoveIk ik(m, 30, 7);
                const auto scene = m->makeScene(s, false);
                double q[ARM_DOF];
                if (cases[i].blockers.empty())
                {
                    EXPECT_EQ(blocker, -1);
                    EXPECT_EQ(goal.can, target);
                }
                else
                {
                    EXPECT_NE(std::find(cases[i].blockers.begin(), cases[i].blockers.end(), blocker),
                              cases[i].blockers.end())
                        << "blocker " << blocker;
                    EXPECT_EQ(goal.can, blocker);
                    if (straight || i == 0)
                    {
                        EXPECT_FALSE(ik.solve(s, space.grasp(s, target), *scene, q)) << "the target is blocked";
                    }
                }
                EXPECT_TRUE(ik.solve(s, goal, *scene, q)) << "the goal's grasp has an IK solution";
            }
            // holding a can, the goal is a slot again
            State holding = s0;
            holding.held = 1;
            EXPECT_EQ(space.goal(holding).kind, ShelfTarget::Kind::Place);
        }
    }

    TEST(ShelfMoveModel, GraspAttachesTheCanWhichFollowsTheHandAndPlaceSnapsItOntoTheSlot)
    {
        const auto &m = *model();
        const ShelfMoveTargetSpace space(model());
        pomdp::Rng rng(3);
        const State s0 = m.trueInitialState();
        const int k = 1;  // the front can
        // sensing it reaches it without a gripper event: nothing is grasped
        Outcome sensed;
        ASSERT_TRUE(execute(s0, space.sense(s0, k), rng, sensed));
        EXPECT_EQ(sensed.state.held, -1);
        // the grasp macro ends with Close at the can: it is held
        Outcome grasp;
        ASSERT_TRUE(execute(s0, space.grasp(s0, k), rng, grasp));
        EXPECT_EQ(grasp.blocked, 0u);
        const State held = grasp.state;
        ASSERT_EQ(held.held, k)
            << "grasp point " << (m.graspPoint(held) - Eigen::Vector3d(s0.can[k][0], s0.can[k][1], s0.can[k][2])).norm()
            << " m from the can";
        // the held can follows the hand (its centre is the grasp point)
        ShelfMoveAction back;
        back.dq[1] = -0.03;
        back.dq[3] = -0.03;
        const State moved = m.step(held, back, rng).next;
        EXPECT_GT(std::abs(moved.q[1] - held.q[1]), 0.02);
        const Eigen::Vector3d ee = m.graspPoint(moved);
        for (int a = 0; a < 3; ++a)
        {
            EXPECT_NEAR(moved.can[k][a], ee[a], 1e-12);
        }
        // the held can is part of the collision model: 2 cm lower, it goes into the board while the hand does not
        ShelfTarget lower = space.grasp(s0, k);
        lower.point[2] -= 0.02;
        double ql[ARM_DOF];
        State empty = s0;
        empty.can[k][1] = 0.32;  // the can elsewhere: only the hand is checked at the can's place
        ASSERT_TRUE(solveTarget(empty, lower, ql));
        State heldLow = held;
        ShelfMoveModel::setJoints(heldLow, ql);
        m.followHand(heldLow);
        EXPECT_FALSE(m.arm().checker()->isValid(m.scene(heldLow), heldLow.q));
        State emptyLow = empty;
        ShelfMoveModel::setJoints(emptyLow, ql);
        EXPECT_TRUE(m.validState(emptyLow));
        // Open away from a slot does nothing
        ShelfMoveAction open;
        open.event = GripperEvent::Open;
        EXPECT_EQ(m.step(moved, open, rng).next.held, k);
        // place on the right top slot (index 2): planned with the can attached, Open snaps it onto the slot
        Outcome place;
        ASSERT_TRUE(execute(held, space.place(2), rng, place)) << place.failure;
        ASSERT_EQ(place.state.held, -1);
        EXPECT_FALSE(place.terminal);  // an obstacle on a non-reserved slot is not the goal
        for (int a = 0; a < 3; ++a)
        {
            EXPECT_DOUBLE_EQ(place.state.can[k][a], m.config().slots[2][static_cast<std::size_t>(a)]);
        }
        EXPECT_TRUE(m.validState(place.state));
    }

    TEST(ShelfMoveModel, ReleasingTheTargetOnTheReservedSlotIsTheGoalAndAnOccupiedSlotRefusesTheRelease)
    {
        const auto &m = *model();
        const ShelfMoveTargetSpace space(model());
        pomdp::Rng rng(5);
        State s = m.trueInitialState();
        // the front cans moved to the lower free spots (slots 3, 4) and a top slot (0)
        const std::size_t moves[3][2] = {{1, 3}, {2, 0}, {3, 4}};
        for (const auto &move : moves)
        {
            for (int a = 0; a < 3; ++a)
            {
                s.can[move[0]][a] = m.config().slots[move[1]][static_cast<std::size_t>(a)];
            }
        }
        ASSERT_TRUE(m.validState(s));
        const int target = static_cast<int>(m.config().targetCan);
        EXPECT_EQ(space.goal(s).kind, ShelfTarget::Kind::Grasp);
        Outcome grasp;
        ASSERT_TRUE(execute(s, space.goal(s), rng, grasp));
        const State at = grasp.state;
        ASSERT_EQ(at.held, target)
            << "blocked " << grasp.blocked << ", grasp point "
            << (m.graspPoint(at) - Eigen::Vector3d(s.can[target][0], s.can[target][1], s.can[target][2])).norm()
            << " m from the can";
        EXPECT_FALSE(grasp.terminal);
        EXPECT_EQ(space.goal(at).kind, ShelfTarget::Kind::Place);
        EXPECT_EQ(space.goal(at).slot, static_cast<int>(m.config().reservedSlot));
        // at the release configuration with an obstacle standing on the reserved slot the release is refused
        double qp[ARM_DOF];
        ASSERT_TRUE(solveTarget(at, space.goal(at), qp));
        State blocked = at;
        ShelfMoveModel::setJoints(blocked, qp);
        m.followHand(blocked);
        EXPECT_EQ(m.releaseSlot(blocked), static_cast<int>(m.config().reservedSlot));
        const auto &reserved = m.config().slots[m.config().reservedSlot];
        blocked.can[2][0] = reserved[0];
        blocked.can[2][1] = reserved[1] + 0.05;
        blocked.can[2][2] = reserved[2];
        EXPECT_EQ(m.releaseSlot(blocked), -1);
        // free: the goal, terminal, with the goal reward
        Outcome place;
        ASSERT_TRUE(execute(at, space.goal(at), rng, place));
        EXPECT_FALSE(m.reachedGoal(at));
        EXPECT_TRUE(place.terminal);
        EXPECT_TRUE(m.reachedGoal(place.state));
        EXPECT_EQ(place.state.held, -1);
        EXPECT_GT(place.reward, 0.5 * m.config().goalReward);
    }

    TEST(ShelfMoveModel, AStepIntoACanOrTheShelfIsBlockedAtItsLastValidConfiguration)
    {
        const auto &m = *model();
        const ShelfMoveTargetSpace space(model());
        pomdp::Rng rng(11);
        const State s0 = m.trueInitialState();
        double q[ARM_DOF];
        ASSERT_TRUE(solveTarget(s0, space.grasp(s0, 1), q));
        State at = s0;
        ShelfMoveModel::setJoints(at, q);
        ASSERT_TRUE(m.validState(at));
        // swing the arm about the vertical axis (joint 1): the fingers straddling can 1 hit it at once
        int blocked = 0;
        State cur = at;
        for (int i = 0; i < 20; ++i)
        {
            ShelfMoveAction a;
            a.dq[0] = 0.05;
            const auto r = m.step(cur, a, rng);
            if (std::abs(r.next.q[0] - cur.q[0]) < 0.045)
            {
                ++blocked;
            }
            EXPECT_TRUE(m.arm().checker()->isValid(m.scene(r.next), r.next.q));
            cur = r.next;
        }
        EXPECT_GT(blocked, 10);
        for (std::size_t k = 0; k < SHELF_CANS; ++k)
        {
            for (int a = 0; a < 3; ++a)
            {
                EXPECT_EQ(cur.can[k][a], s0.can[k][a]);  // no pushing in the model
            }
        }
    }

    // Near a grasp deep in the shelf, noise puts the arm inside the planning margin: valid in the true scene, invalid
    // in the grown one. The adapter's planning scene is the grown one and its trueEnvironment the true one, so the
    // scenario's reference policy plans such a start in its true scene instead of failing every plan as an invalid
    // start; a start invalid in both stays an invalid start.
    TEST(ShelfMoveModel, ParticlesInsideThePlanningMarginPlanInTheirTrueScene)
    {
        const auto &m = *model();
        const ShelfMoveTargetSpace space(model());
        const State s0 = m.trueInitialState();
        double grasp[ARM_DOF];
        ASSERT_TRUE(solveTarget(s0, space.grasp(s0, 1), grasp));
        ShelfMoveAdapter adapter(model(), std::make_unique<ShelfMoveIk>(model(), 30, 3));
        const auto parts = shelfMoveParts();
        const auto policy = test::omplReferencePolicy<ShelfTarget>(parts, "uniform", 5);
        auto *ompl = policy.ompl;
        ASSERT_NE(ompl, nullptr);
        const auto &checker = *m.arm().checker();
        pomdp::Rng rng(12);
        int inside = 0, clear = 0, invalid = 0;
        for (int attempt = 0; attempt < 4000 && (inside < 5 || clear < 5 || invalid < 2); ++attempt)
        {
            State s = s0;
            for (std::size_t j = 0; j < ARM_DOF; ++j)
                s.q[j] = grasp[j] + rng.normal(0.0, 0.03);
            m.arm().clamp(s.q);
            const bool trueValid = checker.isValid(*m.makeScene(s, false), s.q);
            const bool grownValid = checker.isValid(*m.makeScene(s, true), s.q);
            ASSERT_EQ(checker.isValid(*adapter.environment(s), s.q), grownValid);
            ASSERT_EQ(checker.isValid(*adapter.trueEnvironment(s), s.q), trueValid);
            ASSERT_EQ(checker.isValid(*adapter.environment(s), s.q), grownValid) << "the scene cache stays coherent";
            const bool interesting =
                (trueValid && !grownValid && inside < 5) || (grownValid && clear < 5) || (!trueValid && invalid < 2);
            if (!interesting)
                continue;
            const std::size_t margin = ompl->statistics().marginStarts, noTarget = ompl->statistics().noTarget;
            std::vector<ShelfMoveAction> macro;
            ompl->sample(s, pomdp::BeliefView<State>{&s, 1}, rng, macro);
            if (ompl->statistics().noTarget > noTarget)
                continue;  // no plan ran
            if (trueValid && !grownValid)
            {
                ++inside;
                EXPECT_EQ(ompl->statistics().marginStarts, margin + 1);
                EXPECT_NE(ompl->lastStatus(), pomdp::PathPlanStatus::InvalidStart) << "planned in the true scene";
            }
            else if (grownValid)
            {
                ++clear;
                EXPECT_EQ(ompl->statistics().marginStarts, margin);
            }
            else
            {
                ++invalid;
                EXPECT_EQ(ompl->statistics().marginStarts, margin);
                EXPECT_EQ(ompl->lastStatus(), pomdp::PathPlanStatus::InvalidStart) << "an invalid start stays invalid";
            }
        }
        EXPECT_EQ(inside, 5) << "configurations inside the margin near the grasp were found (" << clear << " clear, "
                             << invalid << " in collision)";
        EXPECT_EQ(clear, 5);
        EXPECT_EQ(invalid, 2);
    }

    TEST(ShelfMoveModel, ObservationsDetectNearCansOnlyAndTheirLikelihoodIsTheSoftenedBox)
    {
        const auto &m = *model();
        pomdp::Rng rng(13);
        const State s0 = m.trueInitialState();
        const auto far = m.step(s0, ShelfMoveAction{}, rng);
        EXPECT_EQ(far.observation.detected, 0);  // the start is far from every can
        const ShelfMoveTargetSpace space(model());
        double q[ARM_DOF];
        ASSERT_TRUE(solveTarget(s0, space.sense(s0, 1), q));
        State near = s0;
        ShelfMoveModel::setJoints(near, q);
        const auto r = m.step(near, ShelfMoveAction{}, rng);
        ASSERT_TRUE(r.observation.detected & (1u << 1));
        for (int a = 0; a < 3; ++a)
        {
            EXPECT_LE(std::abs(r.observation.can[1][a] - r.next.can[1][a]), m.config().canObservationNoise);
        }
        const double p = m.observationProbability(r.observation, r.next, ShelfMoveAction{});
        EXPECT_GT(p, 0.0);
        // a particle whose can 1 is 2 cm off in x: equal likelihood inside the box, less outside it
        State off = r.next;
        off.can[1][0] += 0.1;
        const double pOff = m.observationProbability(r.observation, off, ShelfMoveAction{});
        EXPECT_LT(pOff, 1e-6 * p);
        // the detection pattern must match
        auto none = r.observation;
        none.detected = 0;
        EXPECT_EQ(m.observationProbability(none, r.next, ShelfMoveAction{}), 0.0);
        EXPECT_NE(m.observationKey(none), m.observationKey(r.observation));
    }

    TEST(ShelfMoveModel, InitialBeliefAndReinvigorationNeverMakeCansInterpenetrateOrFloat)
    {
        auto json = defaultJson();
        json["initial_can_sigma"] = 0.06;  // wide enough that many draws would overlap
        json["reinvigorate_can_sigma"] = 0.05;
        json["reinvigorate_probability"] = 1.0;
        const auto m = makeModel(json);
        pomdp::Rng rng(17);
        const double r = m->config().canRadius;
        std::size_t moved = 0;
        for (int i = 0; i < 200; ++i)
        {
            State s = m->sampleInitialState(rng);
            for (int t = 0; t < 5; ++t)
            {
                const State before = s;
                m->reinvigorate(s, rng);
                moved += before.can[0][0] != s.can[0][0];
                ASSERT_TRUE(m->validState(s));
                for (std::size_t a = 0; a < SHELF_CANS; ++a)
                {
                    EXPECT_GE(m->supportingBox(s.can[a]), 0);  // on a board: not floating
                    EXPECT_EQ(s.can[a][2], m->config().cans[a][2]);
                    for (std::size_t b = a + 1; b < SHELF_CANS; ++b)
                    {
                        EXPECT_GE(std::hypot(s.can[a][0] - s.can[b][0], s.can[a][1] - s.can[b][1]), 2.0 * r - 1e-12);
                    }
                }
            }
        }
        EXPECT_GT(moved, 100u);  // the jitter was applied, not always rejected
    }

    TEST(ShelfMoveModel, BadConfigurationsAreRefusedNamingTheKey)
    {
        const auto expectError = [](nlohmann::json json, const std::string &key, const std::string &part)
        {
            try
            {
                makeModel(json);
                ADD_FAILURE() << "no error for " << key;
            }
            catch (const Error &e)
            {
                EXPECT_NE(std::string(e.what()).find(part), std::string::npos) << e.what();
            }
        };
        auto j = defaultJson();
        j["cans"][1] = {0.6, 0, 0.7};  // floating
        expectError(j, "cans", "key \"cans\" can 1 does not stand on a shelf box");
        j = defaultJson();
        j["cans"][2] = {0.62, 0.08, 0.64};  // inside can 1
        expectError(j, "cans", "overlaps another can");
        j = defaultJson();
        j["cans"].erase(3);
        expectError(j, "cans", "must list exactly 4");
        j = defaultJson();
        j["reserved_slot"] = 9;
        expectError(j, "reserved_slot", "reserved_slot");
        j = defaultJson();
        j["planning"]["blocking_halfwidth"] = -0.1;
        expectError(j, "blocking_halfwidth", "blocking_halfwidth");
        j["planning"]["blocking_halfwidth"] = std::nan("");
        expectError(j, "blocking_halfwidth", "blocking_halfwidth");
        j = defaultJson();
        j["grasp_approach"] = {0, 0, 1};
        expectError(j, "grasp_approach", "horizontal");
        j = defaultJson();
        j["slots"][0] = {0.56, -0.22, 1.3};
        expectError(j, "slots", "slot 0 is not on a shelf box top");
        j = defaultJson();
        j["step"] = "big";
        expectError(j, "step", "key \"step\"");
        j = defaultJson();
        j["transition_sigma"] = -1;
        expectError(j, "transition_sigma", "transition_sigma");
        j = defaultJson();
        j["action_mode"] = "teleport";
        expectError(j, "action_mode", "must be \"delta\" or \"waypoint\"");
        j = defaultJson();
        j["held_clearance"] = 0.5;
        expectError(j, "held_clearance", "held_clearance");
        j = defaultJson();
        j["planning"]["surprise"] = 1;
        expectError(j, "planning", "surprise");
    }
}  // namespace ropras::scenarios
