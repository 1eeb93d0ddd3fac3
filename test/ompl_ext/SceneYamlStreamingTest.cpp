// The scene reader reads each collision object as soon as yaml-cpp's parser has passed it (events, no node tree of
// the whole file; issue 17, item 12). Cross-checked against the scenes yaml-cpp's own node tree (YAML::Load) gives:
// random scenes in block and flow style, with list and mapping vectors, numbers written in many ways, anchors and
// aliases; and the checks that a streamed read must keep (repeated keys, aliases into earlier objects).
#include <gtest/gtest.h>
#include <yaml-cpp/yaml.h>

#include <Eigen/Geometry>
#include <cmath>
#include <cstdio>
#include <random>
#include <string>
#include <vector>

#define ROPRAS_ALLOCATION_COUNTER_ONLY  // the counting operator new is defined in VectorizedRRTConnectAllocationTest
#include "../AllocationCounter.h"
#include "ExpectError.h"
#include "ropras/core/Error.h"
#include "ropras/ompl_ext/scene/SceneYaml.h"

using namespace ropras::ompl_ext;
using ropras::test::expectErrorMentions;

namespace
{
    /// writes random scenes: every number is written with one of several spellings, poses as lists or mappings
    class SceneWriter
    {
    public:
        explicit SceneWriter(std::uint64_t seed) : rng_(seed) {}

        std::string scene(int objects)
        {
            std::string out = "name: random\nrobot_state: {is_diff: true}\nworld:\n  collision_objects:\n";
            for (int i = 0; i < objects; ++i)
                out += object(i);
            return out;
        }

    private:
        double uniform(double lo, double hi) { return std::uniform_real_distribution<double>(lo, hi)(rng_); }
        int pick(int n) { return std::uniform_int_distribution<int>(0, n - 1)(rng_); }

        /// \a v in one of the spellings yaml-cpp reads as a number
        std::string number(double v)
        {
            char text[64];
            switch (pick(5))
            {
                case 0:
                    std::snprintf(text, sizeof(text), "%.17g", v);
                    break;
                case 1:
                    std::snprintf(text, sizeof(text), "%.3e", v);
                    break;
                case 2:
                    std::snprintf(text, sizeof(text), v >= 0 ? "+%.6f" : "%.6f", v);  // "+": yaml-cpp's own path
                    break;
                case 3:
                    std::snprintf(text, sizeof(text), "\"%.9g\"", v);  // quoted
                    break;
                default:
                    std::snprintf(text, sizeof(text), "%.4f", v);
                    break;
            }
            return text;
        }

        std::string vector(const double *v, int n, const char *const *keys)
        {
            std::string out = pick(2) == 0 ? "[" : "{";
            const bool list = out == "[";
            for (int k = 0; k < n; ++k)
                out += (k ? ", " : "") + (list ? "" : std::string(keys[k]) + ": ") + number(v[k]);
            return out + (list ? "]" : "}");
        }

        std::string pose()
        {
            static const char *const XYZ[] = {"x", "y", "z"};
            static const char *const XYZW[] = {"x", "y", "z", "w"};
            const double p[3] = {uniform(-2, 2), uniform(-2, 2), uniform(0, 2)};
            Eigen::Vector4d q(uniform(-1, 1), uniform(-1, 1), uniform(-1, 1), uniform(-1, 1));
            q *= uniform(0.995, 1.005) / q.norm();  // within the tolerance the reader normalizes
            return "{position: " + vector(p, 3, XYZ) + ", orientation: " + vector(q.data(), 4, XYZW) + "}";
        }

