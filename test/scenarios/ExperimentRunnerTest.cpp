// The experiment runner on a test-only toy scenario: shards, seeds, determinism across thread counts and shard
// splits, the JSON record, recordings, and bad settings.
#include <gtest/gtest.h>
#include <unistd.h>

#include <cstdio>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <limits>
#include <set>
#include <string>
#include <vector>

#include "ExpectError.h"
#include "ropras/core/Error.h"
#include "ropras/scenarios/ExperimentRunner.h"
#include "ropras/scenarios/ResultTable.h"
#include "ropras/scenarios/TreeDump.h"
#include "scenarios/ToyScenario.h"

namespace ropras::scenarios::test
{
    using ropras::test::expectErrorMentions;

    namespace
    {

        /** \brief The record without its wall-clock keys (the only ones that may differ between runs). */
        nlohmann::json withoutTiming(nlohmann::json record)
        {
            record.erase("plan_time_s");
            record.erase("wall_time_s");
            record.erase("threads");
            record.erase("shard");
            return record;
        }

        ExperimentSettings toySettings(const std::string &solver, std::size_t episodes, std::size_t sims)
        {
            ExperimentSettings s;
            s.run.solver = solver;
            s.run.budget = pomdp::Budget::ofSimulations(sims);
            s.episodes = episodes;
            s.seed = 42;
            s.threads = 1;
            return s;
        }

        std::filesystem::path freshDirectory(const std::string &name)
        {
            const auto dir = std::filesystem::temp_directory_path() /
                             ("ropras-runner-test-" + name + "-" + std::to_string(::getpid()));
            std::filesystem::remove_all(dir);
            return dir;
        }
    }  // namespace

    TEST(Shard, ParsesAndOwnsEveryEpisodeExactlyOnce)
    {
        const Shard whole = Shard::parse("0/1");
        EXPECT_EQ(whole.index, 0u);
        EXPECT_EQ(whole.count, 1u);
        const Shard s = Shard::parse("3/10");
        EXPECT_EQ(s.index, 3u);
        EXPECT_EQ(s.count, 10u);
        EXPECT_EQ(s.str(), "3/10");
        for (std::size_t e = 0; e < 100; ++e)
        {
            std::size_t owners = 0;
            for (std::size_t i = 0; i < 7; ++i)
            {
                owners += Shard{i, 7}.owns(e) ? 1 : 0;
            }
            EXPECT_EQ(owners, 1u) << "episode " << e;
            EXPECT_EQ(Shard::parse("2/7").owns(e), e % 7 == 2);
        }
    }

    TEST(Shard, BadTextNamesTheValue)
    {
        for (const std::string bad : {"1/1", "5/3", "1/0", "0/0"})
        {
            expectErrorMentions([&] { Shard::parse(bad); }, {"shard " + bad, "must be"});
        }
        for (const std::string bad : {"", "2", "a/b", "-1/3", "1/2/3", "1 /2", "/4", "3/", "0x1/2"})
        {
            expectErrorMentions([&] { Shard::parse(bad); }, {"shard \"" + bad + "\"", "i/N"});
        }
    }

    TEST(EpisodeSeed, DependsOnRunSeedAndEpisodeOnly)
    {
        std::set<std::uint64_t> seeds;
        for (std::uint64_t run = 0; run < 20; ++run)
        {
            for (std::size_t e = 0; e < 200; ++e)
            {
                seeds.insert(episodeSeed(run, e));
            }
        }
        EXPECT_EQ(seeds.size(), 20u * 200u) << "episode seeds collide";
        EXPECT_EQ(episodeSeed(7, 3), episodeSeed(7, 3));
        EXPECT_NE(episodeSeed(7, 3), episodeSeed(3, 7));
    }

    TEST(ExperimentRunner, DefaultBudgetIsTheScenarioPlanningTime)
    {
        const auto toy = makeToyScenario();
        RunSettings s;
        const RunSettings resolved = resolvedRunSettings(*toy, s);
        EXPECT_EQ(resolved.budget.simulations, 0u);
        EXPECT_DOUBLE_EQ(resolved.budget.seconds, 0.01);
        s.budget = pomdp::Budget::ofSimulations(50);
        EXPECT_EQ(resolvedRunSettings(*toy, s).budget.simulations, 50u);
        EXPECT_DOUBLE_EQ(resolvedRunSettings(*toy, s).budget.seconds, 0.0);
        s.budget.seconds = -1.0;
        expectErrorMentions([&] { resolvedRunSettings(*toy, s); }, {"-1"});
    }

