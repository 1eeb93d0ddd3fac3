// The Panda shipped in robots/panda: its kinematics against the MotionBenchMaker Panda (../shared), its spheres
// against that model's collision meshes (conservative: every sampled surface point inside a sphere of its link),
// its limits against Franka's datasheet, and its SRDF against its own sphere model.
#include <gtest/gtest.h>

#include <filesystem>
#include <iostream>
#include <map>
#include <random>
#include <set>

#include "MeshSurfaceSampling.h"
#include "ropras/ompl_ext/model/MeshLoader.h"
#include "ropras/ompl_ext/model/RobotModel.h"

namespace
{
    namespace fs = std::filesystem;
    using ropras::ompl_ext::CollisionGeometry;
    using ropras::ompl_ext::RobotModel;
    using ropras::ompl_ext::Sphere;

    const fs::path SHARED = ROPRAS_SHARED_DIR;
    const fs::path SOURCE = ROPRAS_SOURCE_DIR;
    const std::string OURS = (SOURCE / "robots/panda/panda.urdf").string();
    const std::string OURS_SRDF = (SOURCE / "robots/panda/panda.srdf").string();
    const std::string MESHES = (SHARED / "robots/panda/panda.urdf").string();

#define ROPRAS_REQUIRE_SHARED_PANDA()                                                                         \
    if (!fs::is_regular_file(MESHES))                                                                         \
    {                                                                                                         \
        GTEST_SKIP() << "../shared not found (" << MESHES << "): the shipped Panda is not compared with the " \
                     << "MotionBenchMaker Panda";                                                             \
    }

    /// a model without SRDF and without the "Always" rule: every pair of links on different frames is checked
    std::shared_ptr<const RobotModel> loadWithAllPairs(const std::string &urdf)
    {
        RobotModel::Options o;
        o.disableAlwaysColliding = false;
        return RobotModel::fromUrdfFile(urdf, "", o);
    }

    /// uniform within the joint limits of \a m
    void sampleConfiguration(const RobotModel &m, std::mt19937_64 &rng, std::vector<double> &q)
    {
        std::uniform_real_distribution<double> u(0.0, 1.0);
        q.resize(m.dof());
        for (std::size_t k = 0; k < m.dof(); ++k)
            q[k] = m.joints()[k].lower + u(rng) * (m.joints()[k].upper - m.joints()[k].lower);
    }

    /// the spheres of each link by link name, centres in the link frame
    std::map<std::string, std::vector<Sphere>> spheresByLink(const RobotModel &m)
    {
        std::map<std::string, std::vector<Sphere>> out;
        for (const auto &cl : m.collisionLinks())
            for (int i = cl.firstSphere; i < cl.firstSphere + cl.sphereCount; ++i)
                out[cl.name].push_back(Sphere{m.spheres()[i].centerInLink, m.spheres()[i].radius});
        return out;
    }
}  // namespace

TEST(PandaModel, LimitsAreFrankasDatasheet)
{
    const auto panda = RobotModel::fromUrdfFile(OURS, OURS_SRDF);
    ASSERT_EQ(panda->dof(), 7u);
    const double lower[7] = {-2.8973, -1.7628, -2.8973, -3.0718, -2.8973, -0.0175, -2.8973};
    const double upper[7] = {2.8973, 1.7628, 2.8973, -0.0698, 2.8973, 3.7525, 2.8973};
    for (int i = 0; i < 7; ++i)
    {
        EXPECT_EQ(panda->joints()[i].name, "panda_joint" + std::to_string(i + 1));
        EXPECT_DOUBLE_EQ(panda->joints()[i].lower, lower[i]) << panda->joints()[i].name;
        EXPECT_DOUBLE_EQ(panda->joints()[i].upper, upper[i]) << panda->joints()[i].name;
    }
}

TEST(PandaModel, LinkFramesMatchTheMotionBenchMakerPanda)
{
    ROPRAS_REQUIRE_SHARED_PANDA();
    const auto ours = RobotModel::fromUrdfFile(OURS, OURS_SRDF);
    const auto reference = loadWithAllPairs(MESHES);
    ASSERT_EQ(ours->dof(), reference->dof());
    for (std::size_t i = 0; i < ours->dof(); ++i)
        ASSERT_EQ(ours->joints()[i].name, reference->joints()[i].name);
    // every link of the reference, found by name in ours (and no extra link in ours)
    ASSERT_EQ(ours->links().size(), reference->links().size());
    std::vector<int> match;
    for (const auto &link : reference->links())
        match.push_back(ours->linkIndex(link.name));

    std::mt19937_64 rng(15);
    std::vector<double> q;
    double worstPosition = 0.0, worstRotation = 0.0;
    for (int sample = 0; sample < 10000; ++sample)
    {
        sampleConfiguration(*ours, rng, q);  // within our limits (the datasheet's: inside the reference's)
        const auto a = ours->linkTransformsReference(q.data());
        const auto b = reference->linkTransformsReference(q.data());
        for (std::size_t l = 0; l < b.size(); ++l)
        {
            worstPosition = std::max(worstPosition, (a[match[l]].translation() - b[l].translation()).norm());
            worstRotation = std::max(worstRotation, (a[match[l]].linear() - b[l].linear()).cwiseAbs().maxCoeff());
        }
    }
    std::cout << "[ panda ] 10000 configurations, " << reference->links().size() << " links: largest frame offset "
              << worstPosition << " m, largest rotation entry difference " << worstRotation << '\n';
    EXPECT_LE(worstPosition, 1e-6);
    EXPECT_LE(worstRotation, 1e-6);
}

