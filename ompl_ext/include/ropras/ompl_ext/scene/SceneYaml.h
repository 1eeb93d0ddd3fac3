#ifndef ROPRAS_OMPL_EXT_SCENE_YAML_H
#define ROPRAS_OMPL_EXT_SCENE_YAML_H

#include <map>
#include <string>
#include <vector>

#include "ropras/ompl_ext/scene/Environment.h"

namespace ropras::ompl_ext
{
    /** \brief Load a MoveIt PlanningScene YAML (`world.collision_objects` with box / cylinder / sphere
        primitives; object pose composed with primitive pose; quaternions x, y, z, w; box dimensions are
        full extents, cylinder [length, radius]). Throws ropras::Error naming the file and the entry. */
    Environment loadPlanningScene(const std::string &path);
    Environment planningSceneFromString(const std::string &yaml, const std::string &sourceName);

    /** \brief A MoveIt MotionPlanRequest: start joint state and the first goal's joint constraints. */
    struct MotionPlanRequest
    {
        std::map<std::string, double> start;
        std::map<std::string, double> goal;
    };
    MotionPlanRequest loadMotionPlanRequest(const std::string &path);
    MotionPlanRequest motionPlanRequestFromString(const std::string &yaml, const std::string &sourceName);
}  // namespace ropras::ompl_ext

#endif
