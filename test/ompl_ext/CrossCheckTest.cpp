// Acceptance test of the collision kernels: CollisionChecker (SIMD and scalar) against the independent FCL
// reference on the MotionBenchMaker scenes, plus hand-computed checks of the FCL reference itself.
#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <limits>
#include <random>

#include "ropras/core/Error.h"
#include "ropras/ompl_ext/collision/CollisionChecker.h"
#include "ropras/ompl_ext/collision/CrossCheck.h"
#include "ropras/ompl_ext/collision/FclReferenceChecker.h"
#include "ropras/ompl_ext/scene/SceneYaml.h"

namespace fs = std::filesystem;
using namespace ropras::ompl_ext;

namespace
{
    const fs::path SHARED = ROPRAS_SHARED_DIR;
    const char *CATEGORIES[] = {"bookshelf_small", "bookshelf_tall",  "bookshelf_thin", "box", "cage",
                                "table_pick",      "table_under_pick"};

    /// \a perCategory scenes of every MBM category (spread over 1..70), plus the empty scene (self-collision only)
    std::vector<CrossCheckScene> mbmScenes(const std::string &robot, int perCategory)
    {
        std::vector<CrossCheckScene> scenes;
        for (const char *category : CATEGORIES)
        {
            for (int k = 0; k < perCategory; ++k)
            {
                char name[32];
                std::snprintf(name, sizeof(name), "scene%04d.yaml", 1 + k * 70 / perCategory);
                const fs::path path = SHARED / "mbm" / robot / category / name;
                scenes.push_back({std::string(category) + "/" + name, loadPlanningScene(path.string())});
            }
        }
        scenes.push_back({"(no obstacles)", Environment()});
        return scenes;
    }

    void printReport(const std::string &robot, const CrossCheckReport &report)
    {
        std::cout << "[ info ] " << robot << ": " << report.configurations << " configurations, FCL reference "
                  << report.referenceValid << " valid\n";
        for (const BackendAgreement &b : report.backends)
            std::cout << "[ info ]   " << simdBackendName(b.backend) << ": agree " << b.agree << ", near contact "
                      << b.nearContact << ", disagreements " << b.disagreements << ", batch mismatches "
                      << b.batchMismatches << ", max centre error " << b.maxCenterError << " m over " << b.centerChecks
                      << " configurations\n";
        for (const std::string &e : report.examples)
            std::cout << "[ info ]   disagreement: " << e << '\n';
    }

    /** \brief A shared robot (\a urdfFile in robots/<robot>/) with its SRDF. Self pairs in contact in every
        configuration (the UR5's force-torque sensor inside wrist_2_link, which the shared SRDF does not know) are
        disabled by RobotModel itself (MoveIt's "Always" rule, on by default). A mesh model disables exactly the
        spherized model's pairs, so that both check the same self pairs. */
    std::shared_ptr<const RobotModel> loadShared(const std::string &robot, const std::string &urdfFile)
    {
        const fs::path dir = SHARED / "robots" / robot;
        const std::string srdf = (dir / (robot + ".srdf")).string();
        const auto spheres = RobotModel::fromUrdfFile((dir / (robot + "_spherized.urdf")).string(), srdf);
        for (const auto &[a, b] : spheres->alwaysCollidingPairs())
            std::cout << "[ info ] " << robot << ": self pair in contact in every configuration disabled: " << a
                      << " - " << b << '\n';
        if (urdfFile == robot + "_spherized.urdf")
            return spheres;
        RobotModel::Options options;
        options.disableAlwaysColliding = false;
        options.disabledPairs = spheres->alwaysCollidingPairs();
        return RobotModel::fromUrdfFile((dir / urdfFile).string(), srdf, options);
    }

