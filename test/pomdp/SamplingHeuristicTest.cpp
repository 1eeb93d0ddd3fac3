#include "ropras/pomdp/SamplingHeuristic.h"

#include <gtest/gtest.h>

#include <cmath>
#include <memory>
#include <vector>

#include "ropras/pomdp/HeuristicReferencePolicy.h"
#include "ropras/pomdp/Tiger.h"

using namespace ropras::pomdp;

namespace
{
    // Agent on a line; state = (agent position, hidden goal id); targets are positions. Goal at 10 or 20,
    // informative landmarks at 1 (distance from 0: 1) and 3 (distance 3). Free space: [100, 101).
    struct LineState
    {
        double x{0.0};
        int goalId{0};
    };

    class LineSpace final : public TargetSpace<LineState, double>
    {
    public:
        double goal(const LineState &s) const override { return s.goalId == 0 ? 10.0 : 20.0; }
        std::size_t numInformative(const LineState &) const override { return 2; }
        double informative(const LineState &, std::size_t i) const override { return i == 0 ? 1.0 : 3.0; }
        double distance(const LineState &agent, const double &target) const override
        {
            return std::abs(agent.x - target);
        }
        std::uint64_t entropyBin(const LineState &s) const override { return static_cast<std::uint64_t>(s.goalId); }
        std::size_t numEntropyBins() const override { return 2; }
        bool sampleFree(Rng &rng, double &out) const override
        {
            out = rng.uniform(100.0, 101.0);
            return true;
        }
    };

    struct Counts
    {
        int goal{0}, near{0}, far{0}, free{0};
    };

    Counts draw(SamplingHeuristic<LineState, double> &h, const std::vector<LineState> &belief, int n)
    {
        Rng rng(123);
        Counts c;
        for (int i = 0; i < n; ++i)
        {
            double t = 0.0;
            EXPECT_TRUE(h.sample(LineState{}, BeliefView<LineState>{belief.data(), belief.size()}, rng, t));
            if (t == 10.0 || t == 20.0)
            {
                ++c.goal;
            }
            else if (t == 1.0)
            {
                ++c.near;
            }
            else if (t == 3.0)
            {
                ++c.far;
            }
            else if (t >= 100.0)
            {
                ++c.free;
            }
        }
        return c;
    }
}  // namespace

TEST(SamplingHeuristicTest, NormalizedEntropy)
{
    std::vector<std::uint64_t> same(10, 4);
    EXPECT_EQ(normalizedEntropy(same, 2), 0.0);
    std::vector<std::uint64_t> half{0, 1, 0, 1};
    EXPECT_NEAR(normalizedEntropy(half, 2), 1.0, 1e-12);
    std::vector<std::uint64_t> quarter{0, 0, 0, 1};
    const double h = -(0.75 * std::log(0.75) + 0.25 * std::log(0.25)) / std::log(2.0);
    EXPECT_NEAR(normalizedEntropy(quarter, 2), h, 1e-12);
}

TEST(SamplingHeuristicTest, UniformPicksGoalHalfTheTime)
{
    auto space = std::make_shared<const LineSpace>();
    UniformHeuristic<LineState, double> h(space);
    const std::vector<LineState> belief{{0.0, 0}, {0.0, 1}};
    const int n = 20000;
    const Counts c = draw(h, belief, n);
    // Binomial(20000, 0.5): SD 71; informative targets split evenly.
    EXPECT_NEAR(c.goal, n / 2, 300);
    EXPECT_NEAR(c.near, n / 4, 300);
    EXPECT_NEAR(c.far, n / 4, 300);
}

TEST(SamplingHeuristicTest, DynamicFollowsEntropyAndDistance)
{
    auto space = std::make_shared<const LineSpace>();
    DynamicHeuristic<LineState, double> h(space);
    const int n = 20000;
    // Certain belief: H = 0, always the goal.
    const std::vector<LineState> certain(8, LineState{0.0, 1});
    EXPECT_EQ(draw(h, certain, n).goal, n);
    // Maximally uncertain: H = 1, always informative, with probability ~ 1/distance: 3/4 near, 1/4 far.
    const std::vector<LineState> uncertain{{0.0, 0}, {0.0, 1}};
    const Counts c = draw(h, uncertain, n);
    EXPECT_EQ(c.goal, 0);
    EXPECT_NEAR(c.near, 0.75 * n, 300);
    EXPECT_NEAR(c.far, 0.25 * n, 300);
    // 3:1 belief: goal with probability 1 - H.
    const std::vector<LineState> skewed{{0.0, 0}, {0.0, 0}, {0.0, 0}, {0.0, 1}};
    const double hSkewed = -(0.75 * std::log(0.75) + 0.25 * std::log(0.25)) / std::log(2.0);
    EXPECT_NEAR(draw(h, skewed, n).goal, (1.0 - hSkewed) * n, 300);
}

TEST(SamplingHeuristicTest, EpsilonGreedyMixesFreeSpace)
{
    auto space = std::make_shared<const LineSpace>();
    EpsilonGreedyHeuristic<LineState, double> h(space, std::make_unique<UniformHeuristic<LineState, double>>(space),
                                                0.2);
    const std::vector<LineState> belief{{0.0, 0}};
    const int n = 20000;
    const Counts c = draw(h, belief, n);
    EXPECT_NEAR(c.free, 0.2 * n, 300);
    EXPECT_NEAR(c.goal, 0.4 * n, 300);
    EXPECT_THROW((EpsilonGreedyHeuristic<LineState, double>(
                     space, std::make_unique<UniformHeuristic<LineState, double>>(space), 1.5)),
                 ropras::Error);
    EXPECT_THROW((UniformHeuristic<LineState, double>(nullptr)), ropras::Error);
    EXPECT_THROW((DynamicHeuristic<LineState, double>(space, std::nan(""))), ropras::Error);
}

TEST(SamplingHeuristicTest, HeuristicReferencePolicyCountsConnectorFailures)
{
    auto space = std::make_shared<const TigerTargetSpace>();
    int calls = 0;
    HeuristicReferencePolicy<TigerModel, TigerModel::Action> failing(
        std::make_unique<UniformHeuristic<TigerModel::State, TigerModel::Action>>(space),
        [&calls](const TigerModel::State &, const TigerModel::Action &, Rng &, std::vector<TigerModel::Action> &)
        {
            ++calls;
            return false;
        },
        "never");
    Rng rng(1);
    std::vector<TigerModel::Action> out;
    const TigerModel::State s = 0;
    EXPECT_FALSE(failing.sample(s, BeliefView<TigerModel::State>{&s, 1}, rng, out));
    EXPECT_EQ(calls, 1);
    // The Tiger reference policy: goal = open the door without the tiger, informative = listen.
    auto policy = tigerComponents().referencePolicy(ParameterMap{});
    const std::vector<TigerModel::State> left(10, 0);
    for (int i = 0; i < 50; ++i)
    {
        out.clear();
        ASSERT_TRUE(policy->sample(0, BeliefView<TigerModel::State>{left.data(), left.size()}, rng, out));
        ASSERT_EQ(out.size(), 1u);
        EXPECT_EQ(out[0], TigerModel::OPEN_RIGHT);  // certain belief: H = 0, always the goal
    }
}
