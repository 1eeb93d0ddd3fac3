// `ropras bench-mbm`: every MotionBenchMaker problem, every planner, with (a) the ropras validators, (b) FCL with
// the same spheres, (c) FCL with the URDF's meshes; same OMPL, same seed, non-threaded termination conditions.
#include <ompl/base/PlannerTerminationCondition.h>
#include <ompl/config.h>
#include <ompl/tools/benchmark/Benchmark.h>
#include <ompl/tools/benchmark/MachineSpecs.h>
#include <ompl/util/Console.h>
#include <ompl/util/RandomNumbers.h>
#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdint>
#include <ctime>
#include <filesystem>
#include <fstream>
#include <iomanip>
#include <iostream>
#include <nlohmann/json.hpp>
#include <sstream>

#include "ArgumentChecks.h"
#include "CommandRegistry.h"
#include "OutputChecks.h"
#include "ropras/core/Error.h"
#include "ropras/ompl_ext/collision/FclReferenceChecker.h"
#include "ropras/ompl_ext/ompl/PlannerRegistry.h"
#include "ropras/ompl_ext/ompl/PlanningContext.h"
#include "ropras/ompl_ext/scene/SceneYaml.h"

namespace
{
    namespace fs = std::filesystem;
    namespace ob = ompl::base;
    using namespace ropras;
    using namespace ropras::ompl_ext;
    using Clock = std::chrono::steady_clock;

    /// CLOCK_MONOTONIC_COARSE in nanoseconds: the time of the last clock tick (4 ms resolution here), read in
    /// about 7 ns where steady_clock takes about 30; for deadlines that planners poll every iteration
    std::int64_t coarseNanoseconds()
    {
        timespec now{};
        clock_gettime(CLOCK_MONOTONIC_COARSE, &now);
        return static_cast<std::int64_t>(now.tv_sec) * 1000000000 + now.tv_nsec;
    }

    struct Args
    {
        std::string urdf, srdf, meshUrdf, problems, json, omplLog;
        std::vector<std::string> planners{"RRTConnect"}, categories, checkers;
        std::vector<std::string> params;
        unsigned repeat{1}, seed{1}, limit{0};
        double time{1.0}, resolution{MotionValidator::DEFAULT_RESOLUTION};
        bool simplify{true};
    };

    /** Motion validator over any state validity function that checks exactly the configurations the ropras
        MotionValidator checks (max-joint step, samples i/n), s2 first then in order: the fair baseline. */
    class SequentialMotionValidator : public ob::MotionValidator
    {
    public:
        SequentialMotionValidator(const ob::SpaceInformationPtr &si, double resolution)
            : ob::MotionValidator(si), resolution_(resolution), dof_(si->getStateDimension())
        {
        }
        bool checkMotion(const ob::State *s1, const ob::State *s2) const override
        {
            std::pair<ob::State *, double> unused{nullptr, 0.0};
            return checkMotion(s1, s2, unused);
        }
        bool checkMotion(const ob::State *s1, const ob::State *s2, std::pair<ob::State *, double> &last) const override
        {
            const double *a = s1->as<ob::RealVectorStateSpace::StateType>()->values;
            const double *b = s2->as<ob::RealVectorStateSpace::StateType>()->values;
            double linf = 0.0;
            for (unsigned k = 0; k < dof_; ++k)
                linf = std::max(linf, std::abs(b[k] - a[k]));
            const int n = std::max(1, static_cast<int>(std::ceil(linf / resolution_)));
            int firstBad = 0;
            if (!si_->isValid(s2))
                firstBad = n;
            ob::State *s = si_->allocState();
            for (int i = 1; i < n && (firstBad == 0 || i < firstBad); ++i)
            {
                si_->getStateSpace()->interpolate(s1, s2, static_cast<double>(i) / n, s);
                if (!si_->isValid(s))
                {
                    firstBad = i;
                    break;
                }
            }
            si_->freeState(s);
            if (firstBad == 0)
            {
                ++valid_;
                return true;
            }
            ++invalid_;
            last.second = static_cast<double>(firstBad - 1) / n;
            if (last.first != nullptr)
                si_->getStateSpace()->interpolate(s1, s2, last.second, last.first);
            return false;
        }

    private:
        double resolution_;
        unsigned dof_;
    };

