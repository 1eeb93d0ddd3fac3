// VectorizedRRTConnect: its float block nearest-neighbour scan against a double brute force, the direct start-goal
// connection, tree storage reused across clear(), and determinism with a fixed seed.
#include <gtest/gtest.h>

#include <ompl/base/PlannerData.h>
#include <ompl/base/PlannerTerminationCondition.h>
#include <ompl/util/Console.h>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <limits>
#include <random>
#include <utility>
#include <vector>

#include "../../ompl_ext/src/planners/NodeBlocks.h"
#include "PointRobotUrdf.h"
#include "ropras/core/Error.h"
#include "ropras/ompl_ext/ompl/PlanningContext.h"
#include "ropras/ompl_ext/planners/VectorizedRRTConnect.h"

namespace fs = std::filesystem;
using namespace ropras::ompl_ext;

namespace
{
    double distSq(const double *a, const double *b, std::size_t dof)
    {
        double d = 0.0;
        for (std::size_t k = 0; k < dof; ++k)
            d += (a[k] - b[k]) * (a[k] - b[k]);
        return d;
    }

    std::string writePointRobotUrdf()
    {
        return ropras::ompl_ext::test::writePointRobotUrdf("ropras_point_robot_vrrtc_test.urdf");
    }

    /// point robot from (0.1, 0.1) to (0.9, 0.1); with \a wall a wall at x = 0.5 up to y = 0.7 blocks the line
    PlanningContext pointContext(bool wall, const std::map<std::string, std::string> &params)
    {
        auto env = std::make_shared<Environment>();
        if (wall)
        {
            Eigen::Isometry3d pose = Eigen::Isometry3d::Identity();
            pose.translation() = Eigen::Vector3d(0.5, 0.35, 0.0);
            env->addBox("wall", pose, Eigen::Vector3d(0.05, 0.7, 0.2));
        }
        PlanningContextOptions options;
        options.planner = "VectorizedRRTConnect";
        options.plannerParams = params;
        PlanningContext c = makePlanningContext(writePointRobotUrdf(), "", env, RobotModel::Options(), options);
        ropras::ompl_ext::test::setPointRobotQuery(*c.setup);
        return c;
    }

    ompl::base::PlannerStatus solve(PlanningContext &c, double seconds = 2.0)
    {
        return c.setup->solve(ompl::base::plannerOrTerminationCondition(
            ompl::base::timedPlannerTerminationCondition(seconds),
            ompl::base::exactSolnPlannerTerminationCondition(c.setup->getProblemDefinition())));
    }

    std::vector<double> pathValues(PlanningContext &c)
    {
        std::vector<double> out;
        for (const ompl::base::State *s : c.setup->getSolutionPath().getStates())
            for (std::size_t k = 0; k < c.robot->dof(); ++k)
                out.push_back(s->as<ompl::base::RealVectorStateSpace::StateType>()->values[k]);
        return out;
    }
}  // namespace

