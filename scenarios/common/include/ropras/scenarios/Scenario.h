#ifndef ROPRAS_SCENARIOS_SCENARIO_H
#define ROPRAS_SCENARIOS_SCENARIO_H

#include <cstdint>
#include <nlohmann/json_fwd.hpp>
#include <string>

#include "ropras/pomdp/Budget.h"
#include "ropras/pomdp/Episode.h"
#include "ropras/pomdp/ParameterMap.h"
#include "ropras/scenarios/TreeDump.h"

namespace ropras::scenarios
{
    /** \brief How the episodes of one experiment are planned (the same for every episode). */
    struct RunSettings
    {
        /// ropras3, pomcp, rpomcp, bplan, refbasic (any name of pomdp::makeSolver)
        std::string solver{"ropras3"};
        /// sampling heuristic of the informed reference policy: "uniform" or "dynamic"
        std::string heuristic{"dynamic"};
        /// epsilon-greedy exploration mixed into the heuristic (0 = none)
        double epsilon{0.0};
        /// OMPL planner of the reference policy, any ompl_ext::PlannerRegistry name
        std::string planner{"VectorizedRRTConnect"};
        /// per planning call; neither set = the scenario's default planning time
        pomdp::Budget budget{};
        /// replan after every primitive step instead of after every executed macro-action
        bool replanEveryStep{false};
        /// solver, particle-filter, reference-policy and planner parameters (`--param name=value`); a name
        /// nobody reads is an error
        pomdp::ParameterMap params;
    };

    /** \brief What to record for pictures: the true trajectory always, belief particles every \c beliefEvery
        steps (0 = at the start and the end only), at most \c maxParticles of them; and the search trees of
        the planning calls \c tree names (written by runEpisode() as they are made, whether or not a recording
        is asked for). */
    struct RecordSettings
    {
        std::size_t beliefEvery{0};
        std::size_t maxParticles{200};
        TreeDumpSettings tree;
    };

    /** \brief One benchmark problem: its POMDP model (what the planner simulates), its world (what really
        happens, e.g. Bullet collision detection), its default configuration and its scene for pictures.

        runEpisode() is const and thread-safe: each call builds its own solver, particle filter and world,
        and draws every random number from streams derived from \a seed alone, so the same seed gives the
        same episode whichever thread runs it (exactly so with a simulation budget and a seeded reference
        planner; a wall-clock budget makes the search depend on timing). */
    class Scenario
    {
    public:
        virtual ~Scenario() = default;

        /// command-line name, e.g. "light-dark"
        virtual std::string name() const = 0;
        virtual std::string description() const = 0;
        /// every parameter of the model, world and defaults (goes into each JSONL record)
        virtual nlohmann::json config() const = 0;
        /// the default planning time per call in seconds (a tenth of the paper's)
        virtual double defaultPlanSeconds() const = 0;
        /// the horizon H (maximum primitive steps of an episode)
        virtual std::size_t horizon() const = 0;

        /** \brief Throws ropras::Error when \a settings cannot run here (unknown solver, heuristic, planner or
            parameter, bad value); cheap enough to call once before starting threads. */
        virtual void validate(const RunSettings &settings) const = 0;

        /** \brief Runs one episode with \a settings (budget already resolved: not empty). When \a recording is
            non-null it receives the episode for `ropras render` (format: doc/scenarios.md). */
        virtual pomdp::EpisodeResult runEpisode(const RunSettings &settings, std::uint64_t seed,
                                                nlohmann::json *recording = nullptr,
                                                const RecordSettings &record = RecordSettings()) const = 0;

        /** \brief The static scene for pictures: bounds, walls, obstacles, danger zones, observation zones,
            goal, start (format: doc/scenarios.md). */
        virtual nlohmann::json scene() const = 0;
    };
}  // namespace ropras::scenarios

#endif