    /// Benchmark subclass used only to write OMPL's log format (ompl_benchmark_statistics / Planner Arena).
    class LogWriter : public ompl::tools::Benchmark
    {
    public:
        using ompl::tools::Benchmark::Benchmark;
        CompleteExperiment &experiment() { return exp_; }
    };

    struct Run
    {
        std::string category;
        int problem{0};
        int status{0};  ///< ompl::base::PlannerStatus::StatusType
        bool solved{false};
        double planUs{0}, simplifyUs{0}, length{0}, simplifiedLength{0};
    };

    struct Problem
    {
        std::string category;
        int index{0};
        std::shared_ptr<const Environment> env;
        std::vector<double> start, goal;  ///< planning-joint values from the request
    };

    double quantile(std::vector<double> v, double q)
    {
        if (v.empty())
            return std::nan("");
        std::sort(v.begin(), v.end());
        const double pos = q * (v.size() - 1);
        const std::size_t lo = static_cast<std::size_t>(std::floor(pos));
        const std::size_t hi = std::min(lo + 1, v.size() - 1);
        return v[lo] + (pos - lo) * (v[hi] - v[lo]);
    }

    std::vector<Problem> loadProblems(const Args &a, const RobotModel &robot)
    {
        std::vector<Problem> problems;
        if (!fs::is_directory(a.problems))
            throw Error("--problems " + a.problems + " is not a directory");
        std::vector<std::string> categories = a.categories;
        if (categories.empty())
            for (const auto &entry : fs::directory_iterator(a.problems))
                if (entry.is_directory())
                    categories.push_back(entry.path().filename().string());
        std::sort(categories.begin(), categories.end());
        for (const std::string &category : categories)
        {
            const fs::path dir = fs::path(a.problems) / category;
            if (!fs::is_directory(dir))
                throw Error("category folder " + dir.string() + " does not exist");
            std::vector<fs::path> scenes;
            for (const auto &entry : fs::directory_iterator(dir))
            {
                const std::string name = entry.path().filename().string();
                const std::string number = entry.path().stem().string().substr(std::min<std::size_t>(5, name.size()));
                // MotionBenchMaker names: sceneNNNN.yaml beside requestNNNN.yaml; other files are ignored
                if (name.rfind("scene", 0) == 0 && entry.path().extension() == ".yaml" && !number.empty() &&
                    number.size() < 9 && number.find_first_not_of("0123456789") == std::string::npos)
                    scenes.push_back(entry.path());
            }
            std::sort(scenes.begin(), scenes.end());
            if (a.limit > 0 && scenes.size() > a.limit)
                scenes.resize(a.limit);
            for (const fs::path &scene : scenes)
            {
                Problem p;
                p.category = category;
                p.index = std::stoi(scene.stem().string().substr(5));
                const fs::path request = dir / ("request" + scene.stem().string().substr(5) + ".yaml");
                p.env = std::make_shared<const Environment>(loadPlanningScene(scene.string()));
                const MotionPlanRequest r = loadMotionPlanRequest(request.string());
                p.start = robot.planningValues(r.start, request.string() + ": start state");
                p.goal = robot.planningValues(r.goal, request.string() + ": goal");
                problems.push_back(std::move(p));
            }
        }
        if (problems.empty())
            throw Error("no sceneNNNN.yaml problems under " + a.problems);
        return problems;
    }

    /// a number for the OMPL log: full precision (std::to_string would round 85 us to 0.000085 s)
    std::string logNumber(double value)
    {
        std::ostringstream out;
        out << std::setprecision(9) << value;
        return out.str();
    }

