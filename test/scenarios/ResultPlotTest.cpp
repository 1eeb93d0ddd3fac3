// ResultPlot (`ropras plot`) and ResultTable::csv (`ropras table --csv`): the points' means and standard errors
// against hand computations, one line per solver and heuristic, the key read from params / the scenario's defaults /
// the budget, a well-formed SVG with one error bar per point, and the errors of a key no record has.
#include <gtest/gtest.h>
#include <tinyxml2.h>

#include <cmath>
#include <sstream>
#include <string>
#include <vector>

#include "ExpectError.h"
#include "ropras/core/Error.h"
#include "ropras/scenarios/ResultPlot.h"
#include "ropras/scenarios/ResultTable.h"

namespace ropras::scenarios::test
{
    using ropras::test::expectErrorMentions;

    namespace
    {
        nlohmann::json episode(const std::string &solver, std::size_t sims, double depth, std::size_t index,
                               bool success, double reward, double planTime)
        {
            nlohmann::json params = nlohmann::json::object();
            if (depth > 0.0)
                params["depth"] = depth;
            return {{"scenario", "maze2d"},
                    {"config", {{"horizon", 800}, {"defaults", {{"depth", 4}, {"beta_a", 2}}}}},
                    {"solver", solver},
                    {"heuristic", "dynamic"},
                    {"epsilon", 0.0},
                    {"planner", "VectorizedRRTConnect"},
                    {"budget", {{"simulations", sims}, {"seconds", 0}}},
                    {"params", params},
                    {"replan_every_step", false},
                    {"seed", 1},
                    {"episode", index},
                    {"success", success},
                    {"discounted_return", reward},
                    {"undiscounted_return", reward},
                    {"steps", 10},
                    {"sims_per_call", static_cast<double>(sims)},
                    {"plan_time_s", planTime},
                    {"ref_failures", 0.0}};
        }

        ResultTable sampleTable()
        {
            ResultTable t;
            // ropras3 at 100 sims: 3 of 4 succeed, returns 10, 20, 30, 40; at 1000 sims: 2 of 2, returns 50, 70
            const double r100[] = {10, 20, 30, 40};
            for (std::size_t e = 0; e < 4; ++e)
                t.add(episode("ropras3", 100, 0, e, e != 2, r100[e], 0.01 * static_cast<double>(e + 1)), "a");
            t.add(episode("ropras3", 1000, 0, 10, true, 50, 0.1), "b");
            t.add(episode("ropras3", 1000, 0, 11, true, 70, 0.3), "b");
            // rpomcp at 100 sims: 1 of 2
            t.add(episode("rpomcp", 100, 0, 0, true, 5, 0.02), "c");
            t.add(episode("rpomcp", 100, 0, 1, false, -5, 0.02), "c");
            t.add(episode("rpomcp", 100, 0, 1, false, -5, 0.02), "c");  // a duplicate: counted once
            return t;
        }
    }  // namespace

    TEST(ResultPlot, PointsAreMeansWithStandardErrorsPerSolverAndKey)
    {
        const ResultTable t = sampleTable();
        ASSERT_EQ(t.records().size(), 8u) << "the duplicate is dropped";
        const auto success = plotSeries(t.records(), t.recordSources(), "sims", PlotMetric::SUCCESS);
        ASSERT_EQ(success.size(), 2u);
        EXPECT_EQ(success[0].label, "ROP-RAS3 dynamic");
        EXPECT_EQ(success[1].label, "R-POMCP dynamic");
        ASSERT_EQ(success[0].points.size(), 2u);
        EXPECT_DOUBLE_EQ(success[0].points[0].x, 100.0);
        EXPECT_DOUBLE_EQ(success[0].points[0].y, 75.0);
        EXPECT_NEAR(success[0].points[0].stdErr, 100.0 * std::sqrt(0.75 * 0.25 / 4.0), 1e-12);
        EXPECT_EQ(success[0].points[0].episodes, 4u);
        EXPECT_DOUBLE_EQ(success[0].points[1].y, 100.0);
        EXPECT_DOUBLE_EQ(success[0].points[1].stdErr, 0.0);
        EXPECT_DOUBLE_EQ(success[1].points[0].y, 50.0);

        const auto ret = plotSeries(t.records(), t.recordSources(), "sims", PlotMetric::RETURN);
        EXPECT_DOUBLE_EQ(ret[0].points[0].y, 25.0);
        // sample s.d. of 10, 20, 30, 40 = sqrt(500 / 3); s.e. = that / 2
        EXPECT_NEAR(ret[0].points[0].stdErr, std::sqrt(500.0 / 3.0) / 2.0, 1e-12);
        EXPECT_DOUBLE_EQ(ret[0].points[1].y, 60.0);
        EXPECT_NEAR(ret[0].points[1].stdErr, 10.0, 1e-12);

        const auto time = plotSeries(t.records(), t.recordSources(), "sims", PlotMetric::PLAN_TIME);
        EXPECT_NEAR(time[0].points[0].y, 0.025, 1e-12);
        EXPECT_NEAR(time[0].points[1].y, 0.2, 1e-12);
    }

