// The OMPL contract of ropras' StateValidityChecker and MotionValidator, the planner registry, and planners
// solving MotionBenchMaker problems through them.
#include <gtest/gtest.h>

#include <ompl/base/DiscreteMotionValidator.h>
#include <ompl/base/PlannerTerminationCondition.h>
#include <ompl/base/terminationconditions/IterationTerminationCondition.h>
#include <ompl/util/Console.h>
#include <ompl/util/RandomNumbers.h>
#include <atomic>
#include <climits>
#include <filesystem>
#include <fstream>
#include <map>
#include <random>
#include <thread>

#include "PointRobotUrdf.h"
#include "ropras/core/Error.h"
#include "ropras/ompl_ext/ompl/JointStateSpace.h"
#include "ropras/ompl_ext/ompl/PlannerRegistry.h"
#include "ropras/ompl_ext/ompl/PlanningContext.h"
#include "ropras/ompl_ext/scene/SceneYaml.h"

namespace fs = std::filesystem;
using namespace ropras::ompl_ext;

namespace
{
    const fs::path SHARED = ROPRAS_SHARED_DIR;

    bool haveShared()
    {
        return fs::exists(SHARED / "robots/panda/panda_spherized.urdf");
    }

    PlanningContext pandaContext(const std::string &category, int problem, const PlanningContextOptions &options = {})
    {
        char name[32];
        std::snprintf(name, sizeof name, "scene%04d.yaml", problem);
        auto env = std::make_shared<Environment>(loadPlanningScene((SHARED / "mbm/panda" / category / name).string()));
        return makePlanningContext((SHARED / "robots/panda/panda_spherized.urdf").string(),
                                   (SHARED / "robots/panda/panda.srdf").string(), env, RobotModel::Options(), options);
    }

    double *values(ompl::base::State *s)
    {
        return s->as<ompl::base::RealVectorStateSpace::StateType>()->values;
    }

    /// a uniform state the validity checker accepts
    void sampleValidState(const PlanningContext &c, ompl::base::StateSampler &sampler, ompl::base::State *s)
    {
        do
            sampler.sampleUniform(s);
        while (!c.validityChecker->isValid(s));
    }

    /// first invalid sample index j in 1..n along q0 -> q1 at max-joint step \a res (0 if all valid), and n
    std::pair<int, int> firstInvalidSample(const PlanningContext &c, const double *q0, const double *q1, double res)
    {
        const std::size_t dof = c.robot->dof();
        double linf = 0.0;
        for (std::size_t k = 0; k < dof; ++k)
            linf = std::max(linf, std::abs(q1[k] - q0[k]));
        const int n = std::max(1, static_cast<int>(std::ceil(linf / res)));
        std::vector<double> q(dof);
        for (int i = 1; i <= n; ++i)
        {
            const double t = static_cast<double>(i) / n;
            for (std::size_t k = 0; k < dof; ++k)
                q[k] = q0[k] + t * (q1[k] - q0[k]);
            if (!c.checker->isValid(*c.validityChecker->environment(), q.data()))
                return {i, n};
        }
        return {0, n};
    }
}  // namespace

#define REQUIRE_SHARED() \
    if (!haveShared())   \
    GTEST_SKIP() << "../shared not found at " << SHARED << ": the Panda and MBM problems are needed"

