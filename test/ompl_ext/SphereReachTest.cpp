// reachableSpherePairs: the sphere pairs that can touch within the joint limits. Checked against a closed form on a
// one-joint robot, and against sampled configurations of the Panda and UR5 (no sphere pair that touches in any
// sample may be missing), with the checker's self-collision verdicts compared to an all-pairs double reference.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <memory>
#include <random>
#include <set>
#include <string>
#include <utility>

#include "ExpectError.h"
#include "ropras/ompl_ext/collision/CollisionChecker.h"
#include "ropras/ompl_ext/model/RobotModel.h"
#include "ropras/ompl_ext/model/SphereReach.h"
#include "ropras/ompl_ext/scene/Environment.h"

using namespace ropras::ompl_ext;

namespace
{
    const std::string SHARED = ROPRAS_SHARED_DIR;

    /** A base sphere at (0.5, 0, 0) and, beyond a revolute joint about z at the origin with limits [1, 2] and a
        fixed joint, a tip sphere at 0.5 from the axis: over the limits their centres are at least
        2 * 0.5 * sin(0.5) = 0.47943 apart (at q = 1). \a jointType "prismatic" makes the joint slide along z. */
    std::string swingUrdf(double baseRadius, double tipRadius, const std::string &jointType = "revolute")
    {
        const auto sphere = [](double x, double r)
        {
            return "<collision><origin xyz=\"" + std::to_string(x) + " 0 0\"/><geometry><sphere radius=\"" +
                   std::to_string(r) + "\"/></geometry></collision>";
        };
        return "<robot name=\"swing\">"
               "<link name=\"base\">" +
               sphere(0.5, baseRadius) + "</link><link name=\"arm\"/><link name=\"tip\">" + sphere(0.5, tipRadius) +
               "</link>"
               "<joint name=\"j\" type=\"" +
               jointType +
               "\"><parent link=\"base\"/><child link=\"arm\"/><axis xyz=\"0 0 1\"/>"
               "<limit lower=\"1\" upper=\"2\" effort=\"1\" velocity=\"1\"/></joint>"
               "<joint name=\"f\" type=\"fixed\"><parent link=\"arm\"/><child link=\"tip\"/></joint></robot>";
    }

    int collisionLink(const RobotModel &model, const std::string &name)
    {
        const auto &links = model.collisionLinks();
        for (std::size_t k = 0; k < links.size(); ++k)
            if (links[k].name == name)
                return static_cast<int>(k);
        ADD_FAILURE() << "no collision link " << name;
        return -1;
    }

    /// ../shared/robots/<name>/<name>_spherized.urdf with its SRDF
    std::shared_ptr<const RobotModel> sharedRobot(const std::string &name)
    {
        return RobotModel::fromUrdfFile(SHARED + "/robots/" + name + "/" + name + "_spherized.urdf",
                                        SHARED + "/robots/" + name + "/" + name + ".srdf");
    }

    const double MIN_GAP = 2.0 * 0.5 * std::sin(0.5);  // closest approach of the two centres
}  // namespace

