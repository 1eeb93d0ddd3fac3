// ResultTable: aggregation (mean, standard error, success rate) against hand computations, grouping, the paper's
// row order, duplicate episodes across shards, and malformed JSON lines.
#include <gtest/gtest.h>

#include <cmath>
#include <sstream>
#include <string>
#include <vector>

#include "ExpectError.h"
#include "ropras/core/Error.h"
#include "ropras/scenarios/ResultTable.h"

namespace ropras::scenarios::test
{
    using ropras::test::expectErrorMentions;

    namespace
    {
        nlohmann::json record(const std::string &solver, const std::string &heuristic, std::size_t episode,
                              bool success, double reward, double steps, double sims, double planTime,
                              double refFailures, std::size_t refRequested = 10)
        {
            return {{"scenario", "maze2d"},
                    {"config", {{"horizon", 800}}},
                    {"solver", solver},
                    {"heuristic", heuristic},
                    {"epsilon", 0.0},
                    {"planner", "VectorizedRRTConnect"},
                    {"budget", {{"simulations", 0}, {"seconds", 0.1}}},
                    {"params", nlohmann::json::object()},
                    {"replan_every_step", false},
                    {"seed", 1},
                    {"episode", episode},
                    {"success", success},
                    {"discounted_return", reward * 0.5},
                    {"undiscounted_return", reward},
                    {"steps", steps},
                    {"sims_per_call", sims},
                    {"plan_time_s", planTime},
                    {"ref_requested", refRequested},
                    {"ref_failed", 0},
                    {"ref_failures", refFailures}};
        }
    }  // namespace

    TEST(ResultTable, MeanStdErrAndRatesMatchAHandComputation)
    {
        ResultTable table;
        // rewards 10, 20, 60: mean 30, sample variance (400 + 100 + 900) / 2 = 700, std err sqrt(700 / 3)
        table.add(record("ropras3", "dynamic", 0, true, 10.0, 100.0, 500.0, 0.10, 0.0), "a:1");
        table.add(record("ropras3", "dynamic", 1, false, 20.0, 200.0, 700.0, 0.20, 0.5), "a:2");
        table.add(record("ropras3", "dynamic", 2, true, 60.0, 330.0, 900.0, 0.12, 0.25), "a:3");
        ASSERT_EQ(table.size(), 3u);
        const auto rows = table.rows();
        ASSERT_EQ(rows.size(), 1u);
        const ResultRow &r = rows[0];
        EXPECT_EQ(r.scenario, "maze2d");
        EXPECT_EQ(r.solver, "ROP-RAS3");
        EXPECT_EQ(r.heuristic, "Dynamic");
        EXPECT_EQ(r.budget, "0.1 s");
        EXPECT_EQ(r.episodes, 3u);
        EXPECT_NEAR(r.successPercent, 200.0 / 3.0, 1e-12);
        EXPECT_NEAR(r.rewardMean, 30.0, 1e-12);
        EXPECT_NEAR(r.rewardStdErr, std::sqrt(700.0 / 3.0), 1e-12);
        EXPECT_NEAR(r.discountedMean, 15.0, 1e-12);
        EXPECT_NEAR(r.discountedStdErr, 0.5 * std::sqrt(700.0 / 3.0), 1e-12);
        EXPECT_NEAR(r.stepsMean, 210.0, 1e-12);
        EXPECT_NEAR(r.simsPerCall, 700.0, 1e-12);
        EXPECT_NEAR(r.planTime, 0.14, 1e-12);
        EXPECT_NEAR(r.refFailPercent, 25.0, 1e-12);
        EXPECT_TRUE(r.hasSimulations);
        EXPECT_TRUE(r.hasReference);
        const std::string md = table.markdown();
        EXPECT_NE(
            md.find("| Scenario | Solver | Heuristic | Sims # | Succ. % | Rewards (std err) | Steps | R.P. Fail % | "
                    "Plan time (s) |"),
            std::string::npos)
            << md;
        // sqrt(700 / 3) = 15.275...
        EXPECT_NE(
            md.find("| maze2d | ROP-RAS3 | Dynamic | 700 | 66.7 | 30.0 (15.3) | 210.0 | 25.0 | 0.140 | 0.1 s | 3 |"),
            std::string::npos)
            << md;
    }

    TEST(ResultTable, OneEpisodeHasZeroStdErr)
    {
        ResultTable table;
        table.add(record("pomcp", "dynamic", 0, false, -80.0, 800.0, 218.0, 0.1, 0.0, 0), "x");
        const auto r = table.rows().at(0);
        EXPECT_DOUBLE_EQ(r.rewardMean, -80.0);
        EXPECT_DOUBLE_EQ(r.rewardStdErr, 0.0);
        EXPECT_EQ(r.heuristic, "N/A") << "POMCP has no reference policy";
        EXPECT_FALSE(r.hasReference);
        EXPECT_NE(table.markdown().find("| maze2d | POMCP | N/A | 218 | 0.0 | -80.0 (0.0) | 800.0 | N/A |"),
                  std::string::npos)
            << table.markdown();
    }

