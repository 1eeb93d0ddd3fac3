// Files from other projects accepted as MoveIt accepts them (issue 16, item 4): SRDF names the URDF lacks, SRDF
// groups, request joints the robot lacks, values just outside a limit; and every MotionBenchMaker robot and
// problem in ../shared loads.
#include <gtest/gtest.h>
#include <kdl_parser/kdl_parser.hpp>

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <set>
#include <sstream>

#include "ExpectError.h"
#include "ropras/core/Error.h"
#include "ropras/ompl_ext/collision/CollisionChecker.h"
#include "ropras/ompl_ext/model/RobotModel.h"
#include "ropras/ompl_ext/scene/SceneYaml.h"

using namespace ropras::ompl_ext;
using ropras::test::expectErrorMentions;
namespace fs = std::filesystem;

namespace
{
    constexpr double PI = 3.14159265358979323846;

    /** A torso on a prismatic joint carrying two arms (left: two revolute joints; right: a revolute and a continuous
        one) and a head, each link with a sphere; fixed tips. */
    std::string twoArmUrdf()
    {
        std::ostringstream u;
        u << "<robot name=\"twoarm\">\n";
        const auto link = [&](const std::string &name)
        {
            u << "<link name=\"" << name << "\"><collision><geometry><sphere radius=\"0.03\"/></geometry>"
              << "</collision></link>\n";
        };
        const auto joint = [&](const std::string &name, const std::string &type, const std::string &parent,
                               const std::string &child, const std::string &xyz, const std::string &limit)
        {
            u << "<joint name=\"" << name << "\" type=\"" << type << "\"><parent link=\"" << parent
              << "\"/><child link=\"" << child << "\"/><origin xyz=\"" << xyz << "\"/><axis xyz=\"0 0 1\"/>" << limit
              << "</joint>\n";
        };
        const std::string revolute = "<limit lower=\"-3.14159\" upper=\"3.14159\" effort=\"1\" velocity=\"1\"/>";
        for (const char *name : {"base", "torso", "l1", "l2", "ltip", "r1", "r2", "rtip", "head"})
            link(name);
        joint("torso_joint", "prismatic", "base", "torso", "0 0 0.5",
              "<limit lower=\"0\" upper=\"0.4\" effort=\"1\" velocity=\"1\"/>");
        joint("l1_joint", "revolute", "torso", "l1", "0 0.3 0", revolute);
        joint("l2_joint", "revolute", "l1", "l2", "0.3 0 0", revolute);
        joint("ltip_joint", "fixed", "l2", "ltip", "0.3 0 0", "");
        joint("r1_joint", "revolute", "torso", "r1", "0 -0.3 0", revolute);
        joint("r2_joint", "continuous", "r1", "r2", "0.3 0 0", "");
        joint("rtip_joint", "fixed", "r2", "rtip", "0.3 0 0", "");
        joint("head_joint", "revolute", "torso", "head", "0 0 0.4", revolute);
        u << "</robot>\n";
        return u.str();
    }

    std::string srdf(const std::string &body)
    {
        return "<?xml version=\"1.0\"?>\n<robot name=\"twoarm\">\n" + body + "</robot>\n";
    }

    std::shared_ptr<const RobotModel> twoArm(const std::string &srdfBody,
                                             const RobotModel::Options &options = RobotModel::Options())
    {
        return RobotModel::fromUrdfString(twoArmUrdf(), ".", "twoarm.urdf", srdf(srdfBody), options);
    }

    bool mentions(const std::vector<std::string> &messages, const std::vector<std::string> &needles)
    {
        return std::any_of(messages.begin(), messages.end(),
                           [&](const std::string &m)
                           {
                               return std::all_of(needles.begin(), needles.end(),
                                                  [&](const std::string &n) { return m.find(n) != std::string::npos; });
                           });
    }

    std::string jointNames(const RobotModel &m)
    {
        std::string out;
        for (const PlanningJoint &j : m.joints())
            out += (out.empty() ? "" : " ") + j.name;
        return out;
    }
}  // namespace

