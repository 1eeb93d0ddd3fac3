// Attached bodies: every path of CollisionChecker against the FCL reference with the same spheres, hand-placed
// cases, the OMPL validators and planners, MoveIt's attached collision objects, and bad input. Per-particle scenes
// are in ParticleSceneTest.cpp.
#include <gtest/gtest.h>

#include <filesystem>
#include <iostream>
#include <memory>
#include <random>
#include <vector>

#include <ompl/base/PlannerTerminationCondition.h>
#include <ompl/base/ScopedState.h>
#include <ompl/geometric/SimpleSetup.h>
#include <ompl/util/Console.h>
#include <ompl/util/RandomNumbers.h>

#include "AttachedBodyTestUtil.h"
#include "ropras/core/Error.h"
#include "ropras/ompl_ext/collision/CollisionChecker.h"
#include "ropras/ompl_ext/collision/CrossCheck.h"
#include "ropras/ompl_ext/collision/FclReferenceChecker.h"
#include "ropras/ompl_ext/ompl/PlannerRegistry.h"
#include "ropras/ompl_ext/ompl/PlanningContext.h"
#include "ropras/ompl_ext/scene/PointCloud.h"
#include "ropras/ompl_ext/scene/SceneYaml.h"

namespace fs = std::filesystem;
using namespace ropras::ompl_ext;

using namespace ropras::test;

namespace
{
    const fs::path SHARED = ROPRAS_SHARED_DIR;
    const fs::path SOURCE = ROPRAS_SOURCE_DIR;

    /// world centre of the attached body's first sphere at q (reference FK)
    Eigen::Vector3d attachedCentre(const RobotModel &robot, const Environment &env, const double *q)
    {
        const AttachedSpheres &a = env.attachedSpheres(0);
        return robot.linkTransformsReference(q)[static_cast<std::size_t>(a.link)] * a.spheresInLink.front().center;
    }
}  // namespace

TEST(AttachedBodyTest, CompilesSpheresThatCoverTheShapesInTheLinkFrame)
{
    const auto robot = arm();
    AttachedBody body = can("can", "tool_link", {"wrist_3_link"});
    body.shapes.push_back(Shape::box(Eigen::Vector3d(0.04, 0.04, 0.02), translation(0, 0, 0.08)));
    body.shapes.push_back(Shape::capsule(0.01, 0.05, translation(0.02, 0, 0)));
    body.shapes.push_back(Shape::sphere(0.015, translation(0, 0.05, 0)));
    const AttachedSpheres a = compileAttachedBody(robot, body);
    EXPECT_EQ(a.link, robot->linkIndex("tool_link"));
    EXPECT_EQ(a.frame, robot->links()[static_cast<std::size_t>(a.link)].frame);
    ASSERT_GT(a.count, 4);
    EXPECT_EQ(a.x.size() % ATTACHED_SPHERE_PADDING, 0u);
    // every surface point of the cylinder (sampled) lies inside some sphere, in the link frame
    std::mt19937_64 rng(3);
    std::uniform_real_distribution<double> u(0.0, 1.0);
    for (int i = 0; i < 2000; ++i)
    {
        const double phi = 2 * M_PI * u(rng), z = -0.06 + 0.12 * u(rng);
        const Eigen::Vector3d p = body.pose * Eigen::Vector3d(0.03 * std::cos(phi), 0.03 * std::sin(phi), z);
        bool inside = false;
        for (const Sphere &s : a.spheresInLink)
            inside = inside || (p - s.center).norm() <= s.radius + 1e-9;
        ASSERT_TRUE(inside) << "cylinder surface point " << p.transpose() << " outside every sphere";
    }
    // the bound encloses every sphere (in the frame)
    for (int k = 0; k < a.count; ++k)
    {
        const auto s = static_cast<std::size_t>(k);
        const double d = std::hypot(a.x[s] - a.bx, std::hypot(a.y[s] - a.by, a.z[s] - a.bz));
        EXPECT_LE(d + a.r[s], a.br * (1 + 1e-6));
    }
    // own link and touch link may be touched, the others not
    for (std::size_t c = 0; c < robot->collisionLinks().size(); ++c)
    {
        const std::string &name = robot->collisionLinks()[c].name;
        EXPECT_EQ(a.mayTouch[c] != 0, name == "tool_link" || name == "wrist_3_link") << name;
    }
    // the kernels skip the links of the body's own frame with one compare; touch links elsewhere are flagged
    const int wrist3 = robot->links()[static_cast<std::size_t>(robot->linkIndex("wrist_3_link"))].frame;
    EXPECT_EQ(a.touchesOtherFrames, wrist3 != a.frame);
    EXPECT_FALSE(compileAttachedBody(robot, can("alone", "tool_link")).touchesOtherFrames);
    EXPECT_TRUE(compileAttachedBody(robot, can("leaning", "tool_link", {"forearm_link"})).touchesOtherFrames);
}

