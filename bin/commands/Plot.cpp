// `ropras plot FILES... --x KEY --y METRIC --out CHART.svg`: the JSON lines of `ropras run` as an SVG line chart.
#include <fstream>
#include <iostream>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "CommandRegistry.h"
#include "OutputChecks.h"
#include "ResultFiles.h"
#include "ropras/core/Error.h"
#include "ropras/scenarios/ResultPlot.h"
#include "ropras/scenarios/ResultTable.h"

namespace
{
    struct PlotOptions
    {
        std::vector<std::string> files;
        std::string x{"sims"};
        std::string y{"success"};
        std::string out;
        std::string title;
        bool logX{false};
        std::vector<std::string> flat;
    };

    int run(const PlotOptions &o)
    {
        namespace sc = ropras::scenarios;
        ropras::bin::refuseOverwritingInputs("--out", o.out, o.files);
        const sc::PlotMetric metric = sc::plotMetricFromName(o.y);
        sc::ResultTable table;  // reads and validates the records as `ropras table` does
        ropras::bin::readResultFiles(table, o.files, "ropras plot");
        auto series = sc::plotSeries(table.records(), table.recordSources(), o.x, metric);
        for (const auto &prefix : o.flat)
        {
            if (sc::flattenSeries(series, prefix, metric == sc::PlotMetric::SUCCESS) == 0)
            {
                throw ropras::Error("--flat \"" + prefix + "\": no line's label starts with it");
            }
        }
        const std::string title =
            o.title.empty() ? sc::plotMetricLabel(metric) + " against " + sc::plotKeyLabel(o.x) : o.title;
        const bool rate = metric == sc::PlotMetric::SUCCESS;  // rates on the whole 0-100 % axis
        const std::string svg = sc::lineChartSvg(series, sc::plotKeyLabel(o.x), sc::plotMetricLabel(metric), title,
                                                 o.logX, rate ? std::optional<double>(0.0) : std::nullopt,
                                                 rate ? std::optional<double>(100.0) : std::nullopt);
        std::ofstream file(o.out);
        file << svg;
        if (!file)
        {
            throw ropras::Error("--out: cannot write \"" + o.out + "\"");
        }
        for (const auto &s : series)
        {
            std::cout << s.label << ":";
            for (const auto &p : s.points)
            {
                std::cout << "  " << p.x << " -> " << p.y << " (" << p.stdErr << ", " << p.episodes << " ep.)";
            }
            std::cout << '\n';
        }
        std::cout << "wrote " << o.out << " (" << series.size() << " lines)\n";
        return 0;
    }

    std::function<int()> setup(CLI::App &app)
    {
        auto o = std::make_shared<PlotOptions>();
        app.add_option("files", o->files, "JSON-lines files written by `ropras run --out`")
            ->required()
            ->check(CLI::ExistingFile);
        app.add_option("--x", o->x,
                       "Horizontal key: sims, plan_time (the budgets), epsilon, sims_per_call, plan_time_s (measured), "
                       "depth or any --param name")
            ->capture_default_str();
        app.add_option("--y", o->y, "Vertical metric: success, return, sims or plan_time")->capture_default_str();
        app.add_option("--out", o->out, "The SVG file to write")->required();
        app.add_option("--title", o->title, "Title of the chart (default: metric against key)");
        app.add_flag("--log-x", o->logX, "Log10 scale on the horizontal axis (e.g. for sims)");
        app.add_option("--flat", o->flat,
                       "Draw the lines whose label starts with this text (e.g. R-POMCP) as dashed horizontal lines at "
                       "their pooled mean: a line to beat (repeatable)");
        return [o] { return run(*o); };
    }

    const ropras::bin::CommandRegistrar reg{
        {"plot", "Draw the JSON lines of `ropras run` as an SVG line chart with error bars (one line per solver)",
         setup}};
}  // namespace