TEST(OtherProjectFiles, SrdfUnknownLinksAreWarningsNamingFileAndLineUnlessStrict)
{
    // line 3: a link of another variant of the robot; line 4: a pair the URDF has
    const std::string body =
        "<disable_collisions link1=\"torso\" link2=\"bellows_link2\" reason=\"Never\"/>\n"
        "<disable_collisions link1=\"l1\" link2=\"head\" reason=\"Never\"/>\n";
    const auto m = twoArm(body);
    EXPECT_TRUE(mentions(m->warnings(), {"twoarm.urdf (SRDF)", "on line 3 names link", "bellows_link2", "skipped"}))
        << (m->warnings().empty() ? "no warning" : m->warnings().front());
    EXPECT_EQ(m->selfCollisionPairs().size(), twoArm("")->selfCollisionPairs().size() - 1);  // line 4 applies
    RobotModel::Options strict;
    strict.strict = true;
    expectErrorMentions([&] { twoArm(body, strict); }, {"twoarm.urdf (SRDF)", "line 3", "bellows_link2"});
}

TEST(OtherProjectFiles, GroupsResolveJointsLinksChainsAndSubgroupsAsMoveItDoes)
{
    const std::string body =
        "<group name=\"left\"><chain base_link=\"torso\" tip_link=\"ltip\"/></group>\n"
        "<group name=\"right\"><link name=\"r1\"/><link name=\"r2\"/><link name=\"rtip\"/></group>\n"
        "<group name=\"arms\"><group name=\"left\"/><group name=\"right\"/></group>\n"
        "<group name=\"tips\"><chain base_link=\"ltip\" tip_link=\"rtip\"/></group>\n"
        "<group name=\"torso_head\"><joint name=\"head_joint\"/><joint name=\"torso_joint\"/>"
        "</group>\n<group name=\"eef\"><link name=\"ltip\"/></group>\n";
    const auto m = twoArm(body);
    EXPECT_TRUE(m->warnings().empty());
    const std::map<std::string, std::vector<std::string>> expected{
        {"left", {"l1_joint", "l2_joint"}},
        {"right", {"r1_joint", "r2_joint"}},  // rtip's parent joint is fixed
        {"arms", {"l1_joint", "l2_joint", "r1_joint", "r2_joint"}},
        {"tips", {"l1_joint", "l2_joint", "r1_joint", "r2_joint"}},  // up to the torso and down: not torso_joint
        {"torso_head", {"torso_joint", "head_joint"}},               // URDF order, not the SRDF's
        {"eef", {}}};
    EXPECT_EQ(m->groups(), expected);
    EXPECT_EQ(m->dof(), 6u);  // no group chosen: every movable joint

    RobotModel::Options arms;
    arms.group = "arms";
    const auto planned = twoArm(body, arms);
    EXPECT_EQ(jointNames(*planned), "l1_joint l2_joint r1_joint r2_joint");
    EXPECT_EQ(planned->group(), "arms");

    RobotModel::Options fromRequest;  // a request's group_name, when the SRDF defines it
    fromRequest.requestGroup = "left";
    EXPECT_EQ(jointNames(*twoArm(body, fromRequest)), "l1_joint l2_joint");
    fromRequest.requestGroup = "manipulator";  // not defined: every movable joint, as without a group
    EXPECT_EQ(twoArm(body, fromRequest)->dof(), 6u);

    RobotModel::Options eef;
    eef.group = "eef";
    expectErrorMentions([&] { twoArm(body, eef); }, {"planning group 'eef'", "no movable joint"});
    RobotModel::Options unknown;
    unknown.group = "torso";
    expectErrorMentions([&] { twoArm(body, unknown); }, {"no group 'torso'", "left, right, arms, tips"});
    RobotModel::Options both = arms;
    both.planningJoints = {"l1_joint"};
    expectErrorMentions([&] { twoArm(body, both); }, {"not both"});
    expectErrorMentions([&] { RobotModel::fromUrdfString(twoArmUrdf(), ".", "twoarm.urdf", "", arms); },
                        {"needs an SRDF", "no SRDF given"});
}

