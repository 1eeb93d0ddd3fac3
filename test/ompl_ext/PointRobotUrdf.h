// A disc robot (radius 0.04) on two prismatic joints x, y in [0, 1], written as a URDF file, and the query the OMPL
// tests pose it.
#ifndef ROPRAS_TEST_OMPL_EXT_POINT_ROBOT_URDF_H
#define ROPRAS_TEST_OMPL_EXT_POINT_ROBOT_URDF_H

#include <filesystem>
#include <fstream>
#include <string>

#include <ompl/base/ScopedState.h>
#include <ompl/geometric/SimpleSetup.h>

namespace ropras::ompl_ext::test
{
    /// writes the URDF to the temporary folder under \a fileName (one name per test executable) and returns its path
    inline std::string writePointRobotUrdf(const std::string &fileName)
    {
        const std::filesystem::path path = std::filesystem::temp_directory_path() / fileName;
        std::ofstream out(path);
        out << R"(<robot name="point">
  <link name="world"/>
  <link name="slider"/>
  <link name="disc"><collision><geometry><sphere radius="0.04"/></geometry></collision></link>
  <joint name="x" type="prismatic"><parent link="world"/><child link="slider"/><axis xyz="1 0 0"/>
    <limit lower="0" upper="1" effort="1" velocity="1"/></joint>
  <joint name="y" type="prismatic"><parent link="slider"/><child link="disc"/><axis xyz="0 1 0"/>
    <limit lower="0" upper="1" effort="1" velocity="1"/></joint>
</robot>)";
        return path.string();
    }

    /// the query the point-robot tests share: (0.1, 0.1) to (0.9, 0.1), then SimpleSetup::setup()
    inline void setPointRobotQuery(ompl::geometric::SimpleSetup &setup)
    {
        ompl::base::ScopedState<> start(setup.getStateSpace()), goal(setup.getStateSpace());
        start[0] = 0.1;
        start[1] = 0.1;
        goal[0] = 0.9;
        goal[1] = 0.1;
        setup.setStartAndGoalStates(start, goal);
        setup.setup();
    }
}  // namespace ropras::ompl_ext::test

#endif
