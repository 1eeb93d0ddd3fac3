#ifndef ROPRAS_BIN_ROBOT_SELECTION_H
#define ROPRAS_BIN_ROBOT_SELECTION_H

#include <CLI/CLI.hpp>
#include <cstddef>
#include <map>
#include <string>
#include <utility>
#include <vector>

#include "ropras/ompl_ext/model/RobotModel.h"
#include "ropras/ompl_ext/scene/SceneYaml.h"

namespace ropras::bin
{
    /** \brief What a command plans and how leniently it reads other projects' files: `--joints`, `--group`,
        `--strict`, `--limit-tolerance` (plan, bench-mbm, bench-collision, check-collision). */
    struct RobotSelection
    {
        std::vector<std::string> joints;
        std::string group;
        bool strict{false};
        double limitTolerance{ompl_ext::RobotModelOptions::DEFAULT_LIMIT_TOLERANCE};

        /// adds the four options to \a app (\a withRequest: the help mentions the request's group and state)
        void addOptions(CLI::App &app, bool withRequest);
        /** \brief The model options: these joints or this group; with a \a request, its group (when the SRDF
            defines it and neither option is given) and its start state for the joints not planned. */
        ompl_ext::RobotModel::Options options(const ompl_ext::MotionPlanRequest *request = nullptr) const;
    };

    /** \brief Warnings to standard error, "ropras <command>: warning: ...". The same message from many files (a
        benchmark's requests all naming a joint the robot lacks) is printed once, with the number of files; at
        most \a maxShown distinct messages are printed, then how many more there were. */
    class Warnings
    {
    public:
        explicit Warnings(std::string command) : command_(std::move(command)) {}
        /// \a messages as RobotModel::planningValues makes them ("<context>: <message>")
        void add(const std::string &context, const std::vector<std::string> &messages);
        void add(const std::vector<std::string> &messages) { add("", messages); }
        void print(std::size_t maxShown = 10) const;

    private:
        std::string command_;
        std::vector<std::pair<std::string, std::size_t>> order_;  ///< (first full message, count) by first sight
        std::map<std::string, std::size_t> index_;                ///< message without its context -> order_ index
    };
}  // namespace ropras::bin

#endif
