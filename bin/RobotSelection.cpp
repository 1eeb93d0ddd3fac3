#include "RobotSelection.h"

#include <iostream>

#include "ArgumentChecks.h"

namespace ropras::bin
{
    void RobotSelection::addOptions(CLI::App &app, bool withRequest)
    {
        const std::string defaultJoints = withRequest ? " (default: the request's group_name when the SRDF defines it, "
                                                        "else every movable joint; the others held at the request's "
                                                        "start state)"
                                                      : " (default: every movable joint; the others held at 0 clamped "
                                                        "into their limits)";
        CLI::Option *jointsOption =
            app.add_option("--joints", joints, "planning joints, comma separated" + defaultJoints)->delimiter(',');
        CLI::Option *groupOption =
            app.add_option("--group", group, "plan the joints of this SRDF <group> (MoveIt planning group)");
        jointsOption->excludes(groupOption);
        app.add_flag("--strict", strict,
                     "refuse what MoveIt accepts with a warning: SRDF names the URDF lacks, request joints the robot "
                     "lacks, values outside a joint limit");
        app.add_option("--limit-tolerance", limitTolerance,
                       "joint values at most this far outside a limit (rad or m) are clamped with a warning")
            ->capture_default_str()
            ->check(NON_NEGATIVE_NUMBER);
    }

    ompl_ext::RobotModel::Options RobotSelection::options(const ompl_ext::MotionPlanRequest *request) const
    {
        ompl_ext::RobotModel::Options options;
        options.planningJoints = joints;
        options.group = group;
        options.strict = strict;
        options.limitTolerance = limitTolerance;
        if (request != nullptr)
        {
            options.requestGroup = request->group;
            options.jointState = request->start;
        }
        return options;
    }

    void Warnings::add(const std::string &context, const std::vector<std::string> &messages)
    {
        for (const std::string &message : messages)
        {
            std::string key = message;
            if (!context.empty() && key.rfind(context + ": ", 0) == 0)
                key = key.substr(context.size() + 2);
            const auto [it, fresh] = index_.emplace(key, order_.size());
            if (fresh)
                order_.emplace_back(message, 1);
            else
                ++order_[it->second].second;
        }
    }

    void Warnings::print(std::size_t maxShown) const
    {
        for (std::size_t i = 0; i < order_.size() && i < maxShown; ++i)
        {
            std::cerr << "ropras " << command_ << ": warning: " << order_[i].first;
            if (order_[i].second > 1)
                std::cerr << " (the same in " << order_[i].second - 1 << " more files)";
            std::cerr << '\n';
        }
        if (order_.size() > maxShown)
            std::cerr << "ropras " << command_ << ": " << order_.size() - maxShown << " more warnings not shown\n";
    }
}  // namespace ropras::bin
