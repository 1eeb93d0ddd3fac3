#ifndef ROPRAS_SCENARIOS_COMMON_BUILTIN_SCENARIOS_H
#define ROPRAS_SCENARIOS_COMMON_BUILTIN_SCENARIOS_H

#include <string>

#include "ropras/scenarios/ScenarioRegistry.h"

namespace ropras::scenarios::detail
{
    /** \brief Registers every built-in scenario (calls the functions below). */
    void addBuiltinScenarios(ScenarioRegistry &registry);

    // One per problem (scenarios/<family>/<problem>/*.cpp or scenarios/<family>/src/).
    void addLightDarkScenario(ScenarioRegistry &registry);     ///< light-dark
    void addMaze2DScenario(ScenarioRegistry &registry);        ///< maze2d
    void addRandom3DScenarios(ScenarioRegistry &registry);     ///< random3d-1 ... random3d-4
    void addMultiDroneScenario(ScenarioRegistry &registry);    ///< multi-drone
    void addSphereSearchScenario(ScenarioRegistry &registry);  ///< sphere-search
    void addShelfMoveScenario(ScenarioRegistry &registry);     ///< shelf-move
    void addCrossingScenario(ScenarioRegistry &registry);      ///< stretch-crossing
    void addRayDetectScenario(ScenarioRegistry &registry);     ///< ray-detect

    /** \brief Registers a navigation scenario \a name whose configuration is the embedded
        "<folder>/default.json" (e.g. folder "navigation/maze2d") with the user's overrides applied
        (makeNavigationScenario; defined in navigation/src/NavigationScenario.cpp). */
    void addNavigationScenario(ScenarioRegistry &registry, const std::string &name, const std::string &description,
                               const std::string &folder);
}  // namespace ropras::scenarios::detail

#endif
