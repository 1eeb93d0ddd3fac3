#ifndef ROPRAS_SCENARIOS_MANIPULATION_SHELF_MOVE_SCENARIO_H
#define ROPRAS_SCENARIOS_MANIPULATION_SHELF_MOVE_SCENARIO_H

#include <memory>
#include <string>

#include "ropras/scenarios/ModelScenario.h"
#include "ropras/scenarios/ScenarioRegistry.h"
#include "ropras/scenarios/manipulation/ShelfMoveModel.h"

namespace ropras::scenarios
{
    /** \brief The parts of the "shelf-move" scenario for manipulation/shelf-move/default.json with \a options
        applied: the model, the world (ShelfMoveWorld, Bullet rigid-body dynamics; with world.type = "model" the
        model itself, pomdp::SimulatedWorld), the reference policy (any OMPL planner by name; IK goal configurations in
        the particle's scene; Uniform / Dynamic / epsilon-greedy heuristics over ShelfMoveTargetSpace;
        PathToMacroAction "entire motion path"), defaults and scene. Throws ropras::Error naming the key for a
        bad configuration. */
    ScenarioParts<ShelfMoveModel> shelfMoveParts(const ScenarioOptions &options = ScenarioOptions());

    /** \brief The recording's event of a step into \a s: "grasp-canK", "release-canK-slotI", then the world's
        reports joined by "+": "moved", "tipped" (the released can settled off the model's snap / tilted),
        "pushed", "verdict-differs" (the model's blocked / valid verdict on the step's motion); "" = nothing. */
    std::string shelfMoveEvent(const ShelfMoveModel::State &s);

    /** \brief The "shelf-move" scenario (what the registry's factory returns). */
    std::unique_ptr<ModelScenario<ShelfMoveModel>> makeShelfMoveScenario(
        const ScenarioOptions &options = ScenarioOptions());
}  // namespace ropras::scenarios

#endif