TEST(SphereReach, SwingMatchesTheClosedForm)
{
    // radii sum 0.47: the spheres stay 0.0094 apart, beyond the 5e-4 margin -> the pair can never touch
    const auto apart = RobotModel::fromUrdfString(swingUrdf(0.2, 0.27), ".", "swing.urdf");
    const SphereReach far = reachableSpherePairs(*apart, collisionLink(*apart, "base"), collisionLink(*apart, "tip"));
    EXPECT_TRUE(far.analysed);
    EXPECT_FALSE(far.budgetExhausted);
    EXPECT_TRUE(far.pairs.empty()) << "closest gap " << MIN_GAP - 0.47;

    // radii sum 0.4792: within the margin of contact at q = 1 -> kept; a sum past the gap touches -> kept
    for (const double tip : {0.2792, 0.29})
    {
        const auto near = RobotModel::fromUrdfString(swingUrdf(0.2, tip), ".", "swing.urdf");
        const SphereReach r = reachableSpherePairs(*near, collisionLink(*near, "base"), collisionLink(*near, "tip"));
        EXPECT_TRUE(r.analysed);
        ASSERT_EQ(r.pairs.size(), 1u) << "tip radius " << tip;
    }

    // the free cells of the kept pair: their gap 2 * 0.5 * sin(q / 2) - 0.4792 grows with q from -0.0000 at q = 1
    {
        const auto near = RobotModel::fromUrdfString(swingUrdf(0.2, 0.2792), ".", "swing.urdf");
        const SphereReach r = reachableSpherePairs(*near, collisionLink(*near, "base"), collisionLink(*near, "tip"));
        const SpherePairFreeCells &grid = r.freeCells;
        ASSERT_EQ(grid.variables, std::vector<int>{0});
        EXPECT_EQ(grid.cells, 128);
        for (const double q : {1.0, 1.001, 1.004})  // gap <= 0.5 mm margin + a cell's slack (0.5 * 1/128 * 0.5)
            EXPECT_FALSE(grid.isFree(&q)) << q;
        for (const double q : {1.3, 1.6, 1.99})  // gap 0.125 .. 0.36 m
            EXPECT_TRUE(grid.isFree(&q)) << q;
        for (const double q : {0.99, 2.01, std::nan("")})  // outside the limits: no claim
            EXPECT_FALSE(grid.isFree(&q)) << q;
        EXPECT_GT(grid.freeFraction(), 0.9);
        SphereReachOptions noGrid;
        noGrid.freeCellsPerJoint = 0;
        EXPECT_TRUE(reachableSpherePairs(*near, 0, 1, noGrid).freeCells.variables.empty());
    }

    // a zero margin keeps the 0.4792 pair out (it never touches), and the CollisionChecker agrees with sampling
    SphereReachOptions exact;
    exact.margin = 0.0;
    const auto almost = RobotModel::fromUrdfString(swingUrdf(0.2, 0.2792), ".", "swing.urdf");
    EXPECT_TRUE(reachableSpherePairs(*almost, collisionLink(*almost, "base"), collisionLink(*almost, "tip"), exact)
                    .pairs.empty());
}

TEST(SphereReach, PrismaticAndLongChainsKeepEveryPair)
{
    const auto slider = RobotModel::fromUrdfString(swingUrdf(0.01, 0.01, "prismatic"), ".", "slider.urdf");
    const SphereReach r = reachableSpherePairs(*slider, collisionLink(*slider, "base"), collisionLink(*slider, "tip"));
    EXPECT_FALSE(r.analysed);
    EXPECT_EQ(r.pairs.size(), 1u);

    SphereReachOptions none;
    none.maxVariables = 0;  // one joint between the links: more than allowed -> not analysed, all kept
    const auto apart = RobotModel::fromUrdfString(swingUrdf(0.2, 0.27), ".", "swing.urdf");
    const SphereReach all =
        reachableSpherePairs(*apart, collisionLink(*apart, "base"), collisionLink(*apart, "tip"), none);
    EXPECT_FALSE(all.analysed);
    EXPECT_EQ(all.pairs.size(), 1u);
}

TEST(SphereReach, BadArgumentsAreErrors)
{
    const auto robot = RobotModel::fromUrdfString(swingUrdf(0.2, 0.27), ".", "swing.urdf");
    ropras::test::expectErrorMentions([&] { reachableSpherePairs(*robot, 0, 7); }, {"swing", "7", "out of range"});
    ropras::test::expectErrorMentions([&] { reachableSpherePairs(*robot, -1, 0); }, {"-1", "out of range"});
    SphereReachOptions bad;
    bad.margin = std::nan("");
    ropras::test::expectErrorMentions([&] { reachableSpherePairs(*robot, 0, 1, bad); }, {"margin"});
    bad = SphereReachOptions();
    bad.boxBudget = 0;
    ropras::test::expectErrorMentions([&] { reachableSpherePairs(*robot, 0, 1, bad); }, {"boxBudget"});
    bad = SphereReachOptions();
    bad.freeCellsPerJoint = -3;
    ropras::test::expectErrorMentions([&] { reachableSpherePairs(*robot, 0, 1, bad); }, {"freeCellsPerJoint", "-3"});
}

