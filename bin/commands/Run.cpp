// `ropras run`: episodes of a built-in scenario with a solver, in parallel threads; JSON lines and the table.
#include <unistd.h>

#include <ompl/util/Console.h>
#include <algorithm>
#include <cstdio>
#include <fstream>
#include <iostream>
#include <memory>
#include <nlohmann/json.hpp>
#include <sstream>
#include <string>
#include <vector>

#include "ArgumentChecks.h"
#include "CommandRegistry.h"
#include "OutputChecks.h"
#include "ProgressBar.h"
#include "ropras/core/Error.h"
#include "ropras/core/InputFile.h"
#include "ropras/scenarios/ExperimentRunner.h"
#include "ropras/scenarios/JsonLinesAppender.h"
#include "ropras/scenarios/ResultTable.h"
#include "ropras/scenarios/ScenarioRegistry.h"

namespace
{
    struct RunOptions
    {
        std::string scenario;
        std::string solver{"ropras3"};
        std::string heuristic{"dynamic"};
        double epsilon{0.0};
        std::string planner{"VectorizedRRTConnect"};
        std::size_t episodes{30};
        double planTime{0.0};
        std::size_t sims{0};
        std::uint64_t seed{1};
        std::size_t threads{0};
        std::string shard{"0/1"};
        std::string out;
        std::string record;
        std::size_t beliefEvery{0};
        std::size_t maxParticles{200};
        std::string dumpTree;
        std::string dumpCalls{"0"};
        std::vector<std::string> params;
        std::string config;
        bool replanEveryStep{false};
        bool printConfig{false};
        bool listScenarios{false};
        bool quiet{false};
    };

    ropras::scenarios::ScenarioOptions scenarioOptions(const std::string &path)
    {
        ropras::scenarios::ScenarioOptions options;
        if (path.empty())
        {
            return options;
        }
        const std::string text = ropras::readInputFile(path, "--config");
        try
        {
            options.overrides = nlohmann::json::parse(text);
        }
        catch (const nlohmann::json::exception &e)  // parse_error, and out_of_range for 1e400
        {
            throw ropras::Error("--config \"" + path + "\": malformed JSON: " + e.what());
        }
        if (!options.overrides.is_object())
        {
            throw ropras::Error("--config \"" + path + "\": must be a JSON object of configuration keys, not " +
                                std::string(options.overrides.type_name()));
        }
        options.source = path;
        return options;
    }

