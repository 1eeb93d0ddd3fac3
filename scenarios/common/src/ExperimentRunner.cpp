#include "ropras/scenarios/ExperimentRunner.h"

#include <algorithm>
#include <atomic>
#include <chrono>
#include <cmath>
#include <exception>
#include <filesystem>
#include <fstream>
#include <mutex>
#include <thread>

#include "ropras/core/Error.h"

namespace ropras::scenarios
{
    namespace
    {
        std::uint64_t splitMix64(std::uint64_t x) noexcept
        {
            x += 0x9E3779B97F4A7C15ULL;
            x = (x ^ (x >> 30)) * 0xBF58476D1CE4E5B9ULL;
            x = (x ^ (x >> 27)) * 0x94D049BB133111EBULL;
            return x ^ (x >> 31);
        }

        bool parseWhole(const std::string &text, std::size_t &out)
        {
            if (text.empty() || text.size() > 18)
            {
                return false;
            }
            std::size_t value = 0;
            for (const char c : text)
            {
                if (c < '0' || c > '9')
                {
                    return false;
                }
                value = value * 10 + static_cast<std::size_t>(c - '0');
            }
            out = value;
            return true;
        }

        double secondsSince(std::chrono::steady_clock::time_point start)
        {
            return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
        }

        /** \brief Creates \a dir and checks that a file can be written there (\a option names it in errors). */
        void prepareRecordDirectory(const std::string &dir, const std::string &option = "--record")
        {
            std::error_code ec;
            std::filesystem::create_directories(dir, ec);
            if (ec || !std::filesystem::is_directory(dir))
            {
                throw Error(option + " directory \"" + dir + "\" cannot be created" +
                            (ec ? ": " + ec.message() : std::string(" (a file of that name exists)")));
            }
            const std::filesystem::path probe = std::filesystem::path(dir) / ".ropras-write-test";
            {
                std::ofstream file(probe);
                if (!file)
                {
                    throw Error(option + " directory \"" + dir + "\" is not writable");
                }
            }
            std::filesystem::remove(probe, ec);
        }
    }  // namespace

    Shard Shard::parse(const std::string &text)
    {
        const auto slash = text.find('/');
        Shard shard;
        if (slash == std::string::npos || !parseWhole(text.substr(0, slash), shard.index) ||
            !parseWhole(text.substr(slash + 1), shard.count))
        {
            throw Error("shard \"" + text + "\" is not of the form i/N (whole numbers, e.g. 0/10)");
        }
        shard.validate();
        return shard;
    }

    void Shard::validate() const
    {
        if (count == 0)
        {
            throw Error("shard " + str() + ": the shard count N must be >= 1");
        }
        if (index >= count)
        {
            throw Error("shard " + str() + ": the shard index i must be < N (shards are 0/N ... " +
                        std::to_string(count - 1) + "/N)");
        }
    }

    std::string Shard::str() const
    {
        return std::to_string(index) + "/" + std::to_string(count);
    }

    std::uint64_t episodeSeed(std::uint64_t runSeed, std::size_t episode) noexcept
    {
        return splitMix64(splitMix64(runSeed) ^ splitMix64(0x5EED0000ULL + static_cast<std::uint64_t>(episode)));
    }

    RunSettings resolvedRunSettings(const Scenario &scenario, const RunSettings &settings)
    {
        RunSettings out = settings;
        const auto &b = out.budget;
        if (!(std::isfinite(b.seconds) && b.seconds >= 0.0))
        {
            throw Error("planning time " + std::to_string(b.seconds) + " s is not a finite number >= 0");
        }
        if (b.simulations == 0 && b.seconds == 0.0)
        {
            out.budget.seconds = scenario.defaultPlanSeconds();
        }
        out.budget.validate();
        return out;
    }

    nlohmann::json experimentConfiguration(const Scenario &scenario, const ExperimentSettings &settings,
                                           const RunSettings &run)
    {
        nlohmann::json params = nlohmann::json::object();
        for (const auto &entry : run.params.values())
        {
            params[entry.first] = entry.second;
        }
        return nlohmann::json{{"scenario", scenario.name()},
                              {"config", scenario.config()},
                              {"solver", run.solver},
                              {"heuristic", run.heuristic},
                              {"epsilon", run.epsilon},
                              {"planner", run.planner},
                              {"budget", {{"simulations", run.budget.simulations}, {"seconds", run.budget.seconds}}},
                              {"params", params},
                              {"replan_every_step", run.replanEveryStep},
                              {"seed", settings.seed},
                              {"episodes", settings.episodes},
                              {"shard", settings.shard.str()}};
    }

    nlohmann::json episodeRecord(const nlohmann::json &configuration, std::size_t episode, std::uint64_t seed,
                                 const pomdp::EpisodeResult &r, double wallSeconds)
    {
        nlohmann::json out = configuration;
        const auto &s = r.search;
        const double plans = static_cast<double>(r.plans);
        out["episode"] = episode;
        out["episode_seed"] = seed;
        out["success"] = r.success;
        out["terminal"] = r.terminal;
        out["discounted_return"] = r.discountedReturn;
        out["undiscounted_return"] = r.undiscountedReturn;
        out["steps"] = r.steps;
        out["plans"] = r.plans;
        out["invalid_plans"] = r.invalidPlans;
        out["depletions"] = r.depletions;
        out["simulations"] = s.simulations;
        out["sims_per_call"] = r.plans > 0 ? static_cast<double>(s.simulations) / plans : 0.0;
        out["plan_time_s"] = r.plans > 0 ? s.seconds / plans : 0.0;
        out["ref_requested"] = s.referenceRequested;
        out["ref_failed"] = s.referenceFailed;
        out["ref_failures"] = s.referenceRequested > 0
                                  ? static_cast<double>(s.referenceFailed) / static_cast<double>(s.referenceRequested)
                                  : 0.0;
        out["max_depth"] = s.maxDepth;
        if (s.fillTried > 0)
        {
            out["fill_tried"] = s.fillTried;
            out["fill_kept"] = s.fillKept;
        }
        out["memory_capped_plans"] = s.memoryCapped;
        out["tree_mb_max"] = static_cast<double>(s.treeBytes) / 1048576.0;
        out["wall_time_s"] = wallSeconds;
        return out;
    }