    void crossCheckRobot(const std::string &robot, std::size_t samples, std::uint64_t seed)
    {
        const fs::path dir = SHARED / "robots" / robot;
        if (!fs::exists(dir) || !fs::exists(SHARED / "mbm" / robot))
            GTEST_SKIP() << "../shared not found: " << dir;
        const auto model = loadShared(robot, robot + "_spherized.urdf");
        const auto scenes = mbmScenes(robot, 2);
        CrossCheckOptions options;
        options.samples = samples;
        options.seed = seed;
        const CrossCheckReport report = crossCheckSpheres(model, scenes, options);
        printReport(robot, report);

        ASSERT_EQ(report.configurations, samples);
        // the sample exercises both verdicts
        EXPECT_GT(report.referenceValid, samples / 10);
        EXPECT_LT(report.referenceValid, samples - samples / 10);
        ASSERT_EQ(report.backends.size(), 2u);
        for (const BackendAgreement &b : report.backends)
        {
            EXPECT_EQ(b.disagreements, 0u) << simdBackendName(b.backend);
            EXPECT_EQ(b.batchMismatches, 0u) << simdBackendName(b.backend);
            EXPECT_EQ(b.agree + b.nearContact + b.disagreements, samples);
            // float kernels may flip only within 0.1 mm of contact, which a uniform sample rarely hits
            EXPECT_LE(b.nearContact, samples / 2000) << simdBackendName(b.backend);
            EXPECT_LE(b.maxCenterError, 1e-5) << simdBackendName(b.backend);
            EXPECT_GT(b.centerChecks, samples / 4);
        }
        EXPECT_TRUE(report.passed(options.centerTolerance));
    }

    Eigen::Isometry3d at(const Eigen::Vector3d &p)
    {
        Eigen::Isometry3d pose = Eigen::Isometry3d::Identity();
        pose.translation() = p;
        return pose;
    }

    // A hand-checkable robot: two sliders along x from a geometry-less base, one sphere each.
    // Slider a: sphere r = 0.1 at x = qa. Slider b: sphere r = 0.2 at x = 1 + qb, y = 0.
    const char *SLIDERS = R"(<?xml version="1.0"?>
<robot name="sliders">
  <link name="base"/>
  <link name="a"><collision><geometry><sphere radius="0.1"/></geometry></collision></link>
  <link name="b"><collision><geometry><sphere radius="0.2"/></geometry></collision></link>
  <joint name="ja" type="prismatic"><parent link="base"/><child link="a"/><axis xyz="1 0 0"/>
    <limit lower="-2" upper="2" effort="1" velocity="1"/></joint>
  <joint name="jb" type="prismatic"><parent link="base"/><child link="b"/><origin xyz="1 0 0"/><axis xyz="1 0 0"/>
    <limit lower="-2" upper="2" effort="1" velocity="1"/></joint>
</robot>)";
}  // namespace

TEST(CrossCheck, PandaSphereKernelsMatchFcl)
{
    crossCheckRobot("panda", 60000, 20240601);
}

TEST(CrossCheck, Ur5SphereKernelsMatchFcl)
{
    crossCheckRobot("ur5", 45000, 20240602);
}

TEST(CrossCheck, SelfCollisionOnlyMatchesFcl)
{
    for (const std::string robot : {"panda", "ur5"})
    {
        const fs::path dir = SHARED / "robots" / robot;
        if (!fs::exists(dir))
            GTEST_SKIP() << "../shared not found: " << dir;
        const auto model = loadShared(robot, robot + "_spherized.urdf");
        ASSERT_FALSE(model->selfCollisionPairs().empty()) << robot;
        CrossCheckOptions options;
        options.samples = 5000;
        options.seed = 11;
        const CrossCheckReport report = crossCheckSpheres(model, {{"(no obstacles)", Environment()}}, options);
        printReport(robot + " (self-collision only)", report);
        // random configurations of these arms fold into themselves now and then
        EXPECT_LT(report.referenceValid, report.configurations) << robot;
        EXPECT_GT(report.referenceValid, report.configurations / 2) << robot;
        EXPECT_TRUE(report.passed(options.centerTolerance)) << robot;
    }
}

