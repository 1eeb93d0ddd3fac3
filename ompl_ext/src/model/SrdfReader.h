#ifndef ROPRAS_OMPL_EXT_SRC_SRDF_READER_H
#define ROPRAS_OMPL_EXT_SRC_SRDF_READER_H

#include <string>
#include <utility>
#include <vector>

namespace ropras::ompl_ext
{
    /** \brief `<disable_collisions link1=".." link2=".."/>`, with its line for messages. */
    struct SrdfDisabledPair
    {
        std::string link1, link2;
        int line{0};
    };

    /** \brief `<group name="..">` as MoveIt's SRDF defines it: `<joint name>`, `<link name>` (its parent joint),
        `<chain base_link tip_link>` (the joints between them) and `<group name>` (a subgroup's joints). */
    struct SrdfGroup
    {
        std::string name;
        int line{0};
        std::vector<std::string> joints, links, subgroups;
        std::vector<std::pair<std::string, std::string>> chains;  ///< (base_link, tip_link)
    };

    /** \brief The parts of an SRDF document ropras reads: disabled collision pairs and groups (group states, end
        effectors and virtual joints are ignored). Names are checked against the URDF by the caller. */
    struct SrdfDocument
    {
        std::vector<SrdfDisabledPair> disabledPairs;
        std::vector<SrdfGroup> groups;
        std::vector<std::string> warnings;  ///< elements skipped as srdfdom skips them (unknown group members)
    };

    /** \brief Parses \a srdfXml. Throws ropras::Error naming \a sourceName and the line on malformed XML, a root
        other than `<robot>`, a missing attribute or a group defined twice. */
    SrdfDocument readSrdf(const std::string &srdfXml, const std::string &sourceName);
}  // namespace ropras::ompl_ext

#endif
