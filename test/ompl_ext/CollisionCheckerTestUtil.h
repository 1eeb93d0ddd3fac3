#ifndef ROPRAS_TEST_COLLISION_CHECKER_TEST_UTIL_H
#define ROPRAS_TEST_COLLISION_CHECKER_TEST_UTIL_H

// What the collision-checker tests share: the robots of ../shared, random configurations, the independent brute
// force (reference centres + Environment::signedDistance + self pairs), random clutter, the compiled backends, and
// a small arm with every joint type.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <memory>
#include <random>
#include <string>
#include <vector>

#include "SharedDir.h"
#include "ropras/ompl_ext/collision/CollisionChecker.h"
#include "ropras/ompl_ext/model/RobotModel.h"
#include "ropras/ompl_ext/scene/SceneYaml.h"

namespace ropras::test
{
    using namespace ropras::ompl_ext;

    inline std::shared_ptr<const RobotModel> loadRobot(const std::string &name)
    {
        return RobotModel::fromUrdfFile(SHARED + "/robots/" + name + "/" + name + "_spherized.urdf",
                                        SHARED + "/robots/" + name + "/" + name + ".srdf");
    }

    inline std::vector<double> randomConfig(const RobotModel &robot, std::mt19937_64 &rng)
    {
        std::vector<double> q(robot.dof());
        for (std::size_t j = 0; j < robot.dof(); ++j)
            q[j] = std::uniform_real_distribution<double>(robot.joints()[j].lower, robot.joints()[j].upper)(rng);
        return q;
    }

    /// independent brute force, obstacles only: min over every sphere of its signed distance to the environment
    /// (reference FK \a c, double precision)
    inline double referenceObstacleMargin(const RobotModel &robot, const Environment &env,
                                          const std::vector<Eigen::Vector3d> &c)
    {
        const auto &spheres = robot.spheres();
        double margin = std::numeric_limits<double>::infinity();
        for (std::size_t s = 0; s < spheres.size(); ++s)
            margin = std::min(margin, env.signedDistance(c[s], spheres[s].radius));
        return margin;
    }

    /// independent brute force: min over every sphere of its signed distance to the environment and over
    /// every self-collision sphere pair of their signed distance (reference FK, double precision)
    inline double referenceMargin(const RobotModel &robot, const Environment &env, const double *q)
    {
        const std::vector<Eigen::Vector3d> c = robot.sphereCentersReference(q);
        const auto &spheres = robot.spheres();
        double margin = referenceObstacleMargin(robot, env, c);
        const auto &links = robot.collisionLinks();
        for (const auto &pair : robot.selfCollisionPairs())
        {
            const CollisionLink &a = links[static_cast<std::size_t>(pair.first)];
            const CollisionLink &b = links[static_cast<std::size_t>(pair.second)];
            for (int i = a.firstSphere; i < a.firstSphere + a.sphereCount; ++i)
                for (int j = b.firstSphere; j < b.firstSphere + b.sphereCount; ++j)
                {
                    const auto si = static_cast<std::size_t>(i), sj = static_cast<std::size_t>(j);
                    margin = std::min(margin, (c[si] - c[sj]).norm() - spheres[si].radius - spheres[sj].radius);
                }
        }
        return margin;
    }

    inline Eigen::Isometry3d pose(const Eigen::Vector3d &t,
                                  const Eigen::Quaterniond &q = Eigen::Quaterniond::Identity())
    {
        Eigen::Isometry3d p = Eigen::Isometry3d::Identity();
        p.linear() = q.normalized().toRotationMatrix();
        p.translation() = t;
        return p;
    }

