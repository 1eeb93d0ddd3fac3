#include "ropras/scenarios/ConfigReader.h"

#include <cmath>
#include <utility>

#include "ropras/core/Error.h"

namespace ropras::scenarios
{
    ConfigReader::ConfigReader(std::string scenario, const nlohmann::json &json, std::string prefix)
        : scenario_(std::move(scenario)), json_(json), prefix_(std::move(prefix))
    {
        if (!json_.is_object())
        {
            if (prefix_.empty())
            {
                throw Error("scenario " + scenario_ + ": the configuration must be a JSON object");
            }
            throw Error("scenario " + scenario_ + ": key \"" + prefix_.substr(0, prefix_.size() - 1) +
                        "\" must be an object, not " + json_.dump());
        }
    }

    void ConfigReader::fail(const std::string &key, const std::string &problem) const
    {
        throw Error("scenario " + scenario_ + ": key \"" + prefix_ + key + "\" " + problem);
    }

    void ConfigReader::requireKnown(const std::set<std::string> &known) const
    {
        for (const auto &item : json_.items())
        {
            if (known.count(item.key()) == 0)
            {
                fail(item.key(), "is unknown");
            }
        }
    }

    const nlohmann::json &ConfigReader::at(const std::string &key) const
    {
        const auto it = json_.find(key);
        if (it == json_.end())
        {
            fail(key, "is missing");
        }
        return *it;
    }

    ConfigReader ConfigReader::sub(const std::string &key) const
    {
        return ConfigReader(scenario_, at(key), prefix_ + key + ".");
    }

    double ConfigReader::number(const std::string &key) const
    {
        return number(key, at(key));
    }

    double ConfigReader::number(const std::string &key, const nlohmann::json &value) const
    {
        if (!value.is_number())
        {
            fail(key, "must be a number, not " + value.dump());
        }
        const double v = value.get<double>();
        if (!std::isfinite(v))
        {
            fail(key, "= " + value.dump() + " is not finite");
        }
        return v;
    }

    double ConfigReader::positive(const std::string &key) const
    {
        const double v = number(key);
        if (!(v > 0.0))
        {
            fail(key, "= " + nlohmann::json(v).dump() + " must be > 0");
        }
        return v;
    }

    double ConfigReader::nonNegative(const std::string &key) const
    {
        const double v = number(key);
        if (!(v >= 0.0))
        {
            fail(key, "= " + nlohmann::json(v).dump() + " must be >= 0");
        }
        return v;
    }

    double ConfigReader::within(const std::string &key, double lo, double hi) const
    {
        const double v = number(key);
        if (!(v >= lo && v <= hi))
        {
            fail(key, "= " + nlohmann::json(v).dump() + " must be in [" + nlohmann::json(lo).dump() + ", " +
                          nlohmann::json(hi).dump() + "]");
        }
        return v;
    }

    std::size_t ConfigReader::count(const std::string &key, std::size_t lo, std::size_t hi) const
    {
        const double v = number(key);
        if (!(v >= static_cast<double>(lo) && v <= static_cast<double>(hi)) || v != std::floor(v))
        {
            fail(key, "= " + nlohmann::json(v).dump() + " must be an integer in [" + std::to_string(lo) + ", " +
                          std::to_string(hi) + "]");
        }
        return static_cast<std::size_t>(v);
    }

    bool ConfigReader::boolean(const std::string &key) const
    {
        const auto &value = at(key);
        if (!value.is_boolean())
        {
            fail(key, "must be true or false, not " + value.dump());
        }
        return value.get<bool>();
    }

    std::string ConfigReader::choice(const std::string &key, const std::vector<std::string> &choices) const
    {
        const auto &value = at(key);
        std::string listed;
        for (const auto &c : choices)
        {
            if (value.is_string() && value.get<std::string>() == c)
                return c;
            listed += (listed.empty() ? "\"" : (&c == &choices.back() ? " or \"" : ", \"")) + c + "\"";
        }
        fail(key, "must be " + listed + ", not " + value.dump());
    }

    std::vector<double> ConfigReader::numbersOf(const std::string &key, const nlohmann::json &value,
                                                std::size_t n) const
    {
        if (!value.is_array() || (n > 0 && value.size() != n) || value.empty())
        {
            fail(key, "must be an array of " + (n > 0 ? std::to_string(n) : std::string("some")) + " numbers, not " +
                          value.dump());
        }
        std::vector<double> out;
        for (const auto &v : value)
        {
            out.push_back(number(key, v));
        }
        return out;
    }

    std::vector<double> ConfigReader::numbers(const std::string &key, std::size_t n) const
    {
        return numbersOf(key, at(key), n);
    }

    std::vector<std::vector<double>> ConfigReader::rows(const std::string &key, std::size_t n) const
    {
        const auto &list = at(key);
        if (!list.is_array())
        {
            fail(key, "must be an array, not " + list.dump());
        }
        std::vector<std::vector<double>> out;
        for (std::size_t i = 0; i < list.size(); ++i)
        {
            out.push_back(numbersOf(key + "[" + std::to_string(i) + "]", list[i], n));
        }
        return out;
    }

    std::map<std::string, std::map<std::string, double>> ConfigReader::solverDefaults() const
    {
        std::map<std::string, std::map<std::string, double>> out;
        if (!json_.contains("solver_defaults"))
        {
            return out;
        }
        const auto &perSolver = at("solver_defaults");
        if (!perSolver.is_object())
        {
            fail("solver_defaults", "must be an object {solver: {parameter: number}}, not " + perSolver.dump());
        }
        for (const auto &solver : perSolver.items())
        {
            const std::string key = "solver_defaults." + solver.key();
            if (!solver.value().is_object())
            {
                fail(key, "must be an object of solver parameters, not " + solver.value().dump());
            }
            auto &own = out[solver.key()];
            for (const auto &item : solver.value().items())
            {
                own[item.key()] = number(key + "." + item.key(), item.value());
            }
        }
        return out;
    }
}  // namespace ropras::scenarios
