#include "RecordingReader.h"

#include <cstdio>
#include <map>

#include "ropras/scenarios/ScenarioRegistry.h"

namespace ropras::scenarios::detail
{
    namespace
    {
        std::vector<std::string> readLabels(const nlohmann::json &recording, const Reader &r)
        {
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
            if (labels.empty())
            {
                labels.push_back("robot");
            }
            return labels;
        }

        std::vector<Vec> pointsOfStep(const nlohmann::json &step, std::size_t count, const std::string &key,
                                      const Reader &r)
        {
            if (!step.is_array() || step.size() != count)
            {
                r.fail(key,
                       "must list " + std::to_string(count) + " point(s) (one per label), not " + Reader::clip(step));
            }
            std::vector<Vec> out;
            out.reserve(count);
            for (std::size_t k = 0; k < count; ++k)
            {
                out.push_back(r.point(step[k], key + "[" + std::to_string(k) + "]"));
            }
            return out;
        }

        std::vector<RecordedBelief> readBeliefs(const nlohmann::json &recording, std::size_t labels, const Reader &r)
        {
            std::vector<RecordedBelief> beliefs;
            if (!recording.contains("beliefs"))
            {
                return beliefs;
            }
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
                RecordedBelief belief{b[i]["step"].get<std::size_t>(), {}};
                const auto &particles = b[i]["particles"];
                belief.particles.reserve(particles.size());
                for (std::size_t p = 0; p < particles.size(); ++p)
                {
                    belief.particles.push_back(
                        pointsOfStep(particles[p], labels, key + ".particles[" + std::to_string(p) + "]", r));
                }
                beliefs.push_back(std::move(belief));
            }
            return beliefs;
        }