    int run(const RunOptions &o)
    {
        namespace sc = ropras::scenarios;
        ropras::bin::refuseOverwritingInputs("--out", o.out, {o.config});
        ompl::msg::setLogLevel(ompl::msg::LOG_WARN);  // OMPL's per-plan info lines would drown the progress
        const auto &registry = sc::scenarioRegistry();
        if (o.listScenarios)
        {
            for (const auto &name : registry.names())
            {
                std::cout << name << ": " << registry.get(name).description << '\n';
            }
            return 0;
        }
        if (o.scenario.empty())
        {
            throw ropras::Error("--scenario is required (known: " +
                                [&]
                                {
                                    std::string known;
                                    for (const auto &n : registry.names())
                                        known += (known.empty() ? "" : ", ") + n;
                                    return known;
                                }() +
                                ")");
        }
        const auto scenario = registry.create(o.scenario, scenarioOptions(o.config));

        sc::ExperimentSettings settings;
        settings.run.solver = o.solver;
        settings.run.heuristic = o.heuristic;
        settings.run.epsilon = o.epsilon;
        settings.run.planner = o.planner;
        settings.run.budget = ropras::pomdp::Budget{o.sims, o.planTime};
        settings.run.replanEveryStep = o.replanEveryStep;
        settings.run.params = ropras::pomdp::ParameterMap::parse(o.params);
        settings.episodes = o.episodes;
        settings.seed = o.seed;
        settings.threads = o.threads;
        settings.shard = sc::Shard::parse(o.shard);
        settings.recordDir = o.record;
        settings.record.beliefEvery = o.beliefEvery;
        settings.record.maxParticles = o.maxParticles;
        settings.record.tree.dir = o.dumpTree;
        settings.record.tree.parseCalls(o.dumpCalls);

        // every setting is checked before anything is written or started
        const auto resolved = sc::resolvedRunSettings(*scenario, settings.run);
        scenario->validate(resolved);
        if (o.printConfig)
        {
            std::cout << sc::experimentConfiguration(*scenario, settings, resolved).dump(2) << '\n';
            return 0;
        }

        std::unique_ptr<sc::JsonLinesAppender> out;
        if (!o.out.empty())
        {
            out = std::make_unique<sc::JsonLinesAppender>(o.out, "--out");
            if (out->repairedLine() > 0)
            {
                std::cerr << "ropras run: warning: " << o.out << ":" << out->repairedLine()
                          << " was a truncated record (an interrupted run); it is ended with a newline so that "
                             "the new records start on their own lines (`ropras table` skips it)\n";
            }
        }

        const bool terminal = isatty(fileno(stderr)) != 0;
        std::size_t successes = 0;
        if (!o.quiet)
        {
            const std::size_t owned = settings.shard.ownedCount(settings.episodes);
            const auto &b = resolved.budget;
            std::cerr << "ropras run: " << scenario->name() << " / " << o.solver << ", " << owned << " of "
                      << settings.episodes << " episodes (shard " << settings.shard.str() << "), "
                      << (b.simulations > 0 ? std::to_string(b.simulations) + " simulations"
                                            : std::to_string(b.seconds) + " s")
                      << " per plan, seed " << o.seed << '\n';
        }
        sc::ExperimentCallbacks callbacks;
        callbacks.onRecord = [&](const nlohmann::json &record)
        {
            if (out)
            {
                out->append(record.dump());
            }
        };
        callbacks.onProgress = [&](const sc::ExperimentProgress &p)
        {
            if (o.quiet)
            {
                return;
            }
            const double eta = ropras::bin::remainingSeconds(p.elapsedSeconds, p.done, p.total);
            const auto &r = *p.record;
            successes += r["success"].get<bool>() ? 1 : 0;
            if (terminal)
            {
                std::cerr << "\r" << ropras::bin::progressBar(p.done, p.total) << " " << p.done << "/" << p.total
                          << " episodes, " << successes << " successes, "
                          << ropras::bin::formatDuration(p.elapsedSeconds) << " elapsed, ETA "
                          << ropras::bin::formatDuration(eta) << "   " << std::flush;
                if (p.done == p.total)
                {
                    std::cerr << '\n';
                }
            }
            else
            {
                char line[256];
                std::snprintf(line, sizeof(line),
                              "episode %zu done (%zu/%zu): %s, return %.1f, %zu steps, %.0f sims/call; elapsed %s, "
                              "ETA %s",
                              r["episode"].get<std::size_t>(), p.done, p.total,
                              r["success"].get<bool>() ? "success" : "failure", r["undiscounted_return"].get<double>(),
                              r["steps"].get<std::size_t>(), r["sims_per_call"].get<double>(),
                              ropras::bin::formatDuration(p.elapsedSeconds).c_str(),
                              ropras::bin::formatDuration(eta).c_str());
                std::cerr << line << '\n';
            }
        };

        const auto records = sc::runExperiment(*scenario, settings, callbacks);
        if (records.empty())
        {
            std::cerr << "ropras run: shard " << settings.shard.str() << " of " << settings.episodes
                      << " episodes owns no episode\n";
            return 0;
        }
        std::size_t capped = 0;
        for (const auto &record : records)
            capped += record.value("memory_capped_plans", std::size_t(0));
        if (capped > 0)
        {
            std::cerr << "ropras run: warning: " << capped
                      << " planning calls stopped early because the search tree reached its memory cap (solver "
                         "parameter max_tree_mb, default 1024 MiB per thread; see memory_capped_plans in the "
                         "records)\n";
        }
        sc::ResultTable table;
        for (std::size_t i = 0; i < records.size(); ++i)
        {
            table.add(records[i], "episode " + records[i]["episode"].dump());
        }
        std::cout << table.markdown();
        return 0;
    }

