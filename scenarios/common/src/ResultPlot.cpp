#include "ropras/scenarios/ResultPlot.h"

#include <algorithm>
#include <cmath>
#include <map>
#include <set>
#include <sstream>

#include "SvgPicture.h"

#include "ropras/core/Error.h"
#include "ropras/scenarios/ResultTable.h"

namespace ropras::scenarios
{
    namespace
    {
        const char *const PALETTE[] = {"#1f77b4", "#d62728", "#2ca02c", "#ff7f0e", "#9467bd",
                                       "#8c564b", "#e377c2", "#17becf", "#7f7f7f", "#bcbd22"};

        double numberAt(const nlohmann::json &object, const std::string &key, bool &found)
        {
            const auto it = object.is_object() ? object.find(key) : object.end();
            found = it != object.end() && it->is_number();
            return found ? it->get<double>() : 0.0;
        }

        std::string shortValue(const nlohmann::json &v)
        {
            if (!v.is_number())
            {
                return v.dump();
            }
            std::ostringstream out;
            out << v.get<double>();
            return out.str();
        }

        double metricValue(const nlohmann::json &r, PlotMetric metric)
        {
            switch (metric)
            {
                case PlotMetric::SUCCESS:
                    return r.at("success").get<bool>() ? 100.0 : 0.0;
                case PlotMetric::RETURN:
                    return r.at("undiscounted_return").get<double>();
                case PlotMetric::SIMS:
                    return r.at("sims_per_call").get<double>();
                case PlotMetric::PLAN_TIME:
                    return r.at("plan_time_s").get<double>();
            }
            return 0.0;
        }

        /// the line a record belongs to (its key) and that line's legend text
        std::pair<std::string, std::string> lineOf(const nlohmann::json &r, const std::string &key)
        {
            const std::string solver = r.value("solver", std::string("?"));
            nlohmann::json id = {{"scenario", r.value("scenario", std::string("?"))}, {"solver", solver}};
            std::string label = solverDisplayName(solver);
            std::vector<std::string> extras;
            if (solver != "pomcp")
            {
                const std::string heuristic = r.value("heuristic", std::string("?"));
                id["heuristic"] = heuristic;
                label += " " + heuristic;
                if (key != "epsilon" && r.contains("epsilon") && r["epsilon"].is_number() &&
                    r["epsilon"].get<double>() > 0.0)
                {
                    id["epsilon"] = r["epsilon"];
                    extras.push_back("eps=" + shortValue(r["epsilon"]));
                }
                if (r.contains("planner") && r["planner"] != "VectorizedRRTConnect")
                {
                    id["planner"] = r["planner"];
                    extras.push_back(r["planner"].get<std::string>());
                }
            }
            if (r.contains("params") && r["params"].is_object())
            {
                for (const auto &item : r["params"].items())
                {
                    if (item.key() != key)
                    {
                        id["params"][item.key()] = item.value();
                        extras.push_back(item.key() + "=" + shortValue(item.value()));
                    }
                }
            }
            if (key != "sims" && key != "plan_time" && r.contains("budget"))
            {
                id["budget"] = r["budget"];
            }
            if (r.value("replan_every_step", false))
            {
                id["replan"] = true;
                extras.push_back("replan every step");
            }
            std::string more;
            for (const auto &e : extras)
                more += (more.empty() ? "" : ", ") + e;
            return {id.dump(), label + (more.empty() ? "" : " [" + more + "]")};
        }

        std::string tickText(double v)
        {
            std::ostringstream out;
            out << (std::abs(v) < 1e-12 ? 0.0 : v);
            return out.str();
        }
    }  // namespace

    PlotMetric plotMetricFromName(const std::string &name)
    {
        if (name == "success")
            return PlotMetric::SUCCESS;
        if (name == "return")
            return PlotMetric::RETURN;
        if (name == "sims")
            return PlotMetric::SIMS;
        if (name == "plan_time")
            return PlotMetric::PLAN_TIME;
        throw Error("unknown metric \"" + name + "\" (known: success, return, sims, plan_time)");
    }

    std::string plotMetricLabel(PlotMetric metric)
    {
        switch (metric)
        {
            case PlotMetric::SUCCESS:
                return "success (%, \u00b1 s.e.)";
            case PlotMetric::RETURN:
                return "mean return (undiscounted, \u00b1 s.e.)";
            case PlotMetric::SIMS:
                return "simulations per planning call (\u00b1 s.e.)";
            case PlotMetric::PLAN_TIME:
                return "planning time per call (s, \u00b1 s.e.)";
        }
        return "";
    }

