#ifndef ROPRAS_OMPL_EXT_SRC_SRDF_READER_H
#define ROPRAS_OMPL_EXT_SRC_SRDF_READER_H

#include <string>
#include <utility>
#include <vector>

namespace ropras::ompl_ext
{
    /** \brief Link pairs named by `<disable_collisions link1=".." link2=".."/>` in an SRDF document.
        Only that element is read; the rest of the SRDF (groups, states, virtual joints) is ignored.
        Throws ropras::Error naming \a sourceName on malformed XML, a missing attribute or a link name not in
        \a knownLinks. */
    std::vector<std::pair<std::string, std::string>> readSrdfDisabledPairs(const std::string &srdfXml,
                                                                           const std::string &sourceName,
                                                                           const std::vector<std::string> &knownLinks);
}  // namespace ropras::ompl_ext

#endif
