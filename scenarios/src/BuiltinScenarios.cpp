#include "BuiltinScenarios.h"

#include <nlohmann/json.hpp>

#include "ropras/scenarios/NavigationPlanning.h"

namespace ropras::scenarios::detail
{
    void addBuiltinScenarios(ScenarioRegistry &registry)
    {
        addLightDarkScenario(registry);
        addMaze2DScenario(registry);
        addRandom3DScenarios(registry);
        addMultiDroneScenario(registry);
    }

    void addNavigationScenario(ScenarioRegistry &registry, const std::string &name, const std::string &description,
                               const std::string &folder)
    {
        ScenarioEntry entry;
        entry.name = name;
        entry.description = description;
        entry.factory = [name, description, folder](const ScenarioOptions &options)
        {
            const auto config =
                applyOverrides(name, nlohmann::json::parse(embeddedFile(folder + "/default.json")), options);
            return makeNavigationScenario(name, description, folder, config);
        };
        registry.add(std::move(entry));
    }
}  // namespace ropras::scenarios::detail
