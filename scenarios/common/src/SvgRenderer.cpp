#include "ropras/scenarios/SvgRenderer.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <map>
#include <sstream>

#include "RecordingReader.h"
#include "ropras/core/Error.h"
#include "ropras/core/InputFile.h"

namespace ropras::scenarios
{
    namespace
    {
        using detail::Reader;
        using detail::Shape;
        using detail::Vec;

        std::string escape(const std::string &text)
        {
            std::string out;
            for (const char c : text)
            {
                switch (c)
                {
                    case '&':
                        out += "&amp;";
                        break;
                    case '<':
                        out += "&lt;";
                        break;
                    case '>':
                        out += "&gt;";
                        break;
                    case '"':
                        out += "&quot;";
                        break;
                    default:
                        // control characters are not allowed in XML 1.0
                        out += (static_cast<unsigned char>(c) < 0x20 && c != '\t' && c != '\n') ? ' ' : c;
                }
            }
            return out;
        }

        std::string num(double v)
        {
            char buffer[32];
            std::snprintf(buffer, sizeof(buffer), "%.2f", v);
            return buffer;
        }

        /** \brief World (x, y) to pixels: x right, y up. */
        struct Frame
        {
            Vec lo, hi;
            double scale{1.0};
            double left{20.0}, top{72.0};
            double x(double wx) const { return left + (wx - lo[0]) * scale; }
            double y(double wy) const { return top + (hi[1] - wy) * scale; }
            double width() const { return (hi[0] - lo[0]) * scale; }
            double height() const { return (hi[1] - lo[1]) * scale; }
        };

        void drawShape(std::ostringstream &svg, const Frame &f, const Shape &s, const std::string &colour,
                       double opacity, bool is3d, double zLo, double zHi, double markerRadius)
        {
            switch (s.kind)
            {
                case Shape::Kind::BOX:
                {
                    double alpha = opacity;
                    if (is3d && zHi > zLo)
                    {
                        // higher boxes darker: opacity from 0.5x to 1.5x by the box's mean height
                        const double t = std::clamp((0.5 * (s.lo[2] + s.hi[2]) - zLo) / (zHi - zLo), 0.0, 1.0);
                        alpha = std::min(1.0, opacity * (0.5 + t));
                    }
                    const double w = std::max(0.5, (s.hi[0] - s.lo[0]) * f.scale);
                    const double h = std::max(0.5, (s.hi[1] - s.lo[1]) * f.scale);
                    svg << "<rect x=\"" << num(f.x(s.lo[0])) << "\" y=\"" << num(f.y(s.hi[1])) << "\" width=\""
                        << num(w) << "\" height=\"" << num(h) << "\" fill=\"" << colour << "\" fill-opacity=\""
                        << num(alpha) << "\" stroke=\"" << colour << "\" stroke-width=\"0.8\"/>\n";
                    break;
                }
                case Shape::Kind::DISC:
                    svg << "<circle cx=\"" << num(f.x(s.lo[0])) << "\" cy=\"" << num(f.y(s.lo[1])) << "\" r=\""
                        << num(std::max(0.5, s.radius * f.scale)) << "\" fill=\"" << colour << "\" fill-opacity=\""
                        << num(opacity) << "\" stroke=\"" << colour << "\" stroke-width=\"0.8\"/>\n";
                    break;
                case Shape::Kind::POINT:
                    svg << "<circle cx=\"" << num(f.x(s.lo[0])) << "\" cy=\"" << num(f.y(s.lo[1])) << "\" r=\""
                        << num(markerRadius) << "\" fill=\"" << colour
                        << "\" stroke=\"#000000\" stroke-width=\"0.6\"/>\n";
                    break;
            }
        }
    }  // namespace

    nlohmann::json loadRecording(const std::string &path)
    {
        const std::string text = readInputFile(path, "recording");
        try
        {
            return nlohmann::json::parse(text);
        }
        catch (const nlohmann::json::exception &e)  // parse_error, and out_of_range for 1e400
        {
            throw Error("recording \"" + path + "\": malformed JSON: " + e.what());
        }
    }

