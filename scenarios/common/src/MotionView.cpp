#include "ropras/scenarios/MotionView.h"

#include <algorithm>
#include <cmath>
#include <sstream>

#include "ViewDocument.h"
#include "ropras/core/Error.h"
#include "ropras/core/InputFile.h"
#include "ropras/ompl_ext/model/RobotModel.h"
#include "ropras/ompl_ext/scene/Environment.h"

namespace ropras::scenarios
{
    namespace
    {
        constexpr std::size_t MAX_ROWS = 1000000;
        constexpr std::size_t MAX_FRAMES = 100000;

        std::vector<std::string> splitCsv(const std::string &line)
        {
            std::vector<std::string> out;
            std::stringstream in(line);
            std::string item;
            while (std::getline(in, item, ','))
            {
                const auto b = item.find_first_not_of(" \t\r");
                const auto e = item.find_last_not_of(" \t\r");
                out.push_back(b == std::string::npos ? std::string() : item.substr(b, e - b + 1));
            }
            if (!line.empty() && line.back() == ',')
            {
                out.emplace_back();
            }
            return out;
        }

        /** \brief The waypoints joined by straight segments of at most \a step per joint. */
        std::vector<std::vector<double>> densify(const std::vector<std::vector<double>> &path, double step)
        {
            std::vector<std::vector<double>> out{path.front()};
            for (std::size_t i = 1; i < path.size(); ++i)
            {
                double largest = 0.0;
                for (std::size_t k = 0; k < path[i].size(); ++k)
                {
                    largest = std::max(largest, std::abs(path[i][k] - path[i - 1][k]));
                }
                const auto pieces = static_cast<std::size_t>(std::max(1.0, std::ceil(largest / step)));
                for (std::size_t s = 1; s <= pieces; ++s)
                {
                    const double t = static_cast<double>(s) / static_cast<double>(pieces);
                    std::vector<double> q(path[i].size());
                    for (std::size_t k = 0; k < q.size(); ++k)
                    {
                        q[k] = path[i - 1][k] + t * (path[i][k] - path[i - 1][k]);
                    }
                    out.push_back(std::move(q));
                    if (out.size() > MAX_FRAMES)
                    {
                        throw Error("motion view: more than " + std::to_string(MAX_FRAMES) +
                                    " frames at a joint step of " + std::to_string(step) + " (choose a larger step)");
                    }
                }
            }
            return out;
        }
    }  // namespace

    std::vector<std::vector<double>> loadJointPathCsv(const std::string &path, const ompl_ext::RobotModel &robot)
    {
        const std::string text = readInputFile(path, "path CSV");
        std::stringstream in(text);
        std::string line;
        std::size_t lineNo = 0;
        const auto fail = [&](const std::string &problem)
        { throw Error("path CSV '" + path + "':" + std::to_string(lineNo) + ": " + problem); };
        std::vector<int> column;  // CSV column -> planning index
        while (std::getline(in, line))
        {
            ++lineNo;
            if (line.find_first_not_of(" \t\r") != std::string::npos)
            {
                break;
            }
        }
        if (lineNo == 0 || line.find_first_not_of(" \t\r") == std::string::npos)
        {
            throw Error("path CSV '" + path + "': the file is empty (expected a header of joint names, then rows)");
        }
        std::vector<bool> seen(robot.dof(), false);
        for (const std::string &name : splitCsv(line))
        {
            int index = -1;
            for (std::size_t k = 0; k < robot.dof(); ++k)
            {
                if (robot.joints()[k].name == name)
                    index = static_cast<int>(k);
            }
            if (index < 0)
            {
                std::string known;
                for (const auto &j : robot.joints())
                    known += (known.empty() ? "" : ", ") + j.name;
                fail("header names '" + name + "', which is not a planning joint of robot '" + robot.name() + "' (" +
                     known + ")");
            }
            if (seen[static_cast<std::size_t>(index)])
            {
                fail("header names joint '" + name + "' twice");
            }
            seen[static_cast<std::size_t>(index)] = true;
            column.push_back(index);
        }
        for (std::size_t k = 0; k < robot.dof(); ++k)
        {
            if (!seen[k])
                fail("header lacks joint '" + robot.joints()[k].name + "' of robot '" + robot.name() + "'");
        }
        std::vector<std::vector<double>> rows;
        while (std::getline(in, line))
        {
            ++lineNo;
            if (line.find_first_not_of(" \t\r") == std::string::npos)
                continue;
            const auto items = splitCsv(line);
            if (items.size() != column.size())
            {
                fail("has " + std::to_string(items.size()) + " values, the header " + std::to_string(column.size()) +
                     " joints");
            }
            std::vector<double> q(robot.dof());
            for (std::size_t c = 0; c < items.size(); ++c)
            {
                const auto &joint = robot.joints()[static_cast<std::size_t>(column[c])];
                std::size_t used = 0;
                double v = 0.0;
                try
                {
                    v = std::stod(items[c], &used);
                }
                catch (const std::exception &)
                {
                    used = 0;
                }
                if (items[c].empty() || used != items[c].size() || !std::isfinite(v))
                {
                    fail("joint '" + joint.name + "': '" + items[c] + "' is not a finite number");
                }
                if (joint.type != ompl_ext::JointType::Continuous && (v < joint.lower - 1e-6 || v > joint.upper + 1e-6))
                {
                    fail("joint '" + joint.name + "' = " + items[c] + " is outside its limits [" +
                         std::to_string(joint.lower) + ", " + std::to_string(joint.upper) + "]");
                }
                q[static_cast<std::size_t>(column[c])] = v;
            }
            rows.push_back(std::move(q));
            if (rows.size() > MAX_ROWS)
            {
                fail("more than " + std::to_string(MAX_ROWS) + " rows");
            }
        }
        if (rows.empty())
        {
            throw Error("path CSV '" + path + "': no waypoints after the header");
        }
        return rows;
    }

