// Loads the arm that ropras installs (from ropras_ROBOTS_DIR, as the package config file sets it), builds a one-box
// scene and checks two configurations.
#include <iostream>
#include <limits>
#include <vector>

#include <ropras/ompl_ext/collision/CollisionChecker.h>
#include <ropras/ompl_ext/model/RobotModel.h>
#include <ropras/ompl_ext/scene/Environment.h>

// The libraries are built with Eigen's alignment pinned to 16 bytes; a consumer that saw another value would lay
// out ropras' public Eigen members differently from the library (the exported targets must carry the definition).
#if !defined(EIGEN_MAX_ALIGN_BYTES) || EIGEN_MAX_ALIGN_BYTES != 16 || !defined(EIGEN_MAX_STATIC_ALIGN_BYTES) || \
    EIGEN_MAX_STATIC_ALIGN_BYTES != 16
#error "ropras::ompl_ext must give its consumers EIGEN_MAX_ALIGN_BYTES=16 and EIGEN_MAX_STATIC_ALIGN_BYTES=16"
#endif

int main()
{
    const std::string dir = ROPRAS_ROBOTS_DIR;
    auto robot = ropras::ompl_ext::RobotModel::fromUrdfFile(dir + "/ropras_arm/ropras_arm.urdf");
    ropras::ompl_ext::Environment env;
    Eigen::Isometry3d pose = Eigen::Isometry3d::Identity();
    pose.translation() = Eigen::Vector3d(0.0, 0.0, -0.05);
    env.addBox("floor", pose, Eigen::Vector3d(2.0, 2.0, 0.02));
    ropras::ompl_ext::CollisionChecker checker(robot);
    std::vector<double> q(robot->dof(), 0.0);
    const bool home = checker.isValid(env, q.data());
    std::vector<double> nan(robot->dof(), std::numeric_limits<double>::quiet_NaN());
    const bool bad = checker.isValid(env, nan.data());
    std::cout << robot->name() << ": " << robot->dof() << " joints, " << robot->spheres().size()
              << " spheres; home valid=" << home << ", NaN valid=" << bad << '\n';
    return (home && !bad) ? 0 : 1;
}