TEST(CrossCheck, SphereModelAgainstMeshes)
{
    for (const std::string robot : {"panda", "ur5"})
    {
        const fs::path dir = SHARED / "robots" / robot;
        if (!fs::exists(dir) || !fs::exists(SHARED / "mbm" / robot))
            GTEST_SKIP() << "../shared not found: " << dir;
        const auto spheres = loadShared(robot, robot + "_spherized.urdf");
        const auto meshes = loadShared(robot, robot + ".urdf");
        CrossCheckOptions options;
        options.samples = 2500;
        options.seed = 5;
        const MeshComparison m = compareWithMeshes(spheres, meshes, mbmScenes(robot, 1), options);
        std::cout << "[ info ] " << robot << " spheres vs meshes: " << m.configurations << " configurations, agree "
                  << m.agree << ", unsafe (spheres free, meshes collide) " << m.unsafe << " ("
                  << 100.0 * double(m.unsafe) / double(m.configurations) << "%, " << m.unsafeSelf
                  << " self), over-conservative " << m.overConservative << " ("
                  << 100.0 * double(m.overConservative) / double(m.configurations) << "%, " << m.overConservativeSelf
                  << " self), meshes free " << m.meshValid << '\n';
        for (const std::string &e : m.unsafeExamples)
            std::cout << "[ info ]   unsafe: " << e << '\n';
        ASSERT_EQ(m.configurations, options.samples);
        EXPECT_EQ(m.agree + m.unsafe + m.overConservative, m.configurations);
        // The shared sphere model is VAMP's and not guaranteed conservative, so unsafe cases are reported,
        // not forbidden, and how conservative it is is a property of the data. What must hold: both describe
        // the same robot in the same scenes, so they agree on most configurations (a wrong mesh scale, frame
        // or pose composition breaks this).
        EXPECT_GT(m.agree, m.configurations * 6 / 10) << robot;
        EXPECT_GT(m.meshValid, 0u);
        EXPECT_LT(m.meshValid, m.configurations);
    }
}

