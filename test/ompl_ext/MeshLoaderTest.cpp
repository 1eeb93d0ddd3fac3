#include <gtest/gtest.h>

#include "ExpectError.h"

#include <filesystem>
#include <fstream>
#include <functional>

#include "ropras/core/Error.h"
#include "ropras/ompl_ext/model/MeshLoader.h"

namespace
{
    namespace fs = std::filesystem;
    using ropras::Error;
    using ropras::ompl_ext::loadMesh;
    using ropras::ompl_ext::resolveMeshPath;

    const std::string SHARED = ROPRAS_SHARED_DIR;

    fs::path tempDir()
    {
        const fs::path dir = fs::path(testing::TempDir()) / "ropras_mesh_loader_test";
        fs::create_directories(dir);
        return dir;
    }

    std::string write(const fs::path &p, const std::string &text)
    {
        fs::create_directories(p.parent_path());
        std::ofstream(p) << text;
        return p.string();
    }

    const char *CUBE_OBJ = R"(# unit cube, 8 vertices, 6 quads
v -0.5 -0.5 -0.5
v 0.5 -0.5 -0.5
v 0.5 0.5 -0.5
v -0.5 0.5 -0.5
v -0.5 -0.5 0.5
v 0.5 -0.5 0.5
v 0.5 0.5 0.5
v -0.5 0.5 0.5
f 1 4 3 2
f 5 6 7 8
f 1 2 6 5
f 2 3 7 6
f 3 4 8 7
f 4 1 5 8
)";

    using ropras::test::expectErrorMentions;
}  // namespace

TEST(MeshLoader, ObjQuadsTriangulatedAndScaled)
{
    const std::string path = write(tempDir() / "cube.obj", CUBE_OBJ);
    const auto mesh = loadMesh(path, Eigen::Vector3d(2.0, 3.0, 4.0));
    EXPECT_EQ(mesh.triangles.size(), 12u);
    Eigen::Vector3d lo = Eigen::Vector3d::Constant(1e9), hi = -lo;
    for (const auto &t : mesh.triangles)
    {
        for (int k = 0; k < 3; ++k)
        {
            ASSERT_GE(t[k], 0);
            ASSERT_LT(t[k], static_cast<int>(mesh.vertices.size()));
            lo = lo.cwiseMin(mesh.vertices[t[k]]);
            hi = hi.cwiseMax(mesh.vertices[t[k]]);
        }
    }
    EXPECT_TRUE(lo.isApprox(Eigen::Vector3d(-1.0, -1.5, -2.0), 1e-12));
    EXPECT_TRUE(hi.isApprox(Eigen::Vector3d(1.0, 1.5, 2.0), 1e-12));
}

TEST(MeshLoader, AsciiStlAndZUpCollada)
{
    const std::string stl = write(tempDir() / "tri.stl", R"(solid t
facet normal 0 0 1
 outer loop
  vertex 0 0 0
  vertex 1 0 0
  vertex 0 1 0.5
 endloop
endfacet
endsolid t
)");
    const auto a = loadMesh(stl);
    ASSERT_EQ(a.triangles.size(), 1u);
    EXPECT_NEAR(a.vertices[a.triangles[0][2]].z(), 0.5, 1e-6);

    // A Z-up COLLADA triangle stays as authored (URDF convention), not rotated to Y-up.
    const std::string dae = write(tempDir() / "tri.dae", R"(<?xml version="1.0" encoding="utf-8"?>
<COLLADA xmlns="http://www.collada.org/2005/11/COLLADASchema" version="1.4.1">
  <asset><unit name="meter" meter="1"/><up_axis>Z_UP</up_axis></asset>
  <library_geometries>
    <geometry id="g" name="g"><mesh>
      <source id="p"><float_array id="pa" count="9">0 0 0 1 0 0 0 0 2</float_array>
        <technique_common><accessor source="#pa" count="3" stride="3">
          <param name="X" type="float"/><param name="Y" type="float"/><param name="Z" type="float"/>
        </accessor></technique_common></source>
      <vertices id="v"><input semantic="POSITION" source="#p"/></vertices>
      <triangles count="1"><input semantic="VERTEX" source="#v" offset="0"/><p>0 1 2</p></triangles>
    </mesh></geometry>
  </library_geometries>
  <library_visual_scenes><visual_scene id="s"><node id="n"><instance_geometry url="#g"/></node></visual_scene>
  </library_visual_scenes>
  <scene><instance_visual_scene url="#s"/></scene>
</COLLADA>
)");
    const auto b = loadMesh(dae);
    ASSERT_EQ(b.triangles.size(), 1u);
    double maxZ = -1e9;
    for (const auto &v : b.vertices)
    {
        maxZ = std::max(maxZ, v.z());
    }
    EXPECT_NEAR(maxZ, 2.0, 1e-6);
}