        std::string object(int i)
        {
            std::string out = "    - id: o" + std::to_string(i) + "\n";
            if (pick(2) == 0)
                out += "      header: {frame_id: world}\n";
            // every fifth object anchors its pose, later ones may reuse it; others have a pose or none
            if (i % 5 == 0)
                out += "      pose: &pose" + std::to_string(i) + " " + pose() + "\n";
            else if (i > 5 && pick(4) == 0)
                out += "      pose: *pose" + std::to_string(5 * pick(i / 5)) + "\n";
            else if (pick(3) > 0)
                out += "      pose: " + pose() + "\n";
            const int count = 1 + pick(3);
            std::string primitives = "      primitives:\n", poses = "      primitive_poses:\n";
            for (int k = 0; k < count; ++k)
            {
                const int type = pick(3);
                const char *names[] = {"box", pick(2) ? "sphere" : "2", "cylinder"};
                std::string dims = number(uniform(0.01, 1));
                if (type != 1)
                    dims += ", " + number(uniform(0.01, 1));
                if (type == 0)
                    dims += ", " + number(uniform(0.01, 1));
                primitives +=
                    pick(2)
                        ? "        - {type: " + std::string(names[type]) + ", dimensions: [" + dims + "]}\n"
                        : "        - type: " + std::string(names[type]) + "\n          dimensions: [" + dims + "]\n";
                poses += "        - " + pose() + "\n";
            }
            out += pick(2) ? primitives + poses : poses + primitives;
            if (pick(4) == 0)
                out += "      operation: " + std::string(pick(2) ? "0" : "ADD") + "\n";
            return out;
        }

        std::mt19937_64 rng_;
    };

    // The reference: yaml-cpp's node tree, read independently of the reader

    double number(const YAML::Node &node)
    {
        return node.as<double>();
    }

    Eigen::Isometry3d referencePose(const YAML::Node &node)
    {
        Eigen::Isometry3d pose = Eigen::Isometry3d::Identity();
        if (!node)
            return pose;
        const YAML::Node p = node["position"], q = node["orientation"];
        const auto at = [](const YAML::Node &v, int i, const char *key)
        { return number(v.IsSequence() ? v[i] : v[key]); };
        pose.translation() = Eigen::Vector3d(at(p, 0, "x"), at(p, 1, "y"), at(p, 2, "z"));
        pose.linear() = Eigen::Quaterniond(at(q, 3, "w"), at(q, 0, "x"), at(q, 1, "y"), at(q, 2, "z"))
                            .normalized()
                            .toRotationMatrix();
        return pose;
    }

    void expectSameAsReference(const std::string &yaml, const Environment &env)
    {
        const YAML::Node objects = YAML::Load(yaml)["world"]["collision_objects"];
        ASSERT_EQ(env.objectCount(), objects.size());
        for (std::size_t i = 0; i < objects.size(); ++i)
        {
            const YAML::Node o = objects[i];
            const int id = static_cast<int>(i);
            ASSERT_EQ(env.objectName(id), o["id"].as<std::string>());
            const Eigen::Isometry3d objectPose = referencePose(o["pose"]);
            const YAML::Node primitives = o["primitives"];
            const std::vector<Shape> &shapes = env.objectShapes(id);
            ASSERT_EQ(shapes.size(), primitives.size()) << env.objectName(id);
            for (std::size_t k = 0; k < shapes.size(); ++k)
            {
                const std::string type = primitives[k]["type"].as<std::string>();
                const YAML::Node d = primitives[k]["dimensions"];
                const Shape &s = shapes[k];
                if (type == "box")
                {
                    ASSERT_EQ(s.type, ShapeType::Box);
                    EXPECT_EQ(s.extents, Eigen::Vector3d(number(d[0]), number(d[1]), number(d[2])));
                }
                else if (type == "cylinder")
                {
                    ASSERT_EQ(s.type, ShapeType::Cylinder);
                    EXPECT_EQ(s.length, number(d[0]));
                    EXPECT_EQ(s.radius, number(d[1]));
                }
                else
                {
                    ASSERT_EQ(s.type, ShapeType::Sphere);
                    EXPECT_EQ(s.radius, number(d[0]));
                }
                const Eigen::Isometry3d expected = objectPose * referencePose(o["primitive_poses"][k]);
                EXPECT_LT((env.shapeWorldPose(id, k).matrix() - expected.matrix()).norm(), 1e-12)
                    << env.objectName(id) << " primitive " << k;
            }
        }
    }
}  // namespace