TEST(FclReferenceChecker, HandComputedSphereDistances)
{
    const auto robot = RobotModel::fromUrdfString(SLIDERS, ".", "sliders.urdf");
    ASSERT_EQ(robot->dof(), 2u);
    ASSERT_EQ(robot->selfCollisionPairs().size(), 1u);
    const FclSphereChecker fcl(robot);

    Environment env;
    // box x in [2.9, 3.1]; sphere r 0.3 at (-2, 0, 0); capsule (axis z) r 0.05 at (0, 1, 0); cylinder (axis z)
    // r 0.1, length 0.4 at (0, -1, 0.5); a point cloud of one point at (-1, 0, 0.35) inflated by 0.05
    env.addBox("box", at(Eigen::Vector3d(3, 0, 0)), Eigen::Vector3d(0.2, 0.2, 0.2));
    env.addSphere("ball", Eigen::Vector3d(-2, 0, 0), 0.3);
    env.addCapsule("pole", at(Eigen::Vector3d(0, 1, 0)), 0.05, 1.0);
    env.addCylinder("can", at(Eigen::Vector3d(0, -1, 0.5)), 0.1, 0.4);
    env.addPointCloud("dust", PointCloud::build({Eigen::Vector3f(-1, 0, 0.35)}, 0.05f));

    struct Case
    {
        double qa, qb, distance;
    };
    // distances: a-b = 1 + qb - qa - 0.3; a-ball = qa + 1.6; b-box = 1.7 - qb; a-pole = sqrt(qa^2 + 1) - 0.15;
    // a-can = sqrt((sqrt(qa^2 + 1) - 0.1)^2 + 0.3^2) - 0.1; a-dust = sqrt((qa + 1)^2 + 0.35^2) - 0.15
    const std::vector<Case> cases = {
        {0.0, 0.0, 0.7},    // a-b 0.7, b-box 1.7, a-pole 0.85, a-ball 1.6, a-dust ~1.0
        {0.0, 1.0, 0.7},    // b-box 0.7, a-b 1.7
        {0.0, 1.6, 0.1},    // b-box 0.1
        {0.0, 1.8, -0.1},   // b penetrates the box by 0.1
        {-1.4, 0.0, 0.2},   // a-ball 0.2
        {-1.7, 0.0, -0.1},  // a penetrates the ball by 0.1
        {0.5, -0.3, -0.1},  // a-b overlap by 0.1 (self)
        {0.5, -0.1, 0.1},   // a-b 0.1 (self)
    };
    for (const Case &c : cases)
    {
        const double q[2] = {c.qa, c.qb};
        EXPECT_NEAR(fcl.distance(env, q), c.distance, 1e-9) << "qa " << c.qa << " qb " << c.qb;
        EXPECT_EQ(fcl.isValid(env, q), c.distance > 0.0) << "qa " << c.qa << " qb " << c.qb;
    }
    // every obstacle type alone (slider b parked far away at x = 3): its distance to sphere a at the origin
    {
        const double q[2] = {0.0, 2.0};
        auto alone = [&](const std::string &name)
        {
            Environment one;
            const int id = env.objectId(name);
            one.addObject(name, env.objectShapes(id), env.objectPose(id));
            return fcl.distance(one, q);
        };
        EXPECT_NEAR(alone("pole"), 1.0 - 0.15, 1e-9);
        EXPECT_NEAR(alone("can"), std::sqrt(0.9 * 0.9 + 0.3 * 0.3) - 0.1, 1e-9);
        EXPECT_NEAR(alone("ball"), 2.0 - 0.4, 1e-9);
        EXPECT_NEAR(alone("dust"), std::sqrt(1.0 + 0.35 * 0.35) - 0.15, 1e-6);
        // b's centre is the box's centre: 0.1 to a face plus b's radius 0.2
        EXPECT_NEAR(alone("box"), -0.3, 1e-9);
    }
    // the point cloud: slider a under the dust point at x = -1: distance 0.35 - 0.1 - 0.05 = 0.2
    const double underDust[2] = {-1.0, 0.0};
    EXPECT_NEAR(fcl.distance(env, underDust), 0.2, 1e-6);  // a-ball 0.6, a-b 1.7
    // what touches is named
    const double selfHit[2] = {0.5, -0.3};
    EXPECT_NE(fcl.describeCollision(env, selfHit).find("self-collision"), std::string::npos);
    const double boxHit[2] = {0.0, 1.8};
    EXPECT_NE(fcl.describeCollision(env, boxHit).find("object 'box'"), std::string::npos);
    EXPECT_EQ(fcl.describeCollision(env, underDust), "");

    // limits and NaN: invalid, and distance refuses NaN
    const double outside[2] = {2.5, 0.0};
    EXPECT_FALSE(fcl.isValid(env, outside));
    const double nan[2] = {std::nan(""), 0.0};
    EXPECT_FALSE(fcl.isValid(env, nan));
    EXPECT_THROW(fcl.distance(env, nan), ropras::Error);

    // the cache follows the environment: moving the box changes the answer
    const double q[2] = {0.0, 1.6};
    EXPECT_TRUE(fcl.isValid(env, q));
    Environment moved = env;
    moved.setObjectPose("box", at(Eigen::Vector3d(2.7, 0, 0)));
    EXPECT_FALSE(fcl.isValid(moved, q));
    EXPECT_NEAR(fcl.distance(moved, q), -0.2, 1e-9);  // b's centre lies on the box's face: depth = radius
    EXPECT_TRUE(fcl.isValid(env, q));
    EXPECT_NEAR(fcl.distance(Environment(), q), 1.0 + 1.6 - 0.3, 1e-9);  // self pair only
}