TEST(NodeBlocks, NearestMatchesDoubleBruteForce)
{
    // Random trees of 1..70 nodes (partial and several blocks) in 2, 7 and 13 dimensions: the float scan's pick
    // is the double nearest, or within float rounding of it; exact duplicates resolve to the earliest node.
    std::mt19937 rng(11);
    std::uniform_real_distribution<double> u(-3.0, 3.0);
    int exact = 0, total = 0;
    for (std::size_t dof : {2u, 7u, 13u})
        for (std::size_t n = 1; n <= 70; n += 3)
        {
            NodeBlocks blocks;
            blocks.reset(dof);
            std::vector<double> nodes(n * dof);
            for (double &v : nodes)
                v = u(rng);
            for (std::size_t i = 0; i < n; ++i)
                blocks.add(nodes.data() + i * dof);
            ASSERT_EQ(blocks.size(), n);
            for (int trial = 0; trial < 40; ++trial)
            {
                std::vector<double> q(dof);
                for (double &v : q)
                    v = u(rng);
                std::size_t brute = 0;
                for (std::size_t i = 1; i < n; ++i)
                    if (distSq(nodes.data() + i * dof, q.data(), dof) <
                        distSq(nodes.data() + brute * dof, q.data(), dof))
                        brute = i;
                const std::size_t got = blocks.nearest(q.data());
                ASSERT_LT(got, n);
                std::vector<float> qf(q.begin(), q.end());
                float distF = -1.0f;
                ASSERT_EQ(blocks.nearest(qf.data(), &distF), got) << "the float query overload is the same scan";
                // the float squared distance is within the rounding bound the planner's early dynamic-domain
                // rejection relies on (coordinates within [-3, 3]: delta = 2 * 2^-24 * 3)
                const double dExact = distSq(nodes.data() + got * dof, q.data(), dof);
                const double delta = 2.0 * 0x1.0p-24 * 3.0;
                const double bound = 1e-3 * dExact + 4.0 * delta * std::sqrt(static_cast<double>(dof) * dExact) +
                                     2.0 * static_cast<double>(dof) * delta * delta;
                EXPECT_LE(std::abs(static_cast<double>(distF) - dExact), bound) << "dof " << dof << ", " << n;
                const double dBrute = distSq(nodes.data() + brute * dof, q.data(), dof);
                const double dGot = distSq(nodes.data() + got * dof, q.data(), dof);
                EXPECT_LE(dGot, dBrute * (1.0 + 1e-5) + 1e-6) << "dof " << dof << ", " << n << " nodes";
                exact += got == brute ? 1 : 0;
                ++total;
            }
        }
    EXPECT_GE(exact, total * 99 / 100) << "float rounding should decide only near-ties";

    // duplicates: the earliest of equal nodes wins, also across blocks
    NodeBlocks dup;
    dup.reset(3);
    const double far[3] = {2.0, 2.0, 2.0}, near[3] = {0.1, 0.2, 0.3};
    for (int i = 0; i < 11; ++i)
        dup.add(far);
    dup.add(near);
    for (int i = 0; i < 9; ++i)
        dup.add(near);
    const double q[3] = {0.0, 0.0, 0.0};
    EXPECT_EQ(dup.nearest(q), 11u);
    // ties within one block: the smallest index among the tied lanes, wherever the lanes sit
    NodeBlocks one;
    one.reset(3);
    for (int i = 0; i < 8; ++i)
        one.add(i == 2 || i == 5 || i == 7 ? near : far);
    EXPECT_EQ(one.nearest(q), 2u);
    // clear() forgets the nodes; a NaN query still returns a valid index
    dup.clear();
    EXPECT_EQ(dup.size(), 0u);
    dup.add(far);
    dup.add(near);
    EXPECT_EQ(dup.nearest(q), 1u);
    const double nanQ[3] = {std::nan(""), 0.0, 0.0};
    EXPECT_LT(dup.nearest(nanQ), dup.size());
}

TEST(VectorizedRRTConnect, DirectConnectionWhenTheStraightMotionIsFree)
{
    ompl::msg::setLogLevel(ompl::msg::LOG_ERROR);
    // free space: one motion check, the path is start -> goal
    PlanningContext free = pointContext(false, {{"seed", "5"}});
    ASSERT_EQ(solve(free), ompl::base::PlannerStatus::EXACT_SOLUTION);
    EXPECT_EQ(free.setup->getSolutionPath().getStateCount(), 2u);
    EXPECT_TRUE(free.setup->getSolutionPath().check());
    ompl::base::PlannerData freeData(free.spaceInformation());
    free.setup->getPlannerData(freeData);
    EXPECT_EQ(freeData.numVertices(), 2u) << "no tree grew";

    // direct = 0: the trees grow (range 0.1 needs several extensions), still a valid path
    PlanningContext grown = pointContext(false, {{"seed", "5"}, {"direct", "0"}, {"range", "0.1"}});
    ASSERT_EQ(solve(grown), ompl::base::PlannerStatus::EXACT_SOLUTION);
    EXPECT_TRUE(grown.setup->getSolutionPath().check());
    EXPECT_GT(grown.setup->getSolutionPath().getStateCount(), 2u);

    // a wall across the straight line: the direct check fails, the path goes around it
    PlanningContext walled = pointContext(true, {{"seed", "5"}});
    ASSERT_EQ(solve(walled), ompl::base::PlannerStatus::EXACT_SOLUTION);
    EXPECT_TRUE(walled.setup->getSolutionPath().check());
    EXPECT_GT(walled.setup->getSolutionPath().getStateCount(), 2u);
    double maxY = 0.0;
    for (const ompl::base::State *s : walled.setup->getSolutionPath().getStates())
        maxY = std::max(maxY, s->as<ompl::base::RealVectorStateSpace::StateType>()->values[1]);
    EXPECT_GT(maxY, 0.7) << "the path must pass through the gap above the wall";
}

