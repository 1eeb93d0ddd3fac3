#include "ropras/pomdp/ModelRegistry.h"

#include "ropras/core/Error.h"
#include "ropras/core/NameList.h"
#include "ropras/pomdp/Tiger.h"

namespace ropras::pomdp
{
    void ModelRegistry::add(ModelEntry entry)
    {
        if (entry.name.empty() || !entry.factory)
        {
            throw Error("ModelRegistry: a model needs a name and a factory (name \"" + entry.name + "\")");
        }
        if (entries_.count(entry.name) != 0)
        {
            throw Error("ModelRegistry: model \"" + entry.name + "\" is registered twice");
        }
        auto name = entry.name;
        entries_.emplace(std::move(name), std::move(entry));
    }

    const ModelEntry &ModelRegistry::get(const std::string &name) const
    {
        const auto it = entries_.find(name);
        if (it == entries_.end())
        {
            throw Error("unknown model \"" + name + "\" (known: " + joinKeys(entries_) + ")");
        }
        return it->second;
    }

    std::vector<std::string> ModelRegistry::names() const
    {
        std::vector<std::string> out;
        for (const auto &entry : entries_)
        {
            out.push_back(entry.first);
        }
        return out;
    }

    ModelRegistry &modelRegistry()
    {
        static ModelRegistry registry = []
        {
            ModelRegistry r;
            registerTiger(r);
            return r;
        }();
        return registry;
    }
}  // namespace ropras::pomdp