TEST(OmplPlugin, MotionContractMatchesDenseReference)
{
    REQUIRE_SHARED();
    ompl::RNG::setSeed(7);  // before any OMPL object creates a generator
    PlanningContext c = pandaContext("table_pick", 1);
    const auto &si = c.spaceInformation();
    auto sampler = si->allocStateSampler();
    ompl::base::State *s1 = si->allocState(), *s2 = si->allocState(), *last = si->allocState();
    int invalidMotions = 0, validMotions = 0;
    for (int trial = 0; trial < 600; ++trial)
    {
        sampleValidState(c, *sampler, s1);
        sampler->sampleUniformNear(s2, s1, 1.5);
        const auto [j, n] = firstInvalidSample(c, values(s1), values(s2), c.motionValidator->resolution());
        std::pair<ompl::base::State *, double> lastValid{last, -1.0};
        const bool ok = c.motionValidator->checkMotion(s1, s2, lastValid);
        ASSERT_EQ(ok, j == 0) << "trial " << trial;
        if (ok)
        {
            ++validMotions;
            EXPECT_EQ(lastValid.second, -1.0) << "lastValid must be untouched on success";
            continue;
        }
        ++invalidMotions;
        const double expected = static_cast<double>(j - 1) / n;
        EXPECT_NEAR(lastValid.second, expected, 1e-12) << "trial " << trial << ", n = " << n;
        EXPECT_TRUE(c.validityChecker->isValid(last)) << "lastValid.first must be a valid state";
        ompl::base::State *interp = si->allocState();
        si->getStateSpace()->interpolate(s1, s2, lastValid.second, interp);
        EXPECT_LT(si->distance(interp, last), 1e-9);
        si->freeState(interp);
    }
    EXPECT_GT(invalidMotions, 50);
    EXPECT_GT(validMotions, 50);
    EXPECT_EQ(c.motionValidator->getValidMotionCount(), static_cast<unsigned>(validMotions));
    EXPECT_EQ(c.motionValidator->getInvalidMotionCount(), static_cast<unsigned>(invalidMotions));
    si->freeState(s1);
    si->freeState(s2);
    si->freeState(last);
}

TEST(OmplPlugin, BothCheckMotionOverloadsMatchTheDenseReference)
{
    // The two checkMotion overloads give the same verdict as a dense scan of the same samples, on every motion
    // from a valid s1, over lengths from one sample (the single-configuration path) to five batches, including
    // sample counts that are multiples of the SIMD width; the counters count both overloads.
    REQUIRE_SHARED();
    ompl::RNG::setSeed(13);  // before any OMPL object creates a generator
    PlanningContext c = pandaContext("bookshelf_tall", 4);
    const auto &si = c.spaceInformation();
    auto sampler = si->allocStateSampler();
    ompl::base::State *s1 = si->allocState(), *s2 = si->allocState(), *last = si->allocState();
    const double res = c.motionValidator->resolution();
    std::mt19937 rng(13);
    int valid = 0, invalid = 0, multiples = 0, singles = 0;
    for (int trial = 0; trial < 800; ++trial)
    {
        sampleValidState(c, *sampler, s1);
        // lengths 1..40 samples along a random direction, max joint step exactly n - 0.5 steps
        const int samples = 1 + static_cast<int>(rng() % 40);
        std::normal_distribution<double> normal;
        std::vector<double> dir(c.robot->dof());
        double linf = 0.0;
        for (double &d : dir)
        {
            d = normal(rng);
            linf = std::max(linf, std::abs(d));
        }
        for (std::size_t k = 0; k < dir.size(); ++k)
            values(s2)[k] = values(s1)[k] + dir[k] / linf * (samples - 0.5) * res;
        if (!si->satisfiesBounds(s2))
            continue;
        const auto [j, n] = firstInvalidSample(c, values(s1), values(s2), res);
        ASSERT_EQ(n, samples);
        multiples += n % c.checker->width() == 0 ? 1 : 0;
        singles += n == 1 ? 1 : 0;
        std::pair<ompl::base::State *, double> lastValid{last, -1.0};
        const bool withLast = c.motionValidator->checkMotion(s1, s2, lastValid);
        const bool plain = c.motionValidator->checkMotion(s1, s2);
        ASSERT_EQ(withLast, j == 0) << "trial " << trial << ", n = " << n;
        ASSERT_EQ(plain, j == 0) << "trial " << trial << ", n = " << n;
        (plain ? valid : invalid) += 1;
    }
    EXPECT_GT(valid, 50);
    EXPECT_GT(invalid, 20);  // 33 with these seeds: short motions from valid states in an open scene
    EXPECT_GT(multiples, 10);
    EXPECT_GT(singles, 5);
    EXPECT_EQ(c.motionValidator->getValidMotionCount(), 2u * static_cast<unsigned>(valid));
    EXPECT_EQ(c.motionValidator->getInvalidMotionCount(), 2u * static_cast<unsigned>(invalid));
    for (auto *s : {s1, s2, last})
        si->freeState(s);
}

