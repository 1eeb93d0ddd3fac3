#ifndef ROPRAS_SCENARIOS_SRC_BUILTIN_SCENARIOS_H
#define ROPRAS_SCENARIOS_SRC_BUILTIN_SCENARIOS_H

#include <string>

#include "ropras/scenarios/ScenarioRegistry.h"

namespace ropras::scenarios::detail
{
    /** \brief Registers every built-in scenario (calls the functions below). */
    void addBuiltinScenarios(ScenarioRegistry &registry);

    // One per scenario folder (scenarios/<folder>/*.cpp).
    void addLightDarkScenario(ScenarioRegistry &registry);   ///< light-dark
    void addMaze2DScenario(ScenarioRegistry &registry);      ///< maze2d
    void addRandom3DScenarios(ScenarioRegistry &registry);   ///< random3d-1 ... random3d-4
    void addMultiDroneScenario(ScenarioRegistry &registry);  ///< multi-drone

    /** \brief Registers a navigation scenario \a name whose configuration is the embedded
        "<folder>/default.json" with the user's overrides applied (makeNavigationScenario). */
    void addNavigationScenario(ScenarioRegistry &registry, const std::string &name, const std::string &description,
                               const std::string &folder);
}  // namespace ropras::scenarios::detail

#endif
