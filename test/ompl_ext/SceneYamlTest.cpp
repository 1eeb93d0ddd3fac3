#include "ropras/ompl_ext/scene/SceneYaml.h"

#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <sstream>

#include "ExpectError.h"
#include "ropras/core/Error.h"

namespace fs = std::filesystem;
using namespace ropras::ompl_ext;
using ropras::test::expectErrorMentions;

namespace
{
    const std::string SHARED_DIR = ROPRAS_SHARED_DIR;

    /// the error message of \a f, or "" when it does not throw ropras::Error
    template <typename F>
    std::string errorOf(F &&f)
    {
        try
        {
            f();
        }
        catch (const ropras::Error &e)
        {
            return e.what();
        }
        return "";
    }

    Environment scene(const std::string &objects)
    {
        return planningSceneFromString("world:\n  collision_objects:\n" + objects, "test.yaml");
    }

    /// one object with one primitive, fields as given (for the malformed-input cases)
    std::string object(const std::string &id = "obj", const std::string &type = "box",
                       const std::string &dims = "[1, 2, 3]", const std::string &position = "[0, 0, 0]",
                       const std::string &orientation = "[0, 0, 0, 1]")
    {
        return "    - id: " + id + "\n      primitives:\n        - type: " + type + "\n          dimensions: " + dims +
               "\n      primitive_poses:\n        - position: " + position + "\n          orientation: " + orientation +
               "\n";
    }

    /// a YAML line without its indentation and list dash ("    - id: x" -> "id: x")
    std::string trimmed(const std::string &line)
    {
        const std::size_t i = line.find_first_not_of(" -");
        return i == std::string::npos ? "" : line.substr(i);
    }

    bool startsWith(const std::string &text, const char *prefix)
    {
        return text.rfind(prefix, 0) == 0;
    }

    std::string readText(const fs::path &path)
    {
        std::ifstream in(path);
        std::stringstream s;
        s << in.rdbuf();
        return s.str();
    }
}  // namespace

TEST(SceneYaml, LoadsEveryMbmPandaScene)
{
    const fs::path root = fs::path(SHARED_DIR) / "mbm" / "panda";
    if (!fs::exists(root))
        GTEST_SKIP() << "../shared not found: " << root;
    int files = 0;
    std::size_t objects = 0;
    for (const char *category :
         {"bookshelf_small", "bookshelf_tall", "bookshelf_thin", "box", "cage", "table_pick", "table_under_pick"})
    {
        for (int i = 1; i <= 70; ++i)
        {
            char name[32];
            std::snprintf(name, sizeof(name), "scene%04d.yaml", i);
            const fs::path path = root / category / name;
            ASSERT_TRUE(fs::exists(path)) << path;
            Environment env;
            ASSERT_NO_THROW(env = loadPlanningScene(path.string())) << path;
            // independent count: the text's object ids and primitive types
            std::size_t ids = 0, types = 0;
            std::istringstream lines(readText(path));
            for (std::string line; std::getline(lines, line);)
            {
                const std::string key = trimmed(line);
                ids += startsWith(key, "id:");
                types += startsWith(key, "type: box") || startsWith(key, "type: cylinder") ||
                         startsWith(key, "type: sphere");
            }
            std::size_t shapes = 0;
            for (std::size_t id = 0; id < env.objectCount(); ++id)
                shapes += env.objectShapes(int(id)).size();
            ASSERT_EQ(env.objectCount(), ids) << path;
            ASSERT_EQ(shapes, types) << path;
            ASSERT_GT(env.objectCount(), 0u) << path;
            objects += env.objectCount();
            ++files;
        }
    }
    EXPECT_EQ(files, 490);
    std::cout << "[ info ] " << files << " Panda MBM scenes, " << objects << " objects\n";
}

