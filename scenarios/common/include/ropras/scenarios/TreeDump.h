#ifndef ROPRAS_SCENARIOS_TREE_DUMP_H
#define ROPRAS_SCENARIOS_TREE_DUMP_H

#include <cstddef>
#include <nlohmann/json_fwd.hpp>
#include <set>
#include <string>

#include "ropras/pomdp/TreeSnapshot.h"

namespace ropras::scenarios
{
    /** \brief Which planning calls `ropras run --dump-tree DIR` writes, and where. */
    struct TreeDumpSettings
    {
        /// empty = no dump
        std::string dir;
        /// planning calls (0-based, per episode) to dump; ignored when allCalls
        std::set<std::size_t> calls{0};
        bool allCalls{false};
        /// the file name's start, "<scenario>-<solver>-<episode>" (set per episode by the experiment runner)
        std::string prefix;

        bool wants(std::size_t call) const { return !dir.empty() && (allCalls || calls.count(call) > 0); }
        /// DIR/<prefix>-plan<call>.json
        std::string fileName(std::size_t call) const;
        /** \brief Parses "all" or a comma-separated list of call indices ("0,5,10"); throws ropras::Error naming
            \a text otherwise. */
        void parseCalls(const std::string &text);
    };

    /** \brief The tree as JSON: {"solver", "plan", "step", "simulations", "reference_requested",
        "reference_per_simulation", "beliefs": [{"id", "parent", "depth", "steps", "key" (hex string), "visits",
        "value", "particles", "actions": [ids]}], "actions": [{"id", "parent", "visits", "q", "pi_star",
        "length", "macro", "children": [ids]}], "levels": per-depth statistics (treeLevelStatistics)}. */
    nlohmann::json treeToJson(const pomdp::TreeSnapshot &tree, std::size_t plan, std::size_t step);

    /** \brief Writes treeToJson() to \a path; throws ropras::Error naming the file when it cannot be written. */
    void writeTreeJson(const std::string &path, const pomdp::TreeSnapshot &tree, std::size_t plan, std::size_t step);

    /** \brief One standalone HTML page (inline script, works offline) drawing \a tree (a treeToJson() document) as a
        collapsible tree: per belief node visits, V, particles, depth, primitive steps and the observation key; per
        action node visits, Q, pi* and the macro in brief (scenarios/common/tree/, doc/pomdp.md). */
    std::string treePage(const nlohmann::json &tree);

    /** \brief Writes treeToJson() to \a jsonPath and treePage() beside it (the same name ending in .html); throws
        ropras::Error naming the file that cannot be written. */
    void writeTreeFiles(const std::string &jsonPath, const pomdp::TreeSnapshot &tree, std::size_t plan,
                        std::size_t step);
}  // namespace ropras::scenarios

#endif