TEST(AttachedBodyTest, ObstacleAtTheHeldBodyMakesTheConfigurationInvalidUntilDetached)
{
    const auto robot = arm();
    const CollisionChecker checker(robot);
    Environment env;
    std::mt19937_64 rng(11);
    std::vector<double> q = randomConfiguration(*robot, rng);
    for (int attempt = 0; attempt < 10000 && !checker.isValid(env, q.data()); ++attempt)
        q = randomConfiguration(*robot, rng);
    ASSERT_TRUE(checker.isValid(env, q.data()));
    env.attach(robot, can("can", "tool_link"));
    const Eigen::Vector3d centre = attachedCentre(*robot, env, q.data());
    Environment withBall = env;
    withBall.addSphere("ball", centre, 0.005);
    // the robot alone does not reach the ball (it sits 10 cm beyond the tool), the held can does
    Environment robotOnly;
    robotOnly.addSphere("ball", centre, 0.005);
    if (checker.isValid(robotOnly, q.data()))
    {
        EXPECT_FALSE(checker.isValid(withBall, q.data()));
        bool verdict = true;
        checker.isValidBatch(withBall, q.data(), 1, &verdict);
        EXPECT_FALSE(verdict);
        EXPECT_FALSE(checker.allValid(withBall, q.data(), 1));
        withBall.detach("can");
        EXPECT_TRUE(checker.isValid(withBall, q.data()));
    }
    EXPECT_THROW(withBall.detach("can"), ropras::Error);
}

TEST(AttachedBodyTest, TouchLinksAreAllowedOtherLinksAreNot)
{
    const auto robot = arm();
    const CollisionChecker checker(robot);
    const FclSphereChecker reference(robot);
    // a big sphere around the tool: it overlaps the tool link and wrist_3 (and maybe wrist_2)
    AttachedBody big;
    big.name = "bulky";
    big.link = "tool_link";
    big.shapes = {Shape::sphere(0.09)};
    const std::vector<double> q(robot->dof(), 0.3);
    Environment alone;
    ASSERT_TRUE(checker.isValid(alone, q.data()));
    std::vector<std::string> touching;
    for (const CollisionLink &cl : robot->collisionLinks())
        touching.push_back(cl.name);
    big.touchLinks = touching;
    Environment allowed;
    allowed.attach(robot, big);
    EXPECT_TRUE(checker.isValid(allowed, q.data()));
    EXPECT_TRUE(reference.isValid(allowed, q.data()));
    big.touchLinks.clear();
    Environment forbidden;
    forbidden.attach(robot, big);
    const bool refValid = reference.isValid(forbidden, q.data());
    EXPECT_EQ(checker.isValid(forbidden, q.data()), refValid) << reference.describeCollision(forbidden, q.data());
    EXPECT_FALSE(refValid) << "the 9 cm sphere should reach a link next to the tool";
}