TEST(OtherProjectFiles, BadGroupsAreSkippedWithAWarningOrRefusedWhenStrictOrChosen)
{
    const std::string body =
        "<group name=\"left\"><joint name=\"l1_joint\"/></group>\n"
        "<group name=\"ghost\"><link name=\"bellows_link\"/></group>\n"
        "<group name=\"loop_a\"><group name=\"loop_b\"/></group>\n"
        "<group name=\"loop_b\"><group name=\"loop_a\"/></group>\n"
        "<group name=\"orphan\"><group name=\"missing\"/></group>\n"
        "<group name=\"odd\"><joint name=\"l2_joint\"/><passive_joint name=\"x\"/></group>\n";
    const auto m = twoArm(body);
    EXPECT_EQ(m->groups().count("left"), 1u);
    EXPECT_EQ(m->groups().count("odd"), 1u);  // srdfdom skips members it does not know
    for (const char *bad : {"ghost", "loop_a", "loop_b", "orphan"})
        EXPECT_EQ(m->groups().count(bad), 0u) << bad;
    EXPECT_TRUE(mentions(m->warnings(), {"line 4", "group 'ghost'", "bellows_link", "skipped"}));
    EXPECT_TRUE(mentions(m->warnings(), {"group 'loop_a'", "contains itself"}));
    EXPECT_TRUE(mentions(m->warnings(), {"no group 'missing'", "subgroup of 'orphan'"}));
    EXPECT_TRUE(mentions(m->warnings(), {"line 8", "<passive_joint>", "skipped"}));
    RobotModel::Options strict;
    strict.strict = true;
    expectErrorMentions([&] { twoArm(body, strict); }, {"group 'ghost'", "bellows_link"});
    RobotModel::Options chosen;
    chosen.group = "ghost";
    expectErrorMentions([&] { twoArm(body, chosen); }, {"group 'ghost'", "bellows_link"});
    expectErrorMentions([&] { twoArm("<group name=\"a\"/><group name=\"a\"/>"); }, {"line 3", "defined twice"});
    expectErrorMentions([&] { twoArm("<group name=\"a\"><chain base_link=\"torso\"/></group>"); },
                        {"<chain>", "tip_link"});
}

TEST(OtherProjectFiles, HeldJointsTakeTheRequestStartState)
{
    RobotModel::Options o;
    o.planningJoints = {"l1_joint", "l2_joint"};
    o.jointState = {{"torso_joint", 0.25}, {"head_joint", 0.5},
                    {"r2_joint", 4.0},     {"l1_joint", 1.0},  // planned: ignored here
                    {"r1_joint", 3.14160},                     // 1e-5 past the limit: clamped
                    {"wheel_joint", 1.0}};                     // not in the URDF: ignored with a warning
    const auto m = twoArm("", o);
    std::map<std::string, double> held;
    for (const UrdfJoint &j : m->urdfJoints())
        if (j.type != JointType::Fixed && j.variable < 0)
            held[j.name] = j.heldValue;
    EXPECT_DOUBLE_EQ(held.at("torso_joint"), 0.25);
    EXPECT_DOUBLE_EQ(held.at("head_joint"), 0.5);
    EXPECT_DOUBLE_EQ(held.at("r1_joint"), 3.14159);
    EXPECT_NEAR(held.at("r2_joint"), 4.0 - 2 * PI, 1e-12);  // continuous: wrapped into [-pi, pi]
    EXPECT_TRUE(mentions(m->warnings(), {"wheel_joint", "ignored"}));
    EXPECT_TRUE(mentions(m->warnings(), {"r1_joint", "clamped to 3.14159"}));
    // the same configuration: the held torso lifts the head's sphere by 0.25 m
    const auto origin = RobotModel::fromUrdfString(twoArmUrdf(), ".", "twoarm.urdf", "",
                                                   []
                                                   {
                                                       RobotModel::Options p;
                                                       p.planningJoints = {"l1_joint", "l2_joint"};
                                                       return p;
                                                   }());
    const double q[2] = {0.1, 0.2};
    const int head = m->linkIndex("head");
    EXPECT_NEAR(
        (m->linkTransformsReference(q)[head].translation() - origin->linkTransformsReference(q)[head].translation())
            .z(),
        0.25, 1e-12);

    o.jointState["torso_joint"] = 0.5;  // far outside [0, 0.4]
    expectErrorMentions([&] { twoArm("", o); }, {"torso_joint", "0.5", "outside its limits"});
    o.jointState["torso_joint"] = 0.25;
    o.jointState["r1_joint"] = 3.0;  // strict does not clamp
    o.strict = true;
    expectErrorMentions([&] { twoArm("", o); }, {"wheel_joint"});
}

