#ifndef ROPRAS_SCENARIOS_MULTI_DRONE_SCENARIO_H
#define ROPRAS_SCENARIOS_MULTI_DRONE_SCENARIO_H

#include <memory>

#include "ropras/scenarios/ModelScenario.h"
#include "ropras/scenarios/ScenarioRegistry.h"
#include "ropras/scenarios/multi-drone/MultiDroneModel.h"

namespace ropras::scenarios
{
    /** \brief The parts of the "multi-drone" scenario (Multi-Drone Tag) for the configuration
        multi-drone/default.json with \a options applied: the model, the Bullet world, the reference policy
        (OMPL planner over the 12-D drones robot with MultiDroneHeuristic), defaults and scene. Throws
        ropras::Error naming the key for a bad configuration. */
    ScenarioParts<MultiDroneModel> multiDroneParts(const ScenarioOptions &options = ScenarioOptions());

    /** \brief The "multi-drone" scenario (what the registry's factory returns). */
    std::unique_ptr<ModelScenario<MultiDroneModel>> makeMultiDroneScenario(
        const ScenarioOptions &options = ScenarioOptions());
}  // namespace ropras::scenarios

#endif