    /** Writes the runs in OMPL's benchmark log format, for ompl_benchmark_statistics.py and Planner Arena: one
        experiment, one planner entry per planner and checker ("geometric_<planner>_<checker>") with the planner's
        parameters as its settings, one run per problem and repetition. */
    void writeOmplLog(const Args &a, const RobotModel &robot, const std::vector<Problem> &problems,
                      const std::map<std::string, std::map<std::string, std::vector<Run>>> &results,
                      const std::map<std::string, std::map<std::string, std::string>> &plannerSettings,
                      double totalSeconds)
    {
        std::vector<std::string> categories;
        for (const Problem &p : problems)
            if (std::find(categories.begin(), categories.end(), p.category) == categories.end())
                categories.push_back(p.category);
        ompl::geometric::SimpleSetup dummy(createStateSpace(robot));
        LogWriter writer(dummy, "ropras-bench-mbm");
        auto &exp = writer.experiment();
        exp.name = "ropras-bench-mbm";
        exp.maxTime = a.time;
        exp.maxMem = 0.0;
        exp.runCount = 0;
        exp.startTime = ompl::time::now();
        exp.totalDuration = totalSeconds;
        exp.seed = a.seed;
        exp.host = ompl::machine::getHostname();
        exp.cpuInfo = ompl::machine::getCPUInfo();
        // Multi-line blocks must end with a newline: the reader stops at a line that starts with "|>>>".
        std::ostringstream setupInfo;
        setupInfo << "ropras bench-mbm: robot " << robot.name() << " (" << a.urdf << "), problems " << a.problems
                  << ", motion-check resolution " << a.resolution << " rad, " << a.repeat << " repeat(s)\n"
                  << "run property 'category' indexes these categories:";
        for (std::size_t i = 0; i < categories.size(); ++i)
            setupInfo << ' ' << i << '=' << categories[i];
        setupInfo << '\n';
        exp.setupInfo = setupInfo.str();
        if (!exp.cpuInfo.empty() && exp.cpuInfo.back() != '\n')
            exp.cpuInfo += '\n';
        exp.parameters["resolution REAL"] = logNumber(a.resolution);
        exp.parameters["problems INTEGER"] = std::to_string(problems.size());
        exp.parameters["repeat INTEGER"] = std::to_string(a.repeat);
        for (const auto &[checkerName, byPlanner] : results)
            for (const auto &[plannerName, runs] : byPlanner)
            {
                ompl::tools::Benchmark::PlannerExperiment pe;
                pe.name = "geometric_" + plannerName + "_" + checkerName;
                if (auto it = plannerSettings.find(plannerName); it != plannerSettings.end())
                    for (const auto &[key, value] : it->second)
                        pe.common[key] = value;  // as OMPL's Benchmark: the planner's parameters by name
                pe.common["checker"] = checkerName;
                for (const Run &run : runs)
                {
                    ompl::tools::Benchmark::RunProperties p;
                    p["time REAL"] = logNumber(run.planUs * 1e-6);
                    p["solved BOOLEAN"] = run.solved ? "1" : "0";
                    p["status ENUM"] = std::to_string(run.status);
                    if (run.solved)  // as OMPL's Benchmark: no path, no length (NULL in the database)
                    {
                        p["length REAL"] = logNumber(run.length);
                        if (a.simplify)
                        {
                            p["simplification time REAL"] = logNumber(run.simplifyUs * 1e-6);
                            p["simplified length REAL"] = logNumber(run.simplifiedLength);
                        }
                    }
                    p["problem INTEGER"] = std::to_string(run.problem);
                    p["category INTEGER"] = std::to_string(
                        std::find(categories.begin(), categories.end(), run.category) - categories.begin());
                    pe.runs.push_back(p);
                }
                exp.runCount = std::max<unsigned>(exp.runCount, static_cast<unsigned>(pe.runs.size()));
                exp.planners.push_back(pe);
            }
        // Debian builds OMPL with an empty OMPL_VERSION, so Benchmark writes "OMPL version " without a number;
        // Planner Arena reads the library and version from that first line.
        std::ostringstream text;
        writer.saveResultsToStream(text);
        std::string log = text.str();
        const std::string versionLine = "OMPL version " + std::to_string(OMPL_MAJOR_VERSION) + "." +
                                        std::to_string(OMPL_MINOR_VERSION) + "." + std::to_string(OMPL_PATCH_VERSION);
        const std::size_t eol = log.find('\n');
        if (log.rfind("OMPL version", 0) == 0 && eol != std::string::npos)
            log.replace(0, eol, versionLine);
        std::ofstream file(a.omplLog);
        if (!(file << log))
            throw Error("cannot write OMPL log " + a.omplLog);
        std::cout << "wrote " << a.omplLog << " (ompl_benchmark_statistics.py " << a.omplLog << ")\n";
    }

