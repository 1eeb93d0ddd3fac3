#include "ropras/scenarios/TreeDump.h"

#include <cstdio>
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>

#include "ropras/core/Error.h"
#include "ropras/scenarios/ScenarioRegistry.h"
#include "ropras/scenarios/ViewerPage.h"

namespace ropras::scenarios
{
    std::string TreeDumpSettings::fileName(std::size_t call) const
    {
        return (std::filesystem::path(dir) / (prefix + "-plan" + std::to_string(call) + ".json")).string();
    }

    void TreeDumpSettings::parseCalls(const std::string &text)
    {
        calls.clear();
        allCalls = text == "all";
        if (allCalls)
        {
            return;
        }
        std::size_t value = 0;
        bool digits = false;
        for (std::size_t i = 0; i <= text.size(); ++i)
        {
            const char c = i < text.size() ? text[i] : ',';
            if (c >= '0' && c <= '9' && value < 100000000)
            {
                value = value * 10 + static_cast<std::size_t>(c - '0');
                digits = true;
            }
            else if (c == ',' && digits)
            {
                calls.insert(value);
                value = 0;
                digits = false;
            }
            else
            {
                throw Error("--dump-calls \"" + text +
                            "\": expected \"all\" or planning-call indices below 10^8 separated by commas, e.g. 0,5");
            }
        }
    }

    nlohmann::json treeToJson(const pomdp::TreeSnapshot &tree, std::size_t plan, std::size_t step)
    {
        using nlohmann::json;
        const auto id = [](std::uint32_t i) { return i == pomdp::TreeSnapshot::NONE ? json(nullptr) : json(i); };
        json beliefs = json::array();
        for (std::size_t i = 0; i < tree.beliefs.size(); ++i)
        {
            const auto &b = tree.beliefs[i];
            char key[19];
            std::snprintf(key, sizeof(key), "%016llx", static_cast<unsigned long long>(b.key));
            beliefs.push_back({{"id", i},
                               {"parent", id(b.parent)},
                               {"depth", b.depth},
                               {"steps", b.steps},
                               {"key", key},
                               {"visits", b.visits},
                               {"value", b.value},
                               {"particles", b.particles},
                               {"actions", b.children}});
        }
        json actions = json::array();
        for (std::size_t i = 0; i < tree.actions.size(); ++i)
        {
            const auto &a = tree.actions[i];
            actions.push_back({{"id", i},
                               {"parent", a.parent},
                               {"visits", a.visits},
                               {"q", a.q},
                               {"pi_star", a.piStar},
                               {"length", a.length},
                               {"macro", a.brief},
                               {"children", a.children}});
        }
        json levels = json::array();
        for (const auto &l : pomdp::treeLevelStatistics(tree))
        {
            const double n = static_cast<double>(l.beliefs);
            levels.push_back({{"beliefs", l.beliefs},
                              {"visited_once", l.visitedOnce},
                              {"visited_once_share", l.visitedOnce / n},
                              {"actions_per_belief", static_cast<double>(l.actions) / n},
                              {"observations_per_action",
                               l.actions > 0 ? static_cast<double>(l.observationChildren) / l.actions : 0.0},
                              {"particles_per_belief", static_cast<double>(l.particles) / n},
                              {"max_particles", l.maxParticles},
                              {"min_steps", l.minSteps},
                              {"max_steps", l.maxSteps}});
        }
        const double sims = static_cast<double>(tree.simulations);
        return {{"solver", tree.solver},
                {"plan", plan},
                {"step", step},
                {"simulations", tree.simulations},
                {"reference_requested", tree.referenceRequested},
                {"reference_per_simulation", sims > 0 ? tree.referenceRequested / sims : 0.0},
                {"levels", std::move(levels)},
                {"beliefs", std::move(beliefs)},
                {"actions", std::move(actions)}};
    }

    namespace
    {
        void writeText(const std::string &path, const std::string &text, const char *what)
        {
            std::ofstream file(path);
            file << text << '\n';
            if (!file)
            {
                throw Error(std::string("cannot write the search tree") + what + " \"" + path + "\"");
            }
        }
    }  // namespace

    void writeTreeJson(const std::string &path, const pomdp::TreeSnapshot &tree, std::size_t plan, std::size_t step)
    {
        writeText(path, treeToJson(tree, plan, step).dump(), "");
    }

    std::string treePage(const nlohmann::json &tree)
    {
        std::string page = embeddedFile("common/tree/tree.html");
        const std::string data = "/*@ROPRAS_TREE_DATA@*/";
        const std::string script = "/*@ROPRAS_TREE_SCRIPT@*/";
        const auto at = page.find(data);
        const auto sat = page.find(script);
        if (at == std::string::npos || sat == std::string::npos || sat < at)
        {
            throw Error("tree page template common/tree/tree.html: a placeholder is missing or out of order");
        }
        // the script goes in first (it comes later in the page), so that no placeholder text inside the data is
        // ever replaced
        page.replace(sat, script.size(), scriptSafe(embeddedFile("common/tree/tree.js")));
        page.replace(at, data.size(), scriptSafe(tree.dump(-1, ' ', false, nlohmann::json::error_handler_t::replace)));
        return page;
    }

    void writeTreeFiles(const std::string &jsonPath, const pomdp::TreeSnapshot &tree, std::size_t plan,
                        std::size_t step)
    {
        const nlohmann::json doc = treeToJson(tree, plan, step);
        writeText(jsonPath, doc.dump(), "");
        writeText(std::filesystem::path(jsonPath).replace_extension(".html").string(), treePage(doc), " page");
    }
}  // namespace ropras::scenarios
