#include "ropras/pomdp/MacroAction.h"

#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "TestModels.h"
#include "ropras/pomdp/Tiger.h"

using namespace ropras::pomdp;

TEST(MacroActionTest, RewardIsDiscountedInsideTheMacro)
{
    const TigerModel tiger;
    const std::vector<TigerModel::Action> listen3(3, TigerModel::LISTEN);
    Rng rng(1);
    const auto result =
        executeMacro(tiger, TigerModel::State{0}, MacroView<TigerModel::Action>{listen3.data(), 3}, rng);
    EXPECT_EQ(result.steps, 3u);
    EXPECT_FALSE(result.terminal);
    EXPECT_NEAR(result.reward, -1.0 - 0.95 - 0.95 * 0.95, 1e-12);
    EXPECT_NEAR(result.discount, std::pow(0.95, 3), 1e-12);
    EXPECT_EQ(result.next, 0);
}

TEST(MacroActionTest, TerminalStepEndsTheMacroEarly)
{
    const test::CounterModel model;  // terminal when the counter reaches 2
    const std::vector<int> macro(5, 1);
    Rng rng(1);
    const auto result = executeMacro(model, 0, MacroView<int>{macro.data(), macro.size()}, rng);
    EXPECT_TRUE(result.terminal);
    EXPECT_EQ(result.steps, 2u);
    EXPECT_EQ(result.next, 2);
    EXPECT_NEAR(result.reward, 1.0 + 0.5, 1e-12);
    EXPECT_NEAR(result.discount, 0.25, 1e-12);
}

TEST(MacroActionTest, ObservationKeyIsTheOrderedSequence)
{
    test::CounterModel model;  // observation = action
    model.terminalAt = 100;
    Rng rng(1);
    const std::vector<int> ab{0, 1}, ba{1, 0}, ab2{0, 1}, a{0};
    const auto kAb = executeMacro(model, 0, MacroView<int>{ab.data(), 2}, rng).observationKey;
    const auto kBa = executeMacro(model, 0, MacroView<int>{ba.data(), 2}, rng).observationKey;
    const auto kAb2 = executeMacro(model, 5, MacroView<int>{ab2.data(), 2}, rng).observationKey;
    const auto kA = executeMacro(model, 0, MacroView<int>{a.data(), 1}, rng).observationKey;
    EXPECT_EQ(kAb, kAb2);
    EXPECT_NE(kAb, kBa);
    EXPECT_NE(kAb, kA);
    const auto empty = executeMacro(model, 3, MacroView<int>{nullptr, 0}, rng);
    EXPECT_EQ(empty.steps, 0u);
    EXPECT_EQ(empty.next, 3);
    EXPECT_EQ(empty.discount, 1.0);
}

TEST(MacroActionTest, SameSeedSameResult)
{
    const TigerModel tiger;
    const std::vector<TigerModel::Action> macro{0, 0, 1, 0, 2, 0};
    Rng a(77), b(77);
    for (int i = 0; i < 100; ++i)
    {
        const auto ra = executeMacro(tiger, TigerModel::State{1}, MacroView<TigerModel::Action>{macro.data(), 6}, a);
        const auto rb = executeMacro(tiger, TigerModel::State{1}, MacroView<TigerModel::Action>{macro.data(), 6}, b);
        ASSERT_EQ(ra.observationKey, rb.observationKey);
        ASSERT_EQ(ra.reward, rb.reward);
        ASSERT_EQ(ra.next, rb.next);
    }
}