    /// random obstacles of every kind in the arm's reach
    inline Environment clutter(std::uint64_t seed)
    {
        std::mt19937_64 rng(seed);
        std::uniform_real_distribution<double> u(-1.0, 1.0);
        std::normal_distribution<double> n(0.0, 1.0);
        const auto where = [&] { return Eigen::Vector3d(0.8 * u(rng), 0.8 * u(rng), 0.5 + 0.5 * u(rng)); };
        const auto turn = [&] { return Eigen::Quaterniond(n(rng), n(rng), n(rng), n(rng)).normalized(); };
        Environment env;
        for (int i = 0; i < 3; ++i)
            env.addBox("box" + std::to_string(i), pose(where(), turn()),
                       {0.05 + 0.2 * std::abs(u(rng)), 0.05 + 0.2 * std::abs(u(rng)), 0.05 + 0.2 * std::abs(u(rng))});
        for (int i = 0; i < 2; ++i)
            env.addCylinder("cylinder" + std::to_string(i), pose(where(), turn()), 0.03 + 0.1 * std::abs(u(rng)),
                            0.1 + 0.3 * std::abs(u(rng)));
        for (int i = 0; i < 2; ++i)
            env.addSphere("sphere" + std::to_string(i), where(), 0.03 + 0.1 * std::abs(u(rng)));
        env.addCapsule("capsule", pose(where(), turn()), 0.05, 0.3);
        std::vector<Eigen::Vector3f> points;
        const Eigen::Vector3d c = where();
        for (int i = 0; i < 200; ++i)
            points.emplace_back((c + 0.15 * Eigen::Vector3d(u(rng), u(rng), u(rng))).cast<float>());
        env.addPointCloud("cloud", PointCloud::build(points, 0.01f));
        env.addBox("floor", pose({0, 0, -0.1}), {2.0, 2.0, 0.1});  // top at z = -0.05, below panda_link0
        return env;
    }

    inline std::vector<SimdBackend> backends()
    {
        std::vector<SimdBackend> b{SimdBackend::Scalar};
        if (simdBackendAvailable(SimdBackend::Avx2))
            b.push_back(SimdBackend::Avx2);
        return b;
    }

    inline void checkCenters(const std::string &robotName, std::uint64_t seed)
    {
        const auto robot = loadRobot(robotName);
        const std::size_t dof = robot->dof(), ns = robot->spheres().size();
        for (SimdBackend backend : backends())
        {
            CollisionChecker checker(robot, backend);
            const int w = checker.width();
            std::mt19937_64 rng(seed);
            std::vector<float> single(4 * ns), batch(4 * ns * static_cast<std::size_t>(w));
            std::vector<double> qs(dof * static_cast<std::size_t>(w));
            double worstSingle = 0.0, worstBatch = 0.0;
            const int configs = 10000;
            for (int k = 0; k < configs; k += w)
            {
                for (int i = 0; i < w; ++i)
                {
                    const auto q = randomConfig(*robot, rng);
                    std::copy(q.begin(), q.end(), qs.begin() + static_cast<std::ptrdiff_t>(i * dof));
                }
                checker.sphereCentersBatch(qs.data(), batch.data());
                for (int i = 0; i < w; ++i)
                {
                    const double *q = qs.data() + i * dof;
                    const auto ref = robot->sphereCentersReference(q);
                    checker.sphereCenters(q, single.data());
                    for (std::size_t s = 0; s < ns; ++s)
                    {
                        const Eigen::Vector3d a(single[4 * s], single[4 * s + 1], single[4 * s + 2]);
                        worstSingle = std::max(worstSingle, (a - ref[s]).norm());
                        const Eigen::Vector3d b(batch[(4 * s) * w + i], batch[(4 * s + 1) * w + i],
                                                batch[(4 * s + 2) * w + i]);
                        worstBatch = std::max(worstBatch, (b - ref[s]).norm());
                        ASSERT_FLOAT_EQ(single[4 * s + 3], static_cast<float>(robot->spheres()[s].radius));
                        ASSERT_FLOAT_EQ(batch[(4 * s + 3) * w + i], static_cast<float>(robot->spheres()[s].radius));
                    }
                }
            }
            EXPECT_LT(worstSingle, 1e-5) << robotName << " " << simdBackendName(backend);
            EXPECT_LT(worstBatch, 1e-5) << robotName << " " << simdBackendName(backend);
            EXPECT_GT(worstSingle, 0.0);  // the comparison really ran on float results
        }
    }

    struct VerdictStats
    {
        int valid{0}, invalid{0}, nearContact{0};
    };