    nlohmann::json motionView(const ompl_ext::RobotModel &robot, const ompl_ext::Environment &environment,
                              const std::vector<std::vector<double>> &path, const MotionViewOptions &options)
    {
        if (path.empty())
        {
            throw Error("motion view: the path has no waypoints");
        }
        for (std::size_t i = 0; i < path.size(); ++i)
        {
            if (path[i].size() != robot.dof())
            {
                throw Error("motion view: waypoint " + std::to_string(i) + " has " + std::to_string(path[i].size()) +
                            " values, robot '" + robot.name() + "' " + std::to_string(robot.dof()) + " joints");
            }
        }
        if (!(options.maxJointStep > 0.0 && std::isfinite(options.maxJointStep)))
        {
            throw Error("motion view: the joint step must be a finite number > 0");
        }
        int tip = -1;
        if (!options.tipLink.empty())
        {
            tip = robot.linkIndex(options.tipLink);
        }
        else if (robot.dof() > 0)
        {
            tip = robot.urdfJoints()[static_cast<std::size_t>(robot.joints().back().urdfJoint)].childLink;
        }
        const auto frames = densify(path, options.maxJointStep);

        detail::ViewDocument view(1e-4);
        auto &doc = view.json();
        doc["title"] = options.title;
        doc["subtitle"] = options.subtitle;
        doc["frames"] = frames.size();
        doc["frame_seconds"] = 0.04;
        doc["frame_label"] = "frame";
        doc["dims"] = 3;
        doc["waypoints"] = path.size();
        detail::addEnvironment(view, environment);

        std::vector<double> radii;
        std::size_t attached = 0;
        const auto centres = detail::robotSphereFrames(robot, &environment, frames, radii, attached);
        const std::size_t robotSpheres = radii.size() - attached;
        std::vector<double> robotCentres, attachedCentres;
        for (std::size_t f = 0; f < frames.size(); ++f)
        {
            const double *frame = centres.data() + f * radii.size() * 3;
            robotCentres.insert(robotCentres.end(), frame, frame + robotSpheres * 3);
            attachedCentres.insert(attachedCentres.end(), frame + robotSpheres * 3, frame + radii.size() * 3);
        }
        view.body("robot spheres", "#5c6bc0", std::vector<double>(radii.begin(), radii.begin() + robotSpheres),
                  robotCentres);
        if (attached > 0)
        {
            view.body("attached objects", "#ef6c00", std::vector<double>(radii.begin() + robotSpheres, radii.end()),
                      attachedCentres);
        }
        if (tip >= 0)
        {
            std::vector<detail::Vec3> trace;
            for (const auto &q : frames)
            {
                const Eigen::Vector3d p =
                    robot.linkTransformsReference(q.data())[static_cast<std::size_t>(tip)].translation();
                trace.push_back({p.x(), p.y(), p.z()});
            }
            view.path(robot.links()[static_cast<std::size_t>(tip)].name, "#d81b60", trace);
        }
        return doc;
    }
}  // namespace ropras::scenarios
