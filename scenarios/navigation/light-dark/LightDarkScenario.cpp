// Light-Dark (paper, Tables "POMDP Summary" / "Spaces and Discounts" / "Functions and Horizons"): a disc robot in
// [-4, 4]^2 with an uncertain initial position must reach the goal box; it can localize only in the light stripe.
// Geometry reconstructed in doc/scenario-light-dark.md.
#include "BuiltinScenarios.h"

namespace ropras::scenarios::detail
{
    void addLightDarkScenario(ScenarioRegistry &registry)
    {
        addNavigationScenario(
            registry, "light-dark",
            "Light-Dark: reach the goal in [-4,4]^2 from an uncertain start; localize in the light stripe",
            "navigation/light-dark");
    }
}  // namespace ropras::scenarios::detail
