#include "ropras/scenarios/ResultTable.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <istream>
#include <sstream>
#include <tuple>

#include "ropras/core/Error.h"
#include "ropras/core/InputFile.h"

namespace ropras::scenarios
{
    namespace
    {
        const nlohmann::json &required(const nlohmann::json &record, const char *key, const std::string &source)
        {
            const auto it = record.find(key);
            if (it == record.end())
            {
                throw Error(source + ": the episode record has no key \"" + key + "\"");
            }
            return *it;
        }

        double number(const nlohmann::json &record, const char *key, const std::string &source)
        {
            const auto &value = required(record, key, source);
            if (!value.is_number())
            {
                throw Error(source + ": key \"" + key + "\" must be a number, not " + value.dump());
            }
            return value.get<double>();
        }

        std::uint64_t whole(const nlohmann::json &record, const char *key, const std::string &source)
        {
            const auto &value = required(record, key, source);
            if (!value.is_number_unsigned() && !(value.is_number_integer() && value.get<std::int64_t>() >= 0))
            {
                throw Error(source + ": key \"" + key + "\" must be a whole number >= 0, not " + value.dump());
            }
            return value.get<std::uint64_t>();
        }

        /// \a min <= value <= \a max (and whole with \a whole), else an Error naming the key and the value
        void requireRange(double value, const char *key, const std::string &source, double min, double max, bool whole,
                          const char *meaning)
        {
            if (value >= min && value <= max && (!whole || value == std::floor(value)))
            {
                return;
            }
            throw Error(source + ": key \"" + key + "\" = " + nlohmann::json(value).dump() + " must be " + meaning);
        }

        /** A record `ropras run` cannot have written: negative or fractional steps, a reference failure rate
            outside [0, 1] (200 %), negative counts or times, more failed than requested reference plans, or
            macro_min > macro_max in its configuration or parameters: an error, never a row averaging it. */
        void checkEpisodeValues(const nlohmann::json &record, const std::string &source, double steps, double sims,
                                double planTime, double refFailures)
        {
            constexpr double BIG = 1e300;
            requireRange(steps, "steps", source, 0.0, BIG, true, "a whole number >= 0");
            requireRange(sims, "sims_per_call", source, 0.0, BIG, false, ">= 0");
            requireRange(planTime, "plan_time_s", source, 0.0, BIG, false, ">= 0 seconds");
            requireRange(refFailures, "ref_failures", source, 0.0, 1.0, false,
                         "a fraction of the reference plans in [0, 1]");
            if (record.contains("epsilon") && record["epsilon"].is_number())
            {
                requireRange(record["epsilon"].get<double>(), "epsilon", source, 0.0, 1.0, false, "in [0, 1]");
            }
            const auto count = [&](const char *key)
            { return record.contains(key) && record[key].is_number() ? record[key].get<double>() : -1.0; };
            if (count("ref_failed") > count("ref_requested") && count("ref_requested") >= 0.0)
            {
                throw Error(source + ": key \"ref_failed\" = " + record["ref_failed"].dump() +
                            " exceeds \"ref_requested\" = " + record["ref_requested"].dump());
            }
            for (const char *part : {"config", "params"})
            {
                if (!record.contains(part) || !record[part].is_object())
                {
                    continue;
                }
                const auto &settings = record[part];
                const auto lo = settings.find("macro_min");
                const auto hi = settings.find("macro_max");
                if (lo != settings.end() && hi != settings.end() && lo->is_number() && hi->is_number() &&
                    lo->get<double>() > hi->get<double>())
                {
                    throw Error(source + ": " + part + " has macro_min = " + lo->dump() +
                                " > macro_max = " + hi->dump());
                }
            }
        }

        std::string text(const nlohmann::json &record, const char *key, const std::string &source)
        {
            const auto &value = required(record, key, source);
            if (!value.is_string())
            {
                throw Error(source + ": key \"" + key + "\" must be a string, not " + value.dump());
            }
            return value.get<std::string>();
        }

        std::string optionalText(const nlohmann::json &record, const char *key, const std::string &fallback,
                                 const std::string &source)
        {
            return record.contains(key) ? text(record, key, source) : fallback;
        }

        std::string format(const char *fmt, double value)
        {
            char buffer[64];
            std::snprintf(buffer, sizeof(buffer), fmt, value);
            return buffer;
        }

        /// the shortest of %g that reads back the same value, for labels
        std::string shortNumber(double value)
        {
            char buffer[64];
            if (value == std::floor(value) && std::abs(value) < 1e15)
            {
                std::snprintf(buffer, sizeof(buffer), "%.0f", value);
                return buffer;
            }
            for (int digits = 1; digits <= 17; ++digits)
            {
                std::snprintf(buffer, sizeof(buffer), "%.*g", digits, value);
                if (std::strtod(buffer, nullptr) == value)
                {
                    break;
                }
            }
            return buffer;
        }

