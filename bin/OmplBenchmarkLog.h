#ifndef ROPRAS_BIN_OMPL_BENCHMARK_LOG_H
#define ROPRAS_BIN_OMPL_BENCHMARK_LOG_H

#include <map>
#include <string>
#include <vector>

#include "BenchMbmTypes.h"
#include "ropras/ompl_ext/model/RobotModel.h"

namespace ropras::bin::mbm
{
    /** Writes the runs in OMPL's benchmark log format, for ompl_benchmark_statistics.py and Planner Arena: one
        experiment, one planner entry per planner and checker ("geometric_<planner>_<checker>") with the planner's
        parameters as its settings, one run per problem and repetition. */
    void writeOmplLog(const Args &a, const ompl_ext::RobotModel &robot, const std::vector<Problem> &problems,
                      const std::map<std::string, std::map<std::string, std::vector<Run>>> &results,
                      const std::map<std::string, std::map<std::string, std::string>> &plannerSettings,
                      double totalSeconds);
}  // namespace ropras::bin::mbm

#endif
