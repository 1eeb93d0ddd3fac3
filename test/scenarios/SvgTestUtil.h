#ifndef ROPRAS_TEST_SCENARIOS_SVG_TEST_UTIL_H
#define ROPRAS_TEST_SCENARIOS_SVG_TEST_UTIL_H
// Looking into the SVG of `ropras render` (parsed with tinyxml2) in the renderer's tests.

#include <tinyxml2.h>

#include <string>

namespace ropras::scenarios::test
{
    /// the first element with id \a id among \a e, its siblings and their descendants (depth first), or nullptr
    inline const tinyxml2::XMLElement *findById(const tinyxml2::XMLElement *e, const std::string &id)
    {
        for (; e; e = e->NextSiblingElement())
        {
            if (e->Attribute("id") && id == e->Attribute("id"))
                return e;
            if (const auto *inner = findById(e->FirstChildElement(), id))
                return inner;
        }
        return nullptr;
    }
}  // namespace ropras::scenarios::test

#endif