    // The same seed gives the same episodes with 1 or 2 threads and with the shard split 1/1 vs 0/2 + 1/2
    // (simulation budget, seeded VectorizedRRTConnect).
    TEST(ExperimentRunner, SameSeedSameRecordsWhateverThreadsAndShards)
    {
        const auto toy = makeToyScenario(30);
        ExperimentSettings s = toySettings("ropras3", 4, 30);
        const auto serial = runExperiment(*toy, s);
        ASSERT_EQ(serial.size(), 4u);
        s.threads = 2;
        const auto parallel = runExperiment(*toy, s);
        ASSERT_EQ(parallel.size(), 4u);
        s.threads = 2;
        s.shard = Shard{0, 2};
        const auto even = runExperiment(*toy, s);
        s.shard = Shard{1, 2};
        const auto odd = runExperiment(*toy, s);
        ASSERT_EQ(even.size(), 2u);
        ASSERT_EQ(odd.size(), 2u);
        std::set<std::uint64_t> distinctSeeds;
        double totalSims = 0.0;
        for (std::size_t e = 0; e < 4; ++e)
        {
            EXPECT_EQ(serial[e]["episode"], e);
            EXPECT_EQ(serial[e]["episode_seed"], episodeSeed(42, e));
            EXPECT_EQ(withoutTiming(serial[e]), withoutTiming(parallel[e])) << "episode " << e << " with 2 threads";
            const auto &sharded = e % 2 == 0 ? even[e / 2] : odd[e / 2];
            EXPECT_EQ(withoutTiming(serial[e]), withoutTiming(sharded)) << "episode " << e << " in shard " << e % 2;
            distinctSeeds.insert(serial[e]["episode_seed"].get<std::uint64_t>());
            totalSims += serial[e]["simulations"].get<double>();
            EXPECT_GT(serial[e]["steps"].get<std::size_t>(), 0u);
        }
        EXPECT_EQ(distinctSeeds.size(), 4u);
        std::set<std::string> outcomes;
        for (const auto &r : serial)
        {
            outcomes.insert(r["undiscounted_return"].dump() + "/" + r["steps"].dump());
            std::printf("[ info ] toy episode %s: success %s, return %s, %s steps, %s sims/call, %s reference plans\n",
                        r["episode"].dump().c_str(), r["success"].dump().c_str(),
                        r["undiscounted_return"].dump().c_str(), r["steps"].dump().c_str(),
                        r["sims_per_call"].dump().c_str(), r["ref_requested"].dump().c_str());
        }
        EXPECT_GT(outcomes.size(), 1u) << "every episode played out the same: the episode seeds are not used";
        EXPECT_GT(totalSims, 0.0);
        // a different run seed gives different episodes
        s.shard = Shard{};
        s.seed = 43;
        const auto other = runExperiment(*toy, s);
        bool anyDifferent = false;
        for (std::size_t e = 0; e < 4; ++e)
        {
            anyDifferent = anyDifferent || withoutTiming(other[e]) != withoutTiming(serial[e]);
        }
        EXPECT_TRUE(anyDifferent);
    }

