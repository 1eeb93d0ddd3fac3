// `ropras view`'s documents and page: robot spheres posed per frame agree with an independent FK (the recorded
// prismatic positions; the Panda's KinematicChain link poses), packed coordinates decode within half a level,
// path CSVs are read in any column order, and the page embeds three.js and the document safely.
#include <gtest/gtest.h>

#include <unistd.h>
#include <Eigen/Geometry>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include "ExpectError.h"
#include "ropras/ompl_ext/kinematics/LinkPoses.h"
#include "ropras/ompl_ext/model/RobotModel.h"
#include "ropras/ompl_ext/scene/SceneYaml.h"
#include "ropras/scenarios/EpisodeView.h"
#include "ropras/scenarios/MotionView.h"
#include "ropras/scenarios/ViewerPage.h"

namespace ropras::scenarios::test
{
    using nlohmann::json;
    using ropras::test::expectErrorMentions;

    namespace
    {
        /** \brief The x, y, z triples of a packed list (ViewDocument::packed), decoded here independently. */
        std::vector<double> unpack(const json &packed)
        {
            const std::string text = packed.at("q16").get<std::string>();
            const std::string alphabet = "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789+/";
            std::vector<unsigned char> bytes;
            unsigned buffer = 0;
            int bits = 0;
            for (const char c : text)
            {
                if (c == '=')
                    break;
                buffer = (buffer << 6) | static_cast<unsigned>(alphabet.find(c));
                bits += 6;
                if (bits >= 8)
                {
                    bits -= 8;
                    bytes.push_back(static_cast<unsigned char>((buffer >> bits) & 0xff));
                }
            }
            std::vector<double> out;
            for (std::size_t i = 0; i + 1 < bytes.size(); i += 2)
            {
                const std::size_t k = (i / 2) % 3;
                out.push_back(packed["origin"][k].get<double>() +
                              packed["step"][k].get<double>() * (bytes[i] | (bytes[i + 1] << 8)));
            }
            return out;
        }

        double halfStep(const json &packed)
        {
            double h = 0.0;
            for (const auto &s : packed["step"])
                h = std::max(h, 0.5 * s.get<double>());
            return h + 1e-12;
        }

        const json *body(const json &view, const std::string &name)
        {
            for (const auto &b : view["bodies"])
                if (b["name"] == name)
                    return &b;
            return nullptr;
        }

        std::string tempFile(const std::string &name, const std::string &text)
        {
            const auto path = std::filesystem::temp_directory_path() /
                              ("ropras-view-test-" + std::to_string(::getpid()) + "-" + name);
            std::ofstream(path) << text;
            return path.string();
        }

        const std::string PANDA = std::string(ROPRAS_SOURCE_DIR) + "/robots/panda/panda.urdf";
    }  // namespace