    TEST(ResultTable, RowsPerConfigurationInThePapersOrder)
    {
        ResultTable table;
        table.add(record("ropras3", "dynamic", 0, true, 1.0, 1.0, 1.0, 0.1, 0.0), "f:1");
        table.add(record("ropras3", "uniform", 0, true, 2.0, 1.0, 1.0, 0.1, 0.0), "f:2");
        table.add(record("bplan", "dynamic", 0, false, 3.0, 1.0, 0.0, 0.1, 0.0), "f:3");
        table.add(record("pomcp", "uniform", 0, false, 4.0, 1.0, 9.0, 0.1, 0.0, 0), "f:4");
        // POMCP ignores the heuristic: a run with another --heuristic is the same row
        table.add(record("pomcp", "dynamic", 1, false, 6.0, 1.0, 9.0, 0.1, 0.0, 0), "f:5");
        auto sims = record("ropras3", "dynamic", 0, true, 5.0, 1.0, 1.0, 0.1, 0.0);
        sims["budget"] = {{"simulations", 1000}, {"seconds", 0.0}};
        table.add(sims, "f:6");
        auto eta = record("ropras3", "dynamic", 0, true, 7.0, 1.0, 1.0, 0.1, 0.0);
        eta["params"] = {{"eta", 0.2}};
        eta["planner"] = "RRTConnect";
        table.add(eta, "f:7");
        auto other = record("ropras3", "dynamic", 0, true, 8.0, 1.0, 1.0, 0.1, 0.0);
        other["scenario"] = "light-dark";
        table.add(other, "f:8");
        const auto rows = table.rows();
        ASSERT_EQ(rows.size(), 7u);
        std::vector<std::string> got;
        for (const auto &r : rows)
        {
            got.push_back(r.scenario + "|" + r.solver + "|" + r.heuristic + "|" + r.budget);
        }
        const std::vector<std::string> expected{
            "maze2d|B-plan|Dynamic|0.1 s",       "maze2d|POMCP|N/A|0.1 s",
            "maze2d|ROP-RAS3|Uniform|0.1 s",     "maze2d|ROP-RAS3|Dynamic|0.1 s",
            "maze2d|ROP-RAS3|Dynamic|1000 sims", "maze2d|ROP-RAS3 [RRTConnect, eta=0.2]|Dynamic|0.1 s",
            "light-dark|ROP-RAS3|Dynamic|0.1 s",
        };
        EXPECT_EQ(got, expected);
        EXPECT_EQ(rows[1].episodes, 2u);
        EXPECT_DOUBLE_EQ(rows[1].rewardMean, 5.0);
        EXPECT_FALSE(rows[0].hasSimulations) << "B-plan runs no simulations: N/A";
        EXPECT_NE(table.markdown().find("| maze2d | B-plan | Dynamic | N/A |"), std::string::npos);
    }

    TEST(ResultTable, SeveralConfigurationsOfOneScenarioAreNumbered)
    {
        ResultTable table;
        auto a = record("ropras3", "dynamic", 0, true, 1.0, 1.0, 1.0, 0.1, 0.0);
        auto b = a;
        b["config"] = {{"horizon", 400}};
        table.add(a, "a");
        table.add(b, "b");
        const auto rows = table.rows();
        ASSERT_EQ(rows.size(), 2u);
        EXPECT_EQ(rows[0].scenario, "maze2d (config 1)");
        EXPECT_EQ(rows[1].scenario, "maze2d (config 2)");
    }

    TEST(ResultTable, OverlappingShardsCountAnEpisodeOnceAndWarn)
    {
        std::stringstream shard0, shard1;
        shard0 << record("ropras3", "dynamic", 0, true, 10.0, 1.0, 1.0, 0.1, 0.0).dump() << "\n\n"
               << record("ropras3", "dynamic", 2, true, 20.0, 1.0, 1.0, 0.1, 0.0).dump() << "\n";
        shard1 << record("ropras3", "dynamic", 1, false, 30.0, 1.0, 1.0, 0.1, 0.0).dump() << "\n"
               << record("ropras3", "dynamic", 2, true, 20.0, 1.0, 1.0, 0.1, 0.0).dump() << "\n";
        ResultTable table;
        EXPECT_EQ(table.addJsonLines(shard0, "shard0.jsonl"), 2u);
        EXPECT_EQ(table.addJsonLines(shard1, "shard1.jsonl"), 2u);
        EXPECT_EQ(table.size(), 3u);
        ASSERT_EQ(table.warnings().size(), 1u);
        EXPECT_NE(table.warnings()[0].find("shard1.jsonl:2: episode 2"), std::string::npos) << table.warnings()[0];
        EXPECT_EQ(table.rows().at(0).episodes, 3u);
        EXPECT_DOUBLE_EQ(table.rows().at(0).rewardMean, 20.0);
        // another run seed is another episode, not a duplicate
        auto again = record("ropras3", "dynamic", 2, true, 20.0, 1.0, 1.0, 0.1, 0.0);
        again["seed"] = 2;
        EXPECT_TRUE(table.add(again, "x"));
        EXPECT_EQ(table.size(), 4u);
    }

