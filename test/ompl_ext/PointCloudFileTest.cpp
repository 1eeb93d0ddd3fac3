// Point clouds from PCD and PLY files and from scene YAML (issue 16, item 3): every format against points written
// by an independent writer, every malformed input refused naming the file, and scenes that hold clouds checked
// against a brute force over the transformed points.
#include <gtest/gtest.h>

#include <cmath>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <random>
#include <sstream>

#include "ExpectError.h"
#include "ropras/ompl_ext/scene/PointCloud.h"
#include "ropras/ompl_ext/scene/PointCloudFile.h"
#include "ropras/ompl_ext/scene/SceneYaml.h"

using namespace ropras::ompl_ext;
using ropras::test::expectErrorMentions;
namespace fs = std::filesystem;

namespace
{
    fs::path dir()
    {
        static const fs::path d = []
        {
            fs::path p = fs::temp_directory_path() / ("ropras_pcfile_" + std::to_string(::getpid()));
            fs::create_directories(p);
            return p;
        }();
        return d;
    }

    std::string write(const std::string &name, const std::string &bytes)
    {
        const fs::path p = dir() / name;
        std::ofstream(p, std::ios::binary) << bytes;
        return p.string();
    }

    std::vector<Eigen::Vector3f> randomPoints(std::size_t n, unsigned seed)
    {
        std::mt19937 rng(seed);
        std::uniform_real_distribution<float> u(-2.0f, 2.0f);
        std::vector<Eigen::Vector3f> p(n);
        for (auto &v : p)
            v = Eigen::Vector3f(u(rng), u(rng), u(rng));
        return p;
    }

    template <typename T>
    void put(std::string &out, T value, bool bigEndian = false)
    {
        char b[sizeof(T)];
        std::memcpy(b, &value, sizeof(T));
        if (bigEndian)
            std::reverse(b, b + sizeof(T));
        out.append(b, sizeof(T));
    }

    /// PCD with fields x y z intensity (intensity an unsigned short) in ascii or binary
    std::string pcd(const std::vector<Eigen::Vector3f> &p, bool binary)
    {
        std::ostringstream h;
        h << "# .PCD v0.7 - Point Cloud Data file format\nVERSION 0.7\nFIELDS x y z intensity\nSIZE 4 4 4 2\n"
          << "TYPE F F F U\nCOUNT 1 1 1 1\nWIDTH " << p.size() << "\nHEIGHT 1\nVIEWPOINT 0 0 0 1 0 0 0\nPOINTS "
          << p.size() << "\nDATA " << (binary ? "binary" : "ascii") << "\n";
        std::string out = h.str();
        for (std::size_t i = 0; i < p.size(); ++i)
        {
            if (binary)
            {
                for (int k = 0; k < 3; ++k)
                    put<float>(out, p[i][k]);
                put<std::uint16_t>(out, std::uint16_t(i));
                continue;
            }
            char line[128];
            std::snprintf(line, sizeof(line), "%.9g %.9g %.9g %zu\n", p[i].x(), p[i].y(), p[i].z(), i);
            out += line;
        }
        return out;
    }

    /// PLY with vertex (uchar red, double x, y, z) and a face element, in any of the three formats
    std::string ply(const std::vector<Eigen::Vector3f> &p, const std::string &format)
    {
        std::ostringstream h;
        h << "ply\nformat " << format << " 1.0\ncomment written by the test\nelement vertex " << p.size()
          << "\nproperty uchar red\nproperty double x\nproperty double y\nproperty double z\nelement face 1\n"
          << "property list uchar int vertex_indices\nend_header\n";
        std::string out = h.str();
        const bool big = format == "binary_big_endian";
        for (const auto &v : p)
        {
            if (format == "ascii")
            {
                char line[128];
                std::snprintf(line, sizeof(line), "7 %.17g %.17g %.17g\n", double(v.x()), double(v.y()), double(v.z()));
                out += line;
                continue;
            }
            put<std::uint8_t>(out, 7);
            for (int k = 0; k < 3; ++k)
                put<double>(out, double(v[k]), big);
        }
        if (format == "ascii")
            return out + "3 0 1 2\n";
        put<std::uint8_t>(out, 3);
        for (int k = 0; k < 3; ++k)
            put<std::int32_t>(out, k, big);
        return out;
    }
}  // namespace

