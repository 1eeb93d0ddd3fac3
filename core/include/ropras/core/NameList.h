#ifndef ROPRAS_CORE_NAME_LIST_H
#define ROPRAS_CORE_NAME_LIST_H

#include <string>

namespace ropras
{
    /** \brief "a, b, c": the names in \a names (any range of strings), for the error messages that list the
        valid names after an unknown one. */
    template <class Names>
    std::string joinNames(const Names &names)
    {
        std::string out;
        for (const auto &name : names)
            out += (out.empty() ? "" : ", ") + std::string(name);
        return out;
    }

    /** \brief "a, b, c": the keys of \a map (a std::map lists them sorted). */
    template <class Map>
    std::string joinKeys(const Map &map)
    {
        std::string out;
        for (const auto &entry : map)
            out += (out.empty() ? "" : ", ") + std::string(entry.first);
        return out;
    }
}  // namespace ropras

#endif