TEST(SphereReach, NoSampledContactIsMissingOnPandaAndUr5)
{
    if (!std::filesystem::exists(SHARED + "/robots"))
        GTEST_SKIP() << "../shared not found: " << SHARED << " (this test needs robots/panda and robots/ur5)";
    for (const std::string name : {"panda", "ur5"})
    {
        const auto robot = sharedRobot(name);
        const auto &links = robot->collisionLinks();
        const auto &spheres = robot->spheres();
        std::set<std::pair<int, int>> kept;
        std::size_t all = 0, analysed = 0;
        for (const auto &pair : robot->selfCollisionPairs())
        {
            const SphereReach r = reachableSpherePairs(*robot, pair.first, pair.second);
            kept.insert(r.pairs.begin(), r.pairs.end());
            all += static_cast<std::size_t>(links[static_cast<std::size_t>(pair.first)].sphereCount *
                                            links[static_cast<std::size_t>(pair.second)].sphereCount);
            analysed += r.analysed ? 1u : 0u;
        }
        EXPECT_GT(analysed, 3u) << name;
        // the analysis must remove a real share of the pairs (Panda: 690 -> 418, UR5: 383 -> 342 when written)
        EXPECT_LT(kept.size(), all - all / 10) << name;

        // every sphere pair in contact in a sampled configuration is kept; the nearest misses are counted
        std::mt19937 rng(11);
        std::vector<double> q(robot->dof());
        std::size_t contacts = 0;
        for (int n = 0; n < 20000; ++n)
        {
            for (std::size_t j = 0; j < q.size(); ++j)
                q[j] = std::uniform_real_distribution<double>(robot->joints()[j].lower, robot->joints()[j].upper)(rng);
            const auto centres = robot->sphereCentersReference(q.data());
            for (const auto &pair : robot->selfCollisionPairs())
            {
                const CollisionLink &a = links[static_cast<std::size_t>(pair.first)];
                const CollisionLink &b = links[static_cast<std::size_t>(pair.second)];
                for (int i = a.firstSphere; i < a.firstSphere + a.sphereCount; ++i)
                    for (int j = b.firstSphere; j < b.firstSphere + b.sphereCount; ++j)
                        if ((centres[static_cast<std::size_t>(i)] - centres[static_cast<std::size_t>(j)]).norm() <=
                            spheres[static_cast<std::size_t>(i)].radius + spheres[static_cast<std::size_t>(j)].radius)
                        {
                            ++contacts;
                            ASSERT_EQ(kept.count({i, j}), 1u)
                                << name << ": spheres " << i << " and " << j << " touch in a sample but were dropped";
                        }
            }
        }
        EXPECT_GT(contacts, 1000u) << name << ": the samples must exercise self contact";
    }
}

TEST(SphereReach, NoFreeCellHoldsAContactOnPandaAndUr5)
{
    if (!std::filesystem::exists(SHARED + "/robots"))
        GTEST_SKIP() << "../shared not found: " << SHARED << " (this test needs robots/panda and robots/ur5)";
    for (const std::string name : {"panda", "ur5"})
    {
        const auto robot = sharedRobot(name);
        const auto &spheres = robot->spheres();
        std::mt19937 rng(23);
        std::uniform_real_distribution<double> u(0.0, 1.0);
        std::vector<double> q(robot->dof());
        std::size_t grids = 0, samples = 0;
        double bestFree = 0.0;
        for (const auto &pair : robot->selfCollisionPairs())
        {
            const SphereReach r = reachableSpherePairs(*robot, pair.first, pair.second);
            const SpherePairFreeCells &grid = r.freeCells;
            if (grid.variables.empty())
                continue;
            ++grids;
            // when written: Panda link5 against link7, hand and fingers 0.95-0.997 free; UR5 0.88-0.89 but one 0
            bestFree = std::max(bestFree, grid.freeFraction());
            // points drawn inside free cells (their corners included), the other joints anywhere: no kept pair
            // may be in contact, nor within the margin minus a float rounding allowance
            std::vector<std::size_t> freeCells;
            const std::size_t nCells = grid.variables.size() == 1 ? static_cast<std::size_t>(grid.cells)
                                                                  : static_cast<std::size_t>(grid.cells) * grid.cells;
            for (std::size_t c = 0; c < nCells; ++c)
                if ((grid.bits[c / 32] >> (c % 32)) & 1u)
                    freeCells.push_back(c);
            for (int n = 0; n < 4000 && !freeCells.empty(); ++n)
            {
                for (std::size_t j = 0; j < q.size(); ++j)
                    q[j] = robot->joints()[j].lower + (robot->joints()[j].upper - robot->joints()[j].lower) * u(rng);
                const std::size_t cell =
                    freeCells[static_cast<std::size_t>(u(rng) * freeCells.size()) % freeCells.size()];
                const std::size_t index[2] = {grid.variables.size() == 1 ? cell : cell / grid.cells, cell % grid.cells};
                for (std::size_t d = 0; d < grid.variables.size(); ++d)
                {
                    const double t = n % 4 == 0 ? 0.0 : n % 4 == 1 ? 1.0 : u(rng);  // corners and insides
                    q[static_cast<std::size_t>(grid.variables[d])] =
                        grid.lower[d] + (static_cast<double>(index[d]) + t) * grid.width[d];
                }
                const auto centres = robot->sphereCentersReference(q.data());
                for (const auto &sp : r.pairs)
                {
                    const double gap =
                        (centres[static_cast<std::size_t>(sp.first)] - centres[static_cast<std::size_t>(sp.second)])
                            .norm() -
                        spheres[static_cast<std::size_t>(sp.first)].radius -
                        spheres[static_cast<std::size_t>(sp.second)].radius;
                    ASSERT_GT(gap, 4e-4) << name << ": spheres " << sp.first << " and " << sp.second
                                         << " within the margin in free cell " << cell;
                }
                ++samples;
            }
        }
        EXPECT_GT(grids, 2u) << name;
        EXPECT_GT(bestFree, 0.85) << name;
        EXPECT_GT(samples, 8000u) << name;
    }
}