TEST(PointCloudFile, EveryFormatReadsTheWrittenPoints)
{
    const std::vector<Eigen::Vector3f> points = randomPoints(500, 7);
    const std::vector<std::pair<std::string, std::string>> files{{"a.pcd", pcd(points, false)},
                                                                 {"b.pcd", pcd(points, true)},
                                                                 {"a.ply", ply(points, "ascii")},
                                                                 {"b.PLY", ply(points, "binary_little_endian")},
                                                                 {"c.ply", ply(points, "binary_big_endian")}};
    for (const auto &[name, bytes] : files)
    {
        const std::vector<Eigen::Vector3f> read = loadPointCloudFile(write(name, bytes));
        ASSERT_EQ(read.size(), points.size()) << name;
        for (std::size_t i = 0; i < points.size(); ++i)
            ASSERT_EQ(read[i], points[i]) << name << " point " << i;  // exact: floats round-trip every format
    }
}

TEST(PointCloudFile, NonFinitePointsAreRefusedOrDropped)
{
    std::vector<Eigen::Vector3f> points = randomPoints(5, 3);
    points[2].y() = std::nanf("");
    const std::string path = write("nan.pcd", pcd(points, true));
    expectErrorMentions([&] { loadPointCloudFile(path); }, {path, "point 2", "not finite", "drop_non_finite"});
    PointCloudFileOptions drop;
    drop.dropNonFinite = true;
    EXPECT_EQ(loadPointCloudFile(path, drop).size(), 4u);
    const std::string ascii = write("inf.ply", ply({{1, 2, 3}, {1e38f, 0, 0}}, "ascii"));
    EXPECT_EQ(loadPointCloudFile(ascii).size(), 2u);
    const std::string big = write("big.ply",
                                  "ply\nformat ascii 1.0\nelement vertex 1\nproperty double x\nproperty "
                                  "double y\nproperty double z\nend_header\n1e300 0 0\n");
    expectErrorMentions([&] { loadPointCloudFile(big); }, {big, "point 0", "as a float"});
}

