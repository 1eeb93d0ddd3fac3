#ifndef ROPRAS_SCENARIOS_CROSSING_SCENARIO_H
#define ROPRAS_SCENARIOS_CROSSING_SCENARIO_H

#include <memory>

#include "ropras/scenarios/ModelScenario.h"
#include "ropras/scenarios/ScenarioRegistry.h"
#include "ropras/scenarios/crossing/CrossingModel.h"

namespace ropras::scenarios
{
    /** \brief The parts of "stretch-crossing" for crossing/stretch-crossing/default.json with \a options
        applied: the model (over the Stretch robot's spheres), the Bullet world, the reference policy (any
        OMPL planner over base x, y, theta in the lab with the particle's pedestrian; the lookahead tracker),
        defaults, scene and event names. Throws ropras::Error naming the key for a bad configuration. */
    ScenarioParts<CrossingModel> crossingParts(const ScenarioOptions &options = ScenarioOptions());

    /** \brief The "stretch-crossing" scenario (what the registry's factory returns). */
    std::unique_ptr<ModelScenario<CrossingModel>> makeCrossingScenario(
        const ScenarioOptions &options = ScenarioOptions());

    /** \brief "too-close", "goal", "pedestrian-collision", "obstacle-collision" or "" (None). */
    const char *crossingEventName(CrossingEvent event);
}  // namespace ropras::scenarios

#endif