TEST(OmplPlugin, AgreesWithDiscreteMotionValidatorOnSingleJointMotions)
{
    // Along one joint, L2 and max-norm steps coincide: OMPL's DiscreteMotionValidator at the same step checks
    // exactly the same configurations, so verdicts, lastValid times and counters must agree.
    REQUIRE_SHARED();
    ompl::RNG::setSeed(11);  // before any OMPL object creates a generator
    PlanningContext c = pandaContext("bookshelf_small", 2);
    const auto &si = c.spaceInformation();
    const double res = c.motionValidator->resolution();
    si->setStateValidityCheckingResolution(res / si->getMaximumExtent());
    si->getStateSpace()->setup();  // the longest valid segment is computed in setup()
    ompl::base::DiscreteMotionValidator dmv(si);
    auto sampler = si->allocStateSampler();
    ompl::base::State *s1 = si->allocState(), *s2 = si->allocState();
    ompl::base::State *l1 = si->allocState(), *l2 = si->allocState();
    std::mt19937 rng(11);
    int compared = 0, invalid = 0;
    while (compared < 400)
    {
        sampleValidState(c, *sampler, s1);
        si->copyState(s2, s1);
        const std::size_t k = rng() % c.robot->dof();
        const auto &joint = c.robot->joints()[k];
        values(s2)[k] = std::uniform_real_distribution<double>(joint.lower, joint.upper)(rng);
        const double steps = std::abs(values(s2)[k] - values(s1)[k]) / res;
        if (std::abs(steps - std::round(steps)) < 1e-6)
            continue;  // avoid a tie in ceil() between the two step computations
        std::pair<ompl::base::State *, double> a{l1, -1.0}, b{l2, -1.0};
        const bool ours = c.motionValidator->checkMotion(s1, s2, a);
        const bool theirs = dmv.checkMotion(s1, s2, b);
        ASSERT_EQ(ours, theirs) << "motion " << compared;
        if (!ours)
        {
            ++invalid;
            EXPECT_NEAR(a.second, b.second, 1e-9) << "motion " << compared;
        }
        ++compared;
    }
    EXPECT_GT(invalid, 25);
    EXPECT_EQ(c.motionValidator->getValidMotionCount(), dmv.getValidMotionCount());
    EXPECT_EQ(c.motionValidator->getInvalidMotionCount(), dmv.getInvalidMotionCount());
    for (auto *s : {s1, s2, l1, l2})
        si->freeState(s);
}

TEST(OmplPlugin, ConcurrentChecksGiveSameVerdictsAndExactCounts)
{
    REQUIRE_SHARED();
    ompl::RNG::setSeed(5);  // before any OMPL object creates a generator
    PlanningContext c = pandaContext("cage", 3);
    const auto &si = c.spaceInformation();
    auto sampler = si->allocStateSampler();
    const int N = 300;
    std::vector<ompl::base::State *> a(N), b(N);
    std::vector<int> expected(N), expectedState(N);
    for (int i = 0; i < N; ++i)
    {
        a[i] = si->allocState();
        b[i] = si->allocState();
        sampler->sampleUniform(a[i]);
        sampler->sampleUniformNear(b[i], a[i], 1.0);
        expectedState[i] = c.validityChecker->isValid(b[i]);
        expected[i] = c.motionValidator->checkMotion(a[i], b[i]);
    }
    c.motionValidator->resetMotionCounter();
    const int threads = 4;
    std::atomic<int> mismatches{0};
    std::vector<std::thread> pool;
    for (int t = 0; t < threads; ++t)
        pool.emplace_back(
            [&]
            {
                for (int i = 0; i < N; ++i)
                {
                    if (c.motionValidator->checkMotion(a[i], b[i]) != static_cast<bool>(expected[i]))
                        ++mismatches;
                    if (c.validityChecker->isValid(b[i]) != static_cast<bool>(expectedState[i]))
                        ++mismatches;
                }
            });
    for (auto &th : pool)
        th.join();
    EXPECT_EQ(mismatches.load(), 0);
    EXPECT_EQ(c.motionValidator->getCheckedMotionCount(), static_cast<unsigned>(threads * N));
    const unsigned validPerRound = static_cast<unsigned>(std::count(expected.begin(), expected.end(), 1));
    EXPECT_EQ(c.motionValidator->getValidMotionCount(), threads * validPerRound);
    for (int i = 0; i < N; ++i)
    {
        si->freeState(a[i]);
        si->freeState(b[i]);
    }
}