TEST(AttachedBodyTest, EveryPathAgreesWithTheFclReferenceOnTheProjectArm)
{
    const auto robot = arm();
    for (int bodies = 1; bodies <= 2; ++bodies)
    {
        CrossCheckScene scene{"clutter", Environment()};
        std::mt19937_64 place(5);
        std::uniform_real_distribution<double> u(-0.8, 0.8), h(0.0, 1.0);
        for (int i = 0; i < 30; ++i)
            scene.env.addSphere("ball" + std::to_string(i), Eigen::Vector3d(u(place), u(place), h(place)), 0.05);
        scene.env.addBox("table", translation(0.5, 0.0, 0.1), Eigen::Vector3d(0.4, 0.6, 0.05));
        // a rod held along the tool axis (a capsule 0.3 m long) sweeps far: many configurations fail only by it
        AttachedBody rod = can("rod", "tool_link", {"wrist_3_link"});
        rod.pose = translation(0.0, 0.0, 0.2);
        rod.shapes = {Shape::capsule(0.03, 0.3)};
        scene.env.attach(robot, rod);
        if (bodies == 2)
        {
            AttachedBody bag = can("bag", "forearm_link");
            bag.pose = translation(0.0, 0.12, 0.15);
            bag.shapes = {Shape::box(Eigen::Vector3d(0.08, 0.08, 0.1))};
            scene.env.attach(robot, bag);
        }
        CrossCheckOptions options;
        options.samples = 6000;
        options.seed = 17 + static_cast<std::uint64_t>(bodies);
        const CrossCheckReport report = crossCheckSpheres(robot, {scene}, options);
        expectAgreement(std::to_string(bodies) + " attached", report);
        // the bodies matter: some configurations are invalid only because of them
        Environment without = scene.env;
        without.detach("rod");
        if (bodies == 2)
            without.detach("bag");
        const CollisionChecker checker(robot);
        std::mt19937_64 rng(99);
        int onlyBecauseOfBodies = 0;
        for (int i = 0; i < 2000; ++i)
        {
            const std::vector<double> q = randomConfiguration(*robot, rng);
            onlyBecauseOfBodies += checker.isValid(without, q.data()) && !checker.isValid(scene.env, q.data());
        }
        EXPECT_GT(onlyBecauseOfBodies, 20) << "too few configurations exercise the attached bodies";
    }
}

TEST(AttachedBodyTest, MotionChecksSeeTheHeldBody)
{
    const auto robot = arm();
    const CollisionChecker checker(robot);
    std::mt19937_64 rng(23);
    Environment env;
    env.attach(robot, can("can", "tool_link", {"wrist_3_link"}));
    const FclSphereChecker reference(robot);
    int blocked = 0, compared = 0;
    for (int trial = 0; trial < 400 && compared < 60; ++trial)
    {
        const std::vector<double> a = randomConfiguration(*robot, rng), b = randomConfiguration(*robot, rng);
        if (!checker.isValid(env, a.data()) || !checker.isValid(env, b.data()))
            continue;
        // a ball on the straight motion's midpoint, beside the can there but clear of the robot at both ends
        std::vector<double> mid(robot->dof());
        for (std::size_t j = 0; j < mid.size(); ++j)
            mid[j] = 0.5 * (a[j] + b[j]);
        Environment withBall = env;
        withBall.addSphere("ball", attachedCentre(*robot, env, mid.data()), 0.01);
        if (!checker.isValid(withBall, a.data()) || !checker.isValid(withBall, b.data()))
            continue;
        ++compared;
        double lastValid = 1.0;
        const bool motion = checker.isMotionValid(withBall, a.data(), b.data(), 0.01, &lastValid);
        EXPECT_FALSE(motion) << "the held can passes through the ball at the midpoint";
        blocked += motion ? 0 : 1;
        if (!motion)
        {
            // every configuration up to lastValid is valid (FCL), one step after it is not
            EXPECT_LT(lastValid, 0.5 + 1e-9);
            std::vector<double> q(robot->dof());
            for (std::size_t j = 0; j < q.size(); ++j)
                q[j] = a[j] + lastValid * (b[j] - a[j]);
            EXPECT_TRUE(reference.isValid(withBall, q.data()));
        }
    }
    EXPECT_GT(compared, 10);
    EXPECT_EQ(blocked, compared);
}

TEST(AttachedBodyTest, BodiesAttachedForAnotherModelMakeEveryConfigurationInvalid)
{
    const auto robot = arm();
    const auto other = RobotModel::fromUrdfFile((SOURCE / "robots/ropras_arm/ropras_arm.urdf").string());
    const CollisionChecker checker(robot);
    Environment env;
    env.attach(other, can("can", "tool_link"));
    const std::vector<double> q(robot->dof(), 0.3);
    EXPECT_FALSE(checker.isValid(env, q.data()));
    std::vector<double> rows;
    for (int i = 0; i < 9; ++i)
        rows.insert(rows.end(), q.begin(), q.end());
    bool verdicts[9];
    EXPECT_EQ(checker.isValidBatch(env, rows.data(), 9, verdicts), 0u);
    EXPECT_FALSE(checker.allValid(env, rows.data(), 9));
    EXPECT_THROW(FclSphereChecker(robot).isValid(env, q.data()), ropras::Error);
}

