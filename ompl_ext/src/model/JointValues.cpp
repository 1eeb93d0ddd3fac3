#include "model/JointValues.h"

#include <algorithm>
#include <cmath>
#include <sstream>

namespace ropras::ompl_ext
{
    std::string fitJointValue(const std::string &joint, JointType type, double lower, double upper, double tolerance,
                              double &value)
    {
        constexpr double PI = 3.14159265358979323846;
        if (!std::isfinite(value) || (value >= lower && value <= upper))
            return "";
        const double given = value;
        std::ostringstream out;
        out.precision(10);
        out << "joint '" << joint << "' value " << given;
        const double outside = value < lower ? lower - value : value - upper;
        if (outside <= tolerance)
        {
            value = std::clamp(value, lower, upper);
            out << " is " << outside << " outside its limits [" << lower << ", " << upper << "] (tolerance "
                << tolerance << "): clamped to " << value;
            return out.str();
        }
        if (type != JointType::Continuous)
            return "";
        value = std::clamp(std::remainder(value, 2.0 * PI), -PI, PI);
        out << " of a continuous joint wrapped into [-pi, pi]: " << value;
        return out.str();
    }
}  // namespace ropras::ompl_ext
