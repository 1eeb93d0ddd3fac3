#include "ropras/pomdp/ParameterMap.h"

#include <cerrno>
#include <cmath>
#include <cstdio>
#include <cstdlib>

#include "ropras/core/Error.h"

namespace ropras::pomdp
{
    ParameterMap ParameterMap::parse(const std::vector<std::string> &entries)
    {
        ParameterMap map;
        for (const auto &entry : entries)
        {
            const auto eq = entry.find('=');
            if (eq == std::string::npos || eq == 0 || eq + 1 == entry.size())
            {
                throw Error("parameter \"" + entry + "\" is malformed: expected name=value");
            }
            const std::string name = entry.substr(0, eq);
            const std::string text = entry.substr(eq + 1);
            errno = 0;
            char *end = nullptr;
            const double value = std::strtod(text.c_str(), &end);
            if (end == text.c_str() || *end != '\0' || errno == ERANGE)
            {
                throw Error("parameter \"" + name + "\": value \"" + text + "\" is not a number");
            }
            if (map.contains(name))
            {
                throw Error("parameter \"" + name + "\" is given twice");
            }
            map.set(name, value);
        }
        return map;
    }

    void ParameterMap::set(const std::string &name, double value)
    {
        if (name.empty())
        {
            throw Error("parameter with an empty name");
        }
        if (!std::isfinite(value))
        {
            throw Error("parameter \"" + name + "\" = " + std::to_string(value) + " is not finite");
        }
        values_[name] = value;
    }

    double ParameterMap::get(const std::string &name, double fallback) const
    {
        used_.insert(name);
        const auto it = values_.find(name);
        return it == values_.end() ? fallback : it->second;
    }

    std::size_t ParameterMap::getCount(const std::string &name, std::size_t fallback, double max) const
    {
        const double value = get(name, static_cast<double>(fallback));
        if (value < 0.0 || value != std::floor(value))
        {
            throw Error("parameter \"" + name + "\" = " + std::to_string(value) + " must be a non-negative integer");
        }
        if (value > max)
        {
            char text[96];
            std::snprintf(text, sizeof(text), "%.17g exceeds the maximum %.17g", value, max);
            throw Error("parameter \"" + name + "\" = " + text);
        }
        return static_cast<std::size_t>(value);
    }

    void ParameterMap::requireAllUsed(const std::string &context, const std::set<std::string> &exempt) const
    {
        std::string unknown;
        for (const auto &entry : values_)
        {
            if (used_.count(entry.first) == 0 && exempt.count(entry.first) == 0)
            {
                unknown += (unknown.empty() ? "" : ", ") + entry.first;
            }
        }
        if (!unknown.empty())
        {
            std::set<std::string> valid = used_;
            valid.insert(exempt.begin(), exempt.end());
            std::string names;
            for (const auto &name : valid)
            {
                names += (names.empty() ? "" : ", ") + name;
            }
            throw Error("unknown parameter(s) for " + context + ": " + unknown + " (valid: " + names + ")");
        }
    }
}  // namespace ropras::pomdp
