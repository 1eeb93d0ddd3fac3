// JointNearestNeighbors against OMPL's NearestNeighborsLinear (the exact answer by definition), and the registry's
// RRTConnect (which uses it) against OMPL's own RRTConnect with GNAT: the same trees, so the same path.
#include "ropras/ompl_ext/planners/JointNearestNeighbors.h"

#include <gtest/gtest.h>
#include <ompl/base/spaces/RealVectorStateSpace.h>
#include <ompl/datastructures/NearestNeighborsLinear.h>
#include <ompl/geometric/SimpleSetup.h>
#include <ompl/geometric/planners/rrt/RRTConnect.h>
#include <ompl/util/Console.h>
#include <ompl/util/RandomNumbers.h>

#include <algorithm>
#include <cmath>
#include <functional>
#include <memory>
#include <vector>

#include "ropras/core/Rng.h"
#include "ropras/ompl_ext/ompl/JointStateSpace.h"
#include "ropras/ompl_ext/ompl/PlannerRegistry.h"

using ropras::ompl_ext::JointNearestNeighbors;
using ropras::ompl_ext::JointStateSpace;

namespace
{
    /// what OMPL's planners store: a record with a state
    struct Node
    {
        ompl::base::State *state{nullptr};
    };

    std::shared_ptr<JointStateSpace> space(unsigned dof, double lo, double hi)
    {
        auto s = std::make_shared<JointStateSpace>(dof);
        s->setBounds(lo, hi);
        s->setup();
        return s;
    }

    double *values(ompl::base::State *s)
    {
        return s->as<ompl::base::RealVectorStateSpace::StateType>()->values;
    }
}  // namespace

TEST(JointNearestNeighbors, AgreesWithTheLinearSearchForEveryQuery)
{
    // dimensions below, at and above one vector (4) and the largest robots' (14); sizes across block boundaries
    ropras::core::Rng rng(11);
    for (unsigned dof : {1u, 3u, 4u, 7u, 8u, 14u})
    {
        auto sp = space(dof, -3.0, 3.0);
        std::vector<Node> nodes(70), queries(40);
        for (auto *list : {&nodes, &queries})
            for (Node &n : *list)
            {
                n.state = sp->allocState();
                for (unsigned k = 0; k < dof; ++k)
                    values(n.state)[k] = rng.uniform(-3.0, 3.0);
            }
        const auto distance = [&](const Node *a, const Node *b) { return sp->distance(a->state, b->state); };
        JointNearestNeighbors<Node *> ours(dof);
        ompl::NearestNeighborsLinear<Node *> linear;
        ours.setDistanceFunction(distance);
        linear.setDistanceFunction(distance);
        EXPECT_THROW(ours.nearest(&queries[0]), ompl::Exception);
        for (std::size_t i = 0; i < nodes.size(); ++i)
        {
            ours.add(&nodes[i]);
            linear.add(&nodes[i]);
            ASSERT_EQ(ours.size(), i + 1);
            for (Node &q : queries)
                ASSERT_EQ(ours.nearest(&q), linear.nearest(&q)) << "dof " << dof << ", " << i + 1 << " nodes";
        }
        // a node is its own nearest; k nearest and radius searches as the linear search's
        for (Node &n : nodes)
            EXPECT_EQ(ours.nearest(&n), &n);
        std::vector<Node *> a, b;
        ours.nearestK(&queries[1], 9, a);
        linear.nearestK(&queries[1], 9, b);
        EXPECT_EQ(a, b);
        const double r = distance(&queries[2], b.back());
        ours.nearestR(&queries[2], r, a);
        linear.nearestR(&queries[2], r, b);
        EXPECT_EQ(a, b);
        EXPECT_FALSE(a.empty());
        // removals (first, inside a block, last) keep every answer exact; list() keeps the order of add()
        for (std::size_t index : {0u, 17u, 5u, 66u})
        {
            Node *gone = &nodes[index];
            EXPECT_TRUE(ours.remove(gone));
            EXPECT_TRUE(linear.remove(gone));
            EXPECT_FALSE(ours.remove(gone));
            for (Node &q : queries)
                ASSERT_EQ(ours.nearest(&q), linear.nearest(&q)) << "dof " << dof << " after removing " << index;
            EXPECT_NE(ours.nearest(gone), gone);
        }
        ours.list(a);
        linear.list(b);
        EXPECT_EQ(a, b);
        ours.clear();
        EXPECT_EQ(ours.size(), 0u);
        ours.add(&nodes[3]);
        EXPECT_EQ(ours.nearest(&queries[0]), &nodes[3]);
        for (auto *list : {&nodes, &queries})
            for (Node &n : *list)
                sp->freeState(n.state);
    }
}

