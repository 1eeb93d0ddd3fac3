// Light-Dark (paper, Tables "POMDP Summary" / "Spaces and Discounts" / "Functions and Horizons"): a disc robot in
// [-4, 4]^2 with an uncertain initial position must reach the goal box; it can localize only in the light stripe.
// Geometry reconstructed in doc/scenario-light-dark.md.
#include "BuiltinScenarios.h"
#include "ropras/scenarios/NavigationPlanning.h"

namespace ropras::scenarios::detail
{
    void addLightDarkScenario(ScenarioRegistry &registry)
    {
        ScenarioEntry entry;
        entry.name = "light-dark";
        entry.description =
            "Light-Dark: reach the goal in [-4,4]^2 from an uncertain start; localize in the light stripe";
        entry.factory = [name = entry.name, description = entry.description](const ScenarioOptions &options)
        {
            const auto config =
                applyOverrides(name, nlohmann::json::parse(embeddedFile("light-dark/default.json")), options);
            return makeNavigationScenario(name, description, "light-dark", config);
        };
        registry.add(std::move(entry));
    }
}  // namespace ropras::scenarios::detail