        int solverRank(const std::string &solver)
        {
            static const std::vector<std::string> order{"bplan", "pomcp", "refbasic", "rpomcp", "ropras3"};
            const auto it = std::find(order.begin(), order.end(), solver);
            return static_cast<int>(it - order.begin());
        }

        int heuristicRank(const std::string &heuristic)
        {
            if (heuristic == "N/A")
                return 0;
            if (heuristic.rfind("Uniform", 0) == 0)
                return 1;
            if (heuristic.rfind("Dynamic", 0) == 0)
                return 2;
            return 3;
        }

        std::string capitalized(std::string s)
        {
            if (!s.empty() && s[0] >= 'a' && s[0] <= 'z')
            {
                s[0] = static_cast<char>(s[0] - 'a' + 'A');
            }
            return s;
        }

        std::string budgetLabel(const nlohmann::json &record, const std::string &source)
        {
            const auto it = record.find("budget");
            if (it == record.end())
            {
                return "?";
            }
            if (!it->is_object())
            {
                throw Error(source + ": key \"budget\" must be an object {simulations, seconds}");
            }
            const double sims = number(*it, "simulations", source + " (budget)");
            const double seconds = number(*it, "seconds", source + " (budget)");
            std::string out;
            if (sims > 0.0)
            {
                out = shortNumber(sims) + " sims";
            }
            if (seconds > 0.0)
            {
                out += (out.empty() ? "" : " / ") + shortNumber(seconds) + " s";
            }
            return out.empty() ? "none" : out;
        }
    }  // namespace

    bool ResultTable::add(const nlohmann::json &record, const std::string &source)
    {
        if (!record.is_object())
        {
            throw Error(source + ": an episode record must be a JSON object, not " + std::string(record.type_name()));
        }
        Group g;
        g.scenario = text(record, "scenario", source);
        g.solver = text(record, "solver", source);
        const std::uint64_t seed = whole(record, "seed", source);
        const std::uint64_t episode = whole(record, "episode", source);
        const auto &success = required(record, "success", source);
        if (!success.is_boolean())
        {
            throw Error(source + ": key \"success\" must be true or false, not " + success.dump());
        }
        const double reward = number(record, "undiscounted_return", source);
        const double discounted = number(record, "discounted_return", source);
        const double steps = number(record, "steps", source);
        const double sims = number(record, "sims_per_call", source);
        const double planTime = number(record, "plan_time_s", source);
        const double refFailures = number(record, "ref_failures", source);
        const bool usesReference = g.solver != "pomcp";
        checkEpisodeValues(record, source, steps, sims, planTime, refFailures);

        // the configuration that makes a row; settings a solver does not use are left out (POMCP: heuristic,
        // epsilon, planner)
        nlohmann::json key = nlohmann::json::object();
        key["scenario"] = g.scenario;
        key["solver"] = g.solver;
        key["budget"] = budgetLabel(record, source);
        g.budget = key["budget"].get<std::string>();
        const nlohmann::json config = record.contains("config") ? record["config"] : nlohmann::json();
        g.configKey = config.dump();
        key["config"] = g.configKey;
        std::vector<std::string> extras;
        if (usesReference)
        {
            const std::string heuristic = optionalText(record, "heuristic", "?", source);
            const double epsilon = record.contains("epsilon") ? number(record, "epsilon", source) : 0.0;
            const std::string planner = optionalText(record, "planner", "VectorizedRRTConnect", source);
            key["heuristic"] = heuristic;
            key["epsilon"] = epsilon;
            key["planner"] = planner;
            g.heuristic = capitalized(heuristic) + (epsilon > 0.0 ? ", eps " + shortNumber(epsilon) : "");
            if (planner != "VectorizedRRTConnect")
            {
                extras.push_back(planner);
            }
        }
        else
        {
            g.heuristic = "N/A";
        }
        if (record.contains("params"))
        {
            const auto &params = record["params"];
            if (!params.is_object())
            {
                throw Error(source + ": key \"params\" must be an object of name: value");
            }
            key["params"] = params;
            for (const auto &item : params.items())
            {
                extras.push_back(
                    item.key() + "=" +
                    (item.value().is_number() ? shortNumber(item.value().get<double>()) : item.value().dump()));
            }
        }
        if (record.contains("replan_every_step"))
        {
            const auto &replan = record["replan_every_step"];
            if (!replan.is_boolean())
            {
                throw Error(source + ": key \"replan_every_step\" must be true or false");
            }
            key["replan_every_step"] = replan;
            if (replan.get<bool>())
            {
                extras.push_back("replan every step");
            }
        }
        for (const auto &e : extras)
        {
            g.extras += (g.extras.empty() ? "" : ", ") + e;
        }

        const std::string groupKey = key.dump();
        const std::string episodeKey = groupKey + "#" + std::to_string(seed) + "#" + std::to_string(episode);
        if (!seen_.insert(episodeKey).second)
        {
            warnings_.push_back(source + ": episode " + std::to_string(episode) + " of " + g.scenario + " / " +
                                g.solver + " (seed " + std::to_string(seed) +
                                ") is already in the table (overlapping shards?); counted once");
            return false;
        }
        auto it = groups_.find(groupKey);
        if (it == groups_.end())
        {
            g.order = groups_.size();
            it = groups_.emplace(groupKey, std::move(g)).first;
            if (std::find(scenarioOrder_.begin(), scenarioOrder_.end(), it->second.scenario) == scenarioOrder_.end())
            {
                scenarioOrder_.push_back(it->second.scenario);
            }
            auto &configs = configs_[it->second.scenario];
            if (std::find(configs.begin(), configs.end(), it->second.configKey) == configs.end())
            {
                configs.push_back(it->second.configKey);
            }
        }
        records_.push_back(record);
        sources_.push_back(source);
        Group &group = it->second;
        group.rewards.push_back(reward);
        group.discounted.push_back(discounted);
        group.steps.push_back(steps);
        group.sims.push_back(sims);
        group.planTimes.push_back(planTime);
        group.refFailures.push_back(refFailures);
        group.successes += success.get<bool>() ? 1 : 0;
        if (record.contains("ref_requested"))
        {
            group.refCounted = true;
            group.refRequested += whole(record, "ref_requested", source);
        }
        return true;
    }