    TEST(ResultPlot, KeyComesFromParamsElseTheScenarioDefaults)
    {
        ResultTable t;
        t.add(episode("ropras3", 100, 8, 0, true, 1, 0.1), "x:1");
        t.add(episode("ropras3", 100, 0, 1, false, 1, 0.1), "x:2");  // no --param depth: the default 4
        const auto s = plotSeries(t.records(), t.recordSources(), "depth", PlotMetric::SUCCESS);
        ASSERT_EQ(s.size(), 1u) << "the key's own parameter does not split the line";
        ASSERT_EQ(s[0].points.size(), 2u);
        EXPECT_DOUBLE_EQ(s[0].points[0].x, 4.0);
        EXPECT_DOUBLE_EQ(s[0].points[0].y, 0.0);
        EXPECT_DOUBLE_EQ(s[0].points[1].x, 8.0);
        EXPECT_DOUBLE_EQ(s[0].points[1].y, 100.0);
        EXPECT_DOUBLE_EQ(plotKeyValue(t.records()[0], "beta_a", "x:1"), 2.0);
        // a default of the record's own solver (config.solver_defaults) comes before the shared one
        auto own = t.records()[1];
        own["config"]["solver_defaults"] = {{"ropras3", {{"depth", 0}}}, {"rpomcp", {{"depth", 9}}}};
        EXPECT_DOUBLE_EQ(plotKeyValue(own, "depth", "x:2"), 0.0);
        EXPECT_DOUBLE_EQ(plotKeyValue(own, "beta_a", "x:2"), 2.0);
        own["solver"] = "bplan";
        EXPECT_DOUBLE_EQ(plotKeyValue(own, "depth", "x:2"), 4.0);
        expectErrorMentions([&] { plotKeyValue(t.records()[0], "dpth", "x:1"); }, {"x:1", "\"dpth\""});
        expectErrorMentions([&] { plotKeyValue(t.records()[0], "plan_time", "x:1"); },
                            {"x:1", "no time budget", "plan_time_s"});
        expectErrorMentions([] { plotMetricFromName("rate"); }, {"\"rate\"", "success, return, sims, plan_time"});
        expectErrorMentions([] { plotSeries({}, {}, "sims", PlotMetric::SUCCESS); }, {"no episode records"});
    }

    TEST(ResultPlot, SvgIsWellFormedWithOneErrorBarPerPointAndALegend)
    {
        const ResultTable t = sampleTable();
        auto series = plotSeries(t.records(), t.recordSources(), "sims", PlotMetric::SUCCESS);
        const std::string svg =
            lineChartSvg(series, plotKeyLabel("sims"), plotMetricLabel(PlotMetric::SUCCESS), "a <title> & more", true);
        tinyxml2::XMLDocument doc;
        ASSERT_EQ(doc.Parse(svg.c_str()), tinyxml2::XML_SUCCESS) << svg.substr(0, 400);
        std::size_t bars = 0, groups = 0, circles = 0;
        for (auto *g = doc.RootElement()->FirstChildElement("g"); g; g = g->NextSiblingElement("g"))
        {
            ++groups;
            for (auto *e = g->FirstChildElement(); e; e = e->NextSiblingElement())
            {
                const char *cls = e->Attribute("class");
                bars += cls && std::string(cls) == "error-bar" ? 1 : 0;
                circles += std::string(e->Name()) == "circle" ? 1 : 0;
            }
        }
        EXPECT_EQ(groups, 2u);
        EXPECT_EQ(bars, 3u) << "2 points of ROP-RAS3, 1 of R-POMCP";
        EXPECT_EQ(circles, 3u);
        EXPECT_NE(svg.find("ROP-RAS3 dynamic</text>"), std::string::npos) << "legend entry";
        EXPECT_NE(svg.find("simulations per planning call (budget) (log scale)"), std::string::npos);
        EXPECT_NE(svg.find("success (%"), std::string::npos);
        EXPECT_NE(svg.find("a &lt;title&gt; &amp; more"), std::string::npos);

        EXPECT_EQ(flattenSeries(series, "R-POMCP", true), 1u);
        EXPECT_TRUE(series[1].flat);
        EXPECT_FALSE(series[0].flat);
        const std::string flat = lineChartSvg(series, "x", "y", "t");
        EXPECT_NE(flat.find("class=\"flat\""), std::string::npos);
        EXPECT_EQ(flattenSeries(series, "B-VAMP", true), 0u);

        series[0].points[0].x = 0.0;
        expectErrorMentions([&] { lineChartSvg(series, "x", "y", "t", true); }, {"--log-x", "not > 0"});
    }