TEST(SceneYaml, LoadsUr5ScenesWithObjectPoses)
{
    const fs::path path = fs::path(SHARED_DIR) / "mbm" / "ur5" / "table_pick" / "scene0001.yaml";
    if (!fs::exists(path))
        GTEST_SKIP() << "../shared not found: " << path;
    const Environment env = loadPlanningScene(path.string());
    // Can1: object pose (p_o, q_o) composed with primitive pose ([0.85, 0, 0.8], identity)
    const int can = env.objectId("Can1");
    const Eigen::Quaterniond qo(0.07409159414259425, 0, 0, 0.9972514405491772);
    const Eigen::Vector3d po(-0.06371788662107358, -0.1102475820769556, 0.08705641176758652);
    const Eigen::Vector3d expected = po + qo.normalized() * Eigen::Vector3d(0.85, 0, 0.8);
    EXPECT_LT((env.shapeWorldPose(can, 0).translation() - expected).norm(), 1e-12);
    EXPECT_EQ(env.objectShapes(can)[0].type, ShapeType::Cylinder);
    EXPECT_DOUBLE_EQ(env.objectShapes(can)[0].length, 0.12);
    EXPECT_DOUBLE_EQ(env.objectShapes(can)[0].radius, 0.03);
}

TEST(SceneYaml, ComposesObjectAndPrimitivePoses)
{
    // object: at (1, 2, 3), turned 90 degrees about z; its box: 1 m along the object's x, turned 90 degrees about x
    const double h = std::sqrt(0.5);
    std::ostringstream yaml;
    yaml << "world:\n  collision_objects:\n"
         << "    - id: shelf\n"
         << "      pose:\n        position: {x: 1, y: 2, z: 3}\n        orientation: {x: 0, y: 0, z: " << h
         << ", w: " << h << "}\n"
         << "      primitives:\n        - type: box\n          dimensions: [0.2, 0.4, 0.6]\n"
         << "        - type: cylinder\n          dimensions: [0.5, 0.1]\n"
         << "        - type: sphere\n          dimensions: [0.25]\n"
         << "      primitive_poses:\n"
         << "        - position: [1, 0, 0]\n          orientation: [" << h << ", 0, 0, " << h << "]\n"
         << "        - position: [0, 0, 1]\n          orientation: [0, 0, 0, 1]\n"
         << "        - position: [0, -1, 0]\n          orientation: [0, 0, 0, 1]\n"
         << "    - id: loose\n"
         << "      primitives:\n        - type: SPHERE\n          dimensions: [0.5]\n"
         << "      primitive_poses:\n        - position: [-4, 0, 0]\n          orientation: [0, 0, 0, 1]\n";
    const Environment env = planningSceneFromString(yaml.str(), "compose.yaml");
    ASSERT_EQ(env.objectCount(), 2u);
    const int shelf = env.objectId("shelf");
    ASSERT_EQ(env.objectShapes(shelf).size(), 3u);

    // box: x_object -> y_world, so the centre is at (1, 3, 3); its axes: x -> y_world, y -> z_world, z -> x_world
    const Eigen::Isometry3d box = env.shapeWorldPose(shelf, 0);
    EXPECT_LT((box.translation() - Eigen::Vector3d(1, 3, 3)).norm(), 1e-12);
    Eigen::Matrix3d expectedAxes;
    expectedAxes << 0, 0, 1,  //
        1, 0, 0,              //
        0, 1, 0;
    EXPECT_LT((box.linear() - expectedAxes).norm(), 1e-12) << box.linear();
    EXPECT_EQ(env.objectShapes(shelf)[0].type, ShapeType::Box);
    EXPECT_EQ(env.objectShapes(shelf)[0].extents, Eigen::Vector3d(0.2, 0.4, 0.6));
    // full extents: the box spans 0.2 along world y, 0.4 along world z, 0.6 along world x
    EXPECT_NEAR(env.signedDistance(Eigen::Vector3d(1, 3.1 + 0.5, 3), 0.5), 0.0, 1e-9);
    EXPECT_NEAR(env.signedDistance(Eigen::Vector3d(1, 3, 3.2 + 0.25), 0.25), 0.0, 1e-9);
    EXPECT_NEAR(env.signedDistance(Eigen::Vector3d(1.3 + 0.1, 3, 3), 0.1), 0.0, 1e-9);

    // cylinder [length, radius]
    const Shape &cylinder = env.objectShapes(shelf)[1];
    EXPECT_EQ(cylinder.type, ShapeType::Cylinder);
    EXPECT_DOUBLE_EQ(cylinder.length, 0.5);
    EXPECT_DOUBLE_EQ(cylinder.radius, 0.1);
    EXPECT_LT((env.shapeWorldPose(shelf, 1).translation() - Eigen::Vector3d(1, 2, 4)).norm(), 1e-12);

    // sphere: object -y is world +x
    EXPECT_DOUBLE_EQ(env.objectShapes(shelf)[2].radius, 0.25);
    EXPECT_LT((env.shapeWorldPose(shelf, 2).translation() - Eigen::Vector3d(2, 2, 3)).norm(), 1e-12);
    EXPECT_LT((env.shapeWorldPose(env.objectId("loose"), 0).translation() - Eigen::Vector3d(-4, 0, 0)).norm(), 1e-12);
}

