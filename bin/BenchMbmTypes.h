#ifndef ROPRAS_BIN_BENCH_MBM_TYPES_H
#define ROPRAS_BIN_BENCH_MBM_TYPES_H

#include <memory>
#include <string>
#include <vector>

#include "RobotSelection.h"
#include "ropras/ompl_ext/ompl/MotionValidator.h"
#include "ropras/ompl_ext/scene/Environment.h"

/// `ropras bench-mbm`'s options, problems and runs (shared by its command file and its OMPL log writer)
namespace ropras::bin::mbm
{
    struct Args
    {
        std::string urdf, srdf, meshUrdf, problems, json, omplLog, clock{"wall"};
        std::vector<std::string> planners{"RRTConnect"}, categories, checkers;
        std::vector<std::string> params;
        unsigned repeat{1}, seed{1}, limit{0};
        double time{1.0}, resolution{ompl_ext::MotionValidator::DEFAULT_RESOLUTION};
        bool simplify{true}, quiet{false};
        RobotSelection selection;
    };

    /// one planning run: a planner, a checker, a problem and a repetition
    struct Run
    {
        std::string category;
        int problem{0};
        int status{0};  ///< ompl::base::PlannerStatus::StatusType
        bool solved{false};
        double planUs{0}, simplifyUs{0}, length{0}, simplifiedLength{0};
    };

    /// a problem's two files
    struct ProblemFiles
    {
        std::string category, scene, request;
        int index{0};
    };

    struct Problem
    {
        std::string category;
        int index{0};
        std::shared_ptr<const ompl_ext::Environment> env;
        std::vector<double> start, goal;  ///< planning-joint values from the request
        std::string request;              ///< the request file
        /// why the start or goal is not a valid state (explainInvalidState); "" for a valid problem
        std::string invalid;
    };
}  // namespace ropras::bin::mbm

#endif
