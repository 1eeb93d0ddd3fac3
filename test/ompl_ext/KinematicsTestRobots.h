#ifndef ROPRAS_TEST_KINEMATICS_TEST_ROBOTS_H
#define ROPRAS_TEST_KINEMATICS_TEST_ROBOTS_H

// Robots and helpers shared by the link-pose and inverse-kinematics tests.
#include <filesystem>
#include <memory>
#include <string>
#include <vector>

#include "ropras/core/Rng.h"
#include "ropras/ompl_ext/model/RobotModel.h"

namespace ropras::test
{
    inline std::string sharedRobot(const std::string &rel)
    {
        return std::string(ROPRAS_SHARED_DIR) + "/robots/" + rel;
    }

    inline bool haveSharedRobots()
    {
        return std::filesystem::is_directory(std::string(ROPRAS_SHARED_DIR) + "/robots/panda");
    }

    /// the arm the project ships
    inline std::string shippedArmUrdf()
    {
        return std::string(ROPRAS_SOURCE_DIR) + "/robots/ropras_arm/ropras_arm.urdf";
    }

    /** \brief A small arm with every joint type the model takes: skew revolute axes, a prismatic joint, a
        continuous joint with a reversed axis, fixed joints in between, a joint held at 0.3 (not planned) and a
        side branch, with a base pose. The chain to "tip" crosses all of them. */
    inline std::shared_ptr<const ompl_ext::RobotModel> everyJointTypeArm()
    {
        const std::string urdf = R"(<?xml version="1.0"?>
<robot name="kinarm">
  <link name="base"/><link name="l1"/><link name="l2"/><link name="mount"/><link name="l3"/><link name="l4"/>
  <link name="l5"/><link name="tip"/><link name="side"/>
  <joint name="a" type="revolute"><parent link="base"/><child link="l1"/>
    <origin xyz="0 0 0.1" rpy="0 0 0.4"/><axis xyz="1 1 0"/><limit lower="-2" upper="2" effort="1" velocity="1"/></joint>
  <joint name="slide" type="prismatic"><parent link="l1"/><child link="l2"/>
    <origin xyz="0.1 0 0.3" rpy="0.5 0.1 0"/><axis xyz="0 0.6 0.8"/><limit lower="-0.1" upper="0.2" effort="1" velocity="1"/></joint>
  <joint name="fix" type="fixed"><parent link="l2"/><child link="mount"/><origin xyz="0 0 0.2" rpy="0 1 0"/></joint>
  <joint name="b" type="revolute"><parent link="mount"/><child link="l3"/>
    <origin xyz="0 0 0.05"/><axis xyz="0 1 0"/><limit lower="-1.5" upper="1.0" effort="1" velocity="1"/></joint>
  <joint name="held" type="revolute"><parent link="l3"/><child link="l4"/>
    <origin xyz="0 0.1 0.25" rpy="0.2 0 0"/><axis xyz="1 0 0"/><limit lower="-1" upper="1" effort="1" velocity="1"/></joint>
  <joint name="c" type="continuous"><parent link="l4"/><child link="l5"/>
    <origin xyz="0 0 0.35" rpy="0.3 -0.2 0.1"/><axis xyz="0 0 -1"/></joint>
  <joint name="d" type="revolute"><parent link="l5"/><child link="tip"/>
    <origin xyz="0.05 0 0.1" rpy="0 0.3 0"/><axis xyz="0.3 -0.4 0.5"/><limit lower="-2.5" upper="2.5" effort="1" velocity="1"/></joint>
  <joint name="side_joint" type="revolute"><parent link="l1"/><child link="side"/>
    <origin xyz="0 0.2 0"/><axis xyz="0 0 1"/><limit lower="-1" upper="1" effort="1" velocity="1"/></joint>
</robot>
)";
        ompl_ext::RobotModel::Options options;
        options.planningJoints = {"side_joint", "a", "slide", "b", "c", "d"};  // not in chain order
        options.heldJointValues["held"] = 0.3;
        options.basePose.translation() = Eigen::Vector3d(0.2, -0.1, 0.5);
        options.basePose.linear() = Eigen::AngleAxisd(0.7, Eigen::Vector3d(1, 2, 3).normalized()).toRotationMatrix();
        return ompl_ext::RobotModel::fromUrdfString(urdf, ".", "kinarm.urdf", "", options);
    }

    /// every planning joint uniform within its limits
    inline std::vector<double> randomConfiguration(const ompl_ext::RobotModel &robot, core::Rng &rng)
    {
        std::vector<double> q;
        for (const ompl_ext::PlanningJoint &j : robot.joints())
            q.push_back(rng.uniform(j.lower, j.upper));
        return q;
    }

    /// angle (rad) of the rotation between two orientations
    inline double rotationAngle(const Eigen::Matrix3d &a, const Eigen::Matrix3d &b)
    {
        return Eigen::AngleAxisd(Eigen::Quaterniond(a.transpose() * b).normalized()).angle();
    }
}  // namespace ropras::test

#endif
