// Registration of a navigation problem (Light-Dark, Maze2D, Random3D) from its embedded default configuration.
#include <nlohmann/json.hpp>

#include "BuiltinScenarios.h"
#include "ropras/scenarios/navigation/NavigationPlanning.h"

namespace ropras::scenarios::detail
{
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
