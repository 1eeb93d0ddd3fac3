#ifndef ROPRAS_OMPL_EXT_MODEL_URDF_SANITY_H
#define ROPRAS_OMPL_EXT_MODEL_URDF_SANITY_H

#include <urdf_model/model.h>

#include <Eigen/Geometry>
#include <string>

#include "ropras/ompl_ext/model/RobotModel.h"

namespace ropras::ompl_ext::urdf_sanity
{
    /** The collision kernels compute in float: sphere centres keep about 1e-5 m of precision only while
        coordinates stay within about 100 m and joint angles within about 100 rad (7.6e-6 is float's step at 100).
        Numbers beyond these are no robot; they are rejected with the joint or link and the value, instead of
        making sampling overflow (limits of +-1e308 give an infinite range) or the kernels disagree with their
        double-precision references. */
    constexpr double MAX_LENGTH = 100.0;  ///< m: prismatic limits, geometry sizes, origin offsets
    constexpr double MAX_ANGLE = 100.0;   ///< rad: revolute limits (16 turns)
    constexpr double MAX_MESH_SCALE = 1000.0;

    /// "" or why the limits [lower, upper] of joint \a name of \a type are beyond what the kernels represent
    std::string limitProblem(const std::string &name, JointType type, double lower, double upper);
    /// "" or why \a value (a size in m, e.g. "sphere radius", or with \a scale a mesh scale factor) is too large
    std::string sizeProblem(const std::string &what, double value, bool scale = false);
    /// "" or why the translation of \a origin (of \a what, e.g. "joint 'j1' <origin>") is beyond MAX_LENGTH
    std::string originProblem(const std::string &what, const Eigen::Isometry3d &origin);
    /** "" or why joint \a joint's <mimic> is wrong: it names a joint the URDF does not have, itself, or has a
        non-finite multiplier or offset */
    std::string mimicProblem(const urdf::ModelInterface &urdf, const urdf::Joint &joint);
}  // namespace ropras::ompl_ext::urdf_sanity

#endif