    std::string recordingFileName(const std::string &scenario, const std::string &solver, std::size_t episode)
    {
        return scenario + "-" + solver + "-" + std::to_string(episode) + ".json";
    }

    std::vector<nlohmann::json> runExperiment(const Scenario &scenario, const ExperimentSettings &settings,
                                              const ExperimentCallbacks &callbacks)
    {
        const auto start = std::chrono::steady_clock::now();
        if (settings.episodes == 0 || settings.episodes > MAX_EPISODES)
        {
            throw Error("the number of episodes " + std::to_string(settings.episodes) + " must be in [1, " +
                        std::to_string(MAX_EPISODES) + "]");
        }
        settings.shard.validate();
        const RunSettings run = resolvedRunSettings(scenario, settings.run);
        scenario.validate(run);
        if (!settings.recordDir.empty())
        {
            prepareRecordDirectory(settings.recordDir);
        }
        if (!settings.record.tree.dir.empty())
        {
            prepareRecordDirectory(settings.record.tree.dir, "--dump-tree");
        }
        const nlohmann::json configuration = experimentConfiguration(scenario, settings, run);

        // the shard's episodes are index, index + N, ...: computed, never searched for among all indices
        const std::size_t owned = settings.shard.ownedCount(settings.episodes);
        std::vector<nlohmann::json> records(owned);
        std::vector<char> finished(owned, 0);
        std::size_t nextToReport = 0, done = 0;
        std::mutex mutex;
        std::atomic<std::size_t> next{0};
        std::atomic<bool> stop{false};
        std::exception_ptr failure;

        const auto work = [&]
        {
            for (;;)
            {
                const std::size_t slot = next.fetch_add(1);
                if (slot >= owned || stop.load())
                {
                    return;
                }
                const std::size_t episode = settings.shard.ownedEpisode(slot);
                const std::uint64_t seed = episodeSeed(settings.seed, episode);
                try
                {
                    const auto episodeStart = std::chrono::steady_clock::now();
                    nlohmann::json recording;
                    const bool record = !settings.recordDir.empty();
                    RecordSettings recordSettings = settings.record;
                    const std::string name = recordingFileName(scenario.name(), run.solver, episode);
                    recordSettings.tree.prefix = name.substr(0, name.size() - 5);  // without ".json"
                    const auto result = scenario.runEpisode(run, seed, record ? &recording : nullptr, recordSettings);
                    nlohmann::json line =
                        episodeRecord(configuration, episode, seed, result, secondsSince(episodeStart));
                    if (record)
                    {
                        recording["solver"] = run.solver;
                        recording["heuristic"] = run.heuristic;
                        recording["planner"] = run.planner;
                        recording["episode"] = episode;
                        recording["run_seed"] = settings.seed;
                        recording["undiscounted_return"] = result.undiscountedReturn;
                        const auto path = std::filesystem::path(settings.recordDir) /
                                          recordingFileName(scenario.name(), run.solver, episode);
                        std::ofstream file(path);
                        file << recording.dump() << '\n';
                        if (!file)
                        {
                            throw Error("cannot write the recording \"" + path.string() + "\"");
                        }
                    }
                    std::lock_guard<std::mutex> lock(mutex);
                    records[slot] = std::move(line);
                    finished[slot] = 1;
                    ++done;
                    if (callbacks.onProgress)
                    {
                        callbacks.onProgress(ExperimentProgress{done, owned, secondsSince(start), &records[slot]});
                    }
                    while (nextToReport < owned && finished[nextToReport])
                    {
                        if (callbacks.onRecord)
                        {
                            callbacks.onRecord(records[nextToReport]);
                        }
                        ++nextToReport;
                    }
                }
                catch (const std::exception &e)
                {
                    std::lock_guard<std::mutex> lock(mutex);
                    if (!failure)
                    {
                        failure = std::make_exception_ptr(Error("scenario " + scenario.name() + ", episode " +
                                                                std::to_string(episode) + " (seed " +
                                                                std::to_string(seed) + "): " + e.what()));
                    }
                    stop.store(true);
                    return;
                }
                catch (...)
                {
                    std::lock_guard<std::mutex> lock(mutex);
                    if (!failure)
                    {
                        failure = std::make_exception_ptr(Error("scenario " + scenario.name() + ", episode " +
                                                                std::to_string(episode) + " (seed " +
                                                                std::to_string(seed) + "): unknown exception"));
                    }
                    stop.store(true);
                    return;
                }
            }
        };

        std::size_t threads = settings.threads;
        if (threads == 0)
        {
            threads = std::max<std::size_t>(1, std::thread::hardware_concurrency());
        }
        threads = std::min(threads, std::max<std::size_t>(1, owned));
        if (threads <= 1)
        {
            work();
        }
        else
        {
            std::vector<std::thread> pool;
            pool.reserve(threads);
            for (std::size_t t = 0; t < threads; ++t)
            {
                pool.emplace_back(work);
            }
            for (auto &thread : pool)
            {
                thread.join();
            }
        }
        if (failure)
        {
            std::rethrow_exception(failure);
        }
        return records;
    }
}  // namespace ropras::scenarios