TEST(OmplPlugin, BatchStateCheckMatchesSingleChecks)
{
    REQUIRE_SHARED();
    ompl::RNG::setSeed(9);  // before any OMPL object creates a generator
    PlanningContext c = pandaContext("box", 4);
    const auto &si = c.spaceInformation();
    auto sampler = si->allocStateSampler();
    const int N = 203;  // not a multiple of the SIMD width
    std::vector<ompl::base::State *> states(N);
    for (auto &s : states)
    {
        s = si->allocState();
        sampler->sampleUniform(s);
    }
    std::unique_ptr<bool[]> verdicts(new bool[N]);
    const std::size_t valid = c.validityChecker->isValidBatch(states.data(), N, verdicts.get());
    std::size_t count = 0;
    for (int i = 0; i < N; ++i)
    {
        EXPECT_EQ(verdicts[i], c.validityChecker->isValid(states[i])) << i;
        count += verdicts[i];
    }
    EXPECT_EQ(valid, count);
    EXPECT_GT(count, 0u);
    EXPECT_LT(count, static_cast<std::size_t>(N));
    for (auto *s : states)
        si->freeState(s);
}

TEST(OmplPlugin, EnvironmentSwapIsSeenByBothValidators)
{
    REQUIRE_SHARED();
    PlanningContext c = pandaContext("table_pick", 5);
    const auto &si = c.spaceInformation();
    ompl::base::State *s = si->allocState();
    for (std::size_t k = 0; k < c.robot->dof(); ++k)
        values(s)[k] = 0.5 * (c.robot->joints()[k].lower + c.robot->joints()[k].upper);
    auto empty = std::make_shared<Environment>();
    c.setEnvironment(empty);
    const bool freeInEmpty = c.validityChecker->isValid(s);
    auto blocked = std::make_shared<Environment>();
    blocked->addSphere("blob", Eigen::Vector3d::Zero(), 3.0);  // swallows the whole robot
    c.setEnvironment(blocked);
    EXPECT_FALSE(c.validityChecker->isValid(s));
    EXPECT_FALSE(c.motionValidator->checkMotion(s, s));
    c.setEnvironment(empty);
    EXPECT_EQ(c.validityChecker->isValid(s), freeInEmpty);
    EXPECT_THROW(c.setEnvironment(nullptr), ropras::Error);
    si->freeState(s);
}

namespace
{
    /// a 3-D unit cube without obstacles, set up: enough to create every planner of the registry
    ompl::base::SpaceInformationPtr freeCubeSpace()
    {
        auto space = std::make_shared<ompl::base::RealVectorStateSpace>(3);
        space->setBounds(-1, 1);
        auto si = std::make_shared<ompl::base::SpaceInformation>(space);
        si->setStateValidityChecker([](const ompl::base::State *) { return true; });
        si->setup();
        return si;
    }
}  // namespace

