// Shelf-Move's scenario: the reference policy's macros (Dynamic heuristic conditioned on what is held, entire
// motion paths ending in the gripper event) with two registry planners.
#include <gtest/gtest.h>

#include <cmath>
#include <string>
#include <vector>

#include <ompl/util/Console.h>

#include "ropras/scenarios/manipulation/ShelfMovePlanning.h"
#include "ropras/scenarios/manipulation/ShelfMoveScenario.h"

namespace ropras::scenarios
{
    namespace
    {
        using State = ShelfMoveModel::State;

        /// a reference macro from \a policy (up to 5 tries: a plan may time out on a loaded machine)
        bool sampleMacro(pomdp::ReferencePolicy<ShelfMoveModel> &policy, const State &s, std::vector<State> &belief,
                         pomdp::Rng &rng, std::vector<ShelfMoveAction> &macro)
        {
            for (int attempt = 0; attempt < 5; ++attempt)
            {
                macro.clear();
                if (policy.sample(s, {belief.data(), belief.size()}, rng, macro))
                {
                    return true;
                }
            }
            return false;
        }

        /// the front cans on the lower free spots (slots 3, 4) and a top slot (0): the target can be grasped
        State cleared(const ShelfMoveModel &m)
        {
            State s = m.trueInitialState();
            const std::size_t moves[3][2] = {{1, 3}, {2, 0}, {3, 4}};
            for (const auto &move : moves)
            {
                for (int a = 0; a < 3; ++a)
                {
                    s.can[move[0]][a] = m.config().slots[move[1]][static_cast<std::size_t>(a)];
                }
            }
            return s;
        }
    }  // namespace

    TEST(ShelfMoveScenario, DynamicMacrosOfACertainBeliefGoToTheGoalOfWhatIsHeldAndEndInItsEvent)
    {
        ompl::msg::setLogLevel(ompl::msg::LOG_ERROR);
        const auto parts = shelfMoveParts();
        const auto &m = *parts.model;
        EXPECT_EQ(parts.name, "shelf-move");
        for (const std::string planner : {"VectorizedRRTConnect", "RRTConnect"})
        {
            RunSettings settings;
            settings.planner = planner;
            settings.heuristic = "dynamic";
            pomdp::ParameterMap params;
            params.set("plan_time", 2.0);
            auto policy = parts.referencePolicy(settings, params, 23);
            pomdp::Rng rng(9);
            // a collapsed belief (H = 0): Dynamic always picks the goal, which depends on what is held
            State s = cleared(m);
            std::vector<State> belief(5, s);
            std::vector<ShelfMoveAction> macro;
            ASSERT_TRUE(sampleMacro(*policy, s, belief, rng, macro)) << planner;
            ASSERT_FALSE(macro.empty());
            EXPECT_EQ(macro.back().event, GripperEvent::Close);
            for (std::size_t i = 0; i + 1 < macro.size(); ++i)
            {
                EXPECT_EQ(macro[i].event, GripperEvent::None);
            }
            // the whole path (no truncation): run it, the target is held
            for (const auto &a : macro)
            {
                s = m.step(s, a, rng).next;
            }
            ASSERT_EQ(s.held, static_cast<int>(m.config().targetCan)) << planner;
            // now the goal is the reserved slot: the macro ends with Open, and running it succeeds
            belief.assign(5, s);
            ASSERT_TRUE(sampleMacro(*policy, s, belief, rng, macro)) << planner;
            EXPECT_EQ(macro.back().event, GripperEvent::Open);
            bool terminal = false;
            for (const auto &a : macro)
            {
                const auto r = m.step(s, a, rng);
                s = r.next;
                terminal = terminal || r.terminal;
            }
            EXPECT_TRUE(terminal) << planner;
            const auto &reserved = m.config().slots[m.config().reservedSlot];
            EXPECT_DOUBLE_EQ(s.can[m.config().targetCan][0], reserved[0]);
        }
    }
}  // namespace ropras::scenarios