    std::size_t ResultTable::addJsonLines(std::istream &in, const std::string &name)
    {
        std::string line;
        std::size_t lineNumber = 0, count = 0;
        while (std::getline(in, line))
        {
            ++lineNumber;
            if (line.find_first_not_of(" \t\r") == std::string::npos)
            {
                continue;
            }
            const std::string source = name + ":" + std::to_string(lineNumber);
            nlohmann::json record;
            try
            {
                record = nlohmann::json::parse(line);
            }
            catch (const nlohmann::json::out_of_range &e)  // a number beyond a double (1e400)
            {
                throw Error(source + ": malformed JSON: " + e.what());
            }
            catch (const nlohmann::json::parse_error &e)
            {
                // an object cut off before its end (what a writer interrupted between its system calls leaves): the
                // parser failed only when the line ran out, past its last byte
                const bool truncated = line.find_first_not_of(" \t") == line.find('{') && e.byte > line.size();
                if (!truncated)
                {
                    throw Error(source + ": malformed JSON: " + e.what());
                }
                warnings_.push_back(source + ": truncated record (" + std::to_string(line.size()) +
                                    " bytes, cut off before its end: an interrupted run?), skipped");
                continue;
            }
            add(record, source);
            ++count;
        }
        return count;
    }

    std::size_t ResultTable::addFile(const std::string &path)
    {
        checkInputFile(path, "results file");
        std::ifstream file(path);
        if (!file)
        {
            throw Error("cannot open the results file \"" + path + "\"");
        }
        return addJsonLines(file, path);
    }

    std::vector<ResultRow> ResultTable::rows() const
    {
        std::vector<const Group *> ordered;
        for (const auto &entry : groups_)
        {
            ordered.push_back(&entry.second);
        }
        const auto scenarioRank = [this](const Group *g)
        { return std::find(scenarioOrder_.begin(), scenarioOrder_.end(), g->scenario) - scenarioOrder_.begin(); };
        const auto configRank = [this](const Group *g)
        {
            const auto &configs = configs_.at(g->scenario);
            return std::find(configs.begin(), configs.end(), g->configKey) - configs.begin();
        };
        std::sort(ordered.begin(), ordered.end(),
                  [&](const Group *a, const Group *b)
                  {
                      const auto ka = std::make_tuple(scenarioRank(a), configRank(a), solverRank(a->solver), a->solver,
                                                      heuristicRank(a->heuristic), a->order);
                      const auto kb = std::make_tuple(scenarioRank(b), configRank(b), solverRank(b->solver), b->solver,
                                                      heuristicRank(b->heuristic), b->order);
                      return ka < kb;
                  });
        std::vector<ResultRow> out;
        for (const Group *g : ordered)
        {
            ResultRow row;
            row.scenario = g->scenario;
            if (configs_.at(g->scenario).size() > 1)
            {
                row.scenario += " (config " + std::to_string(configRank(g) + 1) + ")";
            }
            row.solver = solverDisplayName(g->solver) + (g->extras.empty() ? "" : " [" + g->extras + "]");
            row.heuristic = g->heuristic;
            row.budget = g->budget;
            row.episodes = g->rewards.size();
            row.successPercent = 100.0 * static_cast<double>(g->successes) / static_cast<double>(row.episodes);
            row.rewardMean = sampleMean(g->rewards);
            row.rewardStdErr = standardError(g->rewards);
            row.discountedMean = sampleMean(g->discounted);
            row.discountedStdErr = standardError(g->discounted);
            row.stepsMean = sampleMean(g->steps);
            row.simsPerCall = sampleMean(g->sims);
            row.hasSimulations = std::any_of(g->sims.begin(), g->sims.end(), [](double s) { return s > 0.0; });
            row.refFailPercent = 100.0 * sampleMean(g->refFailures);
            row.hasReference = g->solver != "pomcp" && (!g->refCounted || g->refRequested > 0);
            row.planTime = sampleMean(g->planTimes);
            out.push_back(std::move(row));
        }
        return out;
    }

