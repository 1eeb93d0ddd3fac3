// Maze2D (paper, Tables "POMDP Summary" / "Spaces and Discounts" / "Functions and Horizons"): a disc robot in
// [-25, 25]^2 starting at one of two entry points (bimodal belief) must reach the goal through two wall gaps,
// localizing at landmarks and keeping out of danger zones. Geometry reconstructed in doc/scenario-maze2d.md.
#include "BuiltinScenarios.h"

namespace ropras::scenarios::detail
{
    void addMaze2DScenario(ScenarioRegistry &registry)
    {
        addNavigationScenario(registry, "maze2d",
                              "Maze2D: two entry points, walls, landmarks, danger zones in [-25,25]^2; 20% slip",
                              "navigation/maze2d");
    }
}  // namespace ropras::scenarios::detail