    TEST(ResultTable, MalformedInputNamesTheLineAndTheKey)
    {
        ResultTable table;
        // (an object cut off at the end of its line is a truncated record, skipped with a warning: JsonLinesTest)
        std::stringstream broken("\n{\"scenario\": x}\n");
        expectErrorMentions([&] { table.addJsonLines(broken, "runs.jsonl"); }, {"runs.jsonl:2", "malformed JSON"});
        auto missing = record("ropras3", "dynamic", 0, true, 1.0, 1.0, 1.0, 0.1, 0.0);
        missing.erase("success");
        expectErrorMentions([&] { table.add(missing, "runs.jsonl:7"); }, {"runs.jsonl:7", "\"success\""});
        auto wrongType = record("ropras3", "dynamic", 0, true, 1.0, 1.0, 1.0, 0.1, 0.0);
        wrongType["steps"] = "many";
        expectErrorMentions([&] { table.add(wrongType, "r:1"); }, {"r:1", "\"steps\"", "number"});
        auto negative = record("ropras3", "dynamic", 0, true, 1.0, 1.0, 1.0, 0.1, 0.0);
        negative["episode"] = -1;
        expectErrorMentions([&] { table.add(negative, "r:2"); }, {"\"episode\"", "-1"});
        expectErrorMentions([&] { table.add(nlohmann::json::array(), "r:3"); }, {"r:3", "JSON object"});
        expectErrorMentions([&] { table.addFile("/nonexistent/runs.jsonl"); }, {"/nonexistent/runs.jsonl"});
        EXPECT_EQ(table.size(), 0u);
    }
    // values `ropras run` cannot write: each is an error naming the line and the key, and nothing is counted
    TEST(ResultTable, ImpossibleValuesAreRejected)
    {
        ResultTable table;
        const auto base = record("refbasic", "uniform", 0, true, 1.0, 10.0, 5.0, 0.1, 0.5);
        auto negativeSteps = base;
        negativeSteps["steps"] = -3;
        expectErrorMentions([&] { table.add(negativeSteps, "r:1"); }, {"r:1", "\"steps\"", "-3", "whole number"});
        auto fractionalSteps = base;
        fractionalSteps["steps"] = 2.5;
        expectErrorMentions([&] { table.add(fractionalSteps, "r:2"); }, {"r:2", "\"steps\"", "2.5"});
        auto failureRate = base;
        failureRate["ref_failures"] = 2.0;  // 200 %
        expectErrorMentions([&] { table.add(failureRate, "r:3"); }, {"r:3", "\"ref_failures\"", "[0, 1]"});
        auto negativeRate = base;
        negativeRate["ref_failures"] = -0.1;
        expectErrorMentions([&] { table.add(negativeRate, "r:4"); }, {"r:4", "\"ref_failures\""});
        auto negativeTime = base;
        negativeTime["plan_time_s"] = -1.0;
        expectErrorMentions([&] { table.add(negativeTime, "r:5"); }, {"r:5", "\"plan_time_s\""});
        auto negativeSims = base;
        negativeSims["sims_per_call"] = -5.0;
        expectErrorMentions([&] { table.add(negativeSims, "r:6"); }, {"r:6", "\"sims_per_call\""});
        auto macros = base;
        macros["config"]["macro_min"] = 8;
        macros["config"]["macro_max"] = 2;
        expectErrorMentions([&] { table.add(macros, "r:7"); }, {"r:7", "macro_min = 8 > macro_max = 2"});
        auto paramMacros = base;
        paramMacros["params"] = {{"macro_min", 5}, {"macro_max", 1}};
        expectErrorMentions([&] { table.add(paramMacros, "r:8"); }, {"r:8", "params", "macro_min"});
        auto moreFailedThanRequested = base;
        moreFailedThanRequested["ref_failed"] = 20;
        expectErrorMentions([&] { table.add(moreFailedThanRequested, "r:9"); }, {"r:9", "ref_failed", "ref_requested"});
        auto epsilon = base;
        epsilon["epsilon"] = 1.5;
        expectErrorMentions([&] { table.add(epsilon, "r:10"); }, {"r:10", "\"epsilon\""});
        EXPECT_EQ(table.size(), 0u);
        // the limits themselves are fine
        auto edge = base;
        edge["ref_failures"] = 1.0;
        edge["steps"] = 0;
        edge["config"]["macro_min"] = 3;
        edge["config"]["macro_max"] = 3;
        EXPECT_TRUE(table.add(edge, "r:11"));
    }

    // a number beyond a double in a JSON line (1e400) is a malformed line, named, not an uncaught parser error
    TEST(ResultTable, NumberOverflowIsAMalformedLine)
    {
        ResultTable table;
        std::stringstream overflow("{\"steps\": 1e400}\n");
        expectErrorMentions([&] { table.addJsonLines(overflow, "big.jsonl"); },
                            {"big.jsonl:1", "malformed JSON", "overflow"});
    }
}  // namespace ropras::scenarios::test