    double sampleMean(const std::vector<double> &v)
    {
        double sum = 0.0;
        for (const double x : v)
        {
            sum += x;
        }
        return v.empty() ? 0.0 : sum / static_cast<double>(v.size());
    }

    double standardError(const std::vector<double> &v)
    {
        if (v.size() < 2)
        {
            return 0.0;
        }
        const double m = sampleMean(v);
        double squares = 0.0;
        for (const double x : v)
        {
            squares += (x - m) * (x - m);
        }
        const double n = static_cast<double>(v.size());
        return std::sqrt(squares / (n - 1.0) / n);
    }

    std::string solverDisplayName(const std::string &solver)
    {
        static const std::map<std::string, std::string> names{{"ropras3", "ROP-RAS3"},   {"pomcp", "POMCP"},
                                                              {"rpomcp", "R-POMCP"},     {"bplan", "B-plan"},
                                                              {"refbasic", "Ref-Basic"}, {"rbss", "RBSS"}};
        const auto it = names.find(solver);
        return it == names.end() ? solver : it->second;
    }

    std::string ResultTable::markdown() const
    {
        return markdownTable(rows());
    }

    std::string ResultTable::csv() const
    {
        return csvTable(rows());
    }

    std::string csvTable(const std::vector<ResultRow> &rows)
    {
        const auto field = [](const std::string &text)
        {
            if (text.find_first_of(",\"\r\n") == std::string::npos)
                return text;
            std::string out = "\"";
            for (const char c : text)
                out += c == '"' ? std::string("\"\"") : std::string(1, c);
            return out + "\"";
        };
        const auto number = [](double v) { return format("%.17g", v); };
        std::ostringstream out;
        out << "scenario,solver,heuristic,budget,episodes,sims_per_call,success_percent,success_stderr,reward_mean,"
               "reward_stderr,discounted_mean,discounted_stderr,steps_mean,ref_fail_percent,plan_time_s\r\n";
        for (const auto &r : rows)
        {
            const double share = r.successPercent / 100.0;
            const double successErr = 100.0 * std::sqrt(share * (1.0 - share) / static_cast<double>(r.episodes));
            out << field(r.scenario) << ',' << field(r.solver) << ',' << field(r.heuristic) << ',' << field(r.budget)
                << ',' << r.episodes << ',' << (r.hasSimulations ? number(r.simsPerCall) : "") << ','
                << number(r.successPercent) << ',' << number(successErr) << ',' << number(r.rewardMean) << ','
                << number(r.rewardStdErr) << ',' << number(r.discountedMean) << ',' << number(r.discountedStdErr) << ','
                << number(r.stepsMean) << ',' << (r.hasReference ? number(r.refFailPercent) : "") << ','
                << number(r.planTime) << "\r\n";
        }
        return out.str();
    }

    std::string markdownTable(const std::vector<ResultRow> &rows)
    {
        std::ostringstream out;
        out << "| Scenario | Solver | Heuristic | Sims # | Succ. % | Rewards (std err) | Steps | R.P. Fail % | "
               "Plan time (s) | Budget | Episodes |\n"
            << "| --- | --- | --- | ---: | ---: | ---: | ---: | ---: | ---: | --- | ---: |\n";
        for (const auto &r : rows)
        {
            out << "| " << r.scenario << " | " << r.solver << " | " << r.heuristic << " | "
                << (r.hasSimulations ? format(r.simsPerCall >= 10.0 ? "%.0f" : "%.1f", r.simsPerCall) : "N/A") << " | "
                << format("%.1f", r.successPercent) << " | " << format("%.1f", r.rewardMean) << " ("
                << format("%.1f", r.rewardStdErr) << ") | " << format("%.1f", r.stepsMean) << " | "
                << (r.hasReference ? format("%.1f", r.refFailPercent) : "N/A") << " | "
                << format(r.planTime >= 0.01 || r.planTime == 0.0 ? "%.3f" : "%.5f", r.planTime) << " | " << r.budget
                << " | " << r.episodes << " |\n";
        }
        return out.str();
    }
}  // namespace ropras::scenarios