// Parameter values: every parameter of every planner takes its own default back (no false rejection), and the
// values OMPL would accept silently (range=-1 means "automatic") or reject without a name are errors naming the
// planner, the parameter and the value.
TEST(OmplPlugin, RegistryChecksParameterValues)
{
    const auto si = freeCubeSpace();
    auto &registry = PlannerRegistry::instance();
    std::size_t checked = 0;
    for (const std::string &name : registry.names())
    {
        std::map<std::string, std::string> defaults;
        registry.create(name, si)->params().getParams(defaults);
        for (const auto &[key, value] : defaults)
        {
            if (value.empty() || value == "inf" || value == "-inf")
                continue;  // a parameter without a getter, or an infinite default (OMPL cannot parse "inf" back)
            EXPECT_NO_THROW(registry.create(name, si, {{key, value}})) << name << " " << key << "=" << value;
            ++checked;
        }
    }
    EXPECT_GT(checked, 100u);
    const auto message = [&](const std::string &planner, const std::string &key, const std::string &value)
    {
        try
        {
            registry.create(planner, si, {{key, value}});
        }
        catch (const ropras::Error &e)
        {
            return std::string(e.what());
        }
        return std::string();
    };
    EXPECT_EQ(message("RRTConnect", "range", "-1"),
              "planner RRTConnect: parameter 'range' = '-1' must be >= 0 (OMPL's range for it: 0.:1.:10000.)");
    EXPECT_EQ(message("RRTConnect", "range", "nan"),
              "planner RRTConnect: parameter 'range' = 'nan' must be a finite number");
    EXPECT_EQ(message("RRTConnect", "range", "inf"),
              "planner RRTConnect: parameter 'range' = 'inf' must be a finite number");
    EXPECT_EQ(message("RRTConnect", "range", "1e999"),
              "planner RRTConnect: parameter 'range' = '1e999' is not a number");
    EXPECT_EQ(message("RRTConnect", "range", "2m"), "planner RRTConnect: parameter 'range' = '2m' is not a number");
    EXPECT_EQ(message("RRT", "goal_bias", "1.5").find("planner RRT: parameter 'goal_bias' = '1.5' must be <= 1"), 0u);
    EXPECT_EQ(message("PRM", "max_nearest_neighbors", "2.5"),
              "planner PRM: parameter 'max_nearest_neighbors' = '2.5' must be a whole number");
    EXPECT_NE(message("PRM", "max_nearest_neighbors", "-3"), "");
    // an integer beyond its declared type, or in a form OMPL's std::stoul would misread, is refused
    EXPECT_EQ(message("VectorizedRRTConnect", "max_samples", "4294967296"),
              "planner VectorizedRRTConnect: parameter 'max_samples' = '4294967296' must be a whole number in [0, "
              "4294967295]");
    EXPECT_EQ(message("VectorizedRRTConnect", "max_samples", "1e6"),
              "planner VectorizedRRTConnect: parameter 'max_samples' = '1e6' must be written as a whole number in "
              "digits (no exponent or point)");
    EXPECT_EQ(message("VectorizedRRTConnect", "max_samples", "-1"),
              "planner VectorizedRRTConnect: parameter 'max_samples' = '-1' must be a whole number in [0, 4294967295]");
    EXPECT_EQ(message("VectorizedRRTConnect", "max_samples", "1000000"), "");
    EXPECT_EQ(message("VectorizedRRTConnect", "halton", "2"),
              "planner VectorizedRRTConnect: parameter 'halton' = '2' must be 0, 1, true or false");
    EXPECT_EQ(message("RRTConnect", "range", "0.5"), "");
    EXPECT_EQ(message("VectorizedRRTConnect", "halton", "true"), "");
}

TEST(OmplPlugin, RegistryCreatesEveryPlannerAndRejectsBadNames)
{
    const auto si = freeCubeSpace();
    auto &registry = PlannerRegistry::instance();
    const auto names = registry.names();
    EXPECT_GE(names.size(), 39u);
    for (const std::string &name : names)
    {
        ompl::base::PlannerPtr planner = registry.create(name, si);
        ASSERT_TRUE(planner) << name;
    }
    EXPECT_TRUE(registry.contains("VectorizedRRTConnect"));
    try
    {
        registry.create("RRTConect", si);
        FAIL() << "unknown planner accepted";
    }
    catch (const ropras::Error &e)
    {
        EXPECT_NE(std::string(e.what()).find("RRTConect"), std::string::npos);
        EXPECT_NE(std::string(e.what()).find("RRTConnect"), std::string::npos) << "the message lists valid names";
    }
    auto rrt = registry.create("RRTConnect", si, {{"range", "0.25"}});
    EXPECT_EQ(rrt->params().getParams().size(), rrt->params().getParams().size());
    std::string range;
    ASSERT_TRUE(rrt->params().getParam("range", range));
    EXPECT_DOUBLE_EQ(std::stod(range), 0.25);
    try
    {
        registry.create("RRTConnect", si, {{"rnage", "0.25"}});
        FAIL() << "unknown parameter accepted";
    }
    catch (const ropras::Error &e)
    {
        EXPECT_NE(std::string(e.what()).find("rnage"), std::string::npos);
        EXPECT_NE(std::string(e.what()).find("range"), std::string::npos) << "the message lists valid parameters";
    }
}