    std::string renderSvg(const nlohmann::json &recording, const SvgOptions &options, const std::string &source)
    {
        const Reader r(source);
        if (!recording.is_object())
        {
            r.fail("the recording", "must be a JSON object, not " + std::string(recording.type_name()));
        }
        if (!(std::isfinite(options.width) && options.width >= 50.0))
        {
            r.fail("the picture width", "must be >= 50 px");
        }
        const auto sceneIt = recording.find("scene");
        if (sceneIt == recording.end() || !sceneIt->is_object())
        {
            r.fail("key \"scene\"", "is missing or not an object (a recording of `ropras run --record`?)");
        }
        const nlohmann::json &scene = *sceneIt;
        if (!scene.contains("bounds"))
        {
            r.fail("scene.bounds", "is missing");
        }
        const Shape bounds = r.shape(scene["bounds"], "scene.bounds");
        if (bounds.kind != Shape::Kind::BOX || !(bounds.hi[0] > bounds.lo[0]) || !(bounds.hi[1] > bounds.lo[1]))
        {
            r.fail("scene.bounds", "must be a box [lo, hi] with lo < hi in x and y");
        }
        int dims = scene["bounds"][0].size() == 3 ? 3 : 2;
        if (scene.contains("dims"))
        {
            const double d = r.number(scene["dims"], "scene.dims");
            if (d != 2.0 && d != 3.0)
            {
                r.fail("scene.dims", "must be 2 or 3, not " + Reader::clip(scene["dims"]));
            }
            dims = static_cast<int>(d);
        }

        // labels and the trajectory
        std::vector<std::string> labels;
        if (recording.contains("labels"))
        {
            const auto &l = recording["labels"];
            if (!l.is_array() || l.empty() ||
                !std::all_of(l.begin(), l.end(), [](const nlohmann::json &v) { return v.is_string(); }))
            {
                r.fail("key \"labels\"", "must be a non-empty array of names, not " + Reader::clip(l));
            }
            for (const auto &v : l)
            {
                labels.push_back(v.get<std::string>());
            }
        }
        const auto trajIt = recording.find("trajectory");
        if (trajIt == recording.end() || !trajIt->is_array())
        {
            r.fail("key \"trajectory\"", "is missing or not an array of steps");
        }
        if (labels.empty())
        {
            labels.push_back("robot");
        }
        std::vector<std::vector<Vec>> paths(labels.size());
        for (std::size_t t = 0; t < trajIt->size(); ++t)
        {
            const auto &step = (*trajIt)[t];
            const std::string key = "trajectory[" + std::to_string(t) + "]";
            if (!step.is_array() || step.size() != labels.size())
            {
                r.fail(key, "must list " + std::to_string(labels.size()) + " point(s) (one per label), not " +
                                Reader::clip(step));
            }
            for (std::size_t k = 0; k < labels.size(); ++k)
            {
                paths[k].push_back(r.point(step[k], key + "[" + std::to_string(k) + "]"));
            }
        }

        // beliefs at the chosen steps
        struct Belief
        {
            std::size_t step;
            std::vector<std::vector<Vec>> particles;
        };
        std::vector<Belief> beliefs;
        std::vector<std::size_t> recorded;
        if (recording.contains("beliefs"))
        {
            const auto &b = recording["beliefs"];
            if (!b.is_array())
            {
                r.fail("key \"beliefs\"", "must be an array of {step, particles}");
            }
            for (std::size_t i = 0; i < b.size(); ++i)
            {
                const std::string key = "beliefs[" + std::to_string(i) + "]";
                if (!b[i].is_object() || !b[i].contains("step") || !b[i]["step"].is_number_integer() ||
                    b[i]["step"].get<std::int64_t>() < 0 || !b[i].contains("particles") ||
                    !b[i]["particles"].is_array())
                {
                    r.fail(key, "must be {\"step\": n, \"particles\": [...]}, not " + Reader::clip(b[i]));
                }
                const std::size_t step = b[i]["step"].get<std::size_t>();
                recorded.push_back(step);
                const bool wanted = options.beliefSteps.empty() ||
                                    std::find(options.beliefSteps.begin(), options.beliefSteps.end(), step) !=
                                        options.beliefSteps.end();
                if (!wanted)
                {
                    continue;
                }
                Belief belief{step, {}};
                const auto &particles = b[i]["particles"];
                for (std::size_t p = 0; p < particles.size(); ++p)
                {
                    const std::string pk = key + ".particles[" + std::to_string(p) + "]";
                    if (!particles[p].is_array() || particles[p].size() != labels.size())
                    {
                        r.fail(pk, "must list " + std::to_string(labels.size()) + " point(s), not " +
                                       Reader::clip(particles[p]));
                    }
                    std::vector<Vec> points;
                    for (std::size_t k = 0; k < labels.size(); ++k)
                    {
                        points.push_back(r.point(particles[p][k], pk + "[" + std::to_string(k) + "]"));
                    }
                    belief.particles.push_back(std::move(points));
                }
                beliefs.push_back(std::move(belief));
            }
        }
        for (const std::size_t step : options.beliefSteps)
        {
            if (std::find(recorded.begin(), recorded.end(), step) == recorded.end())
            {
                std::string known;
                for (const std::size_t s : recorded)
                {
                    known += (known.empty() ? "" : ", ") + std::to_string(s);
                }
                r.fail("belief step " + std::to_string(step),
                       "was not recorded (recorded steps: " + (known.empty() ? std::string("none") : known) +
                           "; record more with --belief-every K)");
            }
        }

        // the frame
        Frame f;
        f.lo = bounds.lo;
        f.hi = bounds.hi;
        f.scale = options.width / (f.hi[0] - f.lo[0]);
        const double legendHeight = 40.0;
        const double totalWidth = f.left * 2 + f.width();
        const double totalHeight = f.top + f.height() + legendHeight;
        const bool is3d = dims == 3;
        const double markerRadius = 5.0;

        std::ostringstream svg;
        svg << "<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n"
            << "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"" << num(totalWidth) << "\" height=\""
            << num(totalHeight) << "\" viewBox=\"0 0 " << num(totalWidth) << " " << num(totalHeight)
            << "\" font-family=\"sans-serif\">\n";
        svg << "<rect x=\"0\" y=\"0\" width=\"" << num(totalWidth) << "\" height=\"" << num(totalHeight)
            << "\" fill=\"#ffffff\"/>\n";

        // title: scenario / solver / outcome / steps
        const auto str = [&](const char *key) -> std::string
        {
            const auto it = recording.find(key);
            if (it == recording.end())
                return "";
            return it->is_string() ? it->get<std::string>() : it->dump();
        };
        std::string title = str("scenario").empty() ? std::string("episode") : str("scenario");
        if (!str("solver").empty())
        {
            title += " / " + str("solver");
            if (!str("heuristic").empty() && str("solver") != "pomcp")
            {
                title += " (" + str("heuristic") + ")";
            }
        }
        if (recording.contains("episode"))
        {
            title += ", episode " + str("episode");
        }
        std::string subtitle;
        if (recording.contains("success"))
        {
            subtitle = recording["success"].is_boolean() && recording["success"].get<bool>() ? "success" : "failure";
        }
        if (recording.contains("steps"))
        {
            subtitle += (subtitle.empty() ? "" : ", ") + str("steps") + " steps";
        }
        for (const char *key : {"undiscounted_return", "discounted_return"})
        {
            if (recording.contains(key) && recording[key].is_number())
            {
                subtitle += (subtitle.empty() ? "" : ", ") + std::string(key[0] == 'u' ? "return " : "discounted ") +
                            num(recording[key].get<double>());
            }
        }
        if (recording.contains("seed"))
        {
            subtitle += (subtitle.empty() ? "" : ", ") + std::string("seed ") + str("seed");
        }
        svg << "<title>" << escape(title) << "</title>\n";
        svg << "<text x=\"" << num(f.left) << "\" y=\"22\" font-size=\"16\" font-weight=\"bold\">" << escape(title)
            << "</text>\n";
        svg << "<text x=\"" << num(f.left) << "\" y=\"44\" font-size=\"13\">" << escape(subtitle) << "</text>\n";
        if (is3d)
        {
            svg << "<text x=\"" << num(f.left) << "\" y=\"62\" font-size=\"11\" fill=\"#555555\">top view: z ignored, "
                << "higher boxes darker</text>\n";
        }

        // the bounds
        svg << "<rect id=\"bounds\" x=\"" << num(f.left) << "\" y=\"" << num(f.top) << "\" width=\"" << num(f.width())
            << "\" height=\"" << num(f.height()) << "\" fill=\"#fafafa\" stroke=\"#000000\" stroke-width=\"1.5\"/>\n";

        // scene layers, bottom to top
        std::vector<std::pair<std::string, std::string>> legend;
        const std::pair<const char *, double> layers[] = {
            {"observation_zones", 0.25}, {"landmarks", 0.25}, {"light", 0.25},
            {"danger_zones", 0.45},      {"walls", 0.85},     {"obstacles", 0.5}};
        for (const auto &layer : layers)
        {
            if (!scene.contains(layer.first))
            {
                continue;
            }
            const auto shapes = r.shapes(scene[layer.first], std::string("scene.") + layer.first);
            if (shapes.empty())
            {
                continue;
            }
            const std::string &colour = detail::layerColour(layer.first, 0);
            svg << "<g id=\"" << layer.first << "\">\n";
            for (const auto &s : shapes)
            {
                drawShape(svg, f, s, colour, layer.second, is3d, f.lo[2], f.hi[2], markerRadius);
            }
            svg << "</g>\n";
            std::string name = layer.first;
            std::replace(name.begin(), name.end(), '_', ' ');
            legend.emplace_back(name, colour);
        }
        if (scene.contains("goal"))
        {
            const auto &g = scene["goal"];
            std::vector<Shape> goals;
            if (g.is_array() && !g.empty() && !Reader::isPoint(g) &&
                !(g.size() == 2 && Reader::isPoint(g[0]) && Reader::isPoint(g[1])))
            {
                goals = r.shapes(g, "scene.goal");
            }
            else
            {
                goals.push_back(r.shape(g, "scene.goal"));
            }
            svg << "<g id=\"goal\">\n";
            for (const auto &s : goals)
            {
                drawShape(svg, f, s, detail::layerColour("goal", 0), 0.45, false, 0.0, 0.0, markerRadius + 2.0);
            }
            svg << "</g>\n";
            legend.emplace_back("goal", detail::layerColour("goal", 0));
        }
        if (scene.contains("starts"))
        {
            const auto starts = r.shapes(scene["starts"], "scene.starts");
            svg << "<g id=\"starts\">\n";
            for (const auto &s : starts)
            {
                drawShape(svg, f, s, detail::layerColour("starts", 0), 0.6, false, 0.0, 0.0, markerRadius);
            }
            svg << "</g>\n";
            legend.emplace_back("starts", detail::layerColour("starts", 0));
        }

        // belief particles and the true position at those steps
        if (!beliefs.empty())
        {
            svg << "<g id=\"beliefs\">\n";
            for (const auto &belief : beliefs)
            {
                svg << "<g class=\"belief\" data-step=\"" << belief.step << "\">\n";
                for (const auto &particle : belief.particles)
                {
                    for (const auto &p : particle)
                    {
                        svg << "<circle cx=\"" << num(f.x(p[0])) << "\" cy=\"" << num(f.y(p[1]))
                            << "\" r=\"2.2\" fill=\"#fdd835\" fill-opacity=\"0.35\"/>\n";
                    }
                }
                if (belief.step < paths.front().size())
                {
                    for (const auto &path : paths)
                    {
                        const Vec &p = path[belief.step];
                        svg << "<circle cx=\"" << num(f.x(p[0])) << "\" cy=\"" << num(f.y(p[1]))
                            << "\" r=\"4\" fill=\"none\" stroke=\"#000000\" stroke-width=\"1\"/>\n"
                            << "<text x=\"" << num(f.x(p[0]) + 5) << "\" y=\"" << num(f.y(p[1]) - 5)
                            << "\" font-size=\"10\">t=" << belief.step << "</text>\n";
                    }
                }
                svg << "</g>\n";
            }
            svg << "</g>\n";
            legend.emplace_back("belief particles", "#fdd835");
        }

        // the executed trajectories
        double robotRadius = 0.0;
        if (scene.contains("robot_radius"))
        {
            robotRadius = std::max(0.0, r.number(scene["robot_radius"], "scene.robot_radius"));
        }
        svg << "<g id=\"trajectory\">\n";
        for (std::size_t k = 0; k < labels.size(); ++k)
        {
            const auto &path = paths[k];
            if (path.empty())
            {
                continue;
            }
            const std::string colour = detail::labelColour(labels[k], k);
            // a jump longer than a fifth of the map (the target teleporting across the boundary) starts a new
            // piece instead of a line across the map
            const double jump = 0.2 * std::max(f.hi[0] - f.lo[0], f.hi[1] - f.lo[1]);
            std::size_t begin = 0;
            while (begin < path.size())
            {
                std::size_t stop = begin + 1;
                while (stop < path.size() &&
                       std::hypot(path[stop][0] - path[stop - 1][0], path[stop][1] - path[stop - 1][1]) <= jump)
                {
                    ++stop;
                }
                svg << "<polyline class=\"path\" data-label=\"" << escape(labels[k]) << "\" fill=\"none\" stroke=\""
                    << colour << "\" stroke-width=\"2\" stroke-linejoin=\"round\" points=\"";
                for (std::size_t t = begin; t < stop; ++t)
                {
                    svg << (t > begin ? " " : "") << num(f.x(path[t][0])) << "," << num(f.y(path[t][1]));
                }
                svg << "\"/>\n";
                begin = stop;
            }
            const Vec &end = path.back();
            svg << "<circle cx=\"" << num(f.x(end[0])) << "\" cy=\"" << num(f.y(end[1])) << "\" r=\""
                << num(std::max(3.0, robotRadius * f.scale)) << "\" fill=\"" << colour << "\"/>\n";
            legend.emplace_back(labels[k], colour);
        }
        svg << "</g>\n";

        // multi-drone: the detection range around the agents and the capture radius around the target
        const auto rangeCircles = [&](const char *key, bool aroundTarget, const char *dash)
        {
            if (!scene.contains(key))
            {
                return;
            }
            const double radius = r.number(scene[key], std::string("scene.") + key);
            if (radius <= 0.0)
            {
                return;
            }
            svg << "<g id=\"" << key << "\">\n";
            for (std::size_t k = 0; k < labels.size(); ++k)
            {
                if ((labels[k] == "target") != aroundTarget || paths[k].empty())
                {
                    continue;
                }
                const Vec &end = paths[k].back();
                svg << "<circle cx=\"" << num(f.x(end[0])) << "\" cy=\"" << num(f.y(end[1])) << "\" r=\""
                    << num(radius * f.scale) << "\" fill=\"none\" stroke=\"" << detail::labelColour(labels[k], k)
                    << "\" stroke-dasharray=\"" << dash << "\" stroke-width=\"1\"/>\n";
            }
            svg << "</g>\n";
        };
        rangeCircles("detection_range", false, "4 3");
        rangeCircles("capture_radius", true, "2 2");

        // legend
        double lx = f.left;
        const double ly = f.top + f.height() + 24.0;
        svg << "<g id=\"legend\" font-size=\"12\">\n";
        for (const auto &entry : legend)
        {
            svg << "<rect x=\"" << num(lx) << "\" y=\"" << num(ly - 10) << "\" width=\"12\" height=\"12\" fill=\""
                << entry.second << "\"/>\n<text x=\"" << num(lx + 16) << "\" y=\"" << num(ly) << "\">"
                << escape(entry.first) << "</text>\n";
            lx += 24.0 + 7.0 * static_cast<double>(entry.first.size());
        }
        svg << "</g>\n</svg>\n";
        return svg.str();
    }
}  // namespace ropras::scenarios