TEST(OtherProjectFiles, RequestValuesIgnoreUnknownJointsAndClampWithinTheTolerance)
{
    const auto m = twoArm("");
    const std::map<std::string, double> request{
        {"torso_joint", 0.40005}, {"l1_joint", -3.1415926536}, {"l2_joint", 0.5},      {"r1_joint", 3.2},
        {"r2_joint", -3.5},       {"head_joint", 0.0},         {"l_wheel_joint", 1.0}, {"r_wheel_joint", 2.0}};
    std::vector<std::string> warnings;
    const std::vector<double> q = m->planningValues(request, "req.yaml: goal", &warnings);
    ASSERT_EQ(q.size(), 6u);
    EXPECT_DOUBLE_EQ(q[0], 0.4);       // 5e-5 m past the limit: clamped
    EXPECT_DOUBLE_EQ(q[1], -3.14159);  // pi rounded up, 2.65e-6 past the limit: clamped
    EXPECT_DOUBLE_EQ(q[2], 0.5);
    EXPECT_DOUBLE_EQ(q[3], 3.2);              // 0.058 past: left for the validity check to refuse
    EXPECT_NEAR(q[4], -3.5 + 2 * PI, 1e-12);  // continuous: wrapped
    EXPECT_TRUE(mentions(warnings, {"req.yaml: goal", "l_wheel_joint, r_wheel_joint", "ignored"}));
    EXPECT_TRUE(mentions(warnings, {"req.yaml: goal", "torso_joint", "clamped to 0.4"}));
    EXPECT_FALSE(mentions(warnings, {"r1_joint"}));
    EXPECT_FALSE(m->withinBounds(q.data()));
    const CollisionChecker checker(m);
    Environment empty;
    EXPECT_FALSE(checker.isValid(empty, q.data()));

    RobotModel::Options loose;
    loose.limitTolerance = 0.1;
    EXPECT_DOUBLE_EQ(twoArm("", loose)->planningValues(request, "req")[3], 3.14159);
    RobotModel::Options bad;
    bad.limitTolerance = std::nan("");
    expectErrorMentions([&] { twoArm("", bad); }, {"limitTolerance", "nan"});
    RobotModel::Options strict;
    strict.strict = true;
    expectErrorMentions([&] { twoArm("", strict)->planningValues(request, "req.yaml: goal"); },
                        {"req.yaml: goal", "l_wheel_joint"});
    std::map<std::string, double> known = request;
    known.erase("l_wheel_joint");
    known.erase("r_wheel_joint");
    EXPECT_EQ(twoArm("", strict)->planningValues(known, "req")[0], 0.40005);  // strict: no clamping
    known.erase("l2_joint");
    expectErrorMentions([&] { m->planningValues(known, "req.yaml: goal"); }, {"req.yaml: goal", "l2_joint"});
}

TEST(OtherProjectFiles, ChainGroupsMatchKdlChains)
{
    // independent reference: KDL's tree walk between the same two links (its segments' movable joints)
    const std::string urdf = twoArmUrdf();
    KDL::Tree tree;
    ASSERT_TRUE(kdl_parser::treeFromString(urdf, tree));
    for (const auto &[base, tip] : std::vector<std::pair<std::string, std::string>>{
             {"base", "ltip"}, {"torso", "rtip"}, {"l1", "l2"}, {"base", "head"}, {"base", "base"}})
    {
        const auto m =
            twoArm("<group name=\"g\"><chain base_link=\"" + base + "\" tip_link=\"" + tip + "\"/></group>\n");
        KDL::Chain chain;
        ASSERT_TRUE(tree.getChain(base, tip, chain)) << base << " -> " << tip;
        std::set<std::string> kdl;
        for (const KDL::Segment &s : chain.segments)
            if (s.getJoint().getType() != KDL::Joint::None)
                kdl.insert(s.getJoint().getName());
        const std::vector<std::string> &ours = m->groups().at("g");
        EXPECT_EQ(std::set<std::string>(ours.begin(), ours.end()), kdl) << base << " -> " << tip;
    }
}