TEST(SphereReach, CheckerSelfVerdictsMatchAllPairsOnPanda)
{
    if (!std::filesystem::exists(SHARED + "/robots"))
        GTEST_SKIP() << "../shared not found: " << SHARED << " (this test needs robots/panda)";
    const auto robot =
        RobotModel::fromUrdfFile(SHARED + "/robots/panda/panda_spherized.urdf", SHARED + "/robots/panda/panda.srdf");
    const CollisionChecker checker(robot);
    std::size_t all = 0;
    for (const auto &pair : robot->selfCollisionPairs())
        all += static_cast<std::size_t>(robot->collisionLinks()[static_cast<std::size_t>(pair.first)].sphereCount *
                                        robot->collisionLinks()[static_cast<std::size_t>(pair.second)].sphereCount);
    EXPECT_LT(checker.selfSpherePairs(), all);
    EXPECT_GT(checker.selfSpherePairs(), 0u);

    // empty environment: the verdict is the self-collision verdict; reference: every sphere pair of every self pair
    const Environment empty;
    const auto &links = robot->collisionLinks();
    const auto &spheres = robot->spheres();
    std::mt19937 rng(5);
    const std::size_t dof = robot->dof(), samples = 20000;
    std::vector<double> qs(samples * dof);
    for (std::size_t n = 0; n < samples; ++n)
        for (std::size_t j = 0; j < dof; ++j)
            qs[n * dof + j] =
                std::uniform_real_distribution<double>(robot->joints()[j].lower, robot->joints()[j].upper)(rng);
    // the batch path (8 configurations per call) and the single path, both against the reference
    std::vector<char> batchVerdicts(samples);
    checker.isValidBatch(empty, qs.data(), samples, reinterpret_cast<bool *>(batchVerdicts.data()));
    std::size_t invalid = 0, nearContact = 0;
    for (std::size_t n = 0; n < samples; ++n)
    {
        const double *q = qs.data() + n * dof;
        const auto centres = robot->sphereCentersReference(q);
        double minGap = 1e9;
        for (const auto &pair : robot->selfCollisionPairs())
        {
            const CollisionLink &a = links[static_cast<std::size_t>(pair.first)];
            const CollisionLink &b = links[static_cast<std::size_t>(pair.second)];
            for (int i = a.firstSphere; i < a.firstSphere + a.sphereCount; ++i)
                for (int j = b.firstSphere; j < b.firstSphere + b.sphereCount; ++j)
                    minGap = std::min(
                        minGap, (centres[static_cast<std::size_t>(i)] - centres[static_cast<std::size_t>(j)]).norm() -
                                    spheres[static_cast<std::size_t>(i)].radius -
                                    spheres[static_cast<std::size_t>(j)].radius);
        }
        if (std::abs(minGap) < 1e-4)
        {
            ++nearContact;  // float vs double rounding may decide these either way
            continue;
        }
        const bool valid = checker.isValid(empty, q);
        ASSERT_EQ(valid, minGap > 0.0) << "sample " << n << ", closest sphere gap " << minGap;
        ASSERT_EQ(batchVerdicts[n] != 0, minGap > 0.0) << "batch, sample " << n << ", closest sphere gap " << minGap;
        invalid += valid ? 0u : 1u;
    }
    EXPECT_GT(invalid, 500u) << "the samples must include self collisions";
    EXPECT_LT(nearContact, 50u);
}
