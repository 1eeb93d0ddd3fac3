// The closed-loop episode: the world (not the model) decides what happens, macros are executed whole or only
// their first action, the observer sees every plan and step, and success comes from the model's reachedGoal().
#include <gtest/gtest.h>

#include <memory>
#include <vector>

#include "ropras/pomdp/Episode.h"
#include "ropras/pomdp/PomcpSolver.h"
#include "ropras/pomdp/Tiger.h"
#include "ropras/pomdp/World.h"

namespace
{
    using namespace ropras::pomdp;

    /** \brief Position on a line; every action moves +1; terminal (and a goal) at `goal`. */
    struct LineModel
    {
        using State = int;
        using Action = int;
        using Observation = int;
        int goal{5};

        StepResult<State, Observation> step(State s, Action a, Rng &) const noexcept
        {
            const int next = s + a;
            return {next, next, -1.0, next >= goal};
        }
        double observationProbability(Observation o, State s, Action) const noexcept { return o == s ? 1.0 : 0.0; }
        State sampleInitialState(Rng &) const noexcept { return 0; }
        double discount() const noexcept { return 0.5; }
        std::size_t numActions() const noexcept { return 1; }
        Action action(std::size_t) const noexcept { return 1; }
        bool reachedGoal(State s) const noexcept { return s >= goal; }
    };

    /** \brief Always plans the macro (1, 1, 1). */
    class FixedSolver final : public Solver<LineModel>
    {
    public:
        std::string name() const override { return "fixed"; }
        PlanResult<int> plan(BeliefView<int>, const Budget &, Rng &) override
        {
            PlanResult<int> out;
            out.action = {1, 1, 1};
            out.valid = true;
            out.statistics.simulations = 7;
            return out;
        }
    };

    /** \brief A world that differs from the model: every action moves two cells. */
    class FastWorld final : public World<LineModel>
    {
    public:
        void reset(const int &s) override { state_ = s; }
        const int &state() const override { return state_; }
        StepResult<int, int> step(const int &a, Rng &) override
        {
            state_ += 2 * a;
            return {state_, state_, -1.0, state_ >= 5};
        }

    private:
        int state_{0};
    };

    class CountingObserver final : public EpisodeObserver<LineModel>
    {
    public:
        void onStart(const int &s, const std::vector<int> &) override { states.push_back(s); }
        void onPlan(std::size_t step, const std::vector<int> &macro, const SearchStatistics &) override
        {
            planSteps.push_back(step);
            macroLengths.push_back(macro.size());
        }
        void onStep(std::size_t step, const int &, const StepResult<int, int> &r, const std::vector<int> &) override
        {
            EXPECT_EQ(step, states.size());
            states.push_back(r.next);
        }
        std::vector<int> states;
        std::vector<std::size_t> planSteps, macroLengths;
    };

    /// an episode of \a solver in \a world with a filter of \a particles on \a model (seed \a seed)
    template <class M>
    EpisodeResult runWith(const std::shared_ptr<const M> &model, Solver<M> &solver, World<M> &world,
                          const EpisodeSettings &settings, std::size_t particles, std::uint64_t seed,
                          EpisodeObserver<M> *observer = nullptr)
    {
        ParticleFilterSettings fs;
        fs.numParticles = particles;
        ParticleFilter<M> filter(model, fs);
        Rng rng(seed);
        filter.initialize(rng);
        return runEpisode(*model, solver, filter, world, settings, rng, observer);
    }

    EpisodeResult runLine(World<LineModel> &world, bool replanEveryStep, std::size_t maxSteps,
                          EpisodeObserver<LineModel> *observer = nullptr)
    {
        FixedSolver solver;
        EpisodeSettings settings;
        settings.maxSteps = maxSteps;
        settings.replanEveryStep = replanEveryStep;
        return runWith(std::make_shared<const LineModel>(), solver, world, settings, 4, 3, observer);
    }
}  // namespace

TEST(EpisodeTest, ExecutesWholeMacrosThenReplans)
{
    SimulatedWorld<LineModel> world(std::make_shared<const LineModel>());
    CountingObserver observer;
    const auto r = runLine(world, false, 100, &observer);
    EXPECT_EQ(r.steps, 5u);
    EXPECT_EQ(r.plans, 2u);  // 3 steps, then 2 of the second macro
    EXPECT_TRUE(r.terminal);
    EXPECT_TRUE(r.success);
    EXPECT_EQ(r.search.simulations, 14u);
    EXPECT_DOUBLE_EQ(r.undiscountedReturn, -5.0);
    EXPECT_DOUBLE_EQ(r.discountedReturn, -(1 + 0.5 + 0.25 + 0.125 + 0.0625));
    EXPECT_EQ(observer.states, (std::vector<int>{0, 1, 2, 3, 4, 5}));
    EXPECT_EQ(observer.planSteps, (std::vector<std::size_t>{0, 3}));
    EXPECT_EQ(observer.macroLengths, (std::vector<std::size_t>{3, 3}));
}

