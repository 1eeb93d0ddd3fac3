#include <gtest/gtest.h>

#include "ExpectError.h"
#include "RobotModelTestUtil.h"

#include <algorithm>
#include <cmath>
#include <functional>
#include <set>

#include "ropras/core/Error.h"
#include "ropras/ompl_ext/model/RobotModel.h"

// Bad input to the robot model: options, files and numbers, each an error naming the file or the value.
using namespace ropras::test;
using ropras::Error;
using ropras::ompl_ext::JointType;

TEST(RobotModel, OptionErrors)
{
    const std::string urdf = testArmUrdf();
    auto load = [&](const RobotModel::Options &o) { RobotModel::fromUrdfString(urdf, ".", "arm-src.urdf", "", o); };
    RobotModel::Options unknown;
    unknown.planningJoints = {"a_first", "nope"};
    expectErrorMentions([&] { load(unknown); }, {"arm-src.urdf", "nope", "z_last, a_first, slide, b_elbow"});
    RobotModel::Options fixed;
    fixed.planningJoints = {"fix"};
    expectErrorMentions([&] { load(fixed); }, {"arm-src.urdf", "fix", "fixed"});
    RobotModel::Options twice;
    twice.planningJoints = {"slide", "slide"};
    expectErrorMentions([&] { load(twice); }, {"slide", "twice"});
    RobotModel::Options heldUnknown;
    heldUnknown.heldJointValues = {{"ghost", 0.0}};
    expectErrorMentions([&] { load(heldUnknown); }, {"arm-src.urdf", "ghost"});
    RobotModel::Options heldOut;
    heldOut.planningJoints = {"a_first"};
    heldOut.heldJointValues = {{"slide", 0.5}};
    expectErrorMentions([&] { load(heldOut); }, {"arm-src.urdf", "slide", "0.5", "outside"});
    RobotModel::Options heldNan;
    heldNan.planningJoints = {"a_first"};
    heldNan.heldJointValues = {{"z_last", std::nan("")}};
    expectErrorMentions([&] { load(heldNan); }, {"z_last"});
    RobotModel::Options heldPlanned;
    heldPlanned.heldJointValues = {{"slide", 0.0}};
    expectErrorMentions([&] { load(heldPlanned); }, {"slide", "planning joint"});
    RobotModel::Options badBase;
    badBase.basePose.linear() *= 2.0;
    expectErrorMentions([&] { load(badBase); }, {"arm-src.urdf", "basePose"});
    RobotModel::Options nanBase;
    nanBase.basePose.translation().x() = std::nan("");
    expectErrorMentions([&] { load(nanBase); }, {"basePose"});
}

TEST(RobotModel, BadFilesNameTheFile)
{
    expectErrorMentions([] { RobotModel::fromUrdfFile("/nonexistent/dir/robot.urdf"); },
                        {"/nonexistent/dir/robot.urdf", "not found"});

    const std::string malformed = writeTemp("malformed.urdf", "<robot name=\"x\"><link name=\"a\"></robot>");
    expectErrorMentions([&] { RobotModel::fromUrdfFile(malformed); }, {malformed, "malformed"});

    std::string floating = testArmUrdf();
    floating.replace(floating.find("type=\"revolute\""), 15, "type=\"floating\"");
    const std::string floatingPath = writeTemp("floating.urdf", floating);
    expectErrorMentions([&] { RobotModel::fromUrdfFile(floatingPath); }, {floatingPath, "a_first", "floating"});

    const std::string planar = writeTemp("planar.urdf", testArmUrdf("0.05", "planar"));
    expectErrorMentions([&] { RobotModel::fromUrdfFile(planar); }, {planar, "slide", "planar"});

    const std::string negative = writeTemp("negative.urdf", testArmUrdf("-0.05"));
    expectErrorMentions([&] { RobotModel::fromUrdfFile(negative); }, {negative, "base", "radius"});
    const std::string zero = writeTemp("zero.urdf", testArmUrdf("0"));
    expectErrorMentions([&] { RobotModel::fromUrdfFile(zero); }, {zero, "base", "radius"});
    const std::string nan = writeTemp("nanradius.urdf", testArmUrdf("nan"));
    expectErrorMentions([&] { RobotModel::fromUrdfFile(nan); }, {nan, "base", "radius", "nan"});
    std::string badBox =
        testArmUrdf("0.05", "prismatic", "<collision><geometry><box size=\"0.1 0.2\"/></geometry></collision>");
    const std::string badBoxPath = writeTemp("bad_box.urdf", badBox);
    expectErrorMentions([&] { RobotModel::fromUrdfFile(badBoxPath); }, {badBoxPath, "l2", "box size"});

    const std::string missingMesh = writeTemp(
        "missing_mesh.urdf",
        testArmUrdf(
            "0.05", "prismatic",
            "<collision><geometry><mesh filename=\"package://nopkg/meshes/gone.stl\"/></geometry></collision>"));
    expectErrorMentions([&] { RobotModel::fromUrdfFile(missingMesh); }, {missingMesh, "gone.stl", "not found"});

    const std::string good = writeTemp("good.urdf", testArmUrdf());
    const std::string srdfMissing = "/nonexistent/robot.srdf";
    expectErrorMentions([&] { RobotModel::fromUrdfFile(good, srdfMissing); }, {srdfMissing});
    const std::string badSrdf = writeTemp("bad.srdf", "<robot name=\"testarm\"><disable_collisions link1=\"l1\"");
    expectErrorMentions([&] { RobotModel::fromUrdfFile(good, badSrdf); }, {badSrdf, "malformed"});
    const std::string unknownLink = writeTemp(
        "unknown_link.srdf", "<robot name=\"testarm\"><disable_collisions link1=\"l1\" link2=\"elbow\"/></robot>");
    RobotModel::Options strict;
    strict.strict = true;  // MoveIt's warning is an error (the lenient default: OtherProjectFilesTest.cpp)
    expectErrorMentions([&] { RobotModel::fromUrdfFile(good, unknownLink, strict); }, {unknownLink, "elbow"});
    const std::string okSrdf =
        writeTemp("ok.srdf",
                  "<robot name=\"testarm\"><disable_collisions link1=\"base\" link2=\"l4\" reason=\"Never\"/></robot>");
    EXPECT_EQ(RobotModel::fromUrdfFile(good, okSrdf)->selfCollisionPairs().size(),
              RobotModel::fromUrdfFile(good)->selfCollisionPairs().size() - 1);

    // a URDF without a root element urdfdom accepts
    const std::string twoRoots =
        writeTemp("two_roots.urdf", "<robot name=\"r\"><link name=\"a\"/><link name=\"b\"/></robot>");
    expectErrorMentions([&] { RobotModel::fromUrdfFile(twoRoots); }, {twoRoots});
}