    TEST(ResultPlot, TheVerticalAxisCoversTheRangeItIsGiven)
    {
        // rates of 93-100 %: drawn alone the axis zooms to about 88-100; told to cover 0-100 it has the 0 tick
        std::vector<PlotSeries> series(1);
        series[0].label = "ROP-RAS3 uniform";
        series[0].points = {{1.0, 96.7, 3.3, 30}, {2.0, 93.3, 4.6, 30}, {4.0, 100.0, 0.0, 30}};
        const auto hasTick = [](const std::string &svg, const std::string &t)
        { return svg.find("text-anchor=\"end\" font-size=\"11\">" + t + "</text>") != std::string::npos; };
        const std::string zoomed = lineChartSvg(series, "x", "success (%)", "t");
        EXPECT_FALSE(hasTick(zoomed, "0"));
        EXPECT_TRUE(hasTick(zoomed, "100"));
        const std::string whole = lineChartSvg(series, "x", "success (%)", "t", false, 0.0, 100.0);
        EXPECT_TRUE(hasTick(whole, "0"));
        EXPECT_TRUE(hasTick(whole, "50"));
        EXPECT_TRUE(hasTick(whole, "100"));
        EXPECT_EQ(lineChartSvg(series, "x", "success (%)", "t", false, std::nullopt, std::nullopt), zoomed)
            << "nothing to cover: the data's range only";
        EXPECT_TRUE(hasTick(lineChartSvg(series, "x", "success (%)", "t", false, 0.0), "0")) << "a lower bound alone";
    }

    TEST(ResultTableCsv, RowsAsCsvWithQuotingAndFullPrecision)
    {
        const ResultTable t = sampleTable();
        std::istringstream in(t.csv());
        std::string line;
        std::vector<std::string> lines;
        while (std::getline(in, line))
            lines.push_back(line);
        ASSERT_EQ(lines.size(), 4u) << t.csv();  // header, R-POMCP at 100, ROP-RAS3 at 100 and 1000 sims
        EXPECT_EQ(lines[0].rfind("scenario,solver,heuristic,budget,episodes,sims_per_call,success_percent,", 0), 0u);
        EXPECT_EQ(lines[0].back(), '\r') << "RFC 4180 line ends";
        EXPECT_EQ(lines[1].rfind("maze2d,R-POMCP,Dynamic,100 sims,2,100,50,", 0), 0u) << lines[1];
        EXPECT_EQ(lines[2].rfind("maze2d,ROP-RAS3,Dynamic,100 sims,4,100,75,", 0), 0u) << lines[2];
        // success s.e. sqrt(.75 .25 / 4) = 21.650635094610966 points, then the return mean 25
        EXPECT_NE(lines[2].find(",21.65063509461096"), std::string::npos) << lines[2];
        EXPECT_NE(lines[2].find(",25,"), std::string::npos) << lines[2];

        ResultTable quoted;
        auto r = episode("ropras3", 100, 0, 0, true, 1, 0.1);
        r["params"]["note"] = "a, \"b\"";
        quoted.add(r, "q");
        EXPECT_NE(quoted.csv().find("\"ROP-RAS3 [note=\"\"a, \\\"\"b\\\"\"\"\"]\""), std::string::npos) << quoted.csv();
    }
}  // namespace ropras::scenarios::test