TEST(SceneYaml, NormalizesNearUnitQuaternions)
{
    const Environment env = scene(object("a", "box", "[1, 1, 1]", "[0, 0, 0]", "[0, 0, 0.7072, 0.7072]"));
    const Eigen::Matrix3d r = env.shapeWorldPose(0, 0).linear();
    EXPECT_LT((r * r.transpose() - Eigen::Matrix3d::Identity()).norm(), 1e-12);
    EXPECT_LT((r * Eigen::Vector3d::UnitX() - Eigen::Vector3d::UnitY()).norm(), 1e-12);
}

TEST(SceneYaml, EmptyWorldIsAnEmptyEnvironment)
{
    EXPECT_EQ(planningSceneFromString("world:\n  collision_objects: []\n", "e.yaml").objectCount(), 0u);
    EXPECT_EQ(planningSceneFromString("name: x\nworld: {}\n", "e.yaml").objectCount(), 0u);
}

TEST(SceneYaml, RejectsMalformedScenes)
{
    struct Case
    {
        std::string what, yaml, expect;
    };
    const std::string base = "world:\n  collision_objects:\n";
    const std::vector<Case> cases = {
        {"unknown primitive type", base + object("o", "cone", "[1, 2]"), "unsupported primitive type 'cone'"},
        {"box with 2 dimensions", base + object("o", "box", "[1, 2]"), "box needs 3 dimensions"},
        {"cylinder with 3 dimensions", base + object("o", "cylinder", "[1, 2, 3]"), "cylinder needs 2 dimensions"},
        {"sphere with 2 dimensions", base + object("o", "sphere", "[1, 2]"), "sphere needs 1 dimensions"},
        {"negative dimension", base + object("o", "box", "[1, -2, 3]"), "must be positive"},
        {"zero dimension", base + object("o", "sphere", "[0]"), "must be positive"},
        {"NaN dimension", base + object("o", "box", "[1, .nan, 3]"), "not finite"},
        {"text dimension", base + object("o", "box", "[1, abc, 3]"), "'abc' is not a number"},
        {"NaN position", base + object("o", "box", "[1, 2, 3]", "[0, .NaN, 0]"), "position[1]"},
        {"infinite position", base + object("o", "box", "[1, 2, 3]", "[0, 0, .inf]"), "not finite"},
        {"short position", base + object("o", "box", "[1, 2, 3]", "[0, 0]"), "expected 3 values, got 2"},
        {"zero quaternion", base + object("o", "box", "[1, 2, 3]", "[0, 0, 0]", "[0, 0, 0, 0]"), "zero quaternion"},
        {"non-unit quaternion", base + object("o", "box", "[1, 2, 3]", "[0, 0, 0]", "[0, 0, 0, 2]"), "has norm 2"},
        {"3-value quaternion", base + object("o", "box", "[1, 2, 3]", "[0, 0, 0]", "[0, 0, 1]"), "4 values"},
        {"duplicate id", base + object("twin") + object("twin"), "duplicate object id 'twin'"},
        {"missing id", base + "    - primitives: []\n", "missing key 'id'"},
        {"missing primitives", base + "    - id: p\n      primitive_poses: []\n", "missing key 'primitives'"},
        {"no primitives", base + "    - id: p\n      primitives: []\n      primitive_poses: []\n", "no primitives"},
        {"poses count mismatch",
         base + "    - id: p\n      primitives:\n        - type: sphere\n          dimensions: [1]\n"
                "      primitive_poses: []\n",
         "1 primitives but 0 primitive_poses"},
        {"missing orientation",
         base + "    - id: p\n      primitives:\n        - {type: sphere, dimensions: [1]}\n"
                "      primitive_poses:\n        - position: [0, 0, 0]\n",
         "missing key 'orientation'"},
        {"bad object pose",
         base + "    - id: p\n      pose: {position: [0, 0, 0], orientation: [0, 0, 0, 0]}\n"
                "      primitives:\n        - {type: sphere, dimensions: [1]}\n"
                "      primitive_poses:\n        - {position: [0, 0, 0], orientation: [0, 0, 0, 1]}\n",
         "'p'.pose.orientation"},
        {"mesh obstacles", base + object("m") + "      meshes:\n        - {vertices: [], triangles: []}\n",
         "meshes are not supported"},
        {"remove operation", base + object("r") + "      operation: 1\n", "only ADD"},
        {"collision_objects not a list", "world:\n  collision_objects: 3\n", "expected a list"},
        {"no world", "robot_state: {}\n", "no 'world' key"},
        {"not a mapping", "- 1\n- 2\n", "expected a MoveIt PlanningScene"},
        {"malformed YAML", "world: [collision_objects: {\n", "malformed YAML"},
    };
    for (const Case &c : cases)
    {
        const std::string message = errorOf([&] { planningSceneFromString(c.yaml, "bad-scene.yaml"); });
        ASSERT_FALSE(message.empty()) << c.what << ": no ropras::Error for\n" << c.yaml;
        EXPECT_NE(message.find("bad-scene.yaml"), std::string::npos) << c.what << ": " << message;
        EXPECT_NE(message.find(c.expect), std::string::npos) << c.what << ": " << message;
    }
    // the entry is named: index and id
    const std::string message =
        errorOf([&] { planningSceneFromString(base + object("good") + object("bad", "box", "[1]"), "s.yaml"); });
    EXPECT_NE(message.find("world.collision_objects[1] 'bad'.primitives[0]"), std::string::npos) << message;
    EXPECT_NE(message.find("s.yaml:"), std::string::npos) << message;  // with a line number

    const std::string missing = errorOf([] { loadPlanningScene("/nonexistent/dir/scene.yaml"); });
    EXPECT_NE(missing.find("/nonexistent/dir/scene.yaml"), std::string::npos) << missing;
}