TEST(VectorizedRRTConnect, SameSeedSamePathAcrossInstancesAndClear)
{
    // Two planners with the same seed return the same path; after clear() the reused tree storage holds no stale
    // nodes (every path is valid and the planner data only holds the new query's trees).
    ompl::msg::setLogLevel(ompl::msg::LOG_ERROR);
    const std::map<std::string, std::string> params{{"seed", "9"}, {"range", "0.15"}};
    PlanningContext a = pointContext(true, params), b = pointContext(true, params);
    ASSERT_EQ(solve(a), ompl::base::PlannerStatus::EXACT_SOLUTION);
    ASSERT_EQ(solve(b), ompl::base::PlannerStatus::EXACT_SOLUTION);
    EXPECT_EQ(pathValues(a), pathValues(b));
    ompl::base::PlannerData first(a.spaceInformation());
    a.setup->getPlannerData(first);
    for (int query = 0; query < 5; ++query)
    {
        a.setup->clear();
        ASSERT_EQ(solve(a), ompl::base::PlannerStatus::EXACT_SOLUTION) << "query " << query;
        EXPECT_TRUE(a.setup->getSolutionPath().check());
        ompl::base::PlannerData data(a.spaceInformation());
        a.setup->getPlannerData(data);
        EXPECT_EQ(data.numStartVertices(), 1u);
        EXPECT_EQ(data.numGoalVertices(), 1u);
        EXPECT_EQ(data.numEdges() + 2, data.numVertices()) << "two trees: every node but the roots has a parent";
    }
}

TEST(VectorizedRRTConnect, RejectsBadSettings)
{
    PlanningContext c = pointContext(false, {});
    auto planner = std::make_shared<VectorizedRRTConnect>(c.spaceInformation());
    planner->setRange(std::numeric_limits<double>::quiet_NaN());
    c.setup->setPlanner(planner);
    EXPECT_THROW(c.setup->setup(), ropras::Error);
    planner->setRange(-1.0);
    EXPECT_THROW(planner->setup(), ropras::Error);
    planner->setRange(0.5);
    planner->setTreeRatio(std::numeric_limits<double>::quiet_NaN());
    EXPECT_THROW(planner->setup(), ropras::Error);
    planner->setTreeRatio(-0.5);
    EXPECT_THROW(planner->setup(), ropras::Error);
    planner->setTreeRatio(1.0);
    EXPECT_NO_THROW(planner->setup());
}