    TEST(ExperimentRunner, RecordHoldsTheConfigurationAndTheOutcome)
    {
        const auto toy = makeToyScenario(20);
        ExperimentSettings s = toySettings("ropras3", 2, 20);
        s.run.heuristic = "uniform";
        s.run.epsilon = 0.1;
        s.run.params.set("particles", 50);
        std::vector<std::size_t> order;
        std::size_t progressCalls = 0;
        ExperimentCallbacks callbacks;
        callbacks.onRecord = [&](const nlohmann::json &r) { order.push_back(r["episode"].get<std::size_t>()); };
        callbacks.onProgress = [&](const ExperimentProgress &p)
        {
            ++progressCalls;
            EXPECT_EQ(p.done, progressCalls);
            EXPECT_EQ(p.total, 2u);
            ASSERT_NE(p.record, nullptr);
            EXPECT_GE(p.elapsedSeconds, 0.0);
        };
        s.threads = 2;
        const auto records = runExperiment(*toy, s, callbacks);
        EXPECT_EQ(order, (std::vector<std::size_t>{0, 1}));
        EXPECT_EQ(progressCalls, 2u);
        const nlohmann::json &r = records.at(0);
        for (const char *key : {"scenario",
                                "config",
                                "solver",
                                "heuristic",
                                "epsilon",
                                "planner",
                                "budget",
                                "params",
                                "replan_every_step",
                                "seed",
                                "episode",
                                "episode_seed",
                                "success",
                                "terminal",
                                "discounted_return",
                                "undiscounted_return",
                                "steps",
                                "plans",
                                "invalid_plans",
                                "depletions",
                                "simulations",
                                "sims_per_call",
                                "plan_time_s",
                                "ref_requested",
                                "ref_failed",
                                "ref_failures",
                                "max_depth",
                                "wall_time_s"})
        {
            EXPECT_TRUE(r.contains(key)) << "missing key " << key << " in " << r.dump();
        }
        EXPECT_EQ(r["scenario"], "toy");
        EXPECT_EQ(r["config"], toy->config());
        EXPECT_EQ(r["solver"], "ropras3");
        EXPECT_EQ(r["heuristic"], "uniform");
        EXPECT_DOUBLE_EQ(r["epsilon"].get<double>(), 0.1);
        EXPECT_EQ(r["planner"], "VectorizedRRTConnect");
        EXPECT_EQ(r["budget"]["simulations"], 20);
        EXPECT_EQ(r["params"]["particles"], 50.0);
        EXPECT_EQ(r["seed"], 42);
        EXPECT_TRUE(r["success"].is_boolean());
        EXPECT_EQ(r["replan_every_step"], false);
        // derived keys agree with the counters they come from
        const double plans = r["plans"].get<double>();
        ASSERT_GT(plans, 0.0);
        EXPECT_DOUBLE_EQ(r["sims_per_call"].get<double>(), r["simulations"].get<double>() / plans);
        EXPECT_LE(r["sims_per_call"].get<double>(), 20.0);
        const double requested = r["ref_requested"].get<double>();
        EXPECT_GT(requested, 0.0) << "ropras3 asks its reference policy";
        EXPECT_DOUBLE_EQ(r["ref_failures"].get<double>(), r["ref_failed"].get<double>() / requested);
        EXPECT_LE(r["steps"].get<std::size_t>(), 20u);
        EXPECT_FALSE(r.contains("fill_tried")) << "the belief fill is off by default: no fill keys";
        // the toy pays -1 per step and +100 at the goal (terminal): within 20 steps a success returns > 0, a
        // failure <= 0
        for (const auto &rec : records)
        {
            const bool success = rec["success"].get<bool>();
            EXPECT_EQ(success, rec["undiscounted_return"].get<double>() > 0.0) << rec.dump();
            if (success)
            {
                EXPECT_TRUE(rec["terminal"].get<bool>());
            }
        }
        // the records make a table (one row)
        ResultTable table;
        for (const auto &rec : records)
        {
            EXPECT_TRUE(table.add(rec, "test"));
        }
        ASSERT_EQ(table.rows().size(), 1u);
        EXPECT_EQ(table.rows()[0].episodes, 2u);
        EXPECT_EQ(table.rows()[0].heuristic, "Uniform, eps 0.1");
    }

    TEST(ExperimentRunner, ReplanEveryStepPlansOncePerStep)
    {
        const auto toy = makeToyScenario(12);
        ExperimentSettings s = toySettings("pomcp", 1, 20);
        s.run.replanEveryStep = true;
        const auto r = runExperiment(*toy, s).at(0);
        EXPECT_EQ(r["plans"], r["steps"]);
        EXPECT_EQ(r["replan_every_step"], true);
    }

    TEST(ExperimentRunner, RecordingsAreWrittenPerEpisode)
    {
        const auto toy = makeToyScenario(15);
        ExperimentSettings s = toySettings("pomcp", 3, 20);
        s.shard = Shard{1, 2};
        const auto dir = freshDirectory("record");
        s.recordDir = (dir / "nested").string();
        s.record.beliefEvery = 5;
        const auto records = runExperiment(*toy, s);
        ASSERT_EQ(records.size(), 1u);
        EXPECT_FALSE(std::filesystem::exists(dir / "nested" / "toy-pomcp-0.json")) << "episode 0 is shard 0's";
        const auto path = dir / "nested" / recordingFileName("toy", "pomcp", 1);
        EXPECT_EQ(path.filename().string(), "toy-pomcp-1.json");
        std::ifstream file(path);
        ASSERT_TRUE(file) << path;
        const auto recording = nlohmann::json::parse(file);
        EXPECT_EQ(recording["scenario"], "toy");
        EXPECT_EQ(recording["solver"], "pomcp");
        EXPECT_EQ(recording["episode"], 1);
        EXPECT_EQ(recording["scene"], toy->scene());
        EXPECT_EQ(recording["labels"], nlohmann::json::array({"robot"}));
        const std::size_t steps = records[0]["steps"].get<std::size_t>();
        EXPECT_EQ(recording["steps"], steps);
        EXPECT_EQ(recording["trajectory"].size(), steps + 1) << "the start and one point per step";
        EXPECT_EQ(recording["rewards"].size(), steps);
        EXPECT_EQ(recording["success"], records[0]["success"]);
        ASSERT_GE(recording["beliefs"].size(), 1u);
        EXPECT_EQ(recording["beliefs"][0]["step"], 0);
        std::filesystem::remove_all(dir);
    }

