#ifndef ROPRAS_OMPL_EXT_SRC_MODEL_TEXT_H
#define ROPRAS_OMPL_EXT_SRC_MODEL_TEXT_H

#include <sstream>
#include <string>
#include <vector>

/// numbers and name lists in the robot model's messages
namespace ropras::ompl_ext::model_text
{
    /// \a v with 10 significant digits
    inline std::string fmt(double v)
    {
        std::ostringstream ss;
        ss.precision(10);
        ss << v;
        return ss.str();
    }

    /// "a, b, c", or "(none)" for no names
    inline std::string joinNames(const std::vector<std::string> &names)
    {
        std::string out;
        for (const std::string &n : names)
        {
            out += (out.empty() ? "" : ", ") + n;
        }
        return out.empty() ? std::string("(none)") : out;
    }
}  // namespace ropras::ompl_ext::model_text

#endif