namespace
{
    /** \brief Solves 2 problems per MBM category with \a planner; returns the number solved (out of 14). Each
        solve stops at an exact solution, after \a iterations evaluations of the termination condition (0: no
        such bound) or after \a timeLimit seconds, whichever comes first. */
    int solveMbmSample(const std::string &planner, unsigned iterations, double timeLimit)
    {
        const char *categories[] = {"bookshelf_small", "bookshelf_tall",  "bookshelf_thin", "box", "cage",
                                    "table_pick",      "table_under_pick"};
        int solved = 0;
        for (const char *category : categories)
            for (int problem : {1, 2})
            {
                PlanningContextOptions options;
                options.planner = planner;
                PlanningContext c = pandaContext(category, problem, options);
                char name[32];
                std::snprintf(name, sizeof name, "request%04d.yaml", problem);
                const auto request = loadMotionPlanRequest((SHARED / "mbm/panda" / category / name).string());
                ompl::base::ScopedState<> start(c.setup->getStateSpace()), goal(c.setup->getStateSpace());
                for (std::size_t k = 0; k < c.robot->dof(); ++k)
                {
                    start[k] = request.start.at(c.robot->joints()[k].name);
                    goal[k] = request.goal.at(c.robot->joints()[k].name);
                }
                c.setup->setStartAndGoalStates(start, goal);
                c.setup->setup();
                ompl::base::IterationTerminationCondition budget(iterations > 0 ? iterations : UINT_MAX);
                auto ptc = ompl::base::plannerOrTerminationCondition(
                    ompl::base::plannerOrTerminationCondition(ompl::base::timedPlannerTerminationCondition(timeLimit),
                                                              budget),
                    ompl::base::exactSolnPlannerTerminationCondition(c.setup->getProblemDefinition()));
                if (c.setup->solve(ptc) == ompl::base::PlannerStatus::EXACT_SOLUTION &&
                    c.setup->getSolutionPath().check())
                    ++solved;
            }
        return solved;
    }
}  // namespace

/// a planner, how many of the 14 problems it must solve, and its iteration budget per problem (0: 2 s instead)
struct MbmPlannerCase
{
    const char *planner;
    int minSolved;
    unsigned iterations;
};

class MbmPlanners : public ::testing::TestWithParam<MbmPlannerCase>
{
};

TEST_P(MbmPlanners, SolvesMbmProblemsWithFixedSeeds)
{
    REQUIRE_SHARED();
    ompl::msg::setLogLevel(ompl::msg::LOG_ERROR);
    const MbmPlannerCase &param = GetParam();
    const char *planner = param.planner;
    const int minSolved = param.minSolved;
    ompl::RNG::setSeed(42);  // each test runs in its own process under ctest
    // with an iteration budget the outcome depends on the seeds only, not on the machine's speed; the 60 s bound
    // only guards against a hang
    const int solved = solveMbmSample(planner, param.iterations, param.iterations > 0 ? 60.0 : 2.0);
    RecordProperty("solved", solved);
    EXPECT_GE(solved, minSolved) << planner << " solved " << solved << "/14";
}

