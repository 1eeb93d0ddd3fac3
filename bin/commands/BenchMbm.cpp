// `ropras bench-mbm`: every MotionBenchMaker problem, every planner, with (a) the ropras validators, (b) FCL with
// the same spheres, (c) FCL with the URDF's meshes; same OMPL, same seed, non-threaded termination conditions.
// Problems whose start or goal is invalid (the validation of `ropras plan`) are reported, not run.
#include <ompl/base/PlannerTerminationCondition.h>
#include <ompl/geometric/SimpleSetup.h>
#include <ompl/util/Console.h>
#include <ompl/util/RandomNumbers.h>
#include <unistd.h>
#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <ctime>
#include <filesystem>
#include <fstream>
#include <iomanip>
#include <iostream>
#include <nlohmann/json.hpp>
#include <sstream>

#include "ArgumentChecks.h"
#include "BenchClock.h"
#include "BenchMbmTypes.h"
#include "CommandRegistry.h"
#include "OmplBenchmarkLog.h"
#include "OutputChecks.h"
#include "ProgressBar.h"
#include "SequentialMotionValidator.h"
#include "ropras/core/Error.h"
#include "ropras/ompl_ext/collision/FclReferenceChecker.h"
#include "ropras/ompl_ext/collision/StateDiagnosis.h"
#include "ropras/ompl_ext/ompl/PlannerRegistry.h"
#include "ropras/ompl_ext/ompl/PlanningContext.h"
#include "ropras/ompl_ext/ompl/StateValidityChecker.h"
#include "ropras/ompl_ext/scene/SceneYaml.h"

namespace
{
    namespace fs = std::filesystem;
    namespace ob = ompl::base;
    using namespace ropras;
    using namespace ropras::ompl_ext;
    using namespace ropras::bin::mbm;
    using ropras::bin::SequentialMotionValidator;
    using Clock = std::chrono::steady_clock;
    using Results = std::map<std::string, std::map<std::string, std::vector<Run>>>;  ///< [checker][planner]

    /// CLOCK_MONOTONIC_COARSE in nanoseconds: the time of the last clock tick (4 ms resolution here), read in
    /// about 7 ns where steady_clock takes about 30; for deadlines that planners poll every iteration
    std::int64_t coarseNanoseconds()
    {
        timespec now{};
        clock_gettime(CLOCK_MONOTONIC_COARSE, &now);
        return static_cast<std::int64_t>(now.tv_sec) * 1000000000 + now.tv_nsec;
    }

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