TEST(JointNearestNeighbors, TiesGoToTheFirstNodeAddedAndANanQueryToNodeZero)
{
    auto sp = space(7, -1.0, 1.0);
    std::vector<Node> nodes(9);
    for (std::size_t i = 0; i < nodes.size(); ++i)
    {
        nodes[i].state = sp->allocState();
        for (unsigned k = 0; k < 7; ++k)
            values(nodes[i].state)[k] = (i % 3 == 0) ? 0.5 : -0.5;  // nodes 0, 3, 6 equal; 1, 2, 4, ... equal
    }
    JointNearestNeighbors<Node *> nn(7);
    for (Node &n : nodes)
        nn.add(&n);
    Node q{sp->allocState()};
    for (unsigned k = 0; k < 7; ++k)
        values(q.state)[k] = 0.4;
    EXPECT_EQ(nn.nearest(&q), &nodes[0]);
    for (unsigned k = 0; k < 7; ++k)
        values(q.state)[k] = -0.4;
    EXPECT_EQ(nn.nearest(&q), &nodes[1]);
    values(q.state)[2] = std::nan("");
    EXPECT_EQ(nn.nearest(&q), &nodes[0]);
    sp->freeState(q.state);
    for (Node &n : nodes)
        sp->freeState(n.state);
}

namespace
{
    struct PlanResult
    {
        std::vector<std::vector<double>> path;
        unsigned vertices{0};
    };

    /// one 7-joint RRTConnect query through a wall at q0 = 0 with one gap (|q1 - 1| < 0.5 and |q2 + 1| < 0.6), in a
    /// fresh SimpleSetup after re-seeding OMPL's seed sequence: the trees grow a few hundred nodes
    PlanResult plan(const std::function<ompl::base::PlannerPtr(const ompl::base::SpaceInformationPtr &)> &make)
    {
        auto sp = space(7, -3.0, 3.0);
        ompl::geometric::SimpleSetup ss(sp);
        ss.setStateValidityChecker(
            [](const ompl::base::State *s)
            {
                const double *q = s->as<ompl::base::RealVectorStateSpace::StateType>()->values;
                return std::abs(q[0]) > 0.2 || (std::abs(q[1] - 1.0) < 0.5 && std::abs(q[2] + 1.0) < 0.6);
            });
        ss.getSpaceInformation()->setStateValidityCheckingResolution(0.005);
        ompl::base::ScopedState<> start(sp), goal(sp);
        for (int k = 0; k < 7; ++k)
        {
            start[k] = k == 0 ? -2.5 : 0.3 * k - 1.0;
            goal[k] = k == 0 ? 2.5 : 1.0 - 0.25 * k;
        }
        ss.setStartAndGoalStates(start, goal);
        const auto level = ompl::msg::getLogLevel();
        ompl::msg::setLogLevel(ompl::msg::LOG_NONE);  // re-seeding after the first seed is logged as an error
        ompl::RNG::setSeed(5);                        // restarts OMPL's seed sequence
        ss.setPlanner(make(ss.getSpaceInformation()));
        ss.setup();
        const auto status = ss.solve(10.0);
        ompl::msg::setLogLevel(level);
        EXPECT_EQ(status, ompl::base::PlannerStatus::EXACT_SOLUTION);
        PlanResult result;
        for (ompl::base::State *s : ss.getSolutionPath().getStates())
            result.path.emplace_back(values(s), values(s) + 7);
        ompl::base::PlannerData data(ss.getSpaceInformation());
        ss.getPlanner()->getPlannerData(data);
        result.vertices = data.numVertices();
        return result;
    }
}  // namespace

TEST(JointNearestNeighbors, RegistryRRTConnectGrowsTheTreesOfOmplsOwn)
{
    const PlanResult expected = plan(
        [](const ompl::base::SpaceInformationPtr &si)
        {
            auto planner = std::make_shared<ompl::geometric::RRTConnect>(si);
            planner->setRange(0.5);
            return planner;
        });
    const PlanResult again = plan(
        [](const ompl::base::SpaceInformationPtr &si)
        {
            auto planner = std::make_shared<ompl::geometric::RRTConnect>(si);
            planner->setRange(0.5);
            return planner;
        });
    ASSERT_EQ(again.vertices, expected.vertices) << "OMPL's own run is not reproducible: the comparison means nothing";
    const PlanResult got = plan(
        [](const ompl::base::SpaceInformationPtr &si)
        {
            auto planner = ropras::ompl_ext::PlannerRegistry::instance().create("RRTConnect", si, {{"range", "0.5"}});
            EXPECT_EQ(planner->getName(), "RRTConnect");
            return planner;
        });
    EXPECT_GT(expected.vertices, 50u);  // a query that needs trees, not a straight line
    EXPECT_EQ(got.vertices, expected.vertices);
    ASSERT_EQ(got.path.size(), expected.path.size());
    for (std::size_t i = 0; i < got.path.size(); ++i)
        for (int k = 0; k < 7; ++k)
            EXPECT_NEAR(got.path[i][k], expected.path[i][k], 1e-12) << "state " << i << " joint " << k;
}
