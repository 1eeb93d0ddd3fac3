#include "model/SrdfReader.h"

#include <tinyxml2.h>

#include <set>
#include <string>

#include "ropras/core/Error.h"

namespace ropras::ompl_ext
{
    namespace
    {
        /// the attribute \a name of \a e, which must be there
        std::string attribute(const tinyxml2::XMLElement *e, const char *name, const std::string &sourceName)
        {
            const char *value = e->Attribute(name);
            if (value == nullptr)
                throw Error("SRDF '" + sourceName + "': <" + e->Name() + "> on line " +
                            std::to_string(e->GetLineNum()) + " lacks the " + name + " attribute");
            return value;
        }

        SrdfGroup readGroup(const tinyxml2::XMLElement *e, const std::string &sourceName,
                            std::vector<std::string> &warnings)
        {
            SrdfGroup group;
            group.name = attribute(e, "name", sourceName);
            group.line = e->GetLineNum();
            for (const tinyxml2::XMLElement *c = e->FirstChildElement(); c != nullptr; c = c->NextSiblingElement())
            {
                const std::string tag = c->Name();
                if (tag == "joint")
                    group.joints.push_back(attribute(c, "name", sourceName));
                else if (tag == "link")
                    group.links.push_back(attribute(c, "name", sourceName));
                else if (tag == "group")
                    group.subgroups.push_back(attribute(c, "name", sourceName));
                else if (tag == "chain")
                    group.chains.emplace_back(attribute(c, "base_link", sourceName),
                                              attribute(c, "tip_link", sourceName));
                else  // srdfdom reads only the four members and skips the rest
                    warnings.push_back("SRDF '" + sourceName + "': line " + std::to_string(c->GetLineNum()) + ": <" +
                                       tag + "> in <group name=\"" + group.name +
                                       "\"> skipped (a group holds joint, link, chain and group elements)");
            }
            return group;
        }
    }  // namespace

    SrdfDocument readSrdf(const std::string &srdfXml, const std::string &sourceName)
    {
        tinyxml2::XMLDocument doc;
        if (doc.Parse(srdfXml.c_str(), srdfXml.size()) != tinyxml2::XML_SUCCESS)
            throw Error("SRDF '" + sourceName + "': malformed XML: " + (doc.ErrorStr() ? doc.ErrorStr() : "?"));
        const tinyxml2::XMLElement *robot = doc.RootElement();
        if (robot == nullptr || std::string(robot->Name()) != "robot")
            throw Error("SRDF '" + sourceName + "': the root element must be <robot>");
        SrdfDocument out;
        for (const tinyxml2::XMLElement *e = robot->FirstChildElement("disable_collisions"); e != nullptr;
             e = e->NextSiblingElement("disable_collisions"))
        {
            if (e->Attribute("link1") == nullptr || e->Attribute("link2") == nullptr)
                throw Error("SRDF '" + sourceName + "': <disable_collisions> on line " +
                            std::to_string(e->GetLineNum()) + " lacks the link1 or link2 attribute");
            out.disabledPairs.push_back({e->Attribute("link1"), e->Attribute("link2"), e->GetLineNum()});
        }
        std::set<std::string> names;
        for (const tinyxml2::XMLElement *e = robot->FirstChildElement("group"); e != nullptr;
             e = e->NextSiblingElement("group"))
        {
            SrdfGroup group = readGroup(e, sourceName, out.warnings);
            if (!names.insert(group.name).second)
                throw Error("SRDF '" + sourceName + "': <group name=\"" + group.name + "\"> on line " +
                            std::to_string(group.line) + " is defined twice");
            out.groups.push_back(std::move(group));
        }
        return out;
    }
}  // namespace ropras::ompl_ext
