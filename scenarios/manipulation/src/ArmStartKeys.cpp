#include "ropras/scenarios/manipulation/ArmStartKeys.h"

#include <algorithm>

namespace ropras::scenarios
{
    void readArmStartKeys(const ConfigReader &reader, std::array<double, ARM_DOF> &start, std::string &endEffector)
    {
        const auto q = reader.numbers("start", ARM_DOF);
        std::copy(q.begin(), q.end(), start.begin());
        const auto &ee = reader.at("end_effector");
        if (!ee.is_string() || ee.get<std::string>().empty())
        {
            reader.fail("end_effector", "must be a link name, not " + ee.dump());
        }
        endEffector = ee.get<std::string>();
    }
}  // namespace ropras::scenarios