// yaml-cpp keeps one of two equal keys silently: a repeated key is an error with both lines, in scenes and requests
TEST(SceneYaml, RejectsDuplicateKeys)
{
    expectErrorMentions([] { planningSceneFromString("name: a\nname: b\nworld: {}\n", "dup.yaml"); },
                        {"dup.yaml:2", "key 'name'", "given twice", "first on line 1"});
    const std::string object =
        "world:\n  collision_objects:\n    - id: o\n      primitives:\n        - type: box\n"
        "          dimensions: [1, 1, 1]\n          dimensions: [2, 2, 2]\n"
        "      primitive_poses:\n        - position: [0, 0, 0]\n"
        "          orientation: [0, 0, 0, 1]\n";
    expectErrorMentions([&] { planningSceneFromString(object, "nested.yaml"); },
                        {"nested.yaml:7", "key 'dimensions'", "first on line 6"});
    expectErrorMentions([] { motionPlanRequestFromString("start_state: {}\nstart_state: {}\n", "request.yaml"); },
                        {"request.yaml:2", "key 'start_state'"});
}

TEST(SceneYaml, LoadsMbmRequest)
{
    const fs::path path = fs::path(SHARED_DIR) / "mbm" / "panda" / "bookshelf_small" / "request0001.yaml";
    if (!fs::exists(path))
        GTEST_SKIP() << "../shared not found: " << path;
    const MotionPlanRequest request = loadMotionPlanRequest(path.string());
    EXPECT_EQ(request.start.size(), 9u);
    EXPECT_EQ(request.goal.size(), 7u);
    EXPECT_DOUBLE_EQ(request.start.at("panda_joint4"), -2.356);
    EXPECT_DOUBLE_EQ(request.start.at("panda_finger_joint1"), 0.065);
    EXPECT_DOUBLE_EQ(request.goal.at("panda_joint1"), 1.48904932702624);
    EXPECT_DOUBLE_EQ(request.goal.at("panda_joint7"), 1.06196398075046);
}

