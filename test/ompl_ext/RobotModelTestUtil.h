#ifndef ROPRAS_TEST_ROBOT_MODEL_TEST_UTIL_H
#define ROPRAS_TEST_ROBOT_MODEL_TEST_UTIL_H

// What the robot-model tests share: the reference data's location, the compiled frames evaluated independently,
// random configurations, temporary files and a small URDF with every joint type.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <random>
#include <string>
#include <vector>

#include "SharedDir.h"
#include "ropras/ompl_ext/model/RobotModel.h"

namespace ropras::test
{
    using ompl_ext::JointMotion;
    using ompl_ext::RobotModel;
    namespace fs = std::filesystem;

    /// World pose of every compiled frame, evaluated in double exactly as the header specifies:
    /// T = T_parent * offset * Motion(q[variable]); independent of linkTransformsReference.
    inline std::vector<Eigen::Isometry3d> compiledFrames(const RobotModel &m, const std::vector<double> &q)
    {
        std::vector<Eigen::Isometry3d> t(m.frames().size());
        for (std::size_t f = 0; f < m.frames().size(); ++f)
        {
            const auto &fr = m.frames()[f];
            Eigen::Isometry3d motion = Eigen::Isometry3d::Identity();
            if (fr.motion == JointMotion::RotateZ)
            {
                motion.linear() = Eigen::AngleAxisd(q[fr.variable], Eigen::Vector3d::UnitZ()).toRotationMatrix();
            }
            else if (fr.motion == JointMotion::TranslateZ)
            {
                motion.translation() = Eigen::Vector3d(0, 0, q[fr.variable]);
            }
            const Eigen::Isometry3d parent = fr.parent < 0 ? Eigen::Isometry3d::Identity() : t[fr.parent];
            t[f] = parent * fr.offset * motion;
        }
        return t;
    }

    inline std::vector<double> randomQ(const RobotModel &m, std::mt19937 &rng)
    {
        std::vector<double> q(m.dof());
        for (std::size_t i = 0; i < m.dof(); ++i)
        {
            std::uniform_real_distribution<double> u(m.joints()[i].lower, m.joints()[i].upper);
            q[i] = u(rng);
        }
        return q;
    }

    /// compiled frames vs reference FK for links and spheres over n random configurations
    inline void expectCompiledMatchesReference(const RobotModel &m, int n, unsigned seed)
    {
        std::mt19937 rng(seed);
        double worst = 0.0;
        for (int s = 0; s < n; ++s)
        {
            const std::vector<double> q = randomQ(m, rng);
            const auto frames = compiledFrames(m, q);
            const auto links = m.linkTransformsReference(q.data());
            const auto centers = m.sphereCentersReference(q.data());
            ASSERT_EQ(links.size(), m.links().size());
            ASSERT_EQ(centers.size(), m.spheres().size());
            for (std::size_t l = 0; l < m.links().size(); ++l)
            {
                const Eigen::Isometry3d viaFrame = frames[m.links()[l].frame] * m.links()[l].inFrame;
                worst = std::max(worst, (viaFrame.matrix() - links[l].matrix()).cwiseAbs().maxCoeff());
            }
            for (std::size_t i = 0; i < m.spheres().size(); ++i)
            {
                const auto &sp = m.spheres()[i];
                const auto &cl = m.collisionLinks()[sp.collisionLink];
                const Eigen::Vector3d c = frames[cl.frame] * sp.centerInFrame;
                worst = std::max(worst, (c - centers[i]).norm());
            }
        }
        EXPECT_LT(worst, 1e-9) << m.name();
    }

    inline std::string writeTemp(const std::string &name, const std::string &text)
    {
        const fs::path dir = fs::path(testing::TempDir()) / "ropras_robot_model_test";
        fs::create_directories(dir);
        const fs::path p = dir / name;
        std::ofstream(p) << text;
        return p.string();
    }

    /// a small URDF exercising every joint type and non-axis-aligned axes
    inline std::string testArmUrdf(const std::string &radius = "0.05", const std::string &j2type = "prismatic",
                                   const std::string &extraCollision = "")
    {
        return R"(<?xml version="1.0"?>
<robot name="testarm">
  <link name="base"><collision><geometry><sphere radius=")" +
               radius + R"("/></geometry></collision></link>
  <link name="l1"><collision><origin xyz="0.1 0 0.2"/><geometry><sphere radius="0.04"/></geometry></collision></link>
  <link name="l2"><collision><origin xyz="0 0.1 0.1"/><geometry><sphere radius="0.03"/></geometry></collision>)" +
               extraCollision + R"(</link>
  <link name="mount"/>
  <link name="l3"><collision><origin xyz="0.05 0.05 0.3"/><geometry><sphere radius="0.03"/></geometry></collision>
                  <collision><origin xyz="0 0 0.1"/><geometry><sphere radius="0.02"/></geometry></collision></link>
  <link name="l4"><collision><origin xyz="0 0 0.05"/><geometry><sphere radius="0.02"/></geometry></collision></link>
  <joint name="z_last" type="continuous"><parent link="l3"/><child link="l4"/>
    <origin xyz="0 0 0.35" rpy="0.3 -0.2 0.1"/><axis xyz="0 0 -1"/></joint>
  <joint name="a_first" type="revolute"><parent link="base"/><child link="l1"/>
    <origin xyz="0 0 0.1" rpy="0 0 0.4"/><axis xyz="1 1 0"/><limit lower="-2" upper="2" effort="1" velocity="1"/></joint>
  <joint name="slide" type=")" +
               j2type + R"("><parent link="l1"/><child link="l2"/>
    <origin xyz="0.1 0 0.3" rpy="0.5 0.1 0"/><axis xyz="0 0.6 0.8"/><limit lower="-0.1" upper="0.2" effort="1" velocity="1"/></joint>
  <joint name="fix" type="fixed"><parent link="l2"/><child link="mount"/><origin xyz="0 0 0.2" rpy="0 1 0"/></joint>
  <joint name="b_elbow" type="revolute"><parent link="mount"/><child link="l3"/>
    <origin xyz="0 0 0.05"/><axis xyz="0 1 0"/><limit lower="-1.5" upper="1.0" effort="1" velocity="1"/></joint>
</robot>
)";
    }
}  // namespace ropras::test

#endif