TEST(SceneYamlStreaming, RandomScenesMatchYamlCppsNodeTree)
{
    SceneWriter writer(17);
    for (int scene = 0; scene < 10; ++scene)
    {
        const std::string yaml = writer.scene(200);
        const Environment env = planningSceneFromString(yaml, "random.yaml");
        expectSameAsReference(yaml, env);
        if (HasFatalFailure())
            FAIL() << "scene " << scene << ":\n" << yaml.substr(0, 2000);
    }
}

TEST(SceneYamlStreaming, NumbersAreReadAsYamlCppReadsThem)
{
    // the reader reads plain decimals itself and hands every other spelling to yaml-cpp's conversion
    const std::vector<std::string> texts = {
        "1",        "-2.5",  "+3",     "0.125", ".5",     "-.5",   "5.",
        "1e3",      "1E-3",  "2.5e+2", "007",   "1e-320", "1e400", "-1e400",
        "0x10",     "1_000", "1e",     "e3",    "--1",    "1.2.3", "' 1'",
        "'1 '",     "\"2\"", ".inf",   "-.Inf", ".nan",   "abc",   "1.7976931348623157e308",
        "4.9e-324", "0.1e1", "-0",     "+.5"};
    for (const std::string &text : texts)
    {
        const std::string yaml =
            "world:\n  collision_objects:\n    - id: s\n      primitives:\n        - type: sphere\n"
            "          dimensions: [" +
            text +
            "]\n      primitive_poses:\n        - {position: [0, 0, 0], orientation: "
            "[0, 0, 0, 1]}\n";
        const YAML::Node reference =
            YAML::Load(yaml)["world"]["collision_objects"][0]["primitives"][0]["dimensions"][0];
        double expected = 0.0;
        const bool readable = YAML::convert<double>::decode(reference, expected);
        std::string message;
        double radius = 0.0;
        try
        {
            radius = planningSceneFromString(yaml, "n.yaml").objectShapes(0)[0].radius;
        }
        catch (const ropras::Error &e)
        {
            message = e.what();
        }
        if (!readable)
            EXPECT_NE(message.find("is not a number"), std::string::npos) << text << ": " << message;
        else if (!std::isfinite(expected))
            EXPECT_NE(message.find("is not finite"), std::string::npos) << text << ": " << message;
        else if (expected <= 0.0)
            EXPECT_NE(message.find("must be positive"), std::string::npos) << text << ": " << message;
        else
        {
            EXPECT_EQ(message, "") << text;
            EXPECT_EQ(radius, expected) << text;
        }
    }
}

TEST(SceneYamlStreaming, AliasesReachIntoEarlierObjects)
{
    // the first object's pose and primitive are anchored: the object has been read and dropped by the time the
    // second one refers to them, so the reader must keep anchored nodes
    const std::string yaml =
        "world:\n  collision_objects:\n"
        "    - id: a\n      pose: &p {position: [1, 2, 3], orientation: [0, 0, 0, 1]}\n"
        "      primitives: [&box {type: box, dimensions: [1, 2, 3]}]\n"
        "      primitive_poses: [{position: [0, 0, 0], orientation: [0, 0, 0, 1]}]\n"
        "    - id: b\n      pose: *p\n      primitives: [*box, {type: sphere, dimensions: [0.5]}]\n"
        "      primitive_poses: [{position: [0, 0, 1], orientation: [0, 0, 0, 1]}, {position: [0, 0, 2], orientation: "
        "[0, 0, 0, 1]}]\n"
        "    - &c\n      id: c\n      primitives: [*box]\n      primitive_poses: [{position: [5, 0, 0], orientation: "
        "[0, 0, 0, 1]}]\n";
    const Environment env = planningSceneFromString(yaml, "alias.yaml");
    ASSERT_EQ(env.objectCount(), 3u);
    expectSameAsReference(yaml, env);
    EXPECT_EQ(env.shapeWorldPose(env.objectId("b"), 1).translation(), Eigen::Vector3d(1, 2, 5));
    // an alias of a whole earlier object repeats its id
    expectErrorMentions([&] { planningSceneFromString(yaml + "    - *c\n", "alias.yaml"); },
                        {"alias.yaml:", "world.collision_objects[3] 'c'", "duplicate object id 'c'"});
}

