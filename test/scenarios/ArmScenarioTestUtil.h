// Shared helpers of the arm scenario tests (Sphere-Search, Ray-Detect).
#ifndef ROPRAS_TEST_SCENARIOS_ARM_SCENARIO_TEST_UTIL_H
#define ROPRAS_TEST_SCENARIOS_ARM_SCENARIO_TEST_UTIL_H

#include <gtest/gtest.h>

#include <cmath>
#include <functional>
#include <nlohmann/json.hpp>
#include <string>

#include "ropras/scenarios/Scenario.h"

namespace ropras::scenarios::test
{
    /** \brief Every solver (ropras3, rpomcp, bplan, pomcp, refbasic) runs one recorded episode of \a scenario (made
        with horizon 12) at 8 simulations per call and 20 particles, seed 99: at least one step, at most the
        horizon, a finite return, one trajectory point per step plus the start; \a more adds the scenario's own
        checks on each solver's result and recording. */
    inline void expectEverySolverRunsAnEpisode(
        const Scenario &scenario,
        const std::function<void(const std::string &, const pomdp::EpisodeResult &, const nlohmann::json &)> &more =
            nullptr)
    {
        for (const std::string solver : {"ropras3", "rpomcp", "bplan", "pomcp", "refbasic"})
        {
            RunSettings settings;
            settings.solver = solver;
            settings.budget.simulations = 8;
            settings.params.set("particles", 20);
            scenario.validate(settings);
            nlohmann::json recording;
            const auto result = scenario.runEpisode(settings, 99, &recording, RecordSettings());
            EXPECT_GE(result.steps, 1u) << solver;
            EXPECT_LE(result.steps, 12u) << solver;
            EXPECT_TRUE(std::isfinite(result.undiscountedReturn)) << solver;
            EXPECT_EQ(recording["trajectory"].size(), result.steps + 1) << solver;
            if (more)
            {
                more(solver, result, recording);
            }
        }
    }
}  // namespace ropras::scenarios::test

#endif
