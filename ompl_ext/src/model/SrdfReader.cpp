#include "model/SrdfReader.h"

#include <tinyxml2.h>

#include <string>
#include <unordered_set>

#include "ropras/core/Error.h"

namespace ropras::ompl_ext
{
    std::vector<std::pair<std::string, std::string>> readSrdfDisabledPairs(const std::string &srdfXml,
                                                                           const std::string &sourceName,
                                                                           const std::vector<std::string> &knownLinks)
    {
        tinyxml2::XMLDocument doc;
        if (doc.Parse(srdfXml.c_str(), srdfXml.size()) != tinyxml2::XML_SUCCESS)
        {
            throw Error("SRDF '" + sourceName + "': malformed XML: " + (doc.ErrorStr() ? doc.ErrorStr() : "?"));
        }
        const tinyxml2::XMLElement *robot = doc.RootElement();
        if (robot == nullptr || std::string(robot->Name()) != "robot")
        {
            throw Error("SRDF '" + sourceName + "': the root element must be <robot>");
        }
        const std::unordered_set<std::string> names(knownLinks.begin(), knownLinks.end());  // O(1) per lookup
        auto known = [&](const char *name) { return names.count(name) != 0; };
        std::vector<std::pair<std::string, std::string>> pairs;
        for (const tinyxml2::XMLElement *e = robot->FirstChildElement("disable_collisions"); e != nullptr;
             e = e->NextSiblingElement("disable_collisions"))
        {
            const char *a = e->Attribute("link1");
            const char *b = e->Attribute("link2");
            if (a == nullptr || b == nullptr)
            {
                throw Error("SRDF '" + sourceName + "': <disable_collisions> on line " +
                            std::to_string(e->GetLineNum()) + " lacks the link1 or link2 attribute");
            }
            for (const char *name : {a, b})
            {
                if (!known(name))
                {
                    throw Error("SRDF '" + sourceName + "': <disable_collisions> on line " +
                                std::to_string(e->GetLineNum()) + " names link '" + name +
                                "', which the URDF does not define");
                }
            }
            pairs.emplace_back(a, b);
        }
        return pairs;
    }
}  // namespace ropras::ompl_ext