TEST(FclReferenceChecker, HandComputedMeshDistances)
{
    // slider a carries a mesh cube of side 0.2 (written here as OBJ), slider b a URDF box of side 0.4
    const fs::path dir = fs::temp_directory_path() / "ropras_fcl_mesh_test";
    fs::create_directories(dir);
    {
        std::ofstream obj(dir / "cube.obj");
        obj << "v -0.1 -0.1 -0.1\nv 0.1 -0.1 -0.1\nv 0.1 0.1 -0.1\nv -0.1 0.1 -0.1\n"
               "v -0.1 -0.1 0.1\nv 0.1 -0.1 0.1\nv 0.1 0.1 0.1\nv -0.1 0.1 0.1\n"
               "f 1 3 2\nf 1 4 3\nf 5 6 7\nf 5 7 8\nf 1 2 6\nf 1 6 5\nf 2 3 7\nf 2 7 6\nf 3 4 8\nf 3 8 7\n"
               "f 4 1 5\nf 4 5 8\n";
    }
    const std::string urdf = R"(<?xml version="1.0"?>
<robot name="blocks">
  <link name="base"/>
  <link name="a"><collision><geometry><mesh filename="cube.obj"/></geometry></collision></link>
  <link name="b"><collision><origin xyz="0 0 0"/><geometry><box size="0.4 0.4 0.4"/></geometry></collision></link>
  <joint name="ja" type="prismatic"><parent link="base"/><child link="a"/><axis xyz="1 0 0"/>
    <limit lower="-2" upper="2" effort="1" velocity="1"/></joint>
  <joint name="jb" type="prismatic"><parent link="base"/><child link="b"/><origin xyz="1 0 0"/><axis xyz="1 0 0"/>
    <limit lower="-2" upper="2" effort="1" velocity="1"/></joint>
</robot>)";
    const auto robot = RobotModel::fromUrdfString(urdf, dir.string(), "blocks.urdf");
    const FclMeshChecker fcl(robot);
    EXPECT_EQ(fcl.geometryCount(), 2u);
    EXPECT_EQ(fcl.triangleCount(), 12u);

    Environment env;
    env.addBox("wall", at(Eigen::Vector3d(-1, 0, 0)), Eigen::Vector3d(0.2, 2, 2));
    // cube a spans [qa - 0.1, qa + 0.1]; box b spans [0.8 + qb, 1.2 + qb]; the wall spans [-1.1, -0.9]
    const double free[2] = {0.0, 0.0};
    EXPECT_TRUE(fcl.isValid(env, free));
    EXPECT_NEAR(fcl.distance(env, free), 0.7, 1e-4);  // a-b 0.7, a-wall 0.8
    const double nearWall[2] = {-0.75, 0.0};
    EXPECT_NEAR(fcl.distance(env, nearWall), 0.05, 1e-4);
    const double inWall[2] = {-0.85, 0.0};
    EXPECT_FALSE(fcl.isValid(env, inWall));
    EXPECT_LT(fcl.distance(env, inWall), 0.0);
    EXPECT_NE(fcl.describeCollision(env, inWall).find("object 'wall'"), std::string::npos);
    const double overlap[2] = {0.5, -0.3};  // a [0.4, 0.6], b [0.5, 0.9]
    EXPECT_FALSE(fcl.isValid(env, overlap));
    EXPECT_NE(fcl.describeCollision(env, overlap).find("self-collision"), std::string::npos);
    const double apart[2] = {0.5, 0.0};  // gap 0.8 - 0.6 = 0.2
    EXPECT_NEAR(fcl.distance(env, apart), 0.2, 1e-4);
    fs::remove_all(dir);
}

