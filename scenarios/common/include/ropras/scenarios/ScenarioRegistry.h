#ifndef ROPRAS_SCENARIOS_SCENARIO_REGISTRY_H
#define ROPRAS_SCENARIOS_SCENARIO_REGISTRY_H

#include <functional>
#include <map>
#include <memory>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "ropras/scenarios/Scenario.h"

namespace ropras::scenarios
{
    /** \brief Changes to a scenario's default configuration: a JSON object whose keys replace the defaults of
        the same name (an unknown key or a value of the wrong type is an error naming \c source). */
    struct ScenarioOptions
    {
        nlohmann::json overrides = nlohmann::json::object();
        /// where the overrides came from, for error messages (e.g. the --config file name)
        std::string source{"<command line>"};
    };

    struct ScenarioEntry
    {
        std::string name;
        std::string description;
        std::function<std::unique_ptr<Scenario>(const ScenarioOptions &)> factory;
    };

    /** \brief Scenarios by command-line name. */
    class ScenarioRegistry
    {
    public:
        /** \brief Adds a scenario; throws ropras::Error for an empty or duplicate name or a missing factory. */
        void add(ScenarioEntry entry);
        /** \brief Throws ropras::Error naming the known scenarios when \a name is unknown. */
        const ScenarioEntry &get(const std::string &name) const;
        std::vector<std::string> names() const;
        /** \brief The scenario \a name with \a options; a configuration error names \a options.source (the
            overridden configuration is what failed validation) when the message does not already. */
        std::unique_ptr<Scenario> create(const std::string &name,
                                         const ScenarioOptions &options = ScenarioOptions()) const;

    private:
        std::map<std::string, ScenarioEntry> entries_;
    };

    /** \brief The built-in scenarios: light-dark, maze2d, random3d-1 ... random3d-4, multi-drone, sphere-search. */
    const ScenarioRegistry &scenarioRegistry();

    /** \brief A data file shipped in scenarios/<folder>/ (a robot URDF, a default configuration), compiled into
        the library at build time: `embeddedFile("light_dark/default.json")`. Throws ropras::Error naming the
        path and the available files when there is none. */
    const std::string &embeddedFile(const std::string &path);

    /** \brief Paths of all embedded files. */
    std::vector<std::string> embeddedFiles();

    /** \brief \a defaults with \a options.overrides applied key by key: throws ropras::Error naming the source,
        the scenario and the key for an unknown key or a value whose JSON type differs from the default's
        (numbers: integer and floating point are interchangeable). Objects are merged recursively. */
    nlohmann::json applyOverrides(const std::string &scenario, const nlohmann::json &defaults,
                                  const ScenarioOptions &options);
}  // namespace ropras::scenarios

#endif