TEST(AttachedBodyTest, BadInputIsAClearError)
{
    const auto robot = arm();
    Environment env;
    const auto message = [&](AttachedBody body)
    {
        try
        {
            env.attach(robot, std::move(body));
        }
        catch (const ropras::Error &e)
        {
            return std::string(e.what());
        }
        return std::string("(no error)");
    };
    EXPECT_NE(message(can("a", "no_such_link")).find("no link 'no_such_link'"), std::string::npos);
    EXPECT_NE(message(can("a", "tool_link", {"ghost"})).find("no link 'ghost'"), std::string::npos);
    AttachedBody nanPose = can("a", "tool_link");
    nanPose.pose.translation().x() = std::nan("");
    EXPECT_NE(message(nanPose).find("non-finite"), std::string::npos);
    AttachedBody sheared = can("a", "tool_link");
    sheared.pose.linear() << 1, 0.2, 0, 0, 1, 0, 0, 0, 1;
    EXPECT_NE(message(sheared).find("not a proper rotation"), std::string::npos);
    AttachedBody negative = can("a", "tool_link");
    negative.shapes = {Shape::sphere(-1.0)};
    EXPECT_NE(message(negative).find("radius"), std::string::npos);
    AttachedBody empty = can("a", "tool_link");
    empty.shapes.clear();
    EXPECT_NE(message(empty).find("no shapes"), std::string::npos);
    AttachedBody cloud = can("a", "tool_link");
    cloud.shapes = {Shape::pointCloud(PointCloud::build({Eigen::Vector3f(0, 0, 0)}, 0.01f))};
    EXPECT_NE(message(cloud).find("point clouds cannot be attached"), std::string::npos);
    AttachedBody badMesh = can("a", "tool_link");
    badMesh.shapes.clear();
    badMesh.meshes.push_back({{Eigen::Vector3d::Zero()}, {Eigen::Vector3i(0, 1, 2)}, Eigen::Isometry3d::Identity()});
    EXPECT_NE(message(badMesh).find("triangle names vertex"), std::string::npos);
    EXPECT_NE(message(AttachedBody{}).find("non-empty name"), std::string::npos);
    EXPECT_NO_THROW(env.attach(robot, can("a", "tool_link")));
    EXPECT_NE(message(can("a", "tool_link")).find("already used"), std::string::npos);
    env.addSphere("ball", Eigen::Vector3d::Zero(), 0.1);
    EXPECT_NE(message(can("ball", "tool_link")).find("already used"), std::string::npos);
    EXPECT_THROW(env.attach(nullptr, can("b", "tool_link")), ropras::Error);
    EXPECT_EQ(env.attachedCount(), 1u);
}

TEST(AttachedBodyTest, PandaWithOneAndTwoCansAgreesWithFclOverTheMbmScenes)
{
    const fs::path urdf = SHARED / "robots/panda/panda_spherized.urdf";
    if (!fs::exists(urdf))
        GTEST_SKIP() << "needs " << urdf << " (the shared reference data, ../shared)";
    const auto robot = RobotModel::fromUrdfFile(urdf.string(), (SHARED / "robots/panda/panda.srdf").string());
    std::vector<CrossCheckScene> scenes;
    for (const char *category : {"table_pick", "bookshelf_small", "cage", "box"})
        for (int k : {1, 30})
        {
            char name[32];
            std::snprintf(name, sizeof(name), "scene%04d.yaml", k);
            scenes.push_back({std::string(category) + "/" + name,
                              loadPlanningScene((SHARED / "mbm/panda" / category / name).string())});
        }
    for (int cans = 1; cans <= 2; ++cans)
    {
        std::vector<CrossCheckScene> withCans = scenes;
        for (CrossCheckScene &s : withCans)
        {
            AttachedBody held = can("can", "panda_hand", {"panda_leftfinger", "panda_rightfinger"});
            held.pose = translation(0.0, 0.0, 0.105);
            held.shapes = {Shape::cylinder(0.03, 0.13)};
            s.env.attach(robot, held);
            if (cans == 2)
            {
                AttachedBody second = can("tray", "panda_link5");
                second.pose = translation(0.0, 0.09, -0.1);
                second.shapes = {Shape::box(Eigen::Vector3d(0.06, 0.04, 0.1))};
                second.touchLinks = {"panda_link4", "panda_link6"};
                s.env.attach(robot, second);
            }
        }
        CrossCheckOptions options;
        options.samples = 100000;
        options.seed = 1000 + static_cast<std::uint64_t>(cans);
        options.backends = {SimdBackend::Best};
        options.centerStride = 50;
        const CrossCheckReport report = crossCheckSpheres(robot, withCans, options);
        expectAgreement("Panda, " + std::to_string(cans) + " attached", report);
    }
}

