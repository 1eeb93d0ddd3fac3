// OMPL's benchmark log format for `ropras bench-mbm --ompl-log` (ompl_benchmark_statistics, Planner Arena).
#include "OmplBenchmarkLog.h"

#include <ompl/config.h>
#include <ompl/geometric/SimpleSetup.h>
#include <ompl/tools/benchmark/Benchmark.h>
#include <ompl/tools/benchmark/MachineSpecs.h>
#include <algorithm>
#include <fstream>
#include <iomanip>
#include <iostream>
#include <sstream>

#include "ropras/core/Error.h"
#include "ropras/ompl_ext/ompl/PlanningContext.h"

namespace ropras::bin::mbm
{
    using namespace ropras::ompl_ext;

    namespace
    {
        /// Benchmark subclass used only to write OMPL's log format (ompl_benchmark_statistics / Planner Arena).
        class LogWriter : public ompl::tools::Benchmark
        {
        public:
            using ompl::tools::Benchmark::Benchmark;
            CompleteExperiment &experiment() { return exp_; }
        };

        /// a number for the OMPL log: full precision (std::to_string would round 85 us to 0.000085 s)
        std::string logNumber(double value)
        {
            std::ostringstream out;
            out << std::setprecision(9) << value;
            return out.str();
        }
    }  // namespace

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
}  // namespace ropras::bin::mbm
