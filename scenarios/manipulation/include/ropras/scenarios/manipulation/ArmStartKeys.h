#ifndef ROPRAS_SCENARIOS_MANIPULATION_ARM_START_KEYS_H
#define ROPRAS_SCENARIOS_MANIPULATION_ARM_START_KEYS_H

#include <array>
#include <string>

#include "ropras/scenarios/ConfigReader.h"
#include "ropras/scenarios/manipulation/PandaArm.h"

namespace ropras::scenarios
{
    /** \brief Reads the two keys every arm scenario's configuration starts with: "start" (ARM_DOF finite
        numbers, the true initial configuration in rad; the joint-limit check is PandaArm::requireWithinLimits,
        once the arm is loaded) and "end_effector" (a non-empty link name). Throws ropras::Error naming the key
        and the value (ConfigReader's messages). */
    void readArmStartKeys(const ConfigReader &reader, std::array<double, ARM_DOF> &start, std::string &endEffector);
}  // namespace ropras::scenarios

#endif
