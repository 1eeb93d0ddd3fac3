#ifndef ROPRAS_SCENARIOS_MANIPULATION_SHELF_MOVE_SCENARIO_H
#define ROPRAS_SCENARIOS_MANIPULATION_SHELF_MOVE_SCENARIO_H

#include <memory>

#include "ropras/scenarios/ModelScenario.h"
#include "ropras/scenarios/ScenarioRegistry.h"
#include "ropras/scenarios/manipulation/ShelfMoveModel.h"

namespace ropras::scenarios
{
    /** \brief The parts of the "shelf-move" scenario for manipulation/shelf-move/default.json with \a options
        applied: the model, the world (for now the model itself, pomdp::SimulatedWorld: the Bullet dynamics
        world is not written yet), the reference policy (any OMPL planner by name; IK goal configurations in
        the particle's scene; Uniform / Dynamic / epsilon-greedy heuristics over ShelfMoveTargetSpace;
        PathToMacroAction "entire motion path"), defaults and scene. Throws ropras::Error naming the key for a
        bad configuration. */
    ScenarioParts<ShelfMoveModel> shelfMoveParts(const ScenarioOptions &options = ScenarioOptions());

    /** \brief The "shelf-move" scenario (what the registry's factory returns). */
    std::unique_ptr<ModelScenario<ShelfMoveModel>> makeShelfMoveScenario(
        const ScenarioOptions &options = ScenarioOptions());
}  // namespace ropras::scenarios

#endif