TEST(PandaModel, SpheresCoverTheCollisionMeshes)
{
    ROPRAS_REQUIRE_SHARED_PANDA();
    const auto ours = RobotModel::fromUrdfFile(OURS, OURS_SRDF);
    const auto reference = loadWithAllPairs(MESHES);
    const auto spheres = spheresByLink(*ours);
    int meshes = 0;
    std::size_t points = 0;
    for (const CollisionGeometry &g : reference->collisionGeometries())
    {
        ASSERT_EQ(g.type, CollisionGeometry::Type::Mesh);
        const std::string link = reference->links()[g.link].name;
        ASSERT_TRUE(spheres.count(link)) << link << " has a mesh but no sphere";
        const auto mesh = ropras::ompl_ext::loadMesh(g.meshPath, g.scale);
        // dense: 200 000 points spread by area over the surface (4-20 per mm^2 on these links), and every vertex
        std::vector<Eigen::Vector3d> samples = ropras::test::sampleMeshSurface(mesh, 200000, 7 + meshes);
        double worst = -1.0;
        for (const Eigen::Vector3d &p : samples)
            worst = std::max(worst, ropras::test::uncovered(spheres.at(link), g.origin * p));
        EXPECT_LE(worst, 0.0) << link << " (" << g.meshPath << "): a surface point lies " << worst
                              << " m outside every sphere of the link";
        ++meshes;
        points += samples.size();
    }
    EXPECT_EQ(meshes, 11);
    std::cout << "[ panda ] " << points << " surface points of " << meshes << " meshes, each inside a sphere of its "
              << "link (" << ours->spheres().size() << " spheres)\n";
}

TEST(PandaModel, SrdfPairsHoldOnOtherSamples)
{
    // the SRDF's "Never" pairs came from `ropras collision-matrix --seed 1`: other samples find no contact either,
    // and the loaded model disables no pair by the "Always" rule
    const auto ours = RobotModel::fromUrdfFile(OURS, OURS_SRDF);
    EXPECT_TRUE(ours->alwaysCollidingPairs().empty());
    const auto unfiltered = loadWithAllPairs(OURS);
    std::set<std::pair<std::string, std::string>> kept;
    for (const auto &[a, b] : ours->selfCollisionPairs())
        kept.insert({ours->collisionLinks()[a].name, ours->collisionLinks()[b].name});
    std::vector<std::pair<int, int>> disabled;
    for (const auto &[a, b] : unfiltered->selfCollisionPairs())
        if (!kept.count({unfiltered->collisionLinks()[a].name, unfiltered->collisionLinks()[b].name}))
            disabled.push_back({a, b});
    ASSERT_FALSE(disabled.empty());
    ASSERT_FALSE(kept.empty());

    std::mt19937_64 rng(2024);
    std::vector<double> q;
    std::size_t contacts = 0;
    for (int sample = 0; sample < 20000; ++sample)
    {
        sampleConfiguration(*ours, rng, q);
        const auto c = unfiltered->sphereCentersReference(q.data());
        for (const auto &[a, b] : disabled)
        {
            const auto &la = unfiltered->collisionLinks()[a];
            const auto &lb = unfiltered->collisionLinks()[b];
            for (int i = la.firstSphere; i < la.firstSphere + la.sphereCount; ++i)
                for (int j = lb.firstSphere; j < lb.firstSphere + lb.sphereCount; ++j)
                {
                    const double r = unfiltered->spheres()[i].radius + unfiltered->spheres()[j].radius;
                    if ((c[i] - c[j]).norm() <= r)
                    {
                        ++contacts;
                        ADD_FAILURE() << la.name << " / " << lb.name << " (disabled) touch at sample " << sample;
                        i = la.firstSphere + la.sphereCount;
                        break;
                    }
                }
        }
        if (contacts > 5)
            break;
    }
    EXPECT_EQ(contacts, 0u);
    std::cout << "[ panda ] " << disabled.size() << " disabled pairs (Never) contact-free over 20000 samples; "
              << kept.size() << " pairs checked\n";
}