TEST(VectorizedRRTConnect, EveryTreeEdgeIsAtMostRangeAndValid)
{
    // Extensions take one step of range, connections ceil(d / range) equal steps: no edge of either tree is longer
    // than range, every edge is a valid motion, and the solution path (tree edges only) is valid.
    ompl::msg::setLogLevel(ompl::msg::LOG_ERROR);
    // the balancing and connection variants too: VAMP's tree ratio, connections outside the dynamic domain, and the
    // extension ends batched from the first sample on (no failure needed first)
    std::vector<unsigned> vertices[4];
    const std::pair<std::string, std::string> variants[4] = {
        {"tree_ratio", "0"}, {"tree_ratio", "1"}, {"dd_connect", "0"}, {"batch_after", "0"}};
    for (int variant = 0; variant < 4; ++variant)
        for (const char *range : {"0.07", "0.15", "0.4"})
            for (const char *seed : {"3", "17"})
            {
                PlanningContext c =
                    pointContext(true, {{"seed", seed}, {"range", range}, {"direct", "0"}, variants[variant]});
                ASSERT_EQ(solve(c), ompl::base::PlannerStatus::EXACT_SOLUTION) << "range " << range << " seed " << seed;
                EXPECT_TRUE(c.setup->getSolutionPath().check());
                ompl::base::PlannerData data(c.spaceInformation());
                c.setup->getPlannerData(data);
                ASSERT_GT(data.numEdges(), 2u);
                const double r = std::stod(range);
                const auto &si = c.spaceInformation();
                for (unsigned v = 0; v < data.numVertices(); ++v)
                {
                    std::vector<unsigned> out;
                    data.getEdges(v, out);
                    for (unsigned w : out)
                    {
                        const ompl::base::State *a = data.getVertex(v).getState(), *b = data.getVertex(w).getState();
                        EXPECT_LE(si->distance(a, b), r * (1.0 + 1e-9)) << "range " << range << " seed " << seed;
                        EXPECT_TRUE(si->checkMotion(a, b)) << "range " << range << " seed " << seed;
                    }
                }
                vertices[variant].push_back(data.numVertices());
            }
    // VAMP's balancing rule grows other trees than the default (dd_connect changes nothing in this open plane: its
    // connections do not fail)
    EXPECT_NE(vertices[1], vertices[0]);
    // batched ends grow their queued extensions from the nodes chosen when queued: other trees
    EXPECT_NE(vertices[3], vertices[0]);
}

TEST(VectorizedRRTConnect, BatchedEndsOnlyAfterTheirThresholdOfFailures)
{
    // Until batch_after extensions have failed, every extension is checked on its own: with a threshold no solve
    // reaches, the trees are those of batch_ends = 0 and no batch of ends is checked; with batching from the start,
    // or after 4 failures, batches reject ends that hit the wall (counted by the progress properties), the trees
    // differ, and every path is valid.
    ompl::msg::setLogLevel(ompl::msg::LOG_ERROR);
    const auto property = [](PlanningContext &c, const std::string &name)
    { return std::stoull(c.setup->getPlanner()->getPlannerProgressProperties().at(name + " INTEGER")()); };
    for (const char *seed : {"3", "17", "29"})
    {
        std::vector<double> paths[4];
        unsigned long long batches[4], rejected[4];
        const std::map<std::string, std::string> settings[4] = {
            {{"batch_ends", "0"}}, {{"batch_after", "1000000"}}, {{"batch_after", "0"}}, {{"batch_after", "4"}}};
        for (int k = 0; k < 4; ++k)
        {
            std::map<std::string, std::string> params = settings[k];
            params.insert({{"seed", seed}, {"range", "0.07"}, {"direct", "0"}, {"max_samples", "100000"}});
            PlanningContext c = pointContext(true, params);
            ASSERT_EQ(solve(c, 10.0), ompl::base::PlannerStatus::EXACT_SOLUTION) << "seed " << seed << " setting " << k;
            EXPECT_TRUE(c.setup->getSolutionPath().check());
            paths[k] = pathValues(c);
            batches[k] = property(c, "end batches");
            rejected[k] = property(c, "ends rejected");
            EXPECT_GT(property(c, "motion checks"), 0u);
        }
        EXPECT_EQ(paths[1], paths[0]) << "seed " << seed;
        EXPECT_EQ(batches[0], 0u);
        EXPECT_EQ(batches[1], 0u);
        EXPECT_EQ(rejected[1], 0u);
        for (int k : {2, 3})
        {
            EXPECT_NE(paths[k], paths[0]) << "seed " << seed << " setting " << k;
            EXPECT_GT(batches[k], 0u) << "seed " << seed << " setting " << k;
            EXPECT_GT(rejected[k], 0u) << "ends in the wall are rejected by the batch, seed " << seed;
            EXPECT_LE(rejected[k], 8 * batches[k]);
        }
    }
}
