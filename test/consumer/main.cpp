// Loads the arm that ropras installs, builds a one-box scene and checks two configurations.
#include <iostream>
#include <vector>

#include <ropras/ompl_ext/collision/CollisionChecker.h>
#include <ropras/ompl_ext/model/RobotModel.h>
#include <ropras/ompl_ext/scene/Environment.h>

int main(int argc, char **argv)
{
    if (argc != 2)
    {
        std::cerr << "usage: consumer ROBOTS_DIR\n";
        return 2;
    }
    const std::string dir = argv[1];
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
