// Maze2D (paper, Tables "POMDP Summary" / "Spaces and Discounts" / "Functions and Horizons"): a disc robot in
// [-25, 25]^2 starting at one of two entry points (bimodal belief) must reach the goal through two wall gaps,
// localizing at landmarks and keeping out of danger zones. Geometry reconstructed in doc/scenario-maze2d.md.
#include "BuiltinScenarios.h"
#include "ropras/scenarios/NavigationPlanning.h"

namespace ropras::scenarios::detail
{
    void addMaze2DScenario(ScenarioRegistry &registry)
    {
        ScenarioEntry entry;
        entry.name = "maze2d";
        entry.description = "Maze2D: two entry points, walls, landmarks, danger zones in [-25,25]^2; 20% slip";
        entry.factory = [name = entry.name, description = entry.description](const ScenarioOptions &options)
        {
            const auto config =
                applyOverrides(name, nlohmann::json::parse(embeddedFile("maze2d/default.json")), options);
            return makeNavigationScenario(name, description, "maze2d", config);
        };
        registry.add(std::move(entry));
    }
}  // namespace ropras::scenarios::detail
