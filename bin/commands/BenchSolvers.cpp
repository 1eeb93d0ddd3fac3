// `ropras bench-solvers`: simulations per second per solver on Tiger (depth 50) and the share of search time
// spent inside the model.
#include <ctime>
#include <fstream>
#include <iomanip>
#include <iostream>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "ArgumentChecks.h"
#include "CommandRegistry.h"
#include "ropras/core/Error.h"
#include "ropras/pomdp/ModelRegistry.h"

namespace
{
    struct BenchOptions
    {
        std::string json;
        std::string model{"tiger"};
        std::vector<std::string> solvers{"ropras3", "refbasic", "pomcp", "rpomcp"};
        std::size_t simulations{20000};
        std::size_t repeats{5};
        std::size_t depth{50};
        std::uint64_t seed{1};
        std::vector<std::string> params;
    };

    double threadCpuSeconds()
    {
        timespec t{};
        clock_gettime(CLOCK_THREAD_CPUTIME_ID, &t);
        return static_cast<double>(t.tv_sec) + 1e-9 * static_cast<double>(t.tv_nsec);
    }

    // Runs `repeats` planning calls of `simulations` each (after a warm-up call); the summed statistics and
    // the thread CPU time of the measured calls.
    ropras::pomdp::SearchStatistics measure(const BenchOptions &o, const std::string &solver, bool profile,
                                            double &cpuSeconds)
    {
        auto params = ropras::pomdp::ParameterMap::parse(o.params);
        if (!params.contains("depth") && solver != "bplan")  // B-plan has no search depth
        {
            params.set("depth", static_cast<double>(o.depth));
        }
        if (profile)
        {
            params.set("profile", 1.0);
        }
        auto runner = ropras::pomdp::modelRegistry().create(o.model, solver, params);
        ropras::pomdp::SearchStatistics total;
        runner->planFromInitialBelief(ropras::pomdp::Budget::ofSimulations(o.simulations / 10 + 1), o.seed);  // warm-up
        const double cpuStart = threadCpuSeconds();
        for (std::size_t r = 0; r < o.repeats; ++r)
        {
            total.accumulate(
                runner->planFromInitialBelief(ropras::pomdp::Budget::ofSimulations(o.simulations), o.seed + r));
        }
        cpuSeconds = threadCpuSeconds() - cpuStart;
        return total;
    }

    int run(const BenchOptions &o)
    {
        if (o.simulations == 0 || o.repeats == 0)
        {
            throw ropras::Error("bench-solvers: --simulations and --repeats must be >= 1");
        }
        nlohmann::json out;
        out["model"] = o.model;
        out["depth"] = o.depth;
        out["simulations_per_plan"] = o.simulations;
        out["repeats"] = o.repeats;
        std::cout << std::left << std::setw(10) << "solver" << std::right << std::setw(14) << "sims/cpu-s"
                  << std::setw(14) << "sims/wall-s" << std::setw(12) << "model %" << std::setw(12) << "ref %"
                  << std::setw(14) << "nodes/plan" << std::setw(10) << "depth" << '\n';
        for (const auto &solver : o.solvers)
        {
            double cpuSeconds = 0.0, unused = 0.0;
            const auto plain = measure(o, solver, false, cpuSeconds);
            const auto profiled = measure(o, solver, true, unused);
            // Per core: simulations per second of this thread's CPU time (insensitive to other load on a
            // shared machine); the wall-clock rate is reported beside it.
            const double simsPerSecond = static_cast<double>(plain.simulations) / cpuSeconds;
            const double simsPerWallSecond = static_cast<double>(plain.simulations) / plain.seconds;
            const double modelShare = profiled.modelSeconds / profiled.seconds;
            const double referenceShare = profiled.referenceSeconds / profiled.seconds;
            out[solver + "_sims_per_s"] = simsPerSecond;
            out[solver + "_sims_per_wall_s"] = simsPerWallSecond;
            out[solver + "_model_share"] = modelShare;
            out[solver + "_reference_share"] = referenceShare;
            out[solver + "_belief_nodes_per_plan"] = plain.beliefNodes / o.repeats;
            out[solver + "_max_depth"] = plain.maxDepth;
            std::cout << std::left << std::setw(10) << solver << std::right << std::setw(14) << std::fixed
                      << std::setprecision(0) << simsPerSecond << std::setw(14) << simsPerWallSecond << std::setw(11)
                      << std::setprecision(1) << 100.0 * modelShare << '%' << std::setw(11) << 100.0 * referenceShare
                      << '%' << std::setw(14) << plain.beliefNodes / o.repeats << std::setw(10) << plain.maxDepth
                      << '\n';
        }
        if (!o.json.empty())
        {
            std::ofstream file(o.json);
            if (!file)
            {
                throw ropras::Error("bench-solvers: cannot write JSON file \"" + o.json + "\"");
            }
            file << out.dump(2) << '\n';
        }
        return 0;
    }

    std::function<int()> setup(CLI::App &app)
    {
        auto options = std::make_shared<BenchOptions>();
        app.add_option("--json", options->json, "Write the results as JSON to this file");
        app.add_option("--model", options->model, "Registered model to benchmark")->capture_default_str();
        app.add_option("--solvers", options->solvers, "Solvers to benchmark")->capture_default_str();
        // CLI11 reads "-1" into an unsigned option as 2^64 - 1: counts are range-checked as numbers first
        app.add_option("--simulations", options->simulations, "Simulations per planning call (at most 10^9)")
            ->capture_default_str()
            ->check(ropras::bin::SIMULATIONS);
        app.add_option("--repeats", options->repeats, "Planning calls per solver (at most 10^6)")
            ->capture_default_str()
            ->check(ropras::bin::REPEATS);
        app.add_option("--depth", options->depth, "Search depth D (at most 2^32 - 1)")
            ->capture_default_str()
            ->check(ropras::bin::countCheck(1, 4294967295ULL, "COUNT"));
        app.add_option("--seed", options->seed, "Seed of the first planning call")
            ->capture_default_str()
            ->check(ropras::bin::SEED);
        app.add_option("--param", options->params, "Extra solver parameter name=value (repeatable)");
        return [options] { return run(*options); };
    }

    const ropras::bin::CommandRegistrar reg{
        {"bench-solvers", "Simulations per second per solver on a model (default Tiger, depth 50)", setup}};
}  // namespace