TEST(CrossCheck, ShippedArmAndSceneMatchFclAndCoverTheGeometry)
{
    // our own robot: boxes, cylinders, spheres and a mesh, spherized by ropras (conservative by construction)
    const fs::path root = ROPRAS_SOURCE_DIR;
    const fs::path arm = root / "robots" / "ropras_arm";
    const auto robot = RobotModel::fromUrdfFile((arm / "ropras_arm.urdf").string(), (arm / "ropras_arm.srdf").string());
    const std::vector<CrossCheckScene> scenes = {
        {"tabletop", loadPlanningScene((root / "scenes" / "tabletop.yaml").string())}, {"(no obstacles)", {}}};
    // plus a point cloud obstacle (a scanned blob above the table, 600 points in the sensor frame)
    std::vector<CrossCheckScene> withCloud = scenes;
    {
        std::mt19937 rng(4);
        std::normal_distribution<float> spread(0.0f, 0.08f);
        std::vector<Eigen::Vector3f> points(600);
        for (auto &p : points)
            p = Eigen::Vector3f(spread(rng), spread(rng), 0.5f * spread(rng));
        Eigen::Isometry3d sensor = Eigen::Isometry3d::Identity();
        sensor.translation() = Eigen::Vector3d(0.6, -0.1, 0.75);
        sensor.linear() = Eigen::AngleAxisd(0.4, Eigen::Vector3d::UnitZ()).toRotationMatrix();
        withCloud[0].env.addPointCloud("scan", PointCloud::build(points, 0.01f), sensor);
        withCloud[0].name = "tabletop + point cloud";
    }
    CrossCheckOptions options;
    options.samples = 20000;
    options.seed = 77;
    const CrossCheckReport report = crossCheckSpheres(robot, withCloud, options);
    printReport("ropras_arm", report);
    EXPECT_TRUE(report.passed(options.centerTolerance));
    EXPECT_GT(report.referenceValid, options.samples / 10);
    EXPECT_LT(report.referenceValid, options.samples - options.samples / 10);

    // the same URDF through FclMeshChecker (its boxes, cylinders, spheres and mesh as FCL geometry): a
    // conservative cover is never "free" where the geometry it covers collides
    options.samples = 10000;
    const MeshComparison m = compareWithMeshes(robot, robot, scenes, options);
    std::cout << "[ info ] ropras_arm spheres vs its own geometry: " << m.configurations << " configurations, unsafe "
              << m.unsafe << ", over-conservative " << m.overConservative << " (" << m.overConservativeSelf
              << " self)\n";
    for (const std::string &e : m.unsafeExamples)
        std::cout << "[ info ]   unsafe: " << e << '\n';
    EXPECT_EQ(m.unsafe, 0u);
    EXPECT_GT(m.agree, m.configurations * 9 / 10);
}

TEST(CrossCheck, ReportPassesOnlyWithoutDisagreements)
{
    CrossCheckReport report;
    report.configurations = 10;
    report.backends.resize(2);
    EXPECT_TRUE(report.passed(1e-5));
    report.backends[1].nearContact = 3;  // tolerated
    EXPECT_TRUE(report.passed(1e-5));
    report.backends[1].disagreements = 1;
    EXPECT_FALSE(report.passed(1e-5));
    report.backends[1].disagreements = 0;
    report.backends[0].batchMismatches = 1;
    EXPECT_FALSE(report.passed(1e-5));
    report.backends[0].batchMismatches = 0;
    report.backends[0].maxCenterError = 2e-5;
    EXPECT_FALSE(report.passed(1e-5));
    report.backends[0].maxCenterError = std::numeric_limits<double>::quiet_NaN();
    EXPECT_FALSE(report.passed(1e-5));
    EXPECT_FALSE(CrossCheckReport().passed(1e-5));  // nothing checked is no pass

    const auto robot = RobotModel::fromUrdfString(SLIDERS, ".", "sliders.urdf");
    EXPECT_THROW(crossCheckSpheres(robot, {}, CrossCheckOptions()), ropras::Error);
}