    TEST(ExperimentRunner, TreeDumpsAreValidJsonWithConsistentCounts)
    {
        const auto toy = makeToyScenario(15);
        ExperimentSettings s = toySettings("ropras3", 2, 60);
        const auto dir = freshDirectory("trees");
        s.record.tree.dir = (dir / "t").string();
        s.record.tree.parseCalls("0,1");
        const auto records = runExperiment(*toy, s);
        ASSERT_EQ(records.size(), 2u);
        for (std::size_t episode = 0; episode < 2; ++episode)
        {
            EXPECT_FALSE(
                std::filesystem::exists(dir / "t" / ("toy-ropras3-" + std::to_string(episode) + "-plan2.json")));
            for (std::size_t call = 0; call < 2 && call < records[episode]["plans"].get<std::size_t>(); ++call)
            {
                const auto path =
                    dir / "t" / ("toy-ropras3-" + std::to_string(episode) + "-plan" + std::to_string(call) + ".json");
                std::ifstream file(path);
                ASSERT_TRUE(file) << path;
                const auto tree = nlohmann::json::parse(file);  // throws on invalid JSON
                EXPECT_EQ(tree["solver"], "ropras3");
                EXPECT_EQ(tree["plan"], call);
                EXPECT_EQ(tree["simulations"], 60);
                const auto &beliefs = tree["beliefs"];
                const auto &actions = tree["actions"];
                ASSERT_GE(beliefs.size(), 2u);
                EXPECT_EQ(beliefs[0]["visits"], 60) << "every simulation passes the root";
                EXPECT_TRUE(beliefs[0]["parent"].is_null());
                std::size_t levelTotal = 0;
                for (const auto &l : tree["levels"])
                    levelTotal += l["beliefs"].get<std::size_t>();
                EXPECT_EQ(levelTotal, beliefs.size());
                for (std::size_t i = 0; i < beliefs.size(); ++i)
                {
                    const auto &b = beliefs[i];
                    EXPECT_EQ(b["id"], i);
                    EXPECT_EQ(b["key"].get<std::string>().size(), 16u);
                    std::size_t visits = 0;
                    for (const auto &a : b["actions"])
                    {
                        EXPECT_EQ(actions[a.get<std::size_t>()]["parent"], i);
                        visits += actions[a.get<std::size_t>()]["visits"].get<std::size_t>();
                    }
                    EXPECT_EQ(visits, b["visits"].get<std::size_t>()) << "N(b) = sum N(ba), belief " << i;
                    if (i > 0)
                    {
                        const auto &parent = actions[b["parent"].get<std::size_t>()];
                        const auto &grand = beliefs[parent["parent"].get<std::size_t>()];
                        EXPECT_EQ(b["depth"], grand["depth"].get<std::size_t>() + 1);
                        EXPECT_EQ(b["steps"], grand["steps"].get<std::size_t>() + parent["length"].get<std::size_t>());
                        bool listed = false;
                        for (const auto &c : parent["children"])
                            listed = listed || c == i;
                        EXPECT_TRUE(listed) << "belief " << i << " is a child of its parent action";
                    }
                }
                for (const auto &a : actions)
                {
                    std::size_t below = 0;
                    for (const auto &c : a["children"])
                        below += beliefs[c.get<std::size_t>()]["particles"].get<std::size_t>();
                    EXPECT_LE(below, a["visits"].get<std::size_t>()) << "at most one particle per visit goes down";
                    EXPECT_EQ(a["macro"].get<std::string>().rfind("len " + a["length"].dump(), 0), 0u);
                }
                // the page beside it carries the same document, and the script in place of its placeholder
                auto pagePath = path;
                pagePath.replace_extension(".html");
                std::ifstream pageFile(pagePath);
                ASSERT_TRUE(pageFile) << pagePath;
                const std::string page((std::istreambuf_iterator<char>(pageFile)), std::istreambuf_iterator<char>());
                const std::string open = "<script type=\"application/json\" id=\"ropras-data\">";
                const auto from = page.find(open);
                ASSERT_NE(from, std::string::npos);
                const auto to = page.find("</script>", from);
                ASSERT_NE(to, std::string::npos);
                EXPECT_EQ(nlohmann::json::parse(page.substr(from + open.size(), to - from - open.size())), tree);
                EXPECT_EQ(page.find("@ROPRAS_"), std::string::npos) << "a placeholder was left in the page";
                EXPECT_NE(page.find("function openTo"), std::string::npos) << "the tree script is inline";
            }
        }
        std::filesystem::remove_all(dir);
    }