    std::string plotKeyLabel(const std::string &key)
    {
        if (key == "sims")
            return "simulations per planning call (budget)";
        if (key == "plan_time")
            return "planning time per call (s, budget)";
        if (key == "sims_per_call")
            return "simulations per planning call (measured)";
        if (key == "plan_time_s")
            return "planning time per call (s, measured)";
        if (key == "epsilon")
            return "epsilon (share of uniform targets)";
        if (key == "depth")
            return "tree depth D (macro levels)";
        return key;
    }

    double plotKeyValue(const nlohmann::json &record, const std::string &key, const std::string &source)
    {
        bool found = false;
        if (key == "sims" || key == "plan_time")
        {
            const double v = numberAt(record.value("budget", nlohmann::json::object()),
                                      key == "sims" ? "simulations" : "seconds", found);
            if (!found || !(v > 0.0))
            {
                throw Error(source + ": the record has no " +
                            (key == "sims" ? std::string("simulation budget (run with --sims N)")
                                           : std::string("time budget (run with --plan-time S)")) +
                            "; plot against " + (key == "sims" ? "sims_per_call" : "plan_time_s") +
                            " for the measured value");
            }
            return v;
        }
        if (key == "epsilon" || key == "sims_per_call" || key == "plan_time_s")
        {
            const double v = numberAt(record, key, found);
            if (!found)
                throw Error(source + ": the record has no number \"" + key + "\"");
            return v;
        }
        const double param = numberAt(record.value("params", nlohmann::json::object()), key, found);
        if (found)
            return param;
        const nlohmann::json config = record.value("config", nlohmann::json::object());
        const nlohmann::json perSolver = config.value("solver_defaults", nlohmann::json::object());
        if (perSolver.is_object() && record.contains("solver") && record["solver"].is_string())
        {
            const double own =
                numberAt(perSolver.value(record["solver"].get<std::string>(), nlohmann::json::object()), key, found);
            if (found)
                return own;
        }
        const double fallback = numberAt(config.value("defaults", nlohmann::json::object()), key, found);
        if (found)
            return fallback;
        const double value = numberAt(config, key, found);
        if (found)
            return value;
        throw Error(source + ": no number \"" + key +
                    "\" in the record's params, its scenario's defaults or its configuration (keys: sims, plan_time, "
                    "epsilon, sims_per_call, plan_time_s or a --param name)");
    }

    std::vector<PlotSeries> plotSeries(const std::vector<nlohmann::json> &records,
                                       const std::vector<std::string> &sources, const std::string &key,
                                       PlotMetric metric)
    {
        if (records.empty())
        {
            throw Error("no episode records to plot");
        }
        std::vector<std::string> order;
        std::map<std::string, std::string> labels;
        std::map<std::string, std::map<double, std::vector<double>>> values;
        for (std::size_t i = 0; i < records.size(); ++i)
        {
            const std::string source = i < sources.size() ? sources[i] : "record " + std::to_string(i + 1);
            const double x = plotKeyValue(records[i], key, source);
            const auto line = lineOf(records[i], key);
            if (labels.emplace(line.first, line.second).second)
                order.push_back(line.first);
            values[line.first][x].push_back(metricValue(records[i], metric));
        }
        std::vector<PlotSeries> out;
        for (const auto &id : order)
        {
            PlotSeries s;
            s.label = labels[id];
            for (const auto &entry : values[id])
            {
                PlotPoint p;
                p.x = entry.first;
                p.episodes = entry.second.size();
                p.y = sampleMean(entry.second);
                if (metric == PlotMetric::SUCCESS)
                {
                    const double share = p.y / 100.0;
                    p.stdErr = 100.0 * std::sqrt(share * (1.0 - share) / static_cast<double>(p.episodes));
                }
                else
                {
                    p.stdErr = standardError(entry.second);
                }
                s.points.push_back(p);
            }
            out.push_back(std::move(s));
        }
        return out;
    }

    std::size_t flattenSeries(std::vector<PlotSeries> &series, const std::string &prefix, bool binomial)
    {
        std::size_t marked = 0;
        for (auto &s : series)
        {
            if (s.label.rfind(prefix, 0) != 0 || s.points.empty())
                continue;
            PlotPoint pooled;
            double variance = 0.0;
            for (const auto &p : s.points)
            {
                pooled.episodes += p.episodes;
                pooled.y += p.y * static_cast<double>(p.episodes);
            }
            pooled.y /= static_cast<double>(pooled.episodes);
            for (const auto &p : s.points)
            {
                const double w = static_cast<double>(p.episodes) / static_cast<double>(pooled.episodes);
                variance += w * w * p.stdErr * p.stdErr;
            }
            const double share = pooled.y / 100.0;
            pooled.stdErr = binomial ? 100.0 * std::sqrt(share * (1.0 - share) / static_cast<double>(pooled.episodes))
                                     : std::sqrt(variance);
            pooled.x = s.points.front().x;
            s.points = {pooled};
            s.flat = true;
            ++marked;
        }
        return marked;
    }