TEST(SceneYamlStreaming, RepeatedKeysAreFoundWhileObjectsAreRead)
{
    // a second 'world' is reported as a repeated key before any of its objects is read (not as their repeated ids)
    const std::string world =
        "world:\n  collision_objects:\n    - id: o\n      primitives: [{type: sphere, dimensions: "
        "[1]}]\n      primitive_poses: [{position: [0, 0, 0], orientation: [0, 0, 0, 1]}]\n";
    expectErrorMentions([&] { planningSceneFromString(world + world, "twice.yaml"); },
                        {"twice.yaml:6", "key 'world'", "given twice in one mapping (first on line 1)"});
    // a mapping with many keys (checked with a hash table past 16 keys)
    std::string many = "world: {}\nextra:\n";
    for (int k = 0; k < 40; ++k)
        many += "  k" + std::to_string(k) + ": " + std::to_string(k) + "\n";
    EXPECT_NO_THROW(planningSceneFromString(many, "many.yaml"));
    expectErrorMentions([&] { planningSceneFromString(many + "  k3: again\n", "many.yaml"); },
                        {"many.yaml:43", "key 'k3'", "first on line 6"});
    expectErrorMentions([&] { planningSceneFromString(many + "  k39: again\n", "many.yaml"); },
                        {"many.yaml:43", "key 'k39'", "first on line 42"});
}

TEST(SceneYamlStreaming, ProblemsAreReportedInFileOrder)
{
    // objects are read while the file is parsed: a bad object is reported even when the YAML breaks later, and a
    // YAML error before any bad object is reported as malformed YAML
    const std::string bad =
        "world:\n  collision_objects:\n    - id: o\n      primitives: [{type: cone, dimensions: [1]}]\n"
        "      primitive_poses: [{position: [0, 0, 0], orientation: [0, 0, 0, 1]}]\n";
    expectErrorMentions([&] { planningSceneFromString(bad + "    - [\n", "order.yaml"); },
                        {"order.yaml:4", "unsupported primitive type 'cone'"});
    expectErrorMentions([&] { planningSceneFromString("world: {collision_objects: [\n", "order.yaml"); },
                        {"order.yaml:", "malformed YAML"});
    expectErrorMentions([] { planningSceneFromString("", "empty.yaml"); },
                        {"empty.yaml: document: expected a MoveIt PlanningScene"});
}

TEST(SceneYamlStreaming, AliasesAreNeverExpanded)
{
    // nine levels of ten aliases each: 10^9 nodes if expanded (the old reader walked them until its 5 * 10^7 node
    // limit); the tree shares anchored nodes, so the file reads in memory proportional to its text
    std::string yaml = "extra:\n  a0: &a0 [x, x, x, x, x, x, x, x, x, x]\n";
    for (int level = 1; level < 9; ++level)
    {
        const std::string previous = "*a" + std::to_string(level - 1);
        yaml += "  a" + std::to_string(level) + ": &a" + std::to_string(level) + " [" + previous;
        for (int k = 1; k < 10; ++k)
            yaml += ", " + previous;
        yaml += "]\n";
    }
    const std::string object =
        "    - id: o\n      primitives: [{type: sphere, dimensions: [1]}]\n"
        "      primitive_poses: [{position: [0, 0, 0], orientation: [0, 0, 0, 1]}]\n";
    const std::size_t live = ropras::test::liveBytes.load();
    ropras::test::resetPeakBytes();
    EXPECT_EQ(planningSceneFromString(yaml + "world:\n  collision_objects:\n" + object, "laughs.yaml").objectCount(),
              1u);
    EXPECT_LT(ropras::test::peakBytes.load() - live, 200000u);
    // where the reader does walk a list, an alias is one item: a primitive list of ten lists is ten wrong primitives
    expectErrorMentions(
        [&]
        {
            planningSceneFromString(yaml +
                                        "world:\n  collision_objects:\n    - id: o\n      primitives: *a8\n"
                                        "      primitive_poses: *a8\n",
                                    "laughs.yaml");
        },
        {"laughs.yaml:", "'o'.primitive_poses[0]: expected a pose"});
}