TEST(SceneYaml, LoadsEveryMbmRequest)
{
    const fs::path root = fs::path(SHARED_DIR) / "mbm";
    if (!fs::exists(root))
        GTEST_SKIP() << "../shared not found: " << root;
    int files = 0;
    for (const auto &entry : fs::recursive_directory_iterator(root))
    {
        if (entry.path().filename().string().rfind("request", 0) != 0)
            continue;
        MotionPlanRequest request;
        ASSERT_NO_THROW(request = loadMotionPlanRequest(entry.path().string())) << entry.path();
        ASSERT_FALSE(request.goal.empty()) << entry.path();
        ++files;
    }
    EXPECT_EQ(files, 980);
}

TEST(SceneYaml, RejectsMalformedRequests)
{
    const std::string start = "start_state:\n  joint_state:\n    name: [a, b]\n    position: [1, 2]\n";
    const std::string goal = "goal_constraints:\n  - joint_constraints:\n      - {joint_name: a, position: 0.5}\n";
    struct Case
    {
        std::string what, yaml, expect;
    };
    const std::vector<Case> cases = {
        {"length mismatch", "start_state:\n  joint_state:\n    name: [a, b]\n    position: [1]\n" + goal,
         "2 joint names but 1 positions"},
        {"NaN start", "start_state:\n  joint_state:\n    name: [a, b]\n    position: [1, .nan]\n" + goal,
         "position[1] (b)"},
        {"duplicate start joint", "start_state:\n  joint_state:\n    name: [a, a]\n    position: [1, 2]\n" + goal,
         "duplicate joint name 'a'"},
        {"missing start", goal, "missing key 'start_state'"},
        {"missing goals", start, "missing key 'goal_constraints'"},
        {"empty goals", start + "goal_constraints: []\n", "no goal constraints"},
        {"no joint constraints", start + "goal_constraints:\n  - position_constraints: []\n",
         "missing key 'joint_constraints'"},
        {"goal NaN", start + "goal_constraints:\n  - joint_constraints:\n      - {joint_name: a, position: .nan}\n",
         "position (a)"},
        {"goal without name", start + "goal_constraints:\n  - joint_constraints:\n      - {position: 1}\n",
         "missing key 'joint_name'"},
        {"duplicate goal joint",
         start + "goal_constraints:\n  - joint_constraints:\n      - {joint_name: a, position: 1}\n"
                 "      - {joint_name: a, position: 2}\n",
         "duplicate joint name 'a'"},
    };
    for (const Case &c : cases)
    {
        const std::string message = errorOf([&] { motionPlanRequestFromString(c.yaml, "bad-request.yaml"); });
        ASSERT_FALSE(message.empty()) << c.what << ": no ropras::Error for\n" << c.yaml;
        EXPECT_NE(message.find("bad-request.yaml"), std::string::npos) << c.what << ": " << message;
        EXPECT_NE(message.find(c.expect), std::string::npos) << c.what << ": " << message;
    }
    const MotionPlanRequest ok = motionPlanRequestFromString(start + goal, "ok.yaml");
    EXPECT_EQ(ok.start.at("b"), 2.0);
    EXPECT_EQ(ok.goal.at("a"), 0.5);
}
