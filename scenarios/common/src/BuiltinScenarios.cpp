#include "BuiltinScenarios.h"

namespace ropras::scenarios::detail
{
    void addBuiltinScenarios(ScenarioRegistry &registry)
    {
        addLightDarkScenario(registry);
        addMaze2DScenario(registry);
        addRandom3DScenarios(registry);
        addMultiDroneScenario(registry);
        addSphereSearchScenario(registry);
        addShelfMoveScenario(registry);
        addCrossingScenario(registry);
        addRayDetectScenario(registry);
    }
}  // namespace ropras::scenarios::detail
