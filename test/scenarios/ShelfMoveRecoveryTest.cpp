// Shelf-Move's depletion recovery: a belief that the world contradicts (a grasp the world refused, a can seen where
// no particle has it) is repaired from the observation instead of being kept with the observation ignored.
#include <gtest/gtest.h>

#include <cmath>
#include <cstring>
#include <memory>
#include <vector>

#include "ShelfMoveTestUtil.h"
#include "ropras/pomdp/ParticleFilter.h"
#include "ropras/scenarios/manipulation/ShelfMovePlanning.h"
#include "ropras/scenarios/manipulation/ShelfMoveRecovery.h"
#include "ropras/scenarios/manipulation/ShelfMoveScenario.h"

namespace ropras::scenarios
{
    namespace
    {
        using State = ShelfMoveModel::State;
        using Observation = ShelfMoveModel::Observation;

        /// the true initial state with the arm at a grasp of can \a k (IK in the true scene)
        State atGrasp(const ShelfMoveModel &m, int k)
        {
            const ShelfMoveTargetSpace space(test::shelfMoveModel());
            State s = m.trueInitialState();
            ShelfMoveIk ik(test::shelfMoveModel(), 30, 7);
            double q[ARM_DOF];
            EXPECT_TRUE(ik.solve(s, space.grasp(s, k), *m.makeScene(s, false), q));
            ShelfMoveModel::setJoints(s, q);
            return s;
        }

        std::vector<State> particlesOf(const State &s, std::size_t n)
        {
            return std::vector<State>(n, s);
        }
    }  // namespace

    // The model grasped can 1 in every particle; the world refused the grasp (the gripper reports nothing held). Every
    // particle has zero likelihood. Ignoring the observation keeps a belief that holds the can forever; the repair
    // lets go of it where the hand left it (standing, valid) and takes the observed joints.
    TEST(ShelfMoveRecovery, AGraspTheWorldRefusedIsUndoneInTheBelief)
    {
        const auto &m = *test::shelfMoveModel();
        const State world = atGrasp(m, 1);
        State believed = world;
        believed.held = 1;
        m.followHand(believed);
        ASSERT_TRUE(m.validState(believed));
        pomdp::Rng rng(4);
        Observation o;
        m.observe(world, rng, o);
        ASSERT_EQ(o.held, -1);
        const ShelfMoveModel::Action stay{};
        ASSERT_EQ(m.observationProbability(o, believed, stay), 0.0) << "the belief is depleted";

        std::vector<State> ignored = particlesOf(believed, 20);
        std::vector<double> weights(20, 0.0);
        pomdp::IgnoreObservationRecovery<ShelfMoveModel>().recover(m, stay, o, ignored, weights, rng);
        EXPECT_EQ(ignored[0].held, 1) << "ignoring the observation keeps the refused grasp";

        std::vector<State> repaired = particlesOf(believed, 20);
        ShelfMoveRecovery().recover(m, stay, o, repaired, weights, rng);
        double total = 0.0;
        for (std::size_t i = 0; i < repaired.size(); ++i)
        {
            const State &p = repaired[i];
            EXPECT_EQ(p.held, -1) << i;
            EXPECT_TRUE(m.validState(p)) << i;
            // can 1 stands where the world sees it: within the observation's box (+-w) of the detection, which
            // is within +-w of the truth; standing at the height it had in the hand
            const double w = m.config().canObservationNoise;
            ASSERT_TRUE((o.detected >> 1) & 1u);
            EXPECT_LE(std::abs(p.can[1][0] - o.can[1][0]), w + 1e-12) << i;
            EXPECT_LE(std::abs(p.can[1][1] - o.can[1][1]), w + 1e-12) << i;
            EXPECT_LT(std::hypot(p.can[1][0] - world.can[1][0], p.can[1][1] - world.can[1][1]), 2 * std::sqrt(2.0) * w)
                << i;
            EXPECT_NEAR(p.can[1][2], believed.can[1][2], 1e-12) << i;
            total += weights[i];
        }
        EXPECT_GT(total, 0.0) << "the repaired particles explain the observation";
    }

    // Whatever the mismatch (held or not, cans shifted, joints off), a repair leaves a physically valid particle
    // (no floating or interpenetrating can, the arm clear) or none at all: the particle is then unchanged.
    TEST(ShelfMoveRecovery, ARepairIsPhysicallyValidOrNotMade)
    {
        const auto &m = *test::shelfMoveModel();
        const State grasp = atGrasp(m, 1);
        pomdp::Rng rng(21);
        int repaired = 0, kept = 0;
        for (int trial = 0; trial < 60; ++trial)
        {
            State world = grasp;
            for (std::size_t j = 0; j < ARM_DOF; ++j)
                world.q[j] += rng.normal(0.0, 0.05);
            m.arm().clamp(world.q);
            if (!m.validState(world))
                continue;
            State believed = world;
            for (std::size_t k = 0; k < SHELF_CANS; ++k)
                for (int a = 0; a < 2; ++a)
                    believed.can[k][a] += rng.normal(0.0, 0.02);
            for (std::size_t j = 0; j < ARM_DOF; ++j)
                believed.q[j] += rng.normal(0.0, 0.1);
            m.arm().clamp(believed.q);
            believed.held = trial % 2 == 0 ? 1 : -1;
            m.followHand(believed);
            Observation o;
            m.observe(world, rng, o);
            State s = believed;
            if (ShelfMoveRecovery::repair(m, ShelfMoveModel::Action{}, o, s, rng))
            {
                ++repaired;
                EXPECT_TRUE(m.validState(s)) << trial;
                EXPECT_EQ(s.held, o.held) << trial;
            }
            else
            {
                ++kept;
                EXPECT_EQ(std::memcmp(&s, &believed, sizeof(State)), 0) << trial;
            }
        }
        EXPECT_GE(repaired + kept, 15) << "valid worlds drawn";
        EXPECT_GE(repaired, 8) << kept << " kept";
    }

    TEST(ShelfMoveRecovery, TheScenarioRepairsByDefaultAndIgnoresOnRequest)
    {
        const auto parts = shelfMoveParts();
        ASSERT_TRUE(parts.recovery);
        EXPECT_EQ(parts.recovery()->name(), "shelf-move-observation-repair");
        ScenarioOptions options;
        options.overrides["depletion_recovery"] = "ignore";
        EXPECT_FALSE(shelfMoveParts(options).recovery);
        options.overrides["depletion_recovery"] = "forget";
        try
        {
            shelfMoveParts(options);
            ADD_FAILURE() << "no error for depletion_recovery = forget";
        }
        catch (const Error &e)
        {
            EXPECT_NE(std::string(e.what()).find("depletion_recovery"), std::string::npos) << e.what();
        }
    }
}  // namespace ropras::scenarios
