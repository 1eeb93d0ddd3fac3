#include "model/SrdfGroups.h"

#include <algorithm>
#include <set>

#include "ropras/core/Error.h"

namespace ropras::ompl_ext
{
    namespace
    {
        class GroupResolver
        {
        public:
            GroupResolver(const SrdfDocument &srdf, const std::vector<Link> &links,
                          const std::vector<UrdfJoint> &joints, const std::string &sourceName)
                : srdf_(srdf), links_(links), joints_(joints), source_(sourceName)
            {
            }

            void add(const std::string &name, std::set<int> &out)
            {
                const auto group = std::find_if(srdf_.groups.begin(), srdf_.groups.end(),
                                                [&](const SrdfGroup &g) { return g.name == name; });
                if (group == srdf_.groups.end())
                {
                    std::string known;
                    for (const SrdfGroup &g : srdf_.groups)
                        known += (known.empty() ? "" : ", ") + g.name;
                    throw Error("SRDF '" + source_ + "': no group '" + name + "'" +
                                (open_.empty() ? "" : " (a subgroup of '" + open_.back() + "')") +
                                "; groups: " + (known.empty() ? "(none)" : known));
                }
                if (std::find(open_.begin(), open_.end(), name) != open_.end())
                    fail(*group, "contains itself through its subgroups");
                open_.push_back(name);
                for (const std::string &joint : group->joints)
                    out.insert(jointIndex(*group, joint));
                for (const std::string &link : group->links)
                    if (const int parent = links_[linkIndex(*group, link)].parentJoint; parent >= 0)
                        out.insert(parent);
                for (const auto &[base, tip] : group->chains)
                    addChain(*group, linkIndex(*group, base), linkIndex(*group, tip), out);
                for (const std::string &subgroup : group->subgroups)
                    add(subgroup, out);
                open_.pop_back();
            }

        private:
            [[noreturn]] void fail(const SrdfGroup &group, const std::string &what) const
            {
                throw Error("SRDF '" + source_ + "': line " + std::to_string(group.line) + ": group '" + group.name +
                            "' " + what);
            }

            int jointIndex(const SrdfGroup &group, const std::string &name) const
            {
                for (std::size_t i = 0; i < joints_.size(); ++i)
                    if (joints_[i].name == name)
                        return static_cast<int>(i);
                fail(group, "names joint '" + name + "', which the URDF does not define");
            }

            int linkIndex(const SrdfGroup &group, const std::string &name) const
            {
                for (std::size_t i = 0; i < links_.size(); ++i)
                    if (links_[i].name == name)
                        return static_cast<int>(i);
                fail(group, "names link '" + name + "', which the URDF does not define");
            }

            /// the joints on the tree path between the two links (up from each to their deepest common ancestor)
            void addChain(const SrdfGroup &group, int base, int tip, std::set<int> &out) const
            {
                std::set<int> baseAncestors;
                for (int l = base; l >= 0;)
                {
                    baseAncestors.insert(l);
                    const int j = links_[l].parentJoint;
                    l = j < 0 ? -1 : joints_[j].parentLink;
                }
                int common = tip;
                while (baseAncestors.count(common) == 0)
                {
                    const int j = links_[common].parentJoint;
                    if (j < 0)
                        fail(group, "has a chain whose links '" + links_[base].name + "' and '" + links_[tip].name +
                                        "' are not connected");
                    out.insert(j);
                    common = joints_[j].parentLink;
                }
                for (int l = base; l != common;)
                {
                    const int j = links_[l].parentJoint;
                    out.insert(j);
                    l = joints_[j].parentLink;
                }
            }

            const SrdfDocument &srdf_;
            const std::vector<Link> &links_;
            const std::vector<UrdfJoint> &joints_;
            const std::string &source_;
            std::vector<std::string> open_;  ///< the groups being expanded (cycle check)
        };
    }  // namespace

    std::vector<int> srdfGroupJoints(const SrdfDocument &srdf, const std::string &name, const std::vector<Link> &links,
                                     const std::vector<UrdfJoint> &joints, const std::string &sourceName)
    {
        std::set<int> out;
        GroupResolver(srdf, links, joints, sourceName).add(name, out);
        return {out.begin(), out.end()};
    }
}  // namespace ropras::ompl_ext
