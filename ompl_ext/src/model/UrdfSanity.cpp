#include "model/UrdfSanity.h"

#include <cmath>
#include <sstream>

namespace ropras::ompl_ext::urdf_sanity
{
    namespace
    {
        std::string text(double v)
        {
            std::ostringstream s;
            s.precision(10);
            s << v;
            return s.str();
        }
    }  // namespace

    std::string limitProblem(const std::string &name, JointType type, double lower, double upper)
    {
        if (type != JointType::Revolute && type != JointType::Prismatic)
            return "";
        const bool angular = type == JointType::Revolute;
        const double bound = angular ? MAX_ANGLE : MAX_LENGTH;
        if (std::abs(lower) <= bound && std::abs(upper) <= bound)
            return "";
        return "joint '" + name + "' has limits [" + text(lower) + ", " + text(upper) + "] beyond +-" + text(bound) +
               (angular ? " rad" : " m") +
               " (the float collision kernels would lose their precision there; real joints do not reach so far)";
    }

    std::string sizeProblem(const std::string &what, double value, bool scale)
    {
        const double bound = scale ? MAX_MESH_SCALE : MAX_LENGTH;
        if (std::abs(value) <= bound)
            return "";
        const char *unit = scale ? "" : " m";
        return what + " " + text(value) + unit + " is beyond " + text(bound) + unit +
               " (no robot part is so large; the float collision kernels would lose their precision)";
    }

    std::string originProblem(const std::string &what, const Eigen::Isometry3d &origin)
    {
        const double offset = origin.translation().norm();
        if (offset <= MAX_LENGTH)
            return "";
        return what + " is " + text(offset) + " m from its parent frame, beyond " + text(MAX_LENGTH) +
               " m (the float collision kernels would lose their precision)";
    }

    std::string mimicProblem(const urdf::ModelInterface &urdf, const urdf::Joint &joint)
    {
        if (!joint.mimic)
            return "";
        const std::string &target = joint.mimic->joint_name;
        if (target == joint.name)
            return "joint '" + joint.name + "' mimics itself";
        if (urdf.joints_.count(target) == 0)
            return "joint '" + joint.name + "' mimics joint '" + target + "', which the URDF does not have";
        if (!std::isfinite(joint.mimic->multiplier) || !std::isfinite(joint.mimic->offset))
            return "joint '" + joint.name + "' has a non-finite <mimic> multiplier or offset";
        return "";
    }
}  // namespace ropras::ompl_ext::urdf_sanity