TEST(AttachedBodyTest, MoveItAttachedCollisionObjectsAreReadWithTheRobot)
{
    const auto robot = arm();
    const std::string yaml = R"(
world:
  collision_objects:
    - id: ball
      primitives: [{type: sphere, dimensions: [0.05]}]
      primitive_poses: [{position: [0.5, 0, 0.5], orientation: [0, 0, 0, 1]}]
robot_state:
  attached_collision_objects:
    - link_name: tool_link
      object:
        id: can
        header: {frame_id: tool_link}
        pose: {position: [0, 0, 0.1], orientation: [0, 0, 0, 1]}
        primitives: [{type: cylinder, dimensions: [0.12, 0.03]}]
        primitive_poses: [{position: [0, 0, 0], orientation: [0, 0, 0, 1]}]
      touch_links: [wrist_3_link]
)";
    const Environment env = planningSceneFromString(yaml, "held.yaml", robot);
    EXPECT_EQ(env.objectCount(), 1u);
    ASSERT_EQ(env.attachedCount(), 1u);
    const AttachedBody &body = env.attachedBody(0);
    EXPECT_EQ(body.name, "can");
    EXPECT_EQ(body.link, "tool_link");
    EXPECT_NEAR(body.pose.translation().z(), 0.1, 1e-12);
    EXPECT_EQ(body.touchLinks, std::vector<std::string>{"wrist_3_link"});
    // the same as attaching in code
    Environment code;
    code.attach(robot, can("can", "tool_link", {"wrist_3_link"}));
    EXPECT_EQ(code.attachedSpheres(0).spheresInLink.size(), env.attachedSpheres(0).spheresInLink.size());
    for (std::size_t k = 0; k < code.attachedSpheres(0).spheresInLink.size(); ++k)
        EXPECT_LT(
            (code.attachedSpheres(0).spheresInLink[k].center - env.attachedSpheres(0).spheresInLink[k].center).norm(),
            1e-12);

    const auto error = [&](const std::string &text, std::shared_ptr<const RobotModel> model)
    {
        try
        {
            planningSceneFromString(text, "held.yaml", std::move(model));
        }
        catch (const ropras::Error &e)
        {
            return std::string(e.what());
        }
        return std::string("(no error)");
    };
    EXPECT_NE(error(yaml, nullptr).find("need the robot model"), std::string::npos);
    EXPECT_NE(error(yaml, nullptr).find("held.yaml:"), std::string::npos);
    std::string badLink = yaml;
    badLink.replace(badLink.find("link_name: tool_link"), 20, "link_name: ghost_link");
    badLink.replace(badLink.find("frame_id: tool_link"), 19, "frame_id: ghost_link");
    EXPECT_NE(error(badLink, robot).find("no link 'ghost_link'"), std::string::npos);
    std::string badFrame = yaml;
    badFrame.replace(badFrame.find("frame_id: tool_link"), 19, "frame_id: world");
    EXPECT_NE(error(badFrame, robot).find("frame 'world'"), std::string::npos);
    std::string clash = yaml;
    clash.replace(clash.find("id: can"), 7, "id: ball");
    EXPECT_NE(error(clash, robot).find("duplicate object id 'ball'"), std::string::npos);
    EXPECT_NE(error(yaml + "    - 7\n", robot).find("attached_collision_objects[1]"), std::string::npos);
}