    std::string lineChartSvg(const std::vector<PlotSeries> &series, const std::string &xLabel,
                             const std::string &yLabel, const std::string &title, bool logX,
                             std::optional<double> yCoverLo, std::optional<double> yCoverHi)
    {
        double xLo = INFINITY, xHi = -INFINITY, yLo = INFINITY, yHi = -INFINITY;
        for (const auto &s : series)
            for (const auto &p : s.points)
            {
                if (logX && !(p.x > 0.0))
                    throw Error("--log-x: the key's value " + tickText(p.x) + " of \"" + s.label + "\" is not > 0");
                const double x = logX ? std::log10(p.x) : p.x;
                if (!s.flat || series.size() == 1)
                {
                    xLo = std::min(xLo, x);
                    xHi = std::max(xHi, x);
                }
                yLo = std::min(yLo, p.y - p.stdErr);
                yHi = std::max(yHi, p.y + p.stdErr);
            }
        if (!std::isfinite(xLo) || !std::isfinite(yLo))
            throw Error("nothing to plot: no point in any line");
        if (yCoverLo)
            yLo = std::min(yLo, *yCoverLo);
        if (yCoverHi)
            yHi = std::max(yHi, *yCoverHi);
        if (xHi - xLo < 1e-12)  // one key value: a window around it (half to twice it on a log scale)
        {
            const double half = logX ? std::log10(2.0) : (xLo != 0.0 ? 0.5 * std::abs(xLo) : 1.0);
            xLo -= half;
            xHi += half;
        }
        if (yHi - yLo < 1e-12)
        {
            yLo -= 1.0;
            yHi += 1.0;
        }
        const double yPad = 0.05 * (yHi - yLo);
        yLo -= yPad;
        yHi += yPad;
        const double xPad = 0.04 * (xHi - xLo);
        xLo -= xPad;
        xHi += xPad;
        std::size_t longest = 0;  // the legend's column grows with its longest label (about 6.5 px per character)
        for (const auto &s : series)
            longest = std::max(longest, s.label.size());
        const double right = std::max(200.0, 60.0 + 6.5 * static_cast<double>(longest));
        const double W = 470 + right, H = 440, left = 80, top = 40, bottom = 60;
        const double pw = W - left - right, ph = H - top - bottom;
        const auto X = [&](double x) { return left + ((logX ? std::log10(x) : x) - xLo) / (xHi - xLo) * pw; };
        const auto Y = [&](double y) { return top + (yHi - y) / (yHi - yLo) * ph; };
        std::ostringstream svg;
        svg << "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"" << W << "\" height=\"" << H << "\" viewBox=\"0 0 "
            << W << ' ' << H << "\" font-family=\"sans-serif\">\n"
            << "<rect width=\"100%\" height=\"100%\" fill=\"#ffffff\"/>\n"
            << "<text x=\"" << left + pw / 2 << "\" y=\"22\" text-anchor=\"middle\" font-size=\"15\">"
            << detail::xmlEscape(title) << "</text>\n";
        // y ticks
        const double yStep = detail::niceStep(yHi - yLo);
        for (double t = std::ceil(yLo / yStep) * yStep; t <= yHi + 1e-9 * yStep; t += yStep)
        {
            svg << "<line x1=\"" << left << "\" x2=\"" << left + pw << "\" y1=\"" << detail::num(Y(t)) << "\" y2=\""
                << detail::num(Y(t)) << "\" stroke=\"#e4e4e4\"/>\n"
                << "<text x=\"" << left - 6 << "\" y=\"" << detail::num(Y(t) + 4)
                << "\" text-anchor=\"end\" font-size=\"11\">" << tickText(t) << "</text>\n";
        }
        // x ticks: decades (and 2, 5 times them) on a log scale, nice steps otherwise
        std::vector<double> xTicks;
        if (logX)
        {
            for (int e = static_cast<int>(std::floor(xLo)); e <= static_cast<int>(std::ceil(xHi)); ++e)
                for (const double m : {1.0, 2.0, 5.0})
                {
                    const double v = m * std::pow(10.0, e);
                    if (std::log10(v) >= xLo && std::log10(v) <= xHi)
                        xTicks.push_back(v);
                }
        }
        else
        {
            const double xStep = detail::niceStep(xHi - xLo);
            for (double t = std::ceil(xLo / xStep) * xStep; t <= xHi + 1e-9 * xStep; t += xStep)
                xTicks.push_back(t);
        }
        for (const double t : xTicks)
        {
            svg << "<line x1=\"" << detail::num(X(t)) << "\" x2=\"" << detail::num(X(t)) << "\" y1=\"" << top
                << "\" y2=\"" << top + ph << "\" stroke=\"#e4e4e4\"/>\n"
                << "<text x=\"" << detail::num(X(t)) << "\" y=\"" << top + ph + 16
                << "\" text-anchor=\"middle\" font-size=\"11\">" << tickText(t) << "</text>\n";
        }
        svg << "<rect x=\"" << left << "\" y=\"" << top << "\" width=\"" << pw << "\" height=\"" << ph
            << "\" fill=\"none\" stroke=\"#000000\"/>\n"
            << "<text x=\"" << left + pw / 2 << "\" y=\"" << H - 18 << "\" text-anchor=\"middle\" font-size=\"13\">"
            << detail::xmlEscape(xLabel + (logX ? " (log scale)" : "")) << "</text>\n"
            << "<text transform=\"translate(20 " << top + ph / 2
            << ") rotate(-90)\" text-anchor=\"middle\" font-size=\"13\">" << detail::xmlEscape(yLabel) << "</text>\n";
        for (std::size_t i = 0; i < series.size(); ++i)
        {
            const std::string colour = PALETTE[i % (sizeof(PALETTE) / sizeof(PALETTE[0]))];
            const auto &pts = series[i].points;
            svg << "<g class=\"series\" data-label=\"" << detail::xmlEscape(series[i].label) << "\" data-points=\""
                << pts.size() << "\">\n";
            if (series[i].flat)
            {
                const auto &p = pts.front();
                svg << "<rect x=\"" << left << "\" width=\"" << pw << "\" y=\"" << detail::num(Y(p.y + p.stdErr))
                    << "\" height=\"" << detail::num(Y(p.y - p.stdErr) - Y(p.y + p.stdErr)) << "\" fill=\"" << colour
                    << "\" fill-opacity=\"0.12\"/>\n"
                    << "<line class=\"flat\" x1=\"" << left << "\" x2=\"" << left + pw << "\" y1=\""
                    << detail::num(Y(p.y)) << "\" y2=\"" << detail::num(Y(p.y)) << "\" stroke=\"" << colour
                    << "\" stroke-width=\"2\" stroke-dasharray=\"6 4\"><title>" << detail::xmlEscape(series[i].label)
                    << ": " << tickText(p.y) << " \u00b1 " << tickText(p.stdErr) << " (" << p.episodes
                    << " episodes)</title></line>\n</g>\n";
            }
            else
            {
                if (pts.size() > 1)
                {
                    svg << "<polyline fill=\"none\" stroke=\"" << colour << "\" stroke-width=\"2\" points=\"";
                    for (const auto &p : pts)
                        svg << detail::num(X(p.x)) << ',' << detail::num(Y(p.y)) << ' ';
                    svg << "\"/>\n";
                }
                for (const auto &p : pts)
                {
                    const double x = X(p.x);
                    svg << "<line class=\"error-bar\" x1=\"" << detail::num(x) << "\" x2=\"" << detail::num(x)
                        << "\" y1=\"" << detail::num(Y(p.y - p.stdErr)) << "\" y2=\"" << detail::num(Y(p.y + p.stdErr))
                        << "\" stroke=\"" << colour << "\"/>\n";
                    for (const double e : {p.y - p.stdErr, p.y + p.stdErr})
                        svg << "<line x1=\"" << detail::num(x - 4) << "\" x2=\"" << detail::num(x + 4) << "\" y1=\""
                            << detail::num(Y(e)) << "\" y2=\"" << detail::num(Y(e)) << "\" stroke=\"" << colour
                            << "\"/>\n";
                    svg << "<circle cx=\"" << detail::num(x) << "\" cy=\"" << detail::num(Y(p.y))
                        << "\" r=\"3.5\" fill=\"" << colour << "\"><title>" << detail::xmlEscape(series[i].label)
                        << ": x = " << tickText(p.x) << ", " << tickText(p.y) << " \u00b1 " << tickText(p.stdErr)
                        << " (" << p.episodes << " episodes)</title></circle>\n";
                }
                svg << "</g>\n";
            }
            const double ly = top + 10 + 18.0 * static_cast<double>(i);
            svg << "<line x1=\"" << left + pw + 14 << "\" x2=\"" << left + pw + 38 << "\" y1=\"" << ly << "\" y2=\""
                << ly << "\" stroke=\"" << colour << "\" stroke-width=\"2\""
                << (series[i].flat ? " stroke-dasharray=\"6 4\"" : "") << "/>\n"
                << "<text x=\"" << left + pw + 44 << "\" y=\"" << ly + 4 << "\" font-size=\"11\">"
                << detail::xmlEscape(series[i].label) << "</text>\n";
        }
        svg << "</svg>\n";
        return svg.str();
    }
}  // namespace ropras::scenarios
