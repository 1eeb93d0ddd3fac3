// Generated inputs of a given size for the setup-complexity tests (issue 17, item 12): a chain of n links, one link
// with n spheres, a scene of n boxes. Every link or sphere is a separate element, so the input grows linearly in n.
#ifndef ROPRAS_TEST_OMPL_EXT_LARGE_INPUTS_H
#define ROPRAS_TEST_OMPL_EXT_LARGE_INPUTS_H

#include <cstddef>
#include <string>

namespace ropras::ompl_ext::test
{
    /// a serial chain of \a links links (link i has one sphere of radius 0.04), revolute joints about z, 0.1 m apart
    inline std::string chainUrdf(std::size_t links)
    {
        std::string out = "<robot name=\"chain\">\n  <link name=\"l0\"/>\n";
        for (std::size_t i = 1; i < links; ++i)
        {
            const std::string l = "l" + std::to_string(i);
            out += "  <link name=\"" + l +
                   "\"><collision><geometry><sphere radius=\"0.04\"/></geometry></collision></link>\n";
            out += "  <joint name=\"j" + std::to_string(i) + "\" type=\"revolute\"><parent link=\"l" +
                   std::to_string(i - 1) + "\"/><child link=\"" + l +
                   "\"/><origin xyz=\"0.1 0 0\"/><axis xyz=\"0 0 1\"/><limit lower=\"-0.5\" upper=\"0.5\" effort=\"1\" "
                   "velocity=\"1\"/></joint>\n";
        }
        return out + "</robot>\n";
    }

    /// two links; the second carries \a spheres spheres (radius 0.01, 0.03 m apart in rows of 1000 along x, the rows
    /// 0.03 m apart along y: within the 100 m RobotModel accepts) on one prismatic joint
    inline std::string manySpheresUrdf(std::size_t spheres)
    {
        std::string out = "<robot name=\"spheres\">\n  <link name=\"base\"/>\n  <link name=\"body\">\n";
        for (std::size_t i = 0; i < spheres; ++i)
            out += "    <collision><origin xyz=\"" + std::to_string(0.03 * static_cast<double>(i % 1000)) + " " +
                   std::to_string(0.03 * static_cast<double>(i / 1000)) +
                   " 0\"/><geometry><sphere radius=\"0.01\"/></geometry></collision>\n";
        out +=
            "  </link>\n  <joint name=\"x\" type=\"prismatic\"><parent link=\"base\"/><child link=\"body\"/>"
            "<axis xyz=\"0 0 1\"/><limit lower=\"0\" upper=\"1\" effort=\"1\" velocity=\"1\"/></joint>\n";
        return out + "</robot>\n";
    }

    /// a MoveIt PlanningScene of \a boxes boxes (one collision object each) on a grid
    inline std::string boxesScene(std::size_t boxes)
    {
        std::string out = "name: boxes\nworld:\n  collision_objects:\n";
        for (std::size_t i = 0; i < boxes; ++i)
        {
            out += "    - id: box" + std::to_string(i) +
                   "\n      primitives:\n        - type: box\n          dimensions: [0.05, 0.05, 0.05]\n"
                   "      primitive_poses:\n        - position: [" +
                   std::to_string(static_cast<double>(i % 100) * 0.1) + ", " +
                   std::to_string(static_cast<double>(i / 100 % 100) * 0.1) + ", " +
                   std::to_string(1.0 + static_cast<double>(i / 10000) * 0.1) +
                   "]\n          orientation: [0, 0, 0, 1]\n";
        }
        return out;
    }
}  // namespace ropras::ompl_ext::test

#endif
