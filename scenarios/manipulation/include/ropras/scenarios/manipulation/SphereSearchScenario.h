#ifndef ROPRAS_SCENARIOS_MANIPULATION_SPHERE_SEARCH_SCENARIO_H
#define ROPRAS_SCENARIOS_MANIPULATION_SPHERE_SEARCH_SCENARIO_H

#include <memory>

#include "ropras/scenarios/ModelScenario.h"
#include "ropras/scenarios/ScenarioRegistry.h"
#include "ropras/scenarios/manipulation/SphereSearchModel.h"

namespace ropras::scenarios
{
    /** \brief The parts of the "sphere-search" scenario for manipulation/sphere-search/default.json with
        \a options applied: the model (the embedded Panda in the sphere cage), the Bullet world, the reference
        policy (any OMPL planner by name; IK goal configurations; Uniform / Dynamic / epsilon-greedy
        heuristics), defaults and scene. Throws ropras::Error naming the key for a bad configuration. */
    ScenarioParts<SphereSearchModel> sphereSearchParts(const ScenarioOptions &options = ScenarioOptions());

    /** \brief The "sphere-search" scenario (what the registry's factory returns). */
    std::unique_ptr<ModelScenario<SphereSearchModel>> makeSphereSearchScenario(
        const ScenarioOptions &options = ScenarioOptions());
}  // namespace ropras::scenarios

#endif