TEST(EpisodeTest, ReplanEveryStepExecutesOnlyTheFirstAction)
{
    SimulatedWorld<LineModel> world(std::make_shared<const LineModel>());
    CountingObserver observer;
    const auto r = runLine(world, true, 100, &observer);
    EXPECT_EQ(r.steps, 5u);
    EXPECT_EQ(r.plans, 5u);
    EXPECT_EQ(observer.macroLengths, (std::vector<std::size_t>(5, 1)));
    EXPECT_TRUE(r.success);
}

TEST(EpisodeTest, TheWorldDecidesWhatHappens)
{
    FastWorld world;
    CountingObserver observer;
    const auto r = runLine(world, false, 100, &observer);
    EXPECT_EQ(r.steps, 3u);  // 2, 4, 6: the world moves two cells per action although the model says one
    EXPECT_EQ(observer.states, (std::vector<int>{0, 2, 4, 6}));
    EXPECT_TRUE(r.success);  // reachedGoal() of the world's final state
}

TEST(EpisodeTest, HorizonStopsWithoutSuccess)
{
    SimulatedWorld<LineModel> world(std::make_shared<const LineModel>());
    const auto r = runLine(world, false, 4);
    EXPECT_EQ(r.steps, 4u);
    EXPECT_FALSE(r.terminal);
    EXPECT_FALSE(r.success);
}

TEST(EpisodeTest, SimulatedWorldMatchesTheModelOnlyOverload)
{
    auto model = std::make_shared<const TigerModel>();
    EpisodeSettings settings;
    settings.maxSteps = 30;
    settings.budget = Budget::ofSimulations(300);
    ParticleFilterSettings fs;
    fs.numParticles = 50;
    auto run = [&](bool explicitWorld)
    {
        PomcpSolver<TigerModel> solver(model, nullptr, PomcpSettings(), "pomcp");
        ParticleFilter<TigerModel> filter(model, fs);
        Rng rng(11);
        filter.initialize(rng);
        if (!explicitWorld)
            return runEpisode(*model, solver, filter, settings, rng);
        SimulatedWorld<TigerModel> world(model);
        return runEpisode(*model, solver, filter, world, settings, rng);
    };
    const auto a = run(false);
    const auto b = run(true);
    EXPECT_EQ(a.steps, b.steps);
    EXPECT_DOUBLE_EQ(a.discountedReturn, b.discountedReturn);
    EXPECT_EQ(a.search.simulations, b.search.simulations);
    EXPECT_FALSE(a.success);  // Tiger has no reachedGoal()
}

TEST(EpisodeTest, SimulatedWorldRejectsANullModel)
{
    EXPECT_THROW(SimulatedWorld<TigerModel>(nullptr), ropras::Error);
}

namespace
{
    /** \brief Uninformative: states 0..99 drawn at the start, every action moves +1, observations are always 0. Its
        rollout policy records the states it is asked about. */
    struct BlindModel
    {
        using State = int;
        using Action = int;
        using Observation = int;
        std::vector<int> *asked{nullptr};

        StepResult<State, Observation> step(State s, Action a, Rng &) const noexcept { return {s + a, 0, -1.0, false}; }
        double observationProbability(Observation, State, Action) const noexcept { return 1.0; }
        State sampleInitialState(Rng &rng) const noexcept { return static_cast<int>(rng.uniformIndex(100)); }
        double discount() const noexcept { return 0.9; }
        Action rolloutAction(State s, Rng &) const noexcept
        {
            asked->push_back(s);
            return 1;
        }
    };

    /// a world whose robot is somewhere no particle can be (below 0)
    class FarWorld final : public World<BlindModel>
    {
    public:
        void reset(const int &) override { state_ = -1000; }
        const int &state() const override { return state_; }
        StepResult<int, int> step(const int &a, Rng &) override
        {
            state_ += a;
            return {state_, 0, -1.0, false};
        }

    private:
        int state_{0};
    };

    class NoPlanSolver final : public Solver<BlindModel>
    {
    public:
        std::string name() const override { return "none"; }
        PlanResult<int> plan(BeliefView<int>, const Budget &, Rng &) override { return {}; }
    };
}  // namespace

TEST(EpisodeTest, AFailedPlanFallsBackOnTheBeliefNotOnTheHiddenState)
{
    // When the solver returns no macro-action, the episode executes the model's rollout action; the agent does not
    // know the world's state, so that action is chosen for a particle of its belief.
    std::vector<int> asked;
    auto model = std::make_shared<BlindModel>();
    model->asked = &asked;
    NoPlanSolver solver;
    FarWorld world;
    EpisodeSettings settings;
    settings.maxSteps = 3;
    const auto r = runWith<BlindModel>(model, solver, world, settings, 20, 5);
    EXPECT_EQ(r.steps, 3u);
    EXPECT_EQ(r.invalidPlans, 3u);
    ASSERT_EQ(asked.size(), 3u);
    for (std::size_t k = 0; k < asked.size(); ++k)
    {
        EXPECT_GE(asked[k], static_cast<int>(k)) << "a particle after " << k << " steps";
        EXPECT_LT(asked[k], 100 + static_cast<int>(k));
    }
    EXPECT_EQ(world.state(), -997);
}
