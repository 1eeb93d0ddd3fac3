#ifndef ROPRAS_OMPL_EXT_SRC_JOINT_VALUES_H
#define ROPRAS_OMPL_EXT_SRC_JOINT_VALUES_H

#include <string>

#include "ropras/ompl_ext/model/RobotModel.h"

namespace ropras::ompl_ext
{
    /** \brief MoveIt's leniency with joint values from other programs' files: a value at most \a tolerance
        outside [\a lower, \a upper] is clamped into it; a continuous joint's value outside [-pi, pi] is wrapped
        into it (the same configuration). Returns a warning naming the joint when \a value changed by more than
        rounding, "" otherwise; other values (NaN, far outside a limit) are left for the caller to refuse. */
    std::string fitJointValue(const std::string &joint, JointType type, double lower, double upper, double tolerance,
                              double &value);
}  // namespace ropras::ompl_ext

#endif
