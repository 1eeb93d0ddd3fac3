#ifndef ROPRAS_OMPL_EXT_SCENE_YAML_H
#define ROPRAS_OMPL_EXT_SCENE_YAML_H

#include <map>
#include <memory>
#include <string>
#include <vector>

#include "ropras/ompl_ext/model/RobotModel.h"
#include "ropras/ompl_ext/scene/Environment.h"

namespace ropras::ompl_ext
{
    /** \brief Load a MoveIt PlanningScene YAML (`world.collision_objects` with box / cylinder / sphere
        primitives; object pose composed with primitive pose; quaternions x, y, z, w; box dimensions are
        full extents, cylinder [length, radius]). Throws ropras::Error naming the file and the entry. */
    Environment loadPlanningScene(const std::string &path);
    Environment planningSceneFromString(const std::string &yaml, const std::string &sourceName);

    /** \brief The same, with `robot_state.attached_collision_objects` (MoveIt AttachedCollisionObject: link_name,
        object with id, primitives, primitive_poses and a pose in the link frame, touch_links) attached to
        \a robot. The object's header.frame_id must be empty or the link itself. Without a robot (the overloads
        above) a scene with attached objects is an error naming the file and line. */
    Environment loadPlanningScene(const std::string &path, std::shared_ptr<const RobotModel> robot);
    Environment planningSceneFromString(const std::string &yaml, const std::string &sourceName,
                                        std::shared_ptr<const RobotModel> robot);

    /** \brief A MoveIt MotionPlanRequest: start joint state, the first goal's joint constraints and the planning
        group (`group_name`, "" when absent). */
    struct MotionPlanRequest
    {
        std::map<std::string, double> start;
        std::map<std::string, double> goal;
        std::string group;
    };
    MotionPlanRequest loadMotionPlanRequest(const std::string &path);
    MotionPlanRequest motionPlanRequestFromString(const std::string &yaml, const std::string &sourceName);
}  // namespace ropras::ompl_ext

#endif
