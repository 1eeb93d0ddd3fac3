#ifndef ROPRAS_SCENARIOS_MANIPULATION_RAY_DETECT_SCENARIO_H
#define ROPRAS_SCENARIOS_MANIPULATION_RAY_DETECT_SCENARIO_H

#include <memory>

#include "ropras/scenarios/ModelScenario.h"
#include "ropras/scenarios/ScenarioRegistry.h"
#include "ropras/scenarios/manipulation/RayDetectModel.h"

namespace ropras::scenarios
{
    /** \brief The parts of the "ray-detect" scenario for manipulation/ray-detect/default.json with \a options
        applied: the model (the embedded Panda, the table, the can and 4 obstacles of uncertain pose), the Bullet
        world, the reference policy (any OMPL planner by name, planning in the sampled particle's scene; IK goal
        and look configurations; Uniform / Dynamic / epsilon-greedy heuristics), defaults, scene and rays.
        Throws ropras::Error naming the key for a bad configuration. */
    ScenarioParts<RayDetectModel> rayDetectParts(const ScenarioOptions &options = ScenarioOptions());

    /** \brief The "ray-detect" scenario (what the registry's factory returns). */
    std::unique_ptr<ModelScenario<RayDetectModel>> makeRayDetectScenario(
        const ScenarioOptions &options = ScenarioOptions());
}  // namespace ropras::scenarios

#endif