TEST(PointCloudFile, MalformedFilesAreErrorsNamingTheFile)
{
    const std::string pcdHead =
        "VERSION 0.7\nFIELDS x y z\nSIZE 4 4 4\nTYPE F F F\nCOUNT 1 1 1\nWIDTH 2\nHEIGHT 1\n"
        "POINTS 2\n";
    const std::string plyHead =
        "ply\nformat ascii 1.0\nelement vertex 2\nproperty float x\nproperty float y\n"
        "property float z\nend_header\n";
    const std::vector<std::tuple<std::string, std::string, std::string>> cases{
        {"empty.pcd", "", "no DATA line"},
        {"no_xyz.pcd", "FIELDS a b c\nSIZE 4 4 4\nTYPE F F F\nWIDTH 1\nPOINTS 1\nDATA ascii\n1 2 3\n", "no field 'x'"},
        {"sizes.pcd", "FIELDS x y z\nSIZE 4 4\nTYPE F F F\nWIDTH 1\nPOINTS 1\nDATA ascii\n1 2 3\n", "2 SIZE"},
        {"type.pcd", "FIELDS x y z\nSIZE 4 4 3\nTYPE F F F\nWIDTH 1\nPOINTS 1\nDATA ascii\n1 2 3\n", "TYPE F SIZE 3"},
        {"width.pcd", "FIELDS x y z\nSIZE 4 4 4\nTYPE F F F\nWIDTH 3\nPOINTS 2\nDATA ascii\n1 2 3\n", "WIDTH 3"},
        {"key.pcd", "FIELDS x y z\nCOLOUR red\n", ":2: unknown header line 'COLOUR'"},
        {"twice.pcd", "FIELDS x y z\nFIELDS x y z\n", ":2: FIELDS given twice"},
        {"short.pcd", pcdHead + "DATA ascii\n1 2 3\n", "POINTS 2 ascii points of 3 values cannot fit in the 6 bytes"},
        {"blank.pcd", pcdHead + "DATA ascii\n1 2 3\n          \n", "ends after 1 of POINTS 2"},
        {"word.pcd", pcdHead + "DATA ascii\n1 2 3\n4 five 6\n", ":11: point 1: 'five' is not a number"},
        {"columns.pcd", pcdHead + "DATA ascii\n1 2 3\n4 5\n", "point 1 has 2 values"},
        {"extra.pcd", pcdHead + "DATA ascii\n1 2 3\n4 5 6\n7 8 9\n", "data after the POINTS 2 points"},
        {"binshort.pcd", pcdHead + "DATA binary\n" + std::string(20, '\0'), "do not fit in the 20 bytes of data"},
        {"compressed.pcd", pcdHead + "DATA binary_compressed\n" + std::string(24, '\0'), "binary_compressed"},
        {"huge.pcd",
         "FIELDS x y z\nSIZE 4 4 4\nTYPE F F F\nWIDTH 1000000000000\nHEIGHT 1\nPOINTS 1000000000000\n"
         "DATA binary\n" +
             std::string(12, '\0'),
         "POINTS 1000000000000"},
        {"hugecount.pcd", "FIELDS x y z\nSIZE 4 4 4\nTYPE F F F\nWIDTH 99999999999999999999999\n",
         "not a whole number"},
        {"notply.ply", "solid cube\n", "not a PLY file"},
        {"noformat.ply", "ply\nelement vertex 0\nend_header\n", "no format line"},
        {"noend.ply", "ply\nformat ascii 1.0\nelement vertex 2\n", "no end_header"},
        {"novertex.ply", "ply\nformat ascii 1.0\nend_header\n", "no 'vertex' element"},
        {"noz.ply", "ply\nformat ascii 1.0\nelement vertex 1\nproperty float x\nproperty float y\nend_header\n1 2\n",
         "no scalar property z"},
        {"type.ply", "ply\nformat ascii 1.0\nelement vertex 1\nproperty float128 x\nend_header\n", ":4: expected"},
        {"short.ply", plyHead + "1 2 3\n4 5\n", ":3: element vertex 2: that many instances cannot fit in the 10 bytes"},
        {"missing.ply", plyHead + "1 2 3\n4 5\n      \n", ":9: vertex 1 property z: the line ends"},
        {"truncated.ply", plyHead + "1 2 3\n4 5      ", "the data ends inside vertex 1 property z"},
        {"word.ply", plyHead + "1 2 3\n4 x 6\n", "vertex 1 property y: 'x' is not a number"},
        {"long.ply", plyHead + "1 2 3\n4 5 6 7\n", "vertex 1: more values on the line"},
        {"trailing.ply", plyHead + "1 2 3\n4 5 6\n7 8 9\n", "data after the last element"},
        {"huge.ply",
         "ply\nformat binary_little_endian 1.0\nelement vertex 4000000000\nproperty float x\nproperty "
         "float y\nproperty float z\nend_header\n" +
             std::string(12, '\0'),
         "element vertex 4000000000: that many instances cannot fit in the 12 bytes"},
        {"binshort.ply",
         "ply\nformat binary_big_endian 1.0\nelement vertex 2\nproperty float x\nproperty float "
         "y\nproperty float z\nend_header\n" +
             std::string(20, '\0'),
         "cannot fit in the 20 bytes"},
        {"cloud.xyz", "1 2 3\n", "unknown format '.xyz'"}};
    for (const auto &[name, bytes, message] : cases)
    {
        SCOPED_TRACE(name);
        const std::string path = write(name, bytes);
        expectErrorMentions([&] { loadPointCloudFile(path); }, {"'" + path + "'", message});
    }
    const std::string missing = (dir() / "nowhere.pcd").string();
    expectErrorMentions([&] { loadPointCloudFile(missing); }, {missing});
    expectErrorMentions([&] { loadPointCloudFile("/dev/zero.pcd"); }, {"/dev/zero.pcd"});
    expectErrorMentions([&] { loadPointCloudFile(dir().string() + "/.pcd"); }, {".pcd"});
}

