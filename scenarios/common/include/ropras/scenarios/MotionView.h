#ifndef ROPRAS_SCENARIOS_MOTION_VIEW_H
#define ROPRAS_SCENARIOS_MOTION_VIEW_H

#include <cstddef>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

namespace ropras::ompl_ext
{
    class RobotModel;
    class Environment;
}  // namespace ropras::ompl_ext

namespace ropras::scenarios
{
    /** \brief Reads a joint-space path as `ropras plan --out` writes it: a header of joint names (the robot's
        planning joints, in any order), then one row of values per waypoint; returns the rows in the robot's
        planning order. Throws ropras::Error naming \a path, the line and the problem for a missing or empty file,
        an unknown, repeated or missing joint, a row with the wrong number of values, a value that is not a
        finite number or lies outside its joint's limits (by more than 1e-6), or more than 10^6 rows. */
    std::vector<std::vector<double>> loadJointPathCsv(const std::string &path, const ompl_ext::RobotModel &robot);

    /** \brief What motionView() draws. */
    struct MotionViewOptions
    {
        std::string title{"motion"};
        std::string subtitle;
        /// waypoints are joined by straight joint-space segments of at most this step per joint (rad or m)
        double maxJointStep{0.05};
        /// the link whose origin traces the path; empty = the child link of the last planning joint
        std::string tipLink;
    };

    /** \brief The viewer document (doc/viewer.md) of a joint-space motion of \a robot in \a environment: the
        environment's objects, the robot's collision spheres posed per frame by its forward kinematics with the
        attached bodies' spheres, and the path of the tip link. Throws ropras::Error for an empty path, a row
        with the wrong joint count, an unknown tip link or a non-positive step. */
    nlohmann::json motionView(const ompl_ext::RobotModel &robot, const ompl_ext::Environment &environment,
                              const std::vector<std::vector<double>> &path,
                              const MotionViewOptions &options = MotionViewOptions());
}  // namespace ropras::scenarios

#endif
