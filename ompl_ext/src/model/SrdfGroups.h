#ifndef ROPRAS_OMPL_EXT_SRC_SRDF_GROUPS_H
#define ROPRAS_OMPL_EXT_SRC_SRDF_GROUPS_H

#include <string>
#include <vector>

#include "model/SrdfReader.h"
#include "ropras/ompl_ext/model/RobotModel.h"

namespace ropras::ompl_ext
{
    /** \brief The joints of the SRDF group \a name, as indices into \a joints (every type, ascending: URDF
        document order), by MoveIt's rules: a `<joint>` itself, a `<link>`'s parent joint, a `<chain>`'s joints on
        the tree path from base_link to tip_link, a subgroup's joints. Throws ropras::Error naming \a sourceName,
        the group and its line for an unknown group, link or joint and for subgroups that contain themselves. */
    std::vector<int> srdfGroupJoints(const SrdfDocument &srdf, const std::string &name, const std::vector<Link> &links,
                                     const std::vector<UrdfJoint> &joints, const std::string &sourceName);
}  // namespace ropras::ompl_ext

#endif