TEST(CrossCheck, VerdictsAgreeUpToTheContactTolerance)
{
    // sweep the sliders through contact with the box (b), the ball (a) and each other, 1e-5 m steps
    const auto robot = RobotModel::fromUrdfString(SLIDERS, ".", "sliders.urdf");
    const FclSphereChecker fcl(robot);
    Environment env;
    env.addBox("box", at(Eigen::Vector3d(3, 0, 0)), Eigen::Vector3d(0.2, 0.2, 0.2));
    env.addSphere("ball", Eigen::Vector3d(-2, 0, 0), 0.3);
    for (SimdBackend backend : {SimdBackend::Best, SimdBackend::Scalar})
    {
        const CollisionChecker checker(robot, backend);
        std::size_t checked = 0, flips = 0;
        // contacts at qb = 1.7 (b-box), qa = -1.6 (a-ball), qb = qa - 0.7 (a-b)
        const std::vector<std::array<double, 4>> sweeps = {
            {0.0, 1.7, 0.0, 1.0}, {-1.6, 0.0, 1.0, 0.0}, {0.5, -0.2, 0.0, 1.0}};
        for (const auto &[qa, qb, da, db] : sweeps)
        {
            for (int k = -300; k <= 300; ++k)
            {
                const double t = 1e-5 * k;
                const double q[2] = {qa + t * da, qb + t * db};
                const bool expected = fcl.isValid(env, q);
                const bool verdict = checker.isValid(env, q);
                const double d = fcl.distance(env, q);
                ++checked;
                if (verdict != expected)
                {
                    ++flips;
                    EXPECT_LE(std::abs(d), 1e-4) << simdBackendName(backend) << " q " << q[0] << ", " << q[1];
                }
                if (std::abs(d) > 1e-6)
                {
                    EXPECT_EQ(expected, d > 0.0) << "FCL verdict vs its own distance at " << q[0] << ", " << q[1];
                }
            }
        }
        std::cout << "[ info ] " << simdBackendName(backend) << ": " << flips << " of " << checked
                  << " configurations within 3 mm of contact flip (all within 1e-4 m)\n";
    }
}

TEST(CrossCheck, ChunkedSamplesMatchAnIndependentCountAndUseBoundedMemory)
{
    // crossCheckSpheres samples and checks a scene's configurations a chunk (4096) at a time instead of one
    // count x dof buffer (which overflowed and crashed for --samples 2^64 - 1). Across chunk boundaries the draws,
    // verdicts and centre checks must be those of one sequence: recount them independently with the same generator
    const fs::path root = ROPRAS_SOURCE_DIR;
    const fs::path arm = root / "robots" / "ropras_arm";
    const auto robot = RobotModel::fromUrdfFile((arm / "ropras_arm.urdf").string(), (arm / "ropras_arm.srdf").string());
    const std::vector<CrossCheckScene> scenes = {
        {"tabletop", loadPlanningScene((root / "scenes" / "tabletop.yaml").string())}, {"(no obstacles)", {}}};
    CrossCheckOptions options;
    options.samples = 2 * (2 * 4096 + 37) + 1;  // scene 0: two chunks and a tail of 38, scene 1: 37
    options.seed = 9;
    options.centerStride = 3;  // not a divisor of the chunk: batch starts must continue across chunks
    const CrossCheckReport report = crossCheckSpheres(robot, scenes, options);

    std::mt19937_64 rng(options.seed);
    const FclSphereChecker fcl(robot);
    std::size_t valid = 0;
    std::vector<std::size_t> expectedCenterChecks(options.backends.size(), 0);
    std::vector<double> q(robot->dof());
    for (std::size_t s = 0; s < scenes.size(); ++s)
    {
        const std::size_t count = options.samples / 2 + (s < options.samples % 2 ? 1 : 0);
        for (std::size_t k = 0; k < count; ++k)
        {
            sampleConfiguration(*robot, rng, q.data());
            valid += fcl.isValid(scenes[s].env, q.data());
        }
        for (std::size_t b = 0; b < options.backends.size(); ++b)
        {
            const std::size_t width = std::size_t(CollisionChecker(robot, options.backends[b]).width());
            std::size_t batches = 0;
            for (std::size_t first = 0; first + width <= count; first += width * options.centerStride)
                ++batches;
            expectedCenterChecks[b] += (count + options.centerStride - 1) / options.centerStride + batches * width;
        }
    }
    EXPECT_EQ(report.configurations, options.samples);
    EXPECT_EQ(report.referenceValid, valid);
    ASSERT_EQ(report.backends.size(), options.backends.size());
    for (std::size_t b = 0; b < options.backends.size(); ++b)
    {
        EXPECT_EQ(report.backends[b].centerChecks, expectedCenterChecks[b]) << simdBackendName(options.backends[b]);
        EXPECT_EQ(report.backends[b].agree + report.backends[b].nearContact + report.backends[b].disagreements,
                  options.samples);
    }
    EXPECT_TRUE(report.passed(options.centerTolerance));
}