// numbers no robot has (limits of +-1e308 overflow the sampler's range, a 1e30 m sphere, offsets of 1e30 m) and
// a <mimic> naming a joint that does not exist are errors naming the joint or link; the limits themselves load
TEST(RobotModel, AbsurdNumbersAndUnknownMimicTargetsAreRejected)
{
    const auto arm =
        [](const std::string &limits, const std::string &geometry, const std::string &origin, const std::string &extra)
    {
        return "<robot name=\"r\"><link name=\"base\"/><link name=\"l1\"><collision><geometry>" + geometry +
               "</geometry></collision></link><link name=\"l2\"/>"
               "<joint name=\"j1\" type=\"revolute\"><parent link=\"base\"/><child link=\"l1\"/><origin xyz=\"" +
               origin + "\"/><axis xyz=\"0 0 1\"/><limit " + limits +
               " effort=\"1\" velocity=\"1\"/></joint><joint name=\"j2\" type=\"prismatic\"><parent link=\"l1\"/>"
               "<child link=\"l2\"/><axis xyz=\"1 0 0\"/><limit lower=\"0\" upper=\"0.5\" effort=\"1\" "
               "velocity=\"1\"/>" +
               extra + "</joint></robot>";
    };
    const std::string sphere = "<sphere radius=\"0.1\"/>";
    const std::string limits = "lower=\"-3\" upper=\"3\"";
    EXPECT_EQ(RobotModel::fromUrdfString(arm(limits, sphere, "0 0 0", ""), ".", "ok.urdf")->dof(), 2u);
    EXPECT_EQ(
        RobotModel::fromUrdfString(arm("lower=\"-100\" upper=\"100\"", sphere, "0 0 99", ""), ".", "edge.urdf")->dof(),
        2u);
    expectErrorMentions(
        [&]
        { RobotModel::fromUrdfString(arm("lower=\"-1e308\" upper=\"1e308\"", sphere, "0 0 0", ""), ".", "a.urdf"); },
        {"a.urdf", "joint 'j1'", "1e+308", "beyond +-100 rad"});
    expectErrorMentions(
        [&] { RobotModel::fromUrdfString(arm("lower=\"0\" upper=\"101\"", sphere, "0 0 0", ""), ".", "b.urdf"); },
        {"b.urdf", "joint 'j1'", "101"});
    expectErrorMentions(
        [&] { RobotModel::fromUrdfString(arm(limits, "<sphere radius=\"1e30\"/>", "0 0 0", ""), ".", "c.urdf"); },
        {"c.urdf", "link 'l1'", "sphere radius", "1e+30"});
    expectErrorMentions(
        [&] { RobotModel::fromUrdfString(arm(limits, "<box size=\"1 1e30 1\"/>", "0 0 0", ""), ".", "d.urdf"); },
        {"d.urdf", "link 'l1'", "box size"});
    expectErrorMentions([&] { RobotModel::fromUrdfString(arm(limits, sphere, "1e30 0 0", ""), ".", "e.urdf"); },
                        {"e.urdf", "joint 'j1' <origin>", "1e+30"});
    expectErrorMentions(
        [&] { RobotModel::fromUrdfString(arm(limits, sphere, "0 0 0", "<mimic joint=\"jl\"/>"), ".", "f.urdf"); },
        {"f.urdf", "joint 'j2' mimics joint 'jl', which the URDF does not have"});
    expectErrorMentions(
        [&] { RobotModel::fromUrdfString(arm(limits, sphere, "0 0 0", "<mimic joint=\"j2\"/>"), ".", "g.urdf"); },
        {"g.urdf", "joint 'j2' mimics itself"});
    // a special file is not "not found"
    expectErrorMentions([] { RobotModel::fromUrdfFile("/dev/null"); }, {"/dev/null", "not a regular file"});
    expectErrorMentions([] { RobotModel::fromUrdfFile("/tmp"); }, {"/tmp", "not a regular file"});
}
