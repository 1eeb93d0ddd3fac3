// VectorizedRRTConnect allocates per solve only what it hands over (the solution path and its states) plus OMPL's
// fixed per-query bookkeeping: counted with the global operator new of this test executable.
#include <gtest/gtest.h>

#include <ompl/base/PlannerTerminationCondition.h>
#include <ompl/util/Console.h>

#include "../AllocationCounter.h"
#include "PointRobotUrdf.h"
#include "ropras/ompl_ext/ompl/PlanningContext.h"

using namespace ropras::ompl_ext;

TEST(VectorizedRRTConnect, SolveAllocatesOnlyTheSolutionPath)
{
    // A wall across the straight line (gap above y = 0.7) and range 0.15: the trees grow several nodes per query.
    ompl::msg::setLogLevel(ompl::msg::LOG_ERROR);
    auto env = std::make_shared<Environment>();
    Eigen::Isometry3d pose = Eigen::Isometry3d::Identity();
    pose.translation() = Eigen::Vector3d(0.5, 0.35, 0.0);
    env->addBox("wall", pose, Eigen::Vector3d(0.05, 0.7, 0.2));
    // extensions checked one by one, and with their ends batched from the start (batch_after 0; the queue is sized in
    // setup())
    std::size_t maxExtra = 0;
    for (const char *batchAfter : {"32", "0"})
    {
        PlanningContextOptions options;
        options.planner = "VectorizedRRTConnect";
        options.plannerParams = {{"seed", "9"}, {"range", "0.15"}, {"batch_after", batchAfter}};
        PlanningContext c =
            makePlanningContext(ropras::ompl_ext::test::writePointRobotUrdf("ropras_point_robot_vrrtc_alloc_test.urdf"),
                                "", env, RobotModel::Options(), options);
        ropras::ompl_ext::test::setPointRobotQuery(*c.setup);
        const ompl::base::ProblemDefinition *pdef = c.setup->getProblemDefinition().get();
        const ompl::base::PlannerTerminationCondition ptc([pdef] { return pdef->hasExactSolution(); });
        for (int query = 0; query < 6; ++query)
        {
            c.setup->clear();
            const std::size_t before = ropras::test::allocationCount.load();
            ASSERT_EQ(c.setup->solve(ptc), ompl::base::PlannerStatus::EXACT_SOLUTION)
                << "query " << query << " batch_after " << batchAfter;
            const std::size_t allocations = ropras::test::allocationCount.load() - before;
            const std::size_t states = c.setup->getSolutionPath().getStateCount();
            ASSERT_GT(states, 2u) << "the wall forces a detour: the trees must have grown";
            ASSERT_GE(allocations, states) << "every state of the path is a new allocation";
            // the first query also reserves the planner's tree storage and OMPL's input-state buffer
            if (query > 0)
                maxExtra = std::max(maxExtra, allocations - states);
        }
    }
    RecordProperty("allocations_besides_path_states", static_cast<int>(maxExtra));
    // the path object, its state vector, OMPL's solution record and input-state buffer: nothing per node or sample
    EXPECT_LE(maxExtra, 6u);
}
