#include <map>
#include <string>
#include <vector>

#include "ropras/core/Error.h"
#include "ropras/core/NameList.h"
#include "ropras/scenarios/ScenarioRegistry.h"

namespace ropras::scenarios
{
    namespace detail
    {
        const std::map<std::string, std::string> &embeddedFileTable();  // generated: EmbeddedFiles.cpp
    }

    const std::string &embeddedFile(const std::string &path)
    {
        const auto &table = detail::embeddedFileTable();
        const auto it = table.find(path);
        if (it == table.end())
        {
            throw Error("no embedded scenario file \"" + path + "\" (available: " + joinKeys(table) + ")");
        }
        return it->second;
    }

    std::vector<std::string> embeddedFiles()
    {
        std::vector<std::string> out;
        for (const auto &entry : detail::embeddedFileTable())
        {
            out.push_back(entry.first);
        }
        return out;
    }
}  // namespace ropras::scenarios