    int run(const Args &a)
    {
        for (const auto &[option, out] : {std::pair{"--json", a.json}, std::pair{"--ompl-log", a.omplLog}})
            ropras::bin::refuseOverwritingInputs(option, out, {a.urdf, a.srdf, a.meshUrdf});
        ompl::msg::setLogLevel(ompl::msg::LOG_ERROR);
        ompl::RNG::setSeed(a.seed);
        const auto params = ropras::bin::keyValueOptions(a.params, "--param");
        auto robot = RobotModel::fromUrdfFile(a.urdf, a.srdf);
        std::shared_ptr<const RobotModel> meshRobot;
        if (!a.meshUrdf.empty())
            meshRobot = RobotModel::fromUrdfFile(a.meshUrdf, a.srdf);
        std::vector<std::string> checkers = a.checkers;
        if (checkers.empty())
            checkers = meshRobot ? std::vector<std::string>{"ropras", "fcl_sphere", "fcl_mesh"}
                                 : std::vector<std::string>{"ropras", "fcl_sphere"};
        for (const std::string &c : checkers)
        {
            if (c != "ropras" && c != "fcl_sphere" && c != "fcl_mesh")
                throw Error("unknown checker '" + c + "'; known: ropras, fcl_sphere, fcl_mesh");
            if (c == "fcl_mesh" && !meshRobot)
                throw Error("checker fcl_mesh needs --mesh-urdf");
        }
        for (const std::string &p : a.planners)
            if (!PlannerRegistry::instance().contains(p))
                PlannerRegistry::instance().allocator(p);  // throws, listing the known planners
        if (meshRobot && meshRobot->dof() != robot->dof())
            throw Error("--mesh-urdf " + a.meshUrdf + " has " + std::to_string(meshRobot->dof()) +
                        " planning joints, --urdf has " + std::to_string(robot->dof()));

        const std::vector<Problem> problems = loadProblems(a, *robot);
        auto checker = std::make_shared<const CollisionChecker>(robot);
        auto fclSphere = std::make_shared<FclSphereChecker>(robot);
        std::shared_ptr<FclMeshChecker> fclMesh = meshRobot ? std::make_shared<FclMeshChecker>(meshRobot) : nullptr;
        std::cout << "bench-mbm: " << problems.size() << " problems, robot " << robot->name() << " (" << robot->dof()
                  << " joints, " << robot->spheres().size() << " spheres), checkers";
        for (const auto &c : checkers)
            std::cout << ' ' << c;
        std::cout << ", planners";
        for (const auto &p : a.planners)
            std::cout << ' ' << p;
        std::cout << ", " << a.repeat << " repeat(s), time limit " << a.time << " s\n";

        // results[checker][planner] = runs
        std::map<std::string, std::map<std::string, std::vector<Run>>> results;
        std::map<std::string, std::map<std::string, std::string>> plannerSettings;
        const auto benchStart = Clock::now();
        // Planner by planner: OMPL's random generators take their seeds from one global sequence, so a planner's
        // random draws depend on the generators created before it. With the planners in the outer loop, changing
        // one planner does not change the random draws of the planners listed before it (clean A/B runs).
        for (const std::string &plannerName : a.planners)
            for (const Problem &problem : problems)
            {
                for (const std::string &checkerName : checkers)
                {
                    // Each checker gets its own SimpleSetup over the same state space definition.
                    ompl::geometric::SimpleSetup ss(createStateSpace(*robot));
                    const auto &si = ss.getSpaceInformation();
                    if (checkerName == "ropras")
                    {
                        ss.setStateValidityChecker(std::make_shared<StateValidityChecker>(si, checker, problem.env));
                        si->setMotionValidator(
                            std::make_shared<MotionValidator>(si, checker, problem.env, a.resolution));
                    }
                    else
                    {
                        const Environment *env = problem.env.get();
                        if (checkerName == "fcl_sphere")
                            ss.setStateValidityChecker(
                                [fclSphere, env](const ob::State *s) {
                                    return fclSphere->isValid(*env,
                                                              s->as<ob::RealVectorStateSpace::StateType>()->values);
                                });
                        else
                            ss.setStateValidityChecker(
                                [fclMesh, env](const ob::State *s) {
                                    return fclMesh->isValid(*env, s->as<ob::RealVectorStateSpace::StateType>()->values);
                                });
                        si->setMotionValidator(std::make_shared<SequentialMotionValidator>(si, a.resolution));
                    }
                    si->setup();
                    ob::ScopedState<> start(ss.getStateSpace()), goal(ss.getStateSpace());
                    for (std::size_t k = 0; k < robot->dof(); ++k)
                    {
                        start[k] = problem.start[k];
                        goal[k] = problem.goal[k];
                    }
                    ss.setStartAndGoalStates(start, goal);
                    {
                        ss.setPlanner(PlannerRegistry::instance().create(plannerName, si, params));
                        ss.setup();
                        if (plannerSettings.count(plannerName) == 0)  // every parameter's value, for the OMPL log
                            ss.getPlanner()->params().getParams(plannerSettings[plannerName]);
                        for (unsigned r = 0; r < a.repeat; ++r)
                        {
                            ss.clear();
                            Run run;
                            run.category = problem.category;
                            run.problem = problem.index;
                            // time limit or exact solution, in one non-threaded condition: the same as
                            // plannerOr(timed, exactSoln) with one evaluation instead of three. Planners poll it
                            // once per iteration, inside the timed region, so the deadline is read from the coarse
                            // clock (about 7 ns instead of 30 here; it lags by at most one tick, 4 ms). Limits
                            // beyond 1e9 s (31 years) mean "no limit": they saturate instead of overflowing.
                            const std::int64_t deadline =
                                coarseNanoseconds() + static_cast<std::int64_t>(std::min(a.time, 1e9) * 1e9);
                            const ob::ProblemDefinition *pdef = ss.getProblemDefinition().get();
                            const ob::PlannerTerminationCondition ptc(
                                [deadline, pdef]
                                { return pdef->hasExactSolution() || coarseNanoseconds() > deadline; });
                            const auto t0 = Clock::now();
                            const ob::PlannerStatus status = ss.solve(ptc);
                            run.planUs = std::chrono::duration<double, std::micro>(Clock::now() - t0).count();
                            run.status = static_cast<int>(ob::PlannerStatus::StatusType(status));
                            run.solved = status == ob::PlannerStatus::EXACT_SOLUTION;
                            if (run.solved)
                            {
                                run.length = ss.getSolutionPath().length();
                                if (a.simplify)
                                {
                                    const auto s0 = Clock::now();
                                    ss.simplifySolution();
                                    run.simplifyUs =
                                        std::chrono::duration<double, std::micro>(Clock::now() - s0).count();
                                }
                                run.simplifiedLength = ss.getSolutionPath().length();
                            }
                            results[checkerName][plannerName].push_back(run);
                        }
                    }
                }
            }
        const double totalSeconds = std::chrono::duration<double>(Clock::now() - benchStart).count();

        // Report: per checker and planner, per category and overall.
        nlohmann::json out;
        std::cout << "\n"
                  << std::left << std::setw(12) << "checker" << std::setw(22) << "planner" << std::setw(18)
                  << "category" << std::right << std::setw(8) << "solved" << std::setw(12) << "median_us"
                  << std::setw(12) << "p95_us" << std::setw(12) << "simp_us" << std::setw(10) << "length\n";
        for (const auto &[checkerName, byPlanner] : results)
            for (const auto &[plannerName, runs] : byPlanner)
            {
                std::map<std::string, std::vector<const Run *>> groups;
                for (const Run &run : runs)
                {
                    groups[run.category].push_back(&run);
                    groups["all"].push_back(&run);
                }
                nlohmann::json entry;
                for (const auto &[group, list] : groups)
                {
                    std::vector<double> times, simp, length;
                    std::size_t solved = 0;
                    for (const Run *run : list)
                    {
                        times.push_back(run->planUs);  // failures count with the time they took
                        if (run->solved)
                        {
                            ++solved;
                            simp.push_back(run->simplifyUs);
                            length.push_back(run->simplifiedLength);
                        }
                    }
                    const double solvedFrac = static_cast<double>(solved) / list.size();
                    nlohmann::json g = {{"solved", solvedFrac},
                                        {"runs", list.size()},
                                        {"median_us", quantile(times, 0.5)},
                                        {"p95_us", quantile(times, 0.95)},
                                        {"simplify_median_us", simp.empty() ? 0.0 : quantile(simp, 0.5)},
                                        {"length_median", length.empty() ? 0.0 : quantile(length, 0.5)}};
                    std::cout << std::left << std::setw(12) << checkerName << std::setw(22) << plannerName
                              << std::setw(18) << group << std::right << std::setw(7) << std::fixed
                              << std::setprecision(1) << 100.0 * solvedFrac << "%" << std::setw(12)
                              << quantile(times, 0.5) << std::setw(12) << quantile(times, 0.95) << std::setw(12)
                              << (simp.empty() ? 0.0 : quantile(simp, 0.5)) << std::setw(10) << std::setprecision(3)
                              << (length.empty() ? 0.0 : quantile(length, 0.5)) << '\n';
                    if (group == "all")
                        for (auto it = g.begin(); it != g.end(); ++it)
                            entry[it.key()] = it.value();
                    else
                        entry["categories"][group] = g;
                }
                out[checkerName][plannerName] = entry;
            }
        // Speed ratio of the ropras validators against each FCL baseline, per planner (medians).
        for (const char *baseline : {"fcl_sphere", "fcl_mesh"})
            if (out.contains("ropras") && out.contains(baseline))
                for (const auto &plannerName : a.planners)
                {
                    const double ratio = out[baseline][plannerName]["median_us"].get<double>() /
                                         out["ropras"][plannerName]["median_us"].get<double>();
                    std::cout << plannerName << ": ropras is " << std::setprecision(1) << ratio << "x faster than "
                              << baseline << " (median planning time)\n";
                    out["ratios"][plannerName][baseline] = ratio;
                }
        out["config"] = {
            {"urdf", a.urdf},         {"srdf", a.srdf},   {"mesh_urdf", a.meshUrdf}, {"problems", a.problems},
            {"repeat", a.repeat},     {"time_s", a.time}, {"seed", a.seed},          {"resolution", a.resolution},
            {"total_s", totalSeconds}};
        if (!a.json.empty())
        {
            std::ofstream f(a.json);
            if (!f)
                throw Error("cannot write " + a.json);
            f << out.dump(2) << '\n';
            std::cout << "wrote " << a.json << '\n';
        }
        if (!a.omplLog.empty())
            writeOmplLog(a, *robot, problems, results, plannerSettings, totalSeconds);
        return 0;
    }