    std::function<int()> setup(CLI::App &app)
    {
        auto o = std::make_shared<RunOptions>();
        app.add_option(
            "--scenario", o->scenario,
            "Scenario: light-dark, maze2d, random3d-1 ... random3d-4, multi-drone, sphere-search, shelf-move");
        app.add_option("--solver", o->solver, "ropras3, pomcp, rpomcp, bplan or refbasic")->capture_default_str();
        app.add_option("--heuristic", o->heuristic, "Sampling heuristic of the reference policy: uniform or dynamic")
            ->capture_default_str();
        app.add_option("--epsilon", o->epsilon, "Epsilon-greedy exploration mixed into the heuristic, in [0, 1]")
            ->capture_default_str()
            ->check(ropras::bin::NON_NEGATIVE_NUMBER);
        app.add_option("--planner", o->planner, "OMPL planner of the reference policy (any registered name)")
            ->capture_default_str();
        app.add_option("--episodes", o->episodes, "Episodes of the experiment (all shards together, at most 10^6)")
            ->capture_default_str()
            ->check(ropras::bin::EPISODES);
        auto *planTime =
            app.add_option("--plan-time", o->planTime,
                           "Seconds per planning call (default: the scenario's, a tenth of the paper's; at most 86400)")
                ->check(ropras::bin::PLAN_SECONDS);
        auto *sims =
            app.add_option("--sims", o->sims, "Simulations per planning call (exactly reproducible; at most 10^9)")
                ->check(ropras::bin::SIMULATIONS);
        planTime->excludes(sims);
        app.add_option("--seed", o->seed, "Run seed; episode e runs with a seed mixed from (seed, e)")
            ->capture_default_str()
            ->check(ropras::bin::SEED);
        app.add_option("--threads", o->threads, "Worker threads (0 = hardware concurrency; at most 1024)")
            ->capture_default_str()
            ->check(ropras::bin::countCheck(0, 1024, "COUNT"));
        app.add_option("--shard", o->shard, "Run only episodes e with e % N == i (i/N, e.g. 3/10)")
            ->capture_default_str();
        app.add_option("--out", o->out, "Append one JSON line per episode to this file");
        app.add_option("--record", o->record, "Write DIR/<scenario>-<solver>-<episode>.json for `ropras render`");
        app.add_option("--belief-every", o->beliefEvery,
                       "With --record: belief particles every K steps (0 = at the start and the end)")
            ->capture_default_str()
            ->check(ropras::bin::NON_NEGATIVE_COUNT);
        app.add_option("--max-particles", o->maxParticles, "With --record: at most this many particles per belief")
            ->capture_default_str()
            ->check(ropras::bin::POSITIVE_COUNT);
        app.add_option("--dump-tree", o->dumpTree,
                       "Write the search tree of chosen planning calls as JSON: "
                       "DIR/<scenario>-<solver>-<episode>-plan<k>.json");
        app.add_option("--dump-calls", o->dumpCalls,
                       "With --dump-tree: planning calls (0-based, per episode) to write, e.g. 0,5,10, or all")
            ->capture_default_str();
        app.add_option("--param", o->params, "Solver / filter / planner parameter name=value (repeatable)");
        app.add_option("--config", o->config, "JSON file overriding keys of the scenario's default configuration")
            ->check(CLI::ExistingFile);
        app.add_flag("--replan-every-step", o->replanEveryStep,
                     "Replan after every primitive step (default: after each executed macro-action)");
        app.add_flag("--print-config", o->printConfig, "Print the effective configuration as JSON and exit");
        app.add_flag("--list-scenarios", o->listScenarios, "List the scenarios and exit");
        app.add_flag("--quiet", o->quiet, "No progress output");
        return [o] { return run(*o); };
    }

    const ropras::bin::CommandRegistrar reg{
        {"run", "Run episodes of a scenario with a solver (parallel, sharded); JSON lines and the paper's table",
         setup}};
}  // namespace