// Success thresholds out of 14 problems (2 per category); no wall-clock assertion. Planners that evaluate the
// termination condition once per iteration get an iteration budget, so that their result does not depend on the
// machine's load (KPIECE1 solved 6/14 within 2 s on a slow portable build). PRM (roadmap thread) and BITstar
// (batches) evaluate it too rarely for a budget to be cheap and keep 2 s per problem. Measured here (2026-11-22):
// RRTConnect 14, VectorizedRRTConnect 14, LBKPIECE1 14, BiTRRT 14, KPIECE1 11 (the same in repeated runs); PRM
// 12, BITstar 9 within 2 s.
INSTANTIATE_TEST_SUITE_P(Planners, MbmPlanners,
                         ::testing::Values(MbmPlannerCase{"RRTConnect", 14, 20000},
                                           MbmPlannerCase{"VectorizedRRTConnect", 14, 20000},
                                           MbmPlannerCase{"PRM", 8, 0}, MbmPlannerCase{"KPIECE1", 9, 100000},
                                           MbmPlannerCase{"LBKPIECE1", 12, 20000}, MbmPlannerCase{"BiTRRT", 12, 20000},
                                           MbmPlannerCase{"BITstar", 8, 0}),
                         [](const auto &info) { return std::string(info.param.planner); });

namespace
{
    std::string writePointRobotUrdf()
    {
        return ropras::ompl_ext::test::writePointRobotUrdf("ropras_point_robot_plugin_test.urdf");
    }
}  // namespace

TEST(OmplPlugin, EveryRegisteredPlannerRunsThroughTheValidators)
{
    // Each planner of the registry, on a 2-D problem with a wall and a gap: no crash (projection-based planners
    // included), every solution path valid under the ropras validators, and nearly all planners solve it.
    ompl::msg::setLogLevel(ompl::msg::LOG_ERROR);
    ompl::RNG::setSeed(3);
    auto env = std::make_shared<Environment>();
    Eigen::Isometry3d wall = Eigen::Isometry3d::Identity();
    wall.translation() = Eigen::Vector3d(0.5, 0.35, 0.0);
    env->addBox("wall", wall, Eigen::Vector3d(0.05, 0.7, 0.2));  // gap above y = 0.7
    const std::string urdf = writePointRobotUrdf();
    int solved = 0, total = 0;
    std::vector<std::string> unsolved;
    for (const std::string &name : PlannerRegistry::instance().names())
    {
        // OMPL 1.5.2's LazyLBTRRT can abort on an assertion inside OMPL (LPAstarOnGraph::removeEdge, Debian builds
        // OMPL with assertions); documented in doc/ompl-plugin.md. It is still registered.
        if (name == "LazyLBTRRT")
            continue;
        PlanningContextOptions options;
        options.planner = name;
        PlanningContext c = makePlanningContext(urdf, "", env, RobotModel::Options(), options);
        ropras::ompl_ext::test::setPointRobotQuery(*c.setup);
        auto ptc = ompl::base::plannerOrTerminationCondition(
            ompl::base::timedPlannerTerminationCondition(0.3),
            ompl::base::exactSolnPlannerTerminationCondition(c.setup->getProblemDefinition()));
        const auto status = c.setup->solve(ptc);
        ++total;
        if (status == ompl::base::PlannerStatus::EXACT_SOLUTION)
        {
            EXPECT_TRUE(c.setup->getSolutionPath().check()) << name << " returned an invalid path";
            ++solved;
        }
        else
            unsolved.push_back(name);
    }
    std::string list;
    for (const auto &n : unsolved)
        list += n + " ";
    EXPECT_GE(solved, total - 4) << "unsolved: " << list;
}

TEST(OmplPlugin, CreateStateSpaceMakesAJointStateSpaceOfThePlanningJoints)
{
    // the space's own behaviour is tested in JointStateSpaceTest.cpp
    auto robot = RobotModel::fromUrdfFile(writePointRobotUrdf());
    auto space = createStateSpace(*robot);
    ASSERT_NE(dynamic_cast<JointStateSpace *>(space.get()), nullptr);
    ASSERT_EQ(space->getDimension(), 2u);
    EXPECT_EQ(space->getDimensionName(0), "x");
    EXPECT_EQ(space->getDimensionName(1), "y");
    EXPECT_EQ(space->getBounds().low, std::vector<double>({0.0, 0.0}));
    EXPECT_EQ(space->getBounds().high, std::vector<double>({1.0, 1.0}));
}