    TEST(ExperimentRunner, TreePageKeepsScriptEndTagsOutOfItsData)
    {
        const nlohmann::json tree = {{"solver", "x</script><b>"}, {"beliefs", nlohmann::json::array()}};
        const std::string page = treePage(tree);
        const std::string open = "<script type=\"application/json\" id=\"ropras-data\">";
        const auto from = page.find(open);
        ASSERT_NE(from, std::string::npos);
        const auto to = page.find("</script>", from);
        EXPECT_EQ(nlohmann::json::parse(page.substr(from + open.size(), to - from - open.size())), tree)
            << "the data's own \"</script>\" must not end the element";
    }

    TEST(ExperimentRunner, BadSettingsThrowBeforeAnyEpisode)
    {
        const auto toy = makeToyScenario();
        std::size_t calls = 0;
        ExperimentCallbacks callbacks;
        callbacks.onProgress = [&](const ExperimentProgress &) { ++calls; };
        ExperimentSettings s = toySettings("ropras3", 2, 10);
        auto bad = s;
        bad.episodes = 0;
        expectErrorMentions([&] { runExperiment(*toy, bad, callbacks); }, {"episodes"});
        bad = s;
        bad.shard = Shard{2, 2};
        expectErrorMentions([&] { runExperiment(*toy, bad, callbacks); }, {"shard 2/2"});
        bad = s;
        bad.run.solver = "ropras4";
        expectErrorMentions([&] { runExperiment(*toy, bad, callbacks); }, {"unknown solver \"ropras4\""});
        bad = s;
        bad.run.heuristic = "clever";
        expectErrorMentions([&] { runExperiment(*toy, bad, callbacks); }, {"\"clever\""});
        bad = s;
        bad.run.epsilon = 1.5;
        expectErrorMentions([&] { runExperiment(*toy, bad, callbacks); }, {"epsilon"});
        bad = s;
        bad.run.planner = "RRTConect";
        expectErrorMentions([&] { runExperiment(*toy, bad, callbacks); }, {"RRTConect"});
        bad = s;
        bad.run.params.set("no_such_param", 1.0);
        expectErrorMentions([&] { runExperiment(*toy, bad, callbacks); }, {"no_such_param"});
        bad = s;
        bad.run.budget.seconds = std::numeric_limits<double>::quiet_NaN();
        expectErrorMentions([&] { runExperiment(*toy, bad, callbacks); }, {"nan"});
        // a record directory below a regular file cannot be created
        const auto dir = freshDirectory("bad-record");
        std::filesystem::create_directories(dir);
        std::ofstream(dir / "file") << "x";
        bad = s;
        bad.recordDir = (dir / "file" / "sub").string();
        expectErrorMentions([&] { runExperiment(*toy, bad, callbacks); }, {"--record", "file/sub"});
        std::filesystem::remove_all(dir);
        EXPECT_EQ(calls, 0u) << "no episode may start with bad settings";
    }

    TEST(ExperimentRunner, AnEpisodeErrorNamesTheEpisodeAndStopsTheRun)
    {
        const auto broken = makeToyScenario(10, true);
        ExperimentSettings s = toySettings("pomcp", 6, 5);
        s.threads = 2;
        std::size_t records = 0;
        ExperimentCallbacks callbacks;
        callbacks.onRecord = [&](const nlohmann::json &) { ++records; };
        expectErrorMentions([&] { runExperiment(*broken, s, callbacks); },
                            {"scenario toy, episode", "the world broke"});
        EXPECT_EQ(records, 0u);
    }

    TEST(ExperimentRunner, ShardWithoutEpisodesRunsNothing)
    {
        const auto toy = makeToyScenario();
        ExperimentSettings s = toySettings("pomcp", 2, 5);
        s.shard = Shard{3, 5};
        EXPECT_TRUE(runExperiment(*toy, s).empty());
    }
}  // namespace ropras::scenarios::test
