#ifndef ROPRAS_SCENARIOS_RESULT_TABLE_H
#define ROPRAS_SCENARIOS_RESULT_TABLE_H

#include <cstddef>
#include <iosfwd>
#include <map>
#include <nlohmann/json.hpp>
#include <set>
#include <string>
#include <vector>

namespace ropras::scenarios
{
    /** \brief Aggregate of the episodes of one configuration (one row of the paper's tables). */
    struct ResultRow
    {
        /// display names: the scenario (with " (config k)" when one scenario ran with several configurations),
        /// the solver in the paper's spelling with non-default settings in brackets, the heuristic, the budget
        std::string scenario;
        std::string solver;
        std::string heuristic;
        std::string budget;
        std::size_t episodes{0};
        double successPercent{0.0};
        /// mean undiscounted return and its standard error (sample standard deviation / sqrt(n); 0 for n = 1)
        double rewardMean{0.0};
        double rewardStdErr{0.0};
        double discountedMean{0.0};
        double discountedStdErr{0.0};
        double stepsMean{0.0};
        /// mean over episodes of sims_per_call; N/A in the table when every episode reports 0 (B-plan)
        double simsPerCall{0.0};
        bool hasSimulations{false};
        /// mean over episodes of ref_failures, in %; N/A when no reference plan was requested (POMCP)
        double refFailPercent{0.0};
        bool hasReference{false};
        /// mean over episodes of plan_time_s
        double planTime{0.0};
    };

    /** \brief Merges episode records (the JSON lines of `ropras run`, from one or several files: shards of one
        run, several solvers or scenarios) into one row per scenario configuration x solver x heuristic x
        planner x budget (x epsilon, params, replan mode), in the paper's columns.

        An episode is identified by its configuration, run seed and episode index: a record seen twice (two
        shards overlapping, a file given twice) is counted once and reported in warnings(). */
    class ResultTable
    {
    public:
        /** \brief Adds one episode record; \a source names it in messages (e.g. "run.jsonl:12"). Returns false
            (and adds a warning) when the same episode is already in the table. Throws ropras::Error naming
            \a source and the key when a required key (scenario, solver, seed, episode, success,
            discounted_return, undiscounted_return, steps, sims_per_call, plan_time_s, ref_failures) is missing
            or of the wrong type. */
        bool add(const nlohmann::json &record, const std::string &source);

        /** \brief Adds every line of a JSON-lines stream (blank lines are skipped); a malformed line throws
            ropras::Error naming "name:line". A truncated record (a JSON object cut off before its end, as an
            interrupted writer leaves it) is skipped with a warning naming "name:line". Returns the number of
            records read. */
        std::size_t addJsonLines(std::istream &in, const std::string &name);

        /** \brief addJsonLines() of a file; throws ropras::Error when it cannot be opened, is not a regular file
            or is larger than the input size limit (ropras::checkInputFile()). */
        std::size_t addFile(const std::string &path);

        /// episodes in the table (duplicates counted once)
        std::size_t size() const { return seen_.size(); }
        const std::vector<std::string> &warnings() const { return warnings_; }

        /** \brief The rows, ordered by scenario (first appearance), then solver in the paper's order (B-plan,
            POMCP, Ref-Basic, R-POMCP, ROP-RAS3, others), heuristic (uniform, dynamic), then first appearance. */
        std::vector<ResultRow> rows() const;

        /** \brief The Markdown table: Scenario | Solver | Heuristic | Sims # | Succ. % | Rewards (std err) |
            Steps | R.P. Fail % | Plan time (s) | Budget | Episodes. */
        std::string markdown() const;

        /** \brief The same rows as CSV (RFC 4180 quoting), full precision: scenario, solver, heuristic, budget,
            episodes, sims_per_call, success_percent, success_stderr, reward_mean, reward_stderr,
            discounted_mean, discounted_stderr, steps_mean, ref_fail_percent, plan_time_s (empty for N/A). */
        std::string csv() const;

        /// the accepted records (duplicates dropped) in the order read, and where each came from ("file:line")
        const std::vector<nlohmann::json> &records() const { return records_; }
        const std::vector<std::string> &recordSources() const { return sources_; }

    private:
        struct Group
        {
            std::string scenario;
            std::string configKey;
            std::string solver;
            std::string heuristic;
            std::string extras;
            std::string budget;
            std::size_t order{0};
            std::vector<double> rewards, discounted, steps, sims, refFailures, planTimes;
            std::size_t successes{0};
            std::size_t refRequested{0};
            bool refCounted{false};
        };

        std::map<std::string, Group> groups_;
        std::set<std::string> seen_;
        /// per scenario name: its configurations in order of appearance
        std::map<std::string, std::vector<std::string>> configs_;
        std::vector<std::string> scenarioOrder_;
        std::vector<std::string> warnings_;
        std::vector<nlohmann::json> records_;
        std::vector<std::string> sources_;
    };

    /** \brief The Markdown table of \a rows (see ResultTable::markdown()). */
    std::string markdownTable(const std::vector<ResultRow> &rows);

    /// mean of \a v (0 when empty) and its standard error (sample standard deviation / sqrt(n); 0 for n < 2)
    double sampleMean(const std::vector<double> &v);
    double standardError(const std::vector<double> &v);
    /// the solver's name in the paper's spelling (ropras3 -> ROP-RAS3, ...; unknown names unchanged)
    std::string solverDisplayName(const std::string &solver);

    /** \brief The CSV table of \a rows (see ResultTable::csv()). */
    std::string csvTable(const std::vector<ResultRow> &rows);
}  // namespace ropras::scenarios

#endif