TEST(MeshLoader, SharedRobotMeshes)
{
    if (!fs::is_directory(SHARED + "/robots"))
    {
        GTEST_SKIP() << "../shared not found: " << SHARED;
    }
    const auto obj = loadMesh(SHARED + "/robots/panda/meshes/collision/link0.obj");
    EXPECT_EQ(obj.triangles.size(), 200u);
    const auto stl = loadMesh(SHARED + "/robots/ur5/meshes/ur5/collision/base.stl");
    EXPECT_EQ(stl.triangles.size(), (28984u - 84u) / 50u);  // binary STL: 50 bytes per triangle
}

TEST(MeshLoader, BadMeshFiles)
{
    expectErrorMentions([] { loadMesh("/nonexistent/m.obj"); }, {"/nonexistent/m.obj", "not found"});
    const std::string garbage = write(tempDir() / "garbage.stl", "this is not a mesh\n\x01\x02");
    expectErrorMentions([&] { loadMesh(garbage); }, {garbage});
    const std::string noFaces = write(tempDir() / "points.obj", "v 0 0 0\nv 1 0 0\n");
    expectErrorMentions([&] { loadMesh(noFaces); }, {noFaces});
    const std::string cube = write(tempDir() / "cube2.obj", CUBE_OBJ);
    expectErrorMentions([&] { loadMesh(cube, Eigen::Vector3d(1.0, 0.0, 1.0)); }, {cube, "scale"});
}

TEST(MeshLoader, ResolvePackageRelativeAndAbsolute)
{
    // layout: root/mypkg/meshes/part.obj, root/mypkg/urdf/robot.urdf, root/robot2/meshes/x.obj
    const fs::path root = tempDir() / "resolve";
    const std::string part = write(root / "mypkg" / "meshes" / "part.obj", CUBE_OBJ);
    const std::string x = write(root / "robot2" / "meshes" / "x.obj", CUBE_OBJ);
    const std::string urdfDir = (root / "mypkg" / "urdf").string();
    fs::create_directories(urdfDir);
    const std::string partCanonical = fs::canonical(part).string();

    // package://pkg/rest found by walking up from the URDF folder
    EXPECT_EQ(resolveMeshPath("package://mypkg/meshes/part.obj", urdfDir, "robot.urdf"), partCanonical);
    // relative to a parent folder of the URDF
    EXPECT_EQ(resolveMeshPath("meshes/part.obj", urdfDir, "robot.urdf"), partCanonical);
    EXPECT_EQ(resolveMeshPath("../meshes/part.obj", urdfDir, "robot.urdf"), partCanonical);
    // package named like the folder holding the URDF
    EXPECT_EQ(resolveMeshPath("package://robot2/meshes/x.obj", (root / "robot2").string(), "r2.urdf"),
              fs::canonical(x).string());
    // absolute and file://
    EXPECT_EQ(resolveMeshPath(partCanonical, "/", "robot.urdf"), partCanonical);
    EXPECT_EQ(resolveMeshPath("file://" + partCanonical, "/", "robot.urdf"), partCanonical);

    expectErrorMentions([&] { resolveMeshPath("package://mypkg/meshes/none.obj", urdfDir, "robot.urdf"); },
                        {"robot.urdf", "package://mypkg/meshes/none.obj", "not found"});
    expectErrorMentions([&] { resolveMeshPath("file:///no/such.obj", urdfDir, "robot.urdf"); },
                        {"robot.urdf", "/no/such.obj"});
    expectErrorMentions([&] { resolveMeshPath("package://nopath", urdfDir, "robot.urdf"); }, {"robot.urdf"});
    expectErrorMentions([&] { resolveMeshPath("", urdfDir, "robot.urdf"); }, {"robot.urdf"});

    if (fs::is_directory(SHARED + "/robots"))
    {
        // the shared robots: package://meshes/... next to the URDF
        const std::string p =
            resolveMeshPath("package://meshes/collision/link0.obj", SHARED + "/robots/panda", "panda.urdf");
        EXPECT_TRUE(fs::is_regular_file(p));
        EXPECT_EQ(fs::path(p).filename(), "link0.obj");
    }
}
