#include "SvgArm.h"

#include <algorithm>

namespace ropras::scenarios::detail
{
    ArmPoses armPoses(const nlohmann::json &recording, std::size_t frames, const std::vector<std::size_t> &chosen,
                      const Reader &r, const std::string &folder)
    {
        ArmPoses out;
        if (!recording.contains("robot") || frames == 0)
        {
            return out;
        }
        const RecordedRobot robot = readRecordedRobot(recording["robot"], frames, r, folder);
        out.lastStep = frames - 1;
        out.steps = chosen;
        if (out.steps.empty())
        {
            const std::size_t n = std::min<std::size_t>(6, frames);
            for (std::size_t i = 0; i < n; ++i)
            {
                out.steps.push_back(n == 1 ? 0 : i * out.lastStep / (n - 1));
            }
            out.steps.erase(std::unique(out.steps.begin(), out.steps.end()), out.steps.end());
        }
        for (const std::size_t step : out.steps)
        {
            if (step > out.lastStep)
            {
                r.fail("arm step " + std::to_string(step),
                       "is past the trajectory's last step " + std::to_string(out.lastStep));
            }
        }
        for (const auto &s : robot.model->spheres())
        {
            out.radii.push_back(s.radius);
        }
        for (const std::size_t step : out.steps)
        {
            out.centres.emplace_back();
            for (const auto &c : robot.model->sphereCentersReference(robot.configurations[step].data()))
            {
                out.centres.back().push_back(Vec{c.x(), c.y(), c.z()});
            }
        }
        return out;
    }

    void drawArm(std::ostringstream &svg, const SvgFrame &f, const ArmPoses &poses, bool main)
    {
        if (poses.steps.empty())
        {
            return;
        }
        svg << (main ? "<g id=\"arm\">\n" : "<g class=\"arm\">\n");
        for (std::size_t k = 0; k < poses.steps.size(); ++k)
        {
            const std::size_t step = poses.steps[k];
            const std::string colour = timeColour(poses.lastStep ? double(step) / double(poses.lastStep) : 0.0);
            svg << "<g class=\"arm-pose\" data-step=\"" << step << "\" fill=\"" << colour << "\" stroke=\"" << colour
                << "\">\n";
            for (std::size_t i = 0; i < poses.radii.size(); ++i)
            {
                const Vec &c = poses.centres[k][i];
                svg << "<circle class=\"arm-sphere\" cx=\"" << num(f.x(c[f.u])) << "\" cy=\"" << num(f.y(c[f.v]))
                    << "\" r=\"" << num(std::max(0.5, poses.radii[i] * f.scale))
                    << "\" fill-opacity=\"0.12\" stroke-opacity=\"0.5\" stroke-width=\"0.5\"/>\n";
            }
            svg << "</g>\n";
        }
        svg << "</g>\n";
    }

    void drawRays(std::ostringstream &svg, const SvgFrame &f, const std::vector<RecordedRays> &rays, bool main)
    {
        if (rays.empty())
        {
            return;
        }
        svg << (main ? "<g id=\"rays\">\n" : "<g class=\"rays\">\n");
        for (const auto &entry : rays)
        {
            for (const auto &s : entry.segments)
            {
                svg << "<line class=\"ray\" data-step=\"" << entry.step << "\" x1=\"" << num(f.x(s[0][f.u]))
                    << "\" y1=\"" << num(f.y(s[0][f.v])) << "\" x2=\"" << num(f.x(s[1][f.u])) << "\" y2=\""
                    << num(f.y(s[1][f.v])) << "\" stroke=\"#d32f2f\" stroke-opacity=\"0.6\" stroke-width=\"0.8\"/>\n";
            }
        }
        svg << "</g>\n";
    }
}  // namespace ropras::scenarios::detail
