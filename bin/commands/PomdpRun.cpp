// `ropras pomdp-run`: closed-loop episodes of any registered POMDP model with any solver, by name.
#include <cmath>
#include <fstream>
#include <iomanip>
#include <iostream>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "ArgumentChecks.h"
#include "CommandRegistry.h"
#include "ropras/core/Error.h"
#include "ropras/core/InputFile.h"
#include "ropras/pomdp/ModelRegistry.h"

namespace
{
    struct RunOptions
    {
        std::string model{"tiger"};
        std::string solver{"ropras3"};
        std::size_t episodes{20};
        std::size_t steps{100};
        std::size_t simulations{1000};
        double seconds{0.0};
        std::size_t planningParticles{0};
        std::uint64_t seed{1};
        std::vector<std::string> params;
        std::string json;
        bool listModels{false};
    };

    struct MeanSe
    {
        double sum{0.0}, sumSquares{0.0};
        std::size_t n{0};
        void add(double x)
        {
            sum += x;
            sumSquares += x * x;
            ++n;
        }
        double mean() const { return n ? sum / static_cast<double>(n) : 0.0; }
        double se() const
        {
            if (n < 2)
            {
                return 0.0;
            }
            const double m = mean();
            const double var = (sumSquares - static_cast<double>(n) * m * m) / static_cast<double>(n - 1);
            return std::sqrt(std::max(0.0, var) / static_cast<double>(n));
        }
    };

    int run(const RunOptions &o)
    {
        auto &registry = ropras::pomdp::modelRegistry();
        if (o.listModels)
        {
            for (const auto &name : registry.names())
            {
                std::cout << name << ": " << registry.get(name).description << '\n';
            }
            return 0;
        }
        if (o.episodes == 0)
        {
            throw ropras::Error("pomdp-run: --episodes must be >= 1");
        }
        ropras::pomdp::EpisodeSettings settings;
        settings.maxSteps = o.steps;
        settings.budget = ropras::pomdp::Budget{o.simulations, o.seconds};
        settings.budget.validate();
        settings.planningParticles = o.planningParticles;
        auto runner = registry.create(o.model, o.solver, ropras::pomdp::ParameterMap::parse(o.params));
        MeanSe discounted, undiscounted, steps;
        std::size_t terminal = 0, invalid = 0, depletions = 0;
        ropras::pomdp::SearchStatistics search;
        nlohmann::json episodes = nlohmann::json::array();
        for (std::size_t e = 0; e < o.episodes; ++e)
        {
            const auto r = runner->runEpisode(settings, o.seed + e);
            discounted.add(r.discountedReturn);
            undiscounted.add(r.undiscountedReturn);
            steps.add(static_cast<double>(r.steps));
            terminal += r.terminal ? 1 : 0;
            invalid += r.invalidPlans;
            depletions += r.depletions;
            search.accumulate(r.search);
            episodes.push_back({{"seed", o.seed + e},
                                {"discounted_return", r.discountedReturn},
                                {"undiscounted_return", r.undiscountedReturn},
                                {"steps", r.steps},
                                {"terminal", r.terminal},
                                {"plans", r.plans},
                                {"invalid_plans", r.invalidPlans},
                                {"depletions", r.depletions}});
        }
        std::cout << std::fixed << std::setprecision(2) << o.model << " / " << runner->solverName() << ", "
                  << o.episodes << " episodes\n"
                  << "  discounted return   " << discounted.mean() << " (se " << discounted.se() << ")\n"
                  << "  undiscounted return " << undiscounted.mean() << " (se " << undiscounted.se() << ")\n"
                  << "  steps               " << steps.mean() << "\n"
                  << "  terminal episodes   " << terminal << "\n"
                  << "  invalid plans       " << invalid << ", filter depletions " << depletions << "\n"
                  << "  simulations         " << search.simulations << ", reference plans " << search.referenceRequested
                  << " (failed " << search.referenceFailed << ")\n"
                  << "  tree memory         largest " << ropras::formatBytes(search.treeBytes) << ", "
                  << search.memoryCapped << " plans stopped at the cap (--param max_tree_mb)\n";
        if (search.memoryCapped > 0)
        {
            std::cerr << "ropras pomdp-run: warning: " << search.memoryCapped
                      << " planning calls stopped early because the search tree reached its memory cap "
                         "(solver parameter max_tree_mb, default 1024 MiB)\n";
        }
        if (!o.json.empty())
        {
            nlohmann::json out{{"model", o.model},
                               {"solver", runner->solverName()},
                               {"discounted_return_mean", discounted.mean()},
                               {"discounted_return_se", discounted.se()},
                               {"undiscounted_return_mean", undiscounted.mean()},
                               {"undiscounted_return_se", undiscounted.se()},
                               {"steps_mean", steps.mean()},
                               {"terminal_episodes", terminal},
                               {"invalid_plans", invalid},
                               {"depletions", depletions},
                               {"simulations", search.simulations},
                               {"reference_requested", search.referenceRequested},
                               {"reference_failed", search.referenceFailed},
                               {"memory_capped_plans", search.memoryCapped},
                               {"tree_bytes_max", search.treeBytes},
                               {"episodes", episodes}};
            std::ofstream file(o.json);
            if (!file)
            {
                throw ropras::Error("pomdp-run: cannot write JSON file \"" + o.json + "\"");
            }
            file << out.dump(2) << '\n';
        }
        return 0;
    }

    std::function<int()> setup(CLI::App &app)
    {
        auto o = std::make_shared<RunOptions>();
        app.add_option("--model", o->model, "Registered POMDP model")->capture_default_str();
        app.add_option("--solver", o->solver, "ropras3, refbasic, pomcp, rpomcp, bplan or rbss")->capture_default_str();
        // CLI11 reads "-1" into an unsigned option as 2^64 - 1: counts are range-checked as numbers first
        app.add_option("--episodes", o->episodes, "Number of episodes (at most 10^6)")
            ->capture_default_str()
            ->check(ropras::bin::EPISODES);
        app.add_option("--steps", o->steps, "Maximum primitive steps per episode (at most 10^7)")
            ->capture_default_str()
            ->check(ropras::bin::countCheck(1, 10000000, "COUNT"));
        app.add_option("--simulations", o->simulations, "Simulations per planning call (0 = no limit; at most 10^9)")
            ->capture_default_str()
            ->check(ropras::bin::SIMULATIONS_OR_ZERO);
        app.add_option("--seconds", o->seconds, "Seconds per planning call (0 = no limit; at most 86400)")
            ->capture_default_str()
            ->check(ropras::bin::PLAN_SECONDS_OR_ZERO);
        app.add_option("--planning-particles", o->planningParticles,
                       "Particles handed to the solver per plan (0 = the filter's; memory is checked)")
            ->capture_default_str()
            ->check(ropras::bin::NON_NEGATIVE_COUNT);
        app.add_option("--seed", o->seed, "Seed of the first episode")->capture_default_str()->check(ropras::bin::SEED);
        app.add_option("--param", o->params, "Solver / filter / model parameter name=value (repeatable)");
        app.add_option("--json", o->json, "Write the summary and per-episode results as JSON");
        app.add_flag("--list-models", o->listModels, "List the registered models and exit");
        return [o] { return run(*o); };
    }

    const ropras::bin::CommandRegistrar reg{
        {"pomdp-run", "Run closed-loop episodes of a registered POMDP model with a solver, by name", setup}};
}  // namespace
