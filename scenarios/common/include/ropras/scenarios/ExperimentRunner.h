#ifndef ROPRAS_SCENARIOS_EXPERIMENT_RUNNER_H
#define ROPRAS_SCENARIOS_EXPERIMENT_RUNNER_H

#include <cstdint>
#include <functional>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "ropras/pomdp/Episode.h"
#include "ropras/scenarios/Scenario.h"

namespace ropras::scenarios
{
    /** \brief The part of an experiment one process runs: of the episodes 0 .. N-1 it runs those with
        e % count == index, so that shards 0/k ... (k-1)/k together run every episode exactly once. */
    struct Shard
    {
        std::size_t index{0};
        std::size_t count{1};

        /** \brief Parses "i/N" (whole numbers, N >= 1, i < N); throws ropras::Error naming \a text otherwise. */
        static Shard parse(const std::string &text);

        /** \brief Throws ropras::Error unless count >= 1 and index < count. */
        void validate() const;

        bool owns(std::size_t episode) const noexcept { return episode % count == index; }

        /// how many of the episodes 0 .. episodes-1 this shard owns (computed, not counted)
        std::size_t ownedCount(std::size_t episodes) const noexcept
        {
            return episodes / count + (index < episodes % count ? 1 : 0);
        }

        /// the \a k-th episode this shard owns (k < ownedCount())
        std::size_t ownedEpisode(std::size_t k) const noexcept { return index + k * count; }

        /// "i/N"
        std::string str() const;
    };

    /** \brief The seed of episode \a episode of a run with seed \a runSeed: a SplitMix64 mix of both alone,
        so it does not depend on the thread that runs the episode or on the shard split. */
    std::uint64_t episodeSeed(std::uint64_t runSeed, std::size_t episode) noexcept;

    /// the most episodes of one experiment (all shards together): every record is kept for the table
    constexpr std::size_t MAX_EPISODES = 1000000;

    /** \brief One experiment: \c episodes episodes of one scenario with the same RunSettings. */
    struct ExperimentSettings
    {
        RunSettings run;
        /// episodes of the whole experiment (all shards together), in [1, MAX_EPISODES]
        std::size_t episodes{30};
        /// the run seed; episode e runs with episodeSeed(seed, e)
        std::uint64_t seed{1};
        /// worker threads; 0 = std::thread::hardware_concurrency()
        std::size_t threads{0};
        Shard shard;
        /// when not empty: write DIR/<scenario>-<solver>-<episode>.json (the recording) for every episode
        std::string recordDir;
        RecordSettings record;
    };

    /** \brief Reported after every finished episode (in the order episodes finish). */
    struct ExperimentProgress
    {
        /// episodes finished so far / episodes of this shard
        std::size_t done{0};
        std::size_t total{0};
        /// seconds since runExperiment() started
        double elapsedSeconds{0.0};
        /// the record of the episode that just finished (see episodeRecord())
        const nlohmann::json *record{nullptr};
    };

    /** \brief Optional hooks of runExperiment(); both are called from one thread at a time. */
    struct ExperimentCallbacks
    {
        /// every episode's record, in episode order (as soon as all earlier episodes of the shard are done)
        std::function<void(const nlohmann::json &record)> onRecord;
        /// after each finished episode, in the order they finish (progress bars)
        std::function<void(const ExperimentProgress &progress)> onProgress;
    };

    /** \brief \a settings with the budget resolved: neither a simulation count nor a time limit set means the
        scenario's default planning time. Throws ropras::Error for a budget with a negative or non-finite value. */
    RunSettings resolvedRunSettings(const Scenario &scenario, const RunSettings &settings);

    /** \brief The configuration part of every episode record: scenario, its config(), solver, heuristic,
        epsilon, planner, budget {simulations, seconds}, params, replan_every_step, seed (the run seed),
        episodes, shard. \a run must be resolved (resolvedRunSettings()). */
    nlohmann::json experimentConfiguration(const Scenario &scenario, const ExperimentSettings &settings,
                                           const RunSettings &run);

    /** \brief One JSON record for episode \a episode: experimentConfiguration() plus episode, episode_seed,
        success, terminal, discounted_return, undiscounted_return, steps, plans, invalid_plans, depletions,
        simulations, sims_per_call (mean per planning call), plan_time_s (mean seconds per call), ref_requested,
        ref_failed, ref_failures (ref_failed / ref_requested, 0 when none was requested), max_depth, fill_tried
        and fill_kept (ROP-RAS3's belief fill, only when it drew particles), memory_capped_plans (planning calls
        stopped at the tree memory cap, parameter max_tree_mb), tree_mb_max (the largest tree of the episode,
        MiB) and wall_time_s (the episode's wall-clock seconds). */
    nlohmann::json episodeRecord(const nlohmann::json &configuration, std::size_t episode, std::uint64_t seed,
                                 const pomdp::EpisodeResult &result, double wallSeconds);

    /** \brief The file name of an episode's recording: "<scenario>-<solver>-<episode>.json". */
    std::string recordingFileName(const std::string &scenario, const std::string &solver, std::size_t episode);

    /** \brief Runs the episodes of \a settings.shard in \a settings.threads threads and returns their records in
        episode order. Everything is checked before a thread starts (episodes in [1, MAX_EPISODES], the shard, the
       budget, scenario.validate(), the record directory is created and writable): bad settings throw ropras::Error. An
       exception inside an episode stops the remaining episodes and is rethrown (as ropras::Error naming the episode).
       Same settings and seed: the same records (but for the timing keys) whatever the thread count or shard split,
       exactly so with a simulation budget and a seeded planner. */
    std::vector<nlohmann::json> runExperiment(const Scenario &scenario, const ExperimentSettings &settings,
                                              const ExperimentCallbacks &callbacks = ExperimentCallbacks());
}  // namespace ropras::scenarios

#endif