    // A maze2d robot (a sphere on two prismatic joints) recorded at known positions: its FK sphere centres are the
    // joint values (z = 0), the label marker follows the trajectory, and belief snapshots keep their particles.
    TEST(EpisodeView, RobotSpheresFollowTheRecordedJointValues)
    {
        json r;
        r["scenario"] = "maze2d";
        r["scene"] = {{"dims", 2},
                      {"bounds", {{-25, -25}, {25, 25}}},
                      {"walls", {{{-12, -25}, {-11, -2.5}}}},
                      {"obstacles", json::array()},
                      {"goal", {{19, -2.5}, {24, 2.5}}},
                      {"starts", {{-20, 15}}},
                      {"robot_radius", 0.25}};
        r["labels"] = {"robot"};
        r["robot"] = {{"urdf", "embedded:navigation/maze2d/robot.urdf"}, {"configurations", json::array()}};
        r["trajectory"] = json::array();
        r["beliefs"] = json::array();
        for (int t = 0; t < 40; ++t)
        {
            const double x = -20.0 + 0.7 * t, y = 15.0 - 0.45 * t;
            r["trajectory"].push_back({{x, y}});
            r["robot"]["configurations"].push_back({x, y});
            if (t % 10 == 0)
                r["beliefs"].push_back({{"step", t}, {"particles", {{{x + 0.1, y}}, {{x - 0.1, y}}}}});
        }
        const json view = episodeView(r, "maze.json");
        EXPECT_EQ(view["frames"], 40);
        EXPECT_EQ(view["boxes"].size(), 2u) << "one wall and the goal";
        const json *robot = body(view, "robot spheres");
        ASSERT_NE(robot, nullptr);
        ASSERT_EQ(robot->at("radii").size(), 1u);
        EXPECT_NEAR(robot->at("radii")[0].get<double>(), 0.25, 1e-9);
        const auto centres = unpack(robot->at("centres"));
        ASSERT_EQ(centres.size(), 40u * 3u);
        for (int t = 0; t < 40; ++t)
        {
            EXPECT_NEAR(centres[3 * t], -20.0 + 0.7 * t, halfStep(robot->at("centres")));
            EXPECT_NEAR(centres[3 * t + 1], 15.0 - 0.45 * t, halfStep(robot->at("centres")));
            EXPECT_NEAR(centres[3 * t + 2], 0.0, 1e-9);
        }
        ASSERT_EQ(view["beliefs"].size(), 1u);
        EXPECT_EQ(view["beliefs"][0]["steps"], json({0, 10, 20, 30}));
        EXPECT_EQ(view["beliefs"][0]["offsets"], json({0, 2, 4, 6, 8}));
        const auto particles = unpack(view["beliefs"][0]["points"]);
        EXPECT_NEAR(particles[3], -20.1, halfStep(view["beliefs"][0]["points"]));
    }

    // Labels whose particles all coincide (the drones of multi-drone) have no belief cloud; rays are kept per step.
    TEST(EpisodeView, KnownLabelsHaveNoBeliefAndRaysAreKept)
    {
        json r;
        r["scene"] = {{"bounds", {{0, 0, 0}, {4, 4, 4}}}};
        r["labels"] = {"drone1", "target"};
        r["trajectory"] = {{{1, 1, 1}, {2, 2, 2}}, {{1.5, 1, 1}, {2, 2.5, 2}}};
        r["beliefs"] = {{{"step", 0}, {"particles", {{{1, 1, 1}, {2, 2, 2}}, {{1, 1, 1}, {3, 2, 2}}}}}};
        r["rays"] = {{{"step", 1}, {"segments", {{{0, 0, 0}, {1, 1, 1}}, {{0, 0, 0}, {2, 0, 0}}}}}};
        const json view = episodeView(r, "d.json");
        ASSERT_EQ(view["beliefs"].size(), 1u);
        EXPECT_EQ(view["beliefs"][0]["label"], "target");
        EXPECT_EQ(view["rays"]["steps"], json({1}));
        EXPECT_EQ(view["rays"]["offsets"], json({0, 2}));
        const auto rays = unpack(view["rays"]["segments"]);
        ASSERT_EQ(rays.size(), 12u);
        EXPECT_NEAR(rays[9], 2.0, halfStep(view["rays"]["segments"]));
        r["robot"] = {{"urdf", "embedded:multi-drone/drones.urdf"}, {"configurations", {{1, 2}}}};
        expectErrorMentions([&] { episodeView(r, "d.json"); }, {"d.json", "robot.configurations", "2 steps"});
    }