        /** \brief "maze2d / ropras3 (uniform), episode 3" and "success, 41 steps, discounted 12.30, seed 7". */
        void titles(const nlohmann::json &recording, Recording &out)
        {
            const auto str = [&](const char *key) -> std::string
            {
                const auto it = recording.find(key);
                if (it == recording.end())
                    return "";
                return it->is_string() ? it->get<std::string>() : it->dump();
            };
            const auto fixed2 = [](double v)
            {
                char buffer[32];
                std::snprintf(buffer, sizeof(buffer), "%.2f", v);
                return std::string(buffer);
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
                subtitle =
                    recording["success"].is_boolean() && recording["success"].get<bool>() ? "success" : "failure";
            }
            if (recording.contains("steps"))
            {
                subtitle += (subtitle.empty() ? "" : ", ") + str("steps") + " steps";
            }
            for (const char *key : {"undiscounted_return", "discounted_return"})
            {
                if (recording.contains(key) && recording[key].is_number())
                {
                    subtitle += (subtitle.empty() ? "" : ", ") +
                                std::string(key[0] == 'u' ? "return " : "discounted ") +
                                fixed2(recording[key].get<double>());
                }
            }
            if (recording.contains("seed"))
            {
                subtitle += (subtitle.empty() ? "" : ", ") + std::string("seed ") + str("seed");
            }
            out.title = title;
            out.subtitle = subtitle;
        }
    }  // namespace

    Recording parseRecording(const nlohmann::json &recording, const Reader &r)
    {
        if (!recording.is_object())
        {
            r.fail("the recording", "must be a JSON object, not " + std::string(recording.type_name()));
        }
        const auto sceneIt = recording.find("scene");
        if (sceneIt == recording.end() || !sceneIt->is_object())
        {
            r.fail("key \"scene\"", "is missing or not an object (a recording of `ropras run --record`?)");
        }
        Recording out;
        out.json = &recording;
        out.scene = &*sceneIt;
        const nlohmann::json &scene = *sceneIt;
        if (!scene.contains("bounds"))
        {
            r.fail("scene.bounds", "is missing");
        }
        out.bounds = r.shape(scene["bounds"], "scene.bounds");
        const Shape &bounds = out.bounds;
        if (bounds.kind != Shape::Kind::BOX || !(bounds.hi[0] > bounds.lo[0]) || !(bounds.hi[1] > bounds.lo[1]))
        {
            r.fail("scene.bounds", "must be a box [lo, hi] with lo < hi in x and y");
        }
        out.dims = scene["bounds"][0].size() == 3 ? 3 : 2;
        if (scene.contains("dims"))
        {
            const double d = r.number(scene["dims"], "scene.dims");
            if (d != 2.0 && d != 3.0)
            {
                r.fail("scene.dims", "must be 2 or 3, not " + Reader::clip(scene["dims"]));
            }
            out.dims = static_cast<int>(d);
        }

        out.labels = readLabels(recording, r);
        const auto trajIt = recording.find("trajectory");
        if (trajIt == recording.end() || !trajIt->is_array())
        {
            r.fail("key \"trajectory\"", "is missing or not an array of steps");
        }
        out.paths.assign(out.labels.size(), {});
        for (std::size_t t = 0; t < trajIt->size(); ++t)
        {
            const auto points =
                pointsOfStep((*trajIt)[t], out.labels.size(), "trajectory[" + std::to_string(t) + "]", r);
            for (std::size_t k = 0; k < points.size(); ++k)
            {
                out.paths[k].push_back(points[k]);
            }
        }
        out.beliefs = readBeliefs(recording, out.labels.size(), r);
        titles(recording, out);
        return out;
    }

    std::string layerColour(const std::string &key, std::size_t index)
    {
        static const std::map<std::string, std::string> colours{
            {"walls", "#808080"},        {"obstacles", "#00bcd4"},
            {"danger_zones", "#e53935"}, {"observation_zones", "#8e44ad"},
            {"landmarks", "#8e44ad"},    {"light", "#8e44ad"},
            {"goal", "#2e7d32"},         {"starts", "#fb8c00"}};
        const auto it = colours.find(key);
        if (it != colours.end())
        {
            return it->second;
        }
        static const char *palette[] = {"#795548", "#ff7043", "#26a69a", "#ab47bc", "#9e9d24", "#5d4037"};
        return palette[index % (sizeof(palette) / sizeof(palette[0]))];
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

    std::vector<Shape> sceneGoals(const nlohmann::json &scene, const Reader &r)
    {
        std::vector<Shape> goals;
        if (!scene.contains("goal"))
        {
            return goals;
        }
        const auto &g = scene["goal"];
        if (g.is_array() && !g.empty() && !Reader::isPoint(g) &&
            !(g.size() == 2 && Reader::isPoint(g[0]) && Reader::isPoint(g[1])))
        {
            return r.shapes(g, "scene.goal");
        }
        goals.push_back(r.shape(g, "scene.goal"));
        return goals;
    }

    RecordedRobot readRecordedRobot(const nlohmann::json &robot, std::size_t frames, const Reader &r,
                                    const std::string &folder)
    {
        if (!robot.is_object() || !robot.contains("urdf") || !robot["urdf"].is_string() ||
            !robot.contains("configurations") || !robot["configurations"].is_array())
        {
            r.fail("key \"robot\"",
                   "must be {\"urdf\": FILE, \"configurations\": [[q...], ...]}, not " + Reader::clip(robot));
        }
        const std::string urdf = robot["urdf"].get<std::string>();
        const std::string embedded = "embedded:";
        ompl_ext::RobotModel::Options options;
        options.disableAlwaysColliding = false;  // only poses spheres
        RecordedRobot out;
        if (urdf.compare(0, embedded.size(), embedded) == 0)
        {
            const std::string key = urdf.substr(embedded.size());
            out.model = ompl_ext::RobotModel::fromUrdfString(embeddedFile(key), ".", key, "", options);
        }
        else
        {
            const std::string path = !urdf.empty() && urdf[0] == '/' ? urdf : folder + "/" + urdf;
            out.model = ompl_ext::RobotModel::fromUrdfFile(path, "", options);
        }
        const auto &list = robot["configurations"];
        if (list.size() != frames)
        {
            r.fail("robot.configurations", "has " + std::to_string(list.size()) + " entries, the trajectory " +
                                               std::to_string(frames) + " steps");
        }
        const std::size_t dof = out.model->dof();
        out.configurations.assign(frames, std::vector<double>(dof));
        for (std::size_t t = 0; t < frames; ++t)
        {
            const std::string key = "robot.configurations[" + std::to_string(t) + "]";
            if (!list[t].is_array() || list[t].size() != dof)
            {
                r.fail(key, "must list the " + std::to_string(dof) + " joint values of " + urdf + ", not " +
                                Reader::clip(list[t]));
            }
            for (std::size_t k = 0; k < dof; ++k)
            {
                out.configurations[t][k] = r.number(list[t][k], key + "[" + std::to_string(k) + "]");
            }
        }
        return out;
    }

    std::vector<RecordedRays> readRecordedRays(const nlohmann::json &rays, const Reader &r)
    {
        if (!rays.is_array())
        {
            r.fail("key \"rays\"", "must be an array of {\"step\", \"segments\"}");
        }
        std::vector<RecordedRays> out;
        for (std::size_t i = 0; i < rays.size(); ++i)
        {
            const std::string key = "rays[" + std::to_string(i) + "]";
            const auto &item = rays[i];
            if (!item.is_object() || !item.contains("step") || !item["step"].is_number_integer() ||
                item["step"].get<std::int64_t>() < 0 || !item.contains("segments") || !item["segments"].is_array())
            {
                r.fail(key, "must be {\"step\": n, \"segments\": [[origin, end], ...]}, not " + Reader::clip(item));
            }
            RecordedRays entry;
            entry.step = item["step"].get<std::size_t>();
            for (std::size_t k = 0; k < item["segments"].size(); ++k)
            {
                const auto &s = item["segments"][k];
                const std::string sk = key + ".segments[" + std::to_string(k) + "]";
                if (!s.is_array() || s.size() != 2)
                {
                    r.fail(sk, "must be [origin, end], not " + Reader::clip(s));
                }
                entry.segments.push_back({r.point(s[0], sk), r.point(s[1], sk)});
            }
            out.push_back(std::move(entry));
        }
        return out;
    }
}  // namespace ropras::scenarios::detail