    /// every backend's single and batch verdicts == brute force (except near contact)
    inline VerdictStats checkVerdicts(const std::shared_ptr<const RobotModel> &robot, const Environment &env,
                                      int configs, std::uint64_t seed)
    {
        VerdictStats stats;
        std::mt19937_64 rng(seed);
        const std::size_t dof = robot->dof();
        std::vector<double> qs;
        std::vector<double> margins;
        for (int k = 0; k < configs; ++k)
        {
            const auto q = randomConfig(*robot, rng);
            qs.insert(qs.end(), q.begin(), q.end());
            margins.push_back(referenceMargin(*robot, env, q.data()));
        }
        std::vector<std::unique_ptr<CollisionChecker>> checkers;
        for (SimdBackend b : backends())
            checkers.push_back(std::make_unique<CollisionChecker>(robot, b));
        std::vector<std::vector<char>> batchVerdicts;
        for (const auto &checker : checkers)
        {
            std::unique_ptr<bool[]> v(new bool[static_cast<std::size_t>(configs)]);
            const std::size_t nValid =
                checker->isValidBatch(env, qs.data(), static_cast<std::size_t>(configs), v.get());
            batchVerdicts.emplace_back(v.get(), v.get() + configs);
            EXPECT_EQ(nValid, static_cast<std::size_t>(std::count(v.get(), v.get() + configs, true)));
        }
        for (int k = 0; k < configs; ++k)
        {
            const double *q = qs.data() + static_cast<std::size_t>(k) * dof;
            const double margin = margins[static_cast<std::size_t>(k)];
            std::vector<bool> verdicts;
            for (std::size_t c = 0; c < checkers.size(); ++c)
            {
                verdicts.push_back(checkers[c]->isValid(env, q));
                verdicts.push_back(batchVerdicts[c][static_cast<std::size_t>(k)] != 0);
            }
            // backends agree with each other even near contact? not required (float rounding); with the truth:
            if (std::abs(margin) < 1e-4)
            {
                ++stats.nearContact;
                continue;
            }
            const bool truth = margin > 0.0;
            (truth ? stats.valid : stats.invalid) += 1;
            for (std::size_t v = 0; v < verdicts.size(); ++v)
                EXPECT_EQ(verdicts[v], truth) << "config " << k << " verdict " << v << " margin " << margin;
        }
        return stats;
    }

    /// a small arm with every joint type, skew axes and non-trivial origins (no ../shared needed)
    const char *const ALL_JOINTS_URDF = R"(<?xml version="1.0"?>
<robot name="all_joints">
  <link name="base"><collision><geometry><sphere radius="0.05"/></geometry></collision></link>
  <link name="a"><collision><origin xyz="0.1 0 0.05"/><geometry><sphere radius="0.04"/></geometry></collision>
                 <collision><origin xyz="0.2 0.01 0.05"/><geometry><sphere radius="0.03"/></geometry></collision></link>
  <link name="b"><collision><origin xyz="0 0.1 0"/><geometry><sphere radius="0.03"/></geometry></collision></link>
  <link name="c"><collision><origin xyz="0.05 0 0.02"/><geometry><sphere radius="0.02"/></geometry></collision>
                 <collision><origin xyz="0.1 0 0.02"/><geometry><sphere radius="0.02"/></geometry></collision></link>
  <link name="d"><collision><origin xyz="0 0 0.08"/><geometry><sphere radius="0.025"/></geometry></collision></link>
  <joint name="j_rev" type="revolute"><parent link="base"/><child link="a"/>
    <origin xyz="0 0 0.1" rpy="0.3 -0.2 0.1"/><axis xyz="0.2 0.3 0.9"/><limit lower="-2.5" upper="2.5" effort="1" velocity="1"/></joint>
  <joint name="j_pri" type="prismatic"><parent link="a"/><child link="b"/>
    <origin xyz="0.3 0 0" rpy="0 1.5707963267948966 0"/><axis xyz="1 -1 0.5"/><limit lower="-0.2" upper="0.4" effort="1" velocity="1"/></joint>
  <joint name="j_cont" type="continuous"><parent link="b"/><child link="c"/>
    <origin xyz="0 0.2 0" rpy="-0.4 0 0.7"/><axis xyz="0 1 0"/></joint>
  <joint name="j_fix" type="fixed"><parent link="c"/><child link="d"/><origin xyz="0.15 0 0" rpy="0 0 0.5"/></joint>
</robot>)";

}  // namespace ropras::test

#endif