    // A Panda motion: every frame's sphere centres equal link pose (LinkPoses, the KinematicChain FK) x the sphere's
    // centre in its link; frames follow the joint step; the scene's primitives are all drawn.
    TEST(MotionView, PandaSpheresMatchTheChainFk)
    {
        const auto robot = ompl_ext::RobotModel::fromUrdfFile(PANDA);
        const auto env = ompl_ext::loadPlanningScene(std::string(ROPRAS_SOURCE_DIR) + "/scenes/tabletop.yaml", robot);
        const std::vector<std::vector<double>> path{{0, -0.785, 0, -2.356, 0, 1.571, 0.785},
                                                    {-0.5, 0.1, 0, -1.5, 0, 1.7, 0.785}};
        MotionViewOptions options;
        options.maxJointStep = 0.1;
        options.tipLink = "panda_hand";
        const json view = motionView(*robot, env, path, options);
        // the largest change is joint 2: 0.885 rad -> 9 pieces of <= 0.1
        EXPECT_EQ(view["frames"], 10);
        EXPECT_EQ(view["boxes"].size() + view["cylinders"].size() + view["spheres"].size(), 19u);
        const json *spheres = body(view, "robot spheres");
        ASSERT_NE(spheres, nullptr);
        ASSERT_EQ(spheres->at("radii").size(), robot->spheres().size());
        const auto centres = unpack(spheres->at("centres"));
        ASSERT_EQ(centres.size(), 10u * robot->spheres().size() * 3u);
        const ompl_ext::LinkPoses poses(robot);
        double worst = 0.0;
        for (std::size_t f = 0; f < 10; ++f)
        {
            std::vector<double> q(7);
            for (std::size_t k = 0; k < 7; ++k)
                q[k] = path[0][k] + (path[1][k] - path[0][k]) * static_cast<double>(f) / 9.0;
            for (std::size_t i = 0; i < robot->spheres().size(); ++i)
            {
                const auto &s = robot->spheres()[i];
                const int link = robot->collisionLinks()[static_cast<std::size_t>(s.collisionLink)].link;
                const Eigen::Vector3d c = poses.linkPose(q.data(), link) * s.centerInLink;
                const double *v = &centres[(f * robot->spheres().size() + i) * 3];
                worst = std::max(worst, (c - Eigen::Vector3d(v[0], v[1], v[2])).norm());
            }
        }
        EXPECT_LT(worst, 2.0 * halfStep(spheres->at("centres")) + 1e-6) << "largest centre difference " << worst;
        ASSERT_EQ(view["paths"].size(), 1u);
        EXPECT_EQ(view["paths"][0]["label"], "panda_hand");
    }

    TEST(MotionView, PathCsvInAnyColumnOrder)
    {
        const auto robot = ompl_ext::RobotModel::fromUrdfFile(PANDA);
        const std::string csv =
            tempFile("reversed.csv",
                     "panda_joint7,panda_joint6,panda_joint5,panda_joint4,panda_joint3,panda_joint2,"
                     "panda_joint1\n0.7,1.6,0.5,-2,0.3,0.2,0.1\n");
        const auto rows = loadJointPathCsv(csv, *robot);
        ASSERT_EQ(rows.size(), 1u);
        EXPECT_EQ(rows[0], (std::vector<double>{0.1, 0.2, 0.3, -2, 0.5, 1.6, 0.7}));
        const std::string twice = tempFile("twice.csv", "panda_joint1,panda_joint1\n0,0\n");
        expectErrorMentions([&] { loadJointPathCsv(twice, *robot); }, {"twice.csv", ":1:", "panda_joint1", "twice"});
        std::remove(csv.c_str());
        std::remove(twice.c_str());
    }

    // The page embeds three.js and the document; a "</script>" in a title cannot end the data's script element.
    TEST(ViewerPage, EmbedsThreeAndTheDocumentSafely)
    {
        ThreeJs three;
        three.library = "var THREE = {}; // library";
        three.orbitControls = "THREE.OrbitControls = function () {};";
        json view = {{"title", "a </script><b>title</b>"}, {"frames", 1}};
        const std::string page = viewerPage(view, three);
        EXPECT_NE(page.find("var THREE = {}; // library"), std::string::npos);
        EXPECT_NE(page.find("THREE.OrbitControls = function"), std::string::npos);
        EXPECT_NE(page.find("<title>a &lt;/script&gt;&lt;b&gt;title&lt;/b&gt;</title>"), std::string::npos);
        EXPECT_EQ(page.find("a </script>"), std::string::npos);
        EXPECT_NE(page.find("a <\\/script>"), std::string::npos);
        EXPECT_EQ(page.find("@ROPRAS_"), std::string::npos) << "every placeholder is filled";
        expectErrorMentions([] { loadThreeJs("/nonexistent-three"); },
                            {"/nonexistent-three/three.min.js", "libjs-three"});
    }
}  // namespace ropras::scenarios::test