    std::function<int()> setup(CLI::App &app)
    {
        auto a = std::make_shared<Args>();
        app.add_option("--urdf", a->urdf, "robot URDF (sphere model)")->required()->check(CLI::ExistingFile);
        app.add_option("--srdf", a->srdf, "SRDF")->check(CLI::ExistingFile);
        app.add_option("--mesh-urdf", a->meshUrdf, "URDF with mesh collision geometry (FCL mesh baseline)")
            ->check(CLI::ExistingFile);
        app.add_option("--problems", a->problems,
                       "MotionBenchMaker folder: <category>/sceneNNNN.yaml + requestNNNN.yaml")
            ->required();
        app.add_option("--planners", a->planners, "planners by name")->delimiter(',')->capture_default_str();
        app.add_option("--param", a->params, "planner parameter key=value, for every planner (repeatable)");
        app.add_option("--checkers", a->checkers, "subset of ropras,fcl_sphere,fcl_mesh")->delimiter(',');
        app.add_option("--categories", a->categories, "only these categories")->delimiter(',');
        app.add_option("--limit", a->limit, "at most N problems per category (0: all)")
            ->check(ropras::bin::countCheck(0, 4294967295ULL, "COUNT"));
        app.add_option("--repeat", a->repeat, "runs per problem (at most 10^6)")
            ->capture_default_str()
            ->check(ropras::bin::REPEATS);
        app.add_option("--time", a->time, "time limit per plan (s)")
            ->capture_default_str()
            ->check(ropras::bin::POSITIVE_NUMBER);
        app.add_option("--resolution", a->resolution, "motion-check joint step (rad)")
            ->capture_default_str()
            ->check(ropras::bin::POSITIVE_NUMBER);
        app.add_option("--seed", a->seed, "OMPL random seed")->capture_default_str()->check(ropras::bin::SEED32);
        app.add_flag("!--no-simplify", a->simplify, "skip path simplification");
        app.add_option("--json", a->json, "write the results as JSON");
        app.add_option("--ompl-log", a->omplLog, "write an OMPL benchmark log (ompl_benchmark_statistics.py)");
        return [a] { return run(*a); };
    }

    const ropras::bin::CommandRegistrar reg{
        {"bench-mbm", "MotionBenchMaker planning benchmark: ropras vs FCL validators, any planners", setup}};
}  // namespace