    /// the sceneNNNN.yaml / requestNNNN.yaml pairs of the chosen categories, sorted
    std::vector<ProblemFiles> problemFiles(const Args &a)
    {
        std::vector<ProblemFiles> files;
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
                const std::string number = scene.stem().string().substr(5);
                files.push_back(
                    {category, scene.string(), (dir / ("request" + number + ".yaml")).string(), std::stoi(number)});
            }
        }
        if (files.empty())
            throw Error("no sceneNNNN.yaml problems under " + a.problems);
        return files;
    }

    /** Why the request's start state holds a joint that is not planned elsewhere than \a robot does (one model
        serves every problem: its held values come from the first request), "" when it agrees. */
    std::string heldJointMismatch(const RobotModel &robot, const MotionPlanRequest &r, const std::string &firstRequest)
    {
        for (const UrdfJoint &j : robot.urdfJoints())
        {
            const auto it = r.start.find(j.name);
            if (j.type == JointType::Fixed || j.variable >= 0 || it == r.start.end() ||
                std::abs(it->second - j.heldValue) <= robot.limitTolerance())
                continue;
            std::ostringstream why;
            why << "the start state holds joint '" << j.name << "' at " << it->second << ", the robot model at "
                << j.heldValue << " (the value in " << firstRequest
                << "): bench-mbm holds the joints it does not plan as the first request does";
            return why.str();
        }
        return "";
    }

    std::vector<Problem> loadProblems(const std::vector<ProblemFiles> &files, const RobotModel &robot,
                                      ropras::bin::Warnings &warnings)
    {
        std::vector<Problem> problems;
        for (const ProblemFiles &f : files)
        {
            Problem p;
            p.category = f.category;
            p.index = f.index;
            p.env = std::make_shared<const Environment>(loadPlanningScene(f.scene));
            const MotionPlanRequest r = loadMotionPlanRequest(f.request);
            std::vector<std::string> messages;
            p.start = robot.planningValues(r.start, f.request + ": start state", &messages);
            p.goal = robot.planningValues(r.goal, f.request + ": goal", &messages);
            warnings.add(f.request, messages);
            p.request = f.request;
            const std::string mismatch = heldJointMismatch(robot, r, files.front().request);
            if (!mismatch.empty())
                p.invalid = f.request + ": " + mismatch;
            problems.push_back(std::move(p));
        }
        return problems;
    }

    /** Progress on standard error: a bar with the ETA, redrawn after every run, on a terminal; otherwise a line at
        every tenth of the runs (logs of hours-long runs stay short). */
    class Progress
    {
    public:
        Progress(std::size_t total, bool quiet)
            : total_(total), quiet_(quiet || total == 0), terminal_(isatty(fileno(stderr)) != 0), start_(Clock::now())
        {
        }
        void runDone(const std::string &planner, const Problem &problem)
        {
            ++done_;
            if (quiet_)
                return;
            const double elapsed = std::chrono::duration<double>(Clock::now() - start_).count();
            const std::string eta = ropras::bin::formatDuration(ropras::bin::remainingSeconds(elapsed, done_, total_));
            if (terminal_)
            {
                std::cerr << "\r" << ropras::bin::progressBar(done_, total_) << ' ' << done_ << '/' << total_
                          << " runs (" << planner << ", " << problem.category << '/' << problem.index << "), "
                          << ropras::bin::formatDuration(elapsed) << " elapsed, ETA " << eta << "   "
                          << (done_ == total_ ? "\n" : "") << std::flush;
            }
            else if (done_ * 10 / total_ != (done_ - 1) * 10 / total_ || done_ == total_)
            {
                std::cerr << "bench-mbm: " << done_ << '/' << total_ << " runs, "
                          << ropras::bin::formatDuration(elapsed) << " elapsed, ETA " << eta << '\n';
            }
        }

    private:
        std::size_t total_, done_{0};
        bool quiet_, terminal_;
        Clock::time_point start_;
    };

    /// the validity function and motion validator of one checker on \a si
    void installChecker(ompl::geometric::SimpleSetup &ss, const std::string &checkerName, const Problem &problem,
                        double resolution, const std::shared_ptr<const CollisionChecker> &checker,
                        const std::shared_ptr<FclSphereChecker> &fclSphere,
                        const std::shared_ptr<FclMeshChecker> &fclMesh)
    {
        const auto &si = ss.getSpaceInformation();
        if (checkerName == "ropras")
        {
            ss.setStateValidityChecker(std::make_shared<StateValidityChecker>(si, checker, problem.env));
            si->setMotionValidator(std::make_shared<MotionValidator>(si, checker, problem.env, resolution));
            return;
        }
        const Environment *env = problem.env.get();
        if (checkerName == "fcl_sphere")
            ss.setStateValidityChecker(
                [fclSphere, env](const ob::State *s)
                { return fclSphere->isValid(*env, s->as<ob::RealVectorStateSpace::StateType>()->values); });
        else
            ss.setStateValidityChecker(
                [fclMesh, env](const ob::State *s)
                { return fclMesh->isValid(*env, s->as<ob::RealVectorStateSpace::StateType>()->values); });
        si->setMotionValidator(std::make_shared<SequentialMotionValidator>(si, resolution));
    }

    /// one solve under the time limit or the first exact solution, timed; simplified when asked
    Run solveOnce(const Args &a, const ropras::bin::BenchClock &clock, ompl::geometric::SimpleSetup &ss,
                  const Problem &problem)
    {
        ss.clear();
        Run run;
        run.category = problem.category;
        run.problem = problem.index;
        // time limit or exact solution, in one non-threaded condition: the same as plannerOr(timed, exactSoln) with
        // one evaluation instead of three. Planners poll it once per iteration, inside the timed region, so the
        // deadline is read from the coarse clock (about 7 ns instead of 30 here; it lags by at most one tick,
        // 4 ms). The deadline itself is set from the precise clock (the same CLOCK_MONOTONIC, not truncated to
        // the last tick), so a run never stops before its limit. Limits beyond 1e9 s (31 years) mean "no limit":
        // they saturate instead of overflowing.
        timespec start{};
        clock_gettime(CLOCK_MONOTONIC, &start);
        std::int64_t deadline = static_cast<std::int64_t>(start.tv_sec) * 1000000000 + start.tv_nsec +
                                static_cast<std::int64_t>(std::min(a.time, 1e9) * 1e9);
        const ob::ProblemDefinition *pdef = ss.getProblemDefinition().get();
        // --clock cpu: the limit is this thread's CPU time. The condition still polls the coarse wall clock; when
        // the wall deadline has passed it reads the CPU time once and, while the limit is not used up, moves the
        // deadline by the CPU time left (a thread that waited for a core gets that time back).
        const double cpuLimitNs = a.clock == "cpu" ? std::min(a.time, 1e9) * 1e9 : 0.0;
        const double cpuStartNs = a.clock == "cpu" ? clock.nowNs() : 0.0;
        const ob::PlannerTerminationCondition ptc(
            [deadline, pdef, cpuLimitNs, cpuStartNs, &clock]() mutable
            {
                if (pdef->hasExactSolution())
                    return true;
                const std::int64_t now = coarseNanoseconds();
                if (now <= deadline)
                    return false;
                if (cpuLimitNs <= 0.0)
                    return true;
                const double left = cpuLimitNs - (clock.nowNs() - cpuStartNs);
                if (left <= 0.0)
                    return true;
                deadline = now + static_cast<std::int64_t>(left);
                return false;
            });
        const double t0 = clock.nowNs();
        const ob::PlannerStatus status = ss.solve(ptc);
        run.planUs = (clock.nowNs() - t0) * 1e-3;
        run.status = static_cast<int>(ob::PlannerStatus::StatusType(status));
        run.solved = status == ob::PlannerStatus::EXACT_SOLUTION;
        if (run.solved)
        {
            run.length = ss.getSolutionPath().length();
            if (a.simplify)
            {
                const double s0 = clock.nowNs();
                ss.simplifySolution();
                run.simplifyUs = (clock.nowNs() - s0) * 1e-3;
            }
            run.simplifiedLength = ss.getSolutionPath().length();
        }
        return run;
    }

    /// the number of problems in each category (and "all") whose start or goal is invalid
    std::map<std::string, std::size_t> invalidCounts(const std::vector<Problem> &problems)
    {
        std::map<std::string, std::size_t> counts{{"all", 0}};
        for (const Problem &p : problems)
        {
            counts[p.category] += p.invalid.empty() ? 0 : 1;
            counts["all"] += p.invalid.empty() ? 0 : 1;
        }
        return counts;
    }

    /// the table per checker, planner and category (and "all"), into \a out as JSON too
    void reportTable(const Results &results, const std::vector<Problem> &problems, nlohmann::json &out)
    {
        const auto invalid = invalidCounts(problems);
        std::cout << "\n"
                  << std::left << std::setw(12) << "checker" << std::setw(22) << "planner" << std::setw(18)
                  << "category" << std::right << std::setw(8) << "solved" << std::setw(9) << "invalid" << std::setw(12)
                  << "median_us" << std::setw(12) << "p95_us" << std::setw(12) << "simp_us" << std::setw(10)
                  << "length\n";
        for (const auto &[checkerName, byPlanner] : results)
            for (const auto &[plannerName, runs] : byPlanner)
            {
                std::map<std::string, std::vector<const Run *>> groups;
                for (const auto &[category, count] : invalid)
                    groups[category];  // categories whose problems are all invalid still get a row
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
                    const std::size_t invalidHere = invalid.count(group) ? invalid.at(group) : 0;
                    const double solvedFrac = list.empty() ? std::nan("") : static_cast<double>(solved) / list.size();
                    nlohmann::json g = {
                        {"solved", list.empty() ? nlohmann::json() : nlohmann::json(solvedFrac)},
                        {"runs", list.size()},
                        {"invalid_problems", invalidHere},
                        {"median_us", list.empty() ? nlohmann::json() : nlohmann::json(quantile(times, 0.5))},
                        {"p95_us", list.empty() ? nlohmann::json() : nlohmann::json(quantile(times, 0.95))},
                        {"simplify_median_us", simp.empty() ? 0.0 : quantile(simp, 0.5)},
                        {"length_median", length.empty() ? 0.0 : quantile(length, 0.5)}};
                    std::cout << std::left << std::setw(12) << checkerName << std::setw(22) << plannerName
                              << std::setw(18) << group << std::right << std::fixed << std::setprecision(1);
                    if (list.empty())
                        std::cout << std::setw(8) << "n/a" << std::setw(9) << invalidHere << std::setw(12) << "n/a"
                                  << std::setw(12) << "n/a" << std::setw(12) << "n/a" << std::setw(10) << "n/a\n";
                    else
                        std::cout << std::setw(7) << 100.0 * solvedFrac << "%" << std::setw(9) << invalidHere
                                  << std::setw(12) << quantile(times, 0.5) << std::setw(12) << quantile(times, 0.95)
                                  << std::setw(12) << (simp.empty() ? 0.0 : quantile(simp, 0.5)) << std::setw(10)
                                  << std::setprecision(3) << (length.empty() ? 0.0 : quantile(length, 0.5)) << '\n';
                    if (group == "all")
                        for (auto it = g.begin(); it != g.end(); ++it)
                            entry[it.key()] = it.value();
                    else
                        entry["categories"][group] = g;
                }
                out[checkerName][plannerName] = entry;
            }
    }

    /** Speed of the ropras validators against each FCL baseline, per planner: the ratio of the median planning
        times. It means nothing when either median is the time limit (an anytime planner such as BITstar that
        refines until the limit, or one that fails): then it is n/a, with the reason. */
    void reportRatios(const Args &a, nlohmann::json &out)
    {
        const double limitUs = a.time * 1e6;
        for (const char *baseline : {"fcl_sphere", "fcl_mesh"})
            if (out.contains("ropras") && out.contains(baseline))
                for (const auto &plannerName : a.planners)
                {
                    const auto &ours = out["ropras"][plannerName]["median_us"];
                    const auto &theirs = out[baseline][plannerName]["median_us"];
                    std::cout << plannerName << ": ";
                    if (ours.is_null() || theirs.is_null())
                    {
                        std::cout << "ropras vs " << baseline << ": n/a (no valid problem was run)\n";
                        out["ratios"][plannerName][baseline] = nullptr;
                        continue;
                    }
                    // the coarse deadline lags by up to one 4 ms tick: 0.99 of the limit is "ran to the limit"
                    const bool oursAtLimit = ours.get<double>() >= 0.99 * limitUs;
                    const bool theirsAtLimit = theirs.get<double>() >= 0.99 * limitUs;
                    if (oursAtLimit || theirsAtLimit)
                    {
                        std::cout << "ropras vs " << baseline << ": n/a (the median run of "
                                  << (oursAtLimit && theirsAtLimit ? "both"
                                      : oursAtLimit                ? "ropras"
                                                                   : baseline)
                                  << " lasts the whole " << std::defaultfloat << a.time
                                  << " s time limit: planning times at the limit compare the limit with itself)\n";
                        out["ratios"][plannerName][baseline] = nullptr;
                        continue;
                    }
                    const double ratio = theirs.get<double>() / ours.get<double>();
                    std::cout << "ropras is " << std::fixed << std::setprecision(1) << ratio << "x faster than "
                              << baseline << " (median planning time)\n";
                    out["ratios"][plannerName][baseline] = ratio;
                }
    }

    int run(const Args &a)
    {
        for (const auto &[option, out] : {std::pair{"--json", a.json}, std::pair{"--ompl-log", a.omplLog}})
            ropras::bin::refuseOverwritingInputs(option, out, {a.urdf, a.srdf, a.meshUrdf});
        const ropras::bin::BenchClock clock(a.clock, "bench-mbm");
        ompl::msg::setLogLevel(ompl::msg::LOG_ERROR);
        ompl::RNG::setSeed(a.seed);
        const auto params = ropras::bin::keyValueOptions(a.params, "--param");
        const std::vector<ProblemFiles> files = problemFiles(a);
        // the first request's group and start state choose the planned and the held joints for every problem
        const MotionPlanRequest firstRequest = loadMotionPlanRequest(files.front().request);
        const RobotModel::Options robotOptions = a.selection.options(&firstRequest);
        auto robot = RobotModel::fromUrdfFile(a.urdf, a.srdf, robotOptions);
        ropras::bin::Warnings warnings("bench-mbm");
        warnings.add(robot->warnings());
        std::shared_ptr<const RobotModel> meshRobot;
        if (!a.meshUrdf.empty())
            meshRobot = RobotModel::fromUrdfFile(a.meshUrdf, a.srdf, robotOptions);
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
        {
            // every planner name and every --param value, before any problem is loaded or run
            ompl::geometric::SimpleSetup probe(createStateSpace(*robot));
            for (const std::string &p : a.planners)
                PlannerRegistry::instance().create(p, probe.getSpaceInformation(), params);
        }
        if (meshRobot && meshRobot->dof() != robot->dof())
            throw Error("--mesh-urdf " + a.meshUrdf + " has " + std::to_string(meshRobot->dof()) +
                        " planning joints, --urdf has " + std::to_string(robot->dof()));

        std::vector<Problem> problems = loadProblems(files, *robot, warnings);
        warnings.print();
        auto checker = std::make_shared<const CollisionChecker>(robot);
        auto fclSphere = std::make_shared<FclSphereChecker>(robot);
        std::shared_ptr<FclMeshChecker> fclMesh = meshRobot ? std::make_shared<FclMeshChecker>(meshRobot) : nullptr;
        // the validation of `ropras plan`: an invalid start or goal is reported, not run (it would fail every
        // planner after the whole time limit and count as unsolved)
        std::size_t valid = 0;
        for (Problem &p : problems)
        {
            for (const auto &[what, q] : {std::pair{"start state", &p.start}, std::pair{"goal", &p.goal}})
                if (p.invalid.empty())
                {
                    const std::string why = explainInvalidState(*checker, *p.env, q->data());
                    if (!why.empty())
                        p.invalid = p.request + ": the " + what + " is invalid: " + why;
                }
            valid += p.invalid.empty() ? 1 : 0;
        }
        std::cout << "bench-mbm: " << problems.size() << " problems (" << problems.size() - valid << " invalid), robot "
                  << robot->name() << " (" << robot->dof() << " joints"
                  << (robot->group().empty() ? "" : ", group " + robot->group()) << ", " << robot->spheres().size()
                  << " spheres), checkers";
        for (const auto &c : checkers)
            std::cout << ' ' << c;
        std::cout << ", planners";
        for (const auto &p : a.planners)
            std::cout << ' ' << p;
        std::cout << ", " << a.repeat << " repeat(s), time limit " << a.time << " s\n";
        for (const Problem &p : problems)
            if (!p.invalid.empty())
                std::cout << "invalid problem " << p.category << '/' << p.index << ", not run: " << p.invalid << '\n';

        Results results;
        std::map<std::string, std::map<std::string, std::string>> plannerSettings;
        Progress progress(a.planners.size() * valid * checkers.size() * a.repeat, a.quiet);
        const auto benchStart = Clock::now();
        // Planner by planner: OMPL's random generators take their seeds from one global sequence, so a planner's
        // random draws depend on the generators created before it. With the planners in the outer loop, changing
        // one planner does not change the random draws of the planners listed before it (clean A/B runs).
        for (const std::string &plannerName : a.planners)
            for (const Problem &problem : problems)
            {
                if (!problem.invalid.empty())
                    continue;
                for (const std::string &checkerName : checkers)
                {
                    // Each checker gets its own SimpleSetup over the same state space definition.
                    ompl::geometric::SimpleSetup ss(createStateSpace(*robot));
                    installChecker(ss, checkerName, problem, a.resolution, checker, fclSphere, fclMesh);
                    const auto &si = ss.getSpaceInformation();
                    si->setup();
                    ob::ScopedState<> start(ss.getStateSpace()), goal(ss.getStateSpace());
                    for (std::size_t k = 0; k < robot->dof(); ++k)
                    {
                        start[k] = problem.start[k];
                        goal[k] = problem.goal[k];
                    }
                    ss.setStartAndGoalStates(start, goal);
                    ss.setPlanner(PlannerRegistry::instance().create(plannerName, si, params));
                    ss.setup();
                    if (plannerSettings.count(plannerName) == 0)  // every parameter's value, for the OMPL log
                        ss.getPlanner()->params().getParams(plannerSettings[plannerName]);
                    for (unsigned r = 0; r < a.repeat; ++r)
                    {
                        results[checkerName][plannerName].push_back(solveOnce(a, clock, ss, problem));
                        progress.runDone(plannerName, problem);
                    }
                }
            }
        const double totalSeconds = std::chrono::duration<double>(Clock::now() - benchStart).count();
        if (valid == 0)  // still a table: every planner and checker with its invalid problems
            for (const std::string &checkerName : checkers)
                for (const std::string &plannerName : a.planners)
                    results[checkerName][plannerName];

        nlohmann::json out;
        reportTable(results, problems, out);
        reportRatios(a, out);
        nlohmann::json invalidList = nlohmann::json::array();
        for (const Problem &p : problems)
            if (!p.invalid.empty())
                invalidList.push_back({{"category", p.category}, {"problem", p.index}, {"reason", p.invalid}});
        out["invalid_problems"] = invalidList;
        out["config"] = {
            {"urdf", a.urdf},     {"srdf", a.srdf},         {"mesh_urdf", a.meshUrdf}, {"problems", a.problems},
            {"repeat", a.repeat}, {"time_s", a.time},       {"seed", a.seed},          {"resolution", a.resolution},
            {"clock", a.clock},   {"total_s", totalSeconds}};
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
        app.add_option("--clock", a->clock,
                       "planning times and the --time limit by wall (steady clock) or cpu (this thread's CPU time: use "
                       "on a loaded machine)")
            ->capture_default_str();
        app.add_option("--seed", a->seed, "OMPL random seed")->capture_default_str()->check(ropras::bin::SEED32);
        app.add_flag("!--no-simplify", a->simplify, "skip path simplification");
        app.add_option("--json", a->json, "write the results as JSON");
        app.add_option("--ompl-log", a->omplLog, "write an OMPL benchmark log (ompl_benchmark_statistics)");
        app.add_flag("--quiet", a->quiet, "no progress output on standard error");
        a->selection.addOptions(app, true);
        return [a] { return run(*a); };
    }

    const ropras::bin::CommandRegistrar reg{
        {"bench-mbm", "MotionBenchMaker planning benchmark: ropras vs FCL validators, any planners", setup}};
}  // namespace
