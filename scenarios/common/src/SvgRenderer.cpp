#include "ropras/scenarios/SvgRenderer.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <map>
#include <sstream>

#include "SvgFootprints.h"
#include "ropras/core/Error.h"
#include "ropras/core/InputFile.h"

namespace ropras::scenarios
{
    namespace
    {
        using Vec = std::array<double, 3>;

        /** \brief A scene element: a box, a disc or a point (x, y, z; z = 0 in 2-D). */
        struct Shape
        {
            enum class Kind
            {
                BOX,
                DISC,
                POINT
            } kind{Kind::POINT};
            Vec lo{}, hi{};
            double radius{0.0};
        };

        /** \brief Reads and checks the parts of a recording, naming \a source and the key in every error. */
        class Reader
        {
        public:
            explicit Reader(std::string source) : source_(std::move(source)) {}

            [[noreturn]] void fail(const std::string &key, const std::string &problem) const
            {
                throw Error(source_ + ": " + key + " " + problem);
            }

            /** \brief A coordinate list of 2 or 3 finite numbers (at least \a minDims). */
            Vec point(const nlohmann::json &j, const std::string &key, std::size_t minDims = 2) const
            {
                if (!j.is_array() || j.size() < minDims || j.size() > 3)
                {
                    fail(key, "must be a point [x, y] or [x, y, z], not " + clip(j));
                }
                Vec out{0.0, 0.0, 0.0};
                for (std::size_t k = 0; k < j.size(); ++k)
                {
                    if (!j[k].is_number() || !std::isfinite(j[k].get<double>()))
                    {
                        fail(key, "has a coordinate that is not a finite number: " + clip(j));
                    }
                    out[k] = j[k].get<double>();
                }
                return out;
            }

            static bool isPoint(const nlohmann::json &j)
            {
                return j.is_array() && (j.size() == 2 || j.size() == 3) &&
                       std::all_of(j.begin(), j.end(), [](const nlohmann::json &v) { return v.is_number(); });
            }

            Shape box(const Vec &lo, const Vec &hi, const std::string &key) const
            {
                for (int k = 0; k < 3; ++k)
                {
                    if (lo[k] > hi[k])
                    {
                        fail(key, "is a box whose lower corner exceeds its upper corner on axis " + std::to_string(k));
                    }
                }
                Shape s;
                s.kind = Shape::Kind::BOX;
                s.lo = lo;
                s.hi = hi;
                return s;
            }

            Shape shape(const nlohmann::json &j, const std::string &key) const
            {
                if (isPoint(j))
                {
                    Shape s;
                    s.lo = s.hi = point(j, key);
                    return s;
                }
                if (j.is_array() && j.size() == 2 && isPoint(j[0]) && isPoint(j[1]))
                {
                    return box(point(j[0], key), point(j[1], key), key);
                }
                if (j.is_object())
                {
                    for (const auto &names : {std::pair<const char *, const char *>{"lo", "hi"}, {"min", "max"}})
                    {
                        if (j.contains(names.first) && j.contains(names.second))
                        {
                            return box(point(j[names.first], key + "." + names.first),
                                       point(j[names.second], key + "." + names.second), key);
                        }
                    }
                    const char *centerKey = j.contains("center") ? "center" : j.contains("centre") ? "centre" : nullptr;
                    if (centerKey && j.contains("radius"))
                    {
                        Shape s;
                        s.kind = Shape::Kind::DISC;
                        s.lo = s.hi = point(j[centerKey], key + "." + centerKey);
                        s.radius = number(j["radius"], key + ".radius");
                        if (s.radius < 0.0)
                        {
                            fail(key + ".radius", "is negative");
                        }
                        return s;
                    }
                    if (centerKey && j.contains("half_extents"))
                    {
                        const Vec c = point(j[centerKey], key + "." + centerKey);
                        const Vec h = point(j["half_extents"], key + ".half_extents");
                        return box(Vec{c[0] - h[0], c[1] - h[1], c[2] - h[2]},
                                   Vec{c[0] + h[0], c[1] + h[1], c[2] + h[2]}, key);
                    }
                }
                fail(key, "is not a box [lo, hi], {\"center\", \"radius\"} or a point [x, y(, z)]: " + clip(j));
            }

            std::vector<Shape> shapes(const nlohmann::json &j, const std::string &key) const
            {
                std::vector<Shape> out;
                if (j.is_null())
                {
                    return out;
                }
                if (!j.is_array())
                {
                    fail(key, "must be an array of shapes, not " + clip(j));
                }
                for (std::size_t i = 0; i < j.size(); ++i)
                {
                    out.push_back(shape(j[i], key + "[" + std::to_string(i) + "]"));
                }
                return out;
            }

            double number(const nlohmann::json &j, const std::string &key) const
            {
                if (!j.is_number() || !std::isfinite(j.get<double>()))
                {
                    fail(key, "must be a finite number, not " + clip(j));
                }
                return j.get<double>();
            }

            static std::string clip(const nlohmann::json &j)
            {
                std::string s = j.dump();
                return s.size() > 80 ? s.substr(0, 77) + "..." : s;
            }

        private:
            std::string source_;
        };

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

        const std::map<std::string, std::string> &layerColours()
        {
            static const std::map<std::string, std::string> colours{
                {"walls", "#808080"},        {"obstacles", "#00bcd4"},
                {"danger_zones", "#e53935"}, {"observation_zones", "#8e44ad"},
                {"landmarks", "#8e44ad"},    {"light", "#8e44ad"},
                {"goal", "#2e7d32"},         {"starts", "#fb8c00"}};
            return colours;
        }

        std::string labelColour(const std::string &label, std::size_t index)
        {
            if (label == "target")
                return "#2e7d32";
            if (label == "robot")
                return "#1a4fa0";
            static const char *palette[] = {"#1a4fa0", "#c2185b", "#6d4c41", "#00897b", "#5e35b1", "#f4511e"};
            return palette[index % (sizeof(palette) / sizeof(palette[0]))];
        }

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
            const std::string &colour = layerColours().at(layer.first);
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
                drawShape(svg, f, s, layerColours().at("goal"), 0.45, false, 0.0, 0.0, markerRadius + 2.0);
            }
            svg << "</g>\n";
            legend.emplace_back("goal", layerColours().at("goal"));
        }
        if (scene.contains("starts"))
        {
            const auto starts = r.shapes(scene["starts"], "scene.starts");
            svg << "<g id=\"starts\">\n";
            for (const auto &s : starts)
            {
                drawShape(svg, f, s, layerColours().at("starts"), 0.6, false, 0.0, 0.0, markerRadius);
            }
            svg << "</g>\n";
            legend.emplace_back("starts", layerColours().at("starts"));
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
        // bodies along the paths (a mobile base's footprint, a pedestrian's disc), under the path lines
        detail::drawBodies(
            svg, scene, labels, paths,
            detail::SvgMap{[&f](double x) { return f.x(x); }, [&f](double y) { return f.y(y); }, f.scale}, source);
        svg << "<g id=\"trajectory\">\n";
        for (std::size_t k = 0; k < labels.size(); ++k)
        {
            const auto &path = paths[k];
            if (path.empty())
            {
                continue;
            }
            const std::string colour = labelColour(labels[k], k);
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
                    << num(radius * f.scale) << "\" fill=\"none\" stroke=\"" << labelColour(labels[k], k)
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
