#include "ropras/scenarios/ScenarioRegistry.h"

#include <cmath>

#include "BuiltinScenarios.h"
#include "ropras/core/Error.h"
#include "ropras/core/NameList.h"

namespace ropras::scenarios
{
    void ScenarioRegistry::add(ScenarioEntry entry)
    {
        if (entry.name.empty() || !entry.factory)
        {
            throw Error("ScenarioRegistry: a scenario needs a name and a factory");
        }
        if (entries_.count(entry.name) != 0)
        {
            throw Error("ScenarioRegistry: scenario \"" + entry.name + "\" is registered twice");
        }
        const std::string name = entry.name;
        entries_.emplace(name, std::move(entry));
    }

    const ScenarioEntry &ScenarioRegistry::get(const std::string &name) const
    {
        const auto it = entries_.find(name);
        if (it == entries_.end())
        {
            throw Error("unknown scenario \"" + name + "\" (known: " + joinKeys(entries_) + ")");
        }
        return it->second;
    }

    std::vector<std::string> ScenarioRegistry::names() const
    {
        std::vector<std::string> out;
        for (const auto &entry : entries_)
        {
            out.push_back(entry.first);
        }
        return out;
    }

    const ScenarioRegistry &scenarioRegistry()
    {
        static const ScenarioRegistry registry = []
        {
            ScenarioRegistry r;
            detail::addBuiltinScenarios(r);
            return r;
        }();
        return registry;
    }

    namespace
    {
        void merge(const std::string &where, const nlohmann::json &defaults, const nlohmann::json &overrides,
                   const std::string &prefix, nlohmann::json &out)
        {
            if (!overrides.is_object())
            {
                throw Error(where + ": " + (prefix.empty() ? std::string("the configuration") : "\"" + prefix + "\"") +
                            " must be a JSON object");
            }
            for (const auto &item : overrides.items())
            {
                const std::string key = prefix.empty() ? item.key() : prefix + "." + item.key();
                const auto it = defaults.find(item.key());
                if (it == defaults.end())
                {
                    std::string known;
                    for (const auto &d : defaults.items())
                    {
                        known += (known.empty() ? "" : ", ") + d.key();
                    }
                    throw Error(where + ": unknown key \"" + key + "\" (known here: " + known + ")");
                }
                const auto &value = item.value();
                if (it->is_object())
                {
                    merge(where, *it, value, key, out[item.key()]);
                    continue;
                }
                const bool sameType =
                    (it->is_number() && value.is_number()) || it->type() == value.type() || it->is_null();
                if (!sameType)
                {
                    const std::string expected = it->type_name();
                    const bool vowel = expected.find_first_of("aeiou") == 0;
                    throw Error(where + ": key \"" + key + "\" must be " + (vowel ? "an " : "a ") + expected +
                                ", not " + std::string(value.type_name()) + " (" + value.dump() + ")");
                }
                if (value.is_number_float() && !std::isfinite(value.get<double>()))
                {
                    throw Error(where + ": key \"" + key + "\" is not finite");
                }
                out[item.key()] = value;
            }
        }
    }  // namespace

    std::unique_ptr<Scenario> ScenarioRegistry::create(const std::string &name, const ScenarioOptions &options) const
    {
        const ScenarioEntry &entry = get(name);
        try
        {
            return entry.factory(options);
        }
        catch (const Error &e)
        {
            const std::string message = e.what();
            if (options.overrides.empty() || message.find(options.source) != std::string::npos)
            {
                throw;
            }
            throw Error(options.source + ": " + message);
        }
    }

    nlohmann::json applyOverrides(const std::string &scenario, const nlohmann::json &defaults,
                                  const ScenarioOptions &options)
    {
        nlohmann::json out = defaults;
        merge(options.source + " (scenario " + scenario + ")", defaults, options.overrides, "", out);
        return out;
    }
}  // namespace ropras::scenarios