TEST(PointCloudFile, SceneYamlCloudsMatchABruteForceOverTheTransformedPoints)
{
    const std::vector<Eigen::Vector3f> points = randomPoints(300, 11);
    fs::create_directories(dir() / "clouds");
    write("clouds/scan.ply", ply(points, "binary_little_endian"));
    const std::string scenePath = write(
        "cloud_scene.yaml",
        "world:\n  collision_objects:\n    - id: table\n      primitives: [{type: box, dimensions: [0.5, 0.5, 0.1]}]\n"
        "      primitive_poses: [{position: [3, 0, 0], orientation: [0, 0, 0, 1]}]\n"
        "  point_clouds:\n    - id: scan\n      file: clouds/scan.ply\n      point_radius: 0.02\n"
        "      pose: {position: [0.5, -0.25, 1.0], orientation: [0, 0, 0.3826834, 0.9238795]}\n");
    const Environment env = loadPlanningScene(scenePath);
    ASSERT_EQ(env.objectCount(), 2u);
    Eigen::Isometry3d pose = Eigen::Isometry3d::Identity();
    pose.translation() = Eigen::Vector3d(0.5, -0.25, 1.0);
    pose.linear() = Eigen::Quaterniond(0.9238795, 0, 0, 0.3826834).normalized().toRotationMatrix();
    std::mt19937 rng(5);
    std::uniform_real_distribution<double> u(-2.5, 3.0), r(0.0, 0.3);
    for (int k = 0; k < 2000; ++k)
    {
        const Eigen::Vector3d c(u(rng), u(rng), u(rng) + 1.0);
        const double radius = r(rng);
        double nearest = std::numeric_limits<double>::infinity();
        for (const auto &p : points)
            nearest = std::min(nearest, (pose * p.cast<double>() - c).norm() - radius - 0.02);
        const Eigen::Vector3d toBox = (c - Eigen::Vector3d(3, 0, 0)).cwiseAbs() - Eigen::Vector3d(0.25, 0.25, 0.05);
        const double box = toBox.cwiseMax(0.0).norm() + std::min(toBox.maxCoeff(), 0.0) - radius;
        ASSERT_NEAR(env.signedDistance(c, radius), std::min(nearest, box), 1e-5) << c.transpose();
    }
}

TEST(PointCloudFile, BadSceneEntriesNameTheSceneAndTheCloud)
{
    write("ok.pcd", pcd(randomPoints(4, 1), false));
    std::vector<Eigen::Vector3f> withNan = randomPoints(4, 2);
    withNan[1].x() = std::nanf("");
    write("nan_points.pcd", pcd(withNan, false));
    const auto sceneWith = [](const std::string &entry)
    { return write("bad_scene.yaml", "world:\n  point_clouds:\n    - " + entry + "\n"); };
    const std::vector<std::pair<std::string, std::vector<std::string>>> cases{
        {"{id: a, file: gone.pcd}", {"bad_scene.yaml:3", "'a'.file", "gone.pcd"}},
        {"{id: a}", {"bad_scene.yaml:3", "missing key 'file'"}},
        {"{file: ok.pcd}", {"missing key 'id'"}},
        {"{id: a, file: ok.pcd, point_radius: -1}", {"point_radius", "must be in [0, 1000]"}},
        {"{id: a, file: ok.pcd, point_radius: .nan}", {"point_radius", "not finite"}},
        {"{id: a, file: ok.pcd, drop_non_finite: maybe}", {"drop_non_finite", "true or false"}},
        {"{id: a, file: ok.pcd, pose: {position: [0, 0, 0], orientation: [0, 0, 0, 0]}}", {"zero quaternion"}},
        {"{id: a, file: nan_points.pcd}", {"'a'.file", "nan_points.pcd", "point 1", "drop_non_finite"}},
        {"[not, a, mapping]", {"expected a point cloud"}}};
    for (const auto &[entry, needles] : cases)
    {
        SCOPED_TRACE(entry);
        const std::string path = sceneWith(entry);
        expectErrorMentions([&] { loadPlanningScene(path); }, needles);
    }
    EXPECT_EQ(loadPlanningScene(sceneWith("{id: a, file: nan_points.pcd, drop_non_finite: true}")).objectCount(), 1u);
    const std::string duplicate =
        write("dup_scene.yaml",
              "world:\n  collision_objects:\n    - id: a\n      primitives: [{type: sphere, "
              "dimensions: [0.1]}]\n      primitive_poses: [{position: [0, 0, 0], orientation: [0, "
              "0, 0, 1]}]\n  point_clouds:\n    - {id: a, file: ok.pcd}\n");
    expectErrorMentions([&] { loadPlanningScene(duplicate); }, {"duplicate object id 'a'"});
}
