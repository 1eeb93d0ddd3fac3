#ifndef ROPRAS_SCENARIOS_RESULT_PLOT_H
#define ROPRAS_SCENARIOS_RESULT_PLOT_H

#include <cstddef>
#include <nlohmann/json.hpp>
#include <optional>
#include <string>
#include <vector>

namespace ropras::scenarios
{
    /** \brief What `ropras plot` draws on the vertical axis, per point the mean over its episodes and an error
        bar of one standard error: success (%, s.e. sqrt(p (1 - p) / n)), return (the undiscounted total
        reward), sims (simulations per planning call, as measured) and plan_time (seconds per planning call, as
        measured). */
    enum class PlotMetric
    {
        SUCCESS,
        RETURN,
        SIMS,
        PLAN_TIME
    };

    /** \brief The metric named \a name (success, return, sims, plan_time); throws ropras::Error naming the
        valid ones otherwise. */
    PlotMetric plotMetricFromName(const std::string &name);

    /** \brief The horizontal value of one episode record for key \a key: "sims" = the simulation budget per
        call (`--sims`), "plan_time" = the time budget per call (`--plan-time`, or the scenario's default),
        "epsilon" = the heuristic's epsilon, "sims_per_call" / "plan_time_s" = the measured means, any other
        name = that `--param` of the record, else the scenario's default of that name for the record's solver
        (config.solver_defaults.SOLVER, then config.defaults), else a
        number of its configuration. Throws ropras::Error naming \a source and the key when the record has no
        such number (or a zero budget for sims / plan_time). */
    double plotKeyValue(const nlohmann::json &record, const std::string &key, const std::string &source);

    /** \brief One point of a line: the mean and its standard error over the episodes at one key value. */
    struct PlotPoint
    {
        double x{0.0};
        double y{0.0};
        double stdErr{0.0};
        std::size_t episodes{0};
    };

    /** \brief One line: the episodes of one scenario x solver x heuristic (x the parameters other than the
        key), points in increasing x. */
    struct PlotSeries
    {
        std::string label;
        std::vector<PlotPoint> points;
        /// drawn as a dashed horizontal line at the mean of its points across the whole chart (a line to beat,
        /// e.g. R-POMCP at epsilon 0 in the paper's ablation), its error band one standard error wide
        bool flat{false};
    };

    /** \brief The lines of \a metric against \a key over episode records (as ResultTable::records() keeps them:
        validated, duplicates dropped); \a sources names each record in messages. Throws ropras::Error when a
        record lacks the key (plotKeyValue()) or there is no record. */
    std::vector<PlotSeries> plotSeries(const std::vector<nlohmann::json> &records,
                                       const std::vector<std::string> &sources, const std::string &key,
                                       PlotMetric metric);

    /** \brief Axis labels with units: of the metric ("success (%)", ...) and of the key ("simulations per
        planning call (budget)", "planning time per call (s)", "epsilon", "tree depth D (macro levels)", or the
        parameter's name). */
    std::string plotMetricLabel(PlotMetric metric);
    std::string plotKeyLabel(const std::string &key);

    /** \brief Marks as flat (PlotSeries::flat) every series whose label starts with \a prefix, pooling its points
        into one (episode-weighted mean; standard error from the pooled binomial or the points' errors). Returns
        how many series it marked. */
    std::size_t flattenSeries(std::vector<PlotSeries> &series, const std::string &prefix, bool binomial);

    /** \brief A standalone SVG line chart: one coloured line per series with markers and error bars of one
        standard error, axes with ticks and labels, a legend, \a title on top; \a logX draws x on a log10 scale
        (every x must then be > 0, else ropras::Error). The vertical axis spans the points and their error bars,
        widened to cover [\a yCoverLo, \a yCoverHi] where those are given (`ropras plot` gives 0 and 100 for
        success, so rates are never drawn on a zoomed axis that makes a few points look like a cliff). */
    std::string lineChartSvg(const std::vector<PlotSeries> &series, const std::string &xLabel,
                             const std::string &yLabel, const std::string &title, bool logX = false,
                             std::optional<double> yCoverLo = std::nullopt,
                             std::optional<double> yCoverHi = std::nullopt);
}  // namespace ropras::scenarios

#endif