namespace
{
    /// robot folders to test: ../shared/robots/* and, for local runs, ROPRAS_MBM_RESOURCES (a folder laid out the same)
    std::vector<fs::path> resourceRoots()
    {
        std::vector<fs::path> roots;
        if (fs::is_directory(fs::path(ROPRAS_SHARED_DIR) / "robots"))
            roots.emplace_back(ROPRAS_SHARED_DIR);
        if (const char *extra = std::getenv("ROPRAS_MBM_RESOURCES"); extra && fs::is_directory(extra))
            roots.emplace_back(extra);
        return roots;
    }
}  // namespace

// "Every MotionBenchMaker file from another robot's resources that MoveIt loads, ropras loads": each robot's
// spherized URDF with its SRDF, then each problem (scene + request) with the request's group, start and goal.
TEST(OtherProjectFiles, EveryMotionBenchMakerRobotAndProblemLoads)
{
    const std::vector<fs::path> roots = resourceRoots();
    if (roots.empty())
        GTEST_SKIP() << ROPRAS_SHARED_DIR << "/robots not found: the MotionBenchMaker files are not available";
    std::size_t robots = 0, problems = 0;
    for (const fs::path &root : roots)
        for (const auto &entry : fs::directory_iterator(root / "robots"))
        {
            const std::string name = entry.path().filename().string();
            const fs::path urdf = entry.path() / (name + "_spherized.urdf"), srdfPath = entry.path() / (name + ".srdf");
            fs::path mbm = root / "mbm" / name;
            if (fs::is_directory(mbm / "problems"))
                mbm /= "problems";  // the layout of VAMP's problems.tar.bz2
            if (!fs::exists(urdf) || !fs::exists(srdfPath) || !fs::is_directory(mbm))
                continue;
            std::vector<fs::path> requests;
            for (const auto &file : fs::recursive_directory_iterator(mbm))
                if (file.path().filename().string().rfind("request", 0) == 0)
                    requests.push_back(file.path());
            std::sort(requests.begin(), requests.end());
            ASSERT_FALSE(requests.empty()) << mbm;
            const MotionPlanRequest first = loadMotionPlanRequest(requests.front().string());
            RobotModel::Options options;
            options.requestGroup = first.group;
            options.jointState = first.start;
            std::shared_ptr<const RobotModel> robot;
            ASSERT_NO_THROW(robot = RobotModel::fromUrdfFile(urdf.string(), srdfPath.string(), options)) << urdf;
            EXPECT_EQ(robot->group(), first.group) << urdf;
            ++robots;
            for (const fs::path &request : requests)
            {
                const std::string number = request.stem().string().substr(7);
                const fs::path scene = request.parent_path() / ("scene" + number + ".yaml");
                SCOPED_TRACE(request.string());
                ASSERT_NO_THROW(loadPlanningScene(scene.string()));
                const MotionPlanRequest r = loadMotionPlanRequest(request.string());
                EXPECT_EQ(r.group, first.group);
                std::vector<double> start, goal;
                ASSERT_NO_THROW(start = robot->planningValues(r.start, "start", nullptr));
                ASSERT_NO_THROW(goal = robot->planningValues(r.goal, "goal", nullptr));
                EXPECT_TRUE(robot->withinBounds(start.data()));
                EXPECT_TRUE(robot->withinBounds(goal.data()));
                ++problems;
            }
            std::cout << name << ": " << robot->dof() << " joints (group " << robot->group() << "), " << requests.size()
                      << " problems load\n";
        }
    if (robots == 0)
        GTEST_SKIP() << "no robot with <name>_spherized.urdf, <name>.srdf and mbm/<name> under the resource folders";
    EXPECT_GT(problems, 0u);
}
