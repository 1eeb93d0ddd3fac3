#include "ropras/scenarios/EpisodeView.h"

#include <algorithm>
#include <cmath>

#include "RecordingReader.h"
#include "ViewDocument.h"
#include "ropras/core/Error.h"
#include "ropras/core/InputFile.h"
#include "ropras/ompl_ext/model/RobotModel.h"
#include "ropras/scenarios/ScenarioRegistry.h"

namespace ropras::scenarios
{
    namespace
    {
        using detail::Reader;
        using detail::Recording;
        using detail::Shape;
        using detail::Vec3;

        /// keys of the scene that are numbers or settings, never drawn as shapes
        bool isSetting(const std::string &key)
        {
            static const char *settings[] = {"dims",         "bounds",         "starts",          "goal",
                                             "robot_radius", "capture_radius", "detection_range", "target_step",
                                             "teleport_axes"};
            return std::find(std::begin(settings), std::end(settings), key) != std::end(settings);
        }

        bool isRegion(const std::string &key)
        {
            return key == "danger_zones" || key == "observation_zones" || key == "landmarks" || key == "light" ||
                   key == "goal";
        }

        /** \brief Draws shapes of one layer; a 2-D box becomes a slab from \a zLo to \a zHi. */
        void drawShapes(detail::ViewDocument &view, int layer, const std::vector<Shape> &shapes, bool flat, double zLo,
                        double zHi, double markerRadius)
        {
            for (const auto &s : shapes)
            {
                Vec3 lo = s.lo, hi = s.hi;
                if (flat)
                {
                    lo[2] = zLo;
                    hi[2] = zHi;
                }
                switch (s.kind)
                {
                    case Shape::Kind::BOX:
                    {
                        const Vec3 size{std::max(hi[0] - lo[0], 1e-3), std::max(hi[1] - lo[1], 1e-3),
                                        std::max(hi[2] - lo[2], 1e-3)};
                        view.box(layer, {0.5 * (lo[0] + hi[0]), 0.5 * (lo[1] + hi[1]), 0.5 * (lo[2] + hi[2])}, size);
                        break;
                    }
                    case Shape::Kind::DISC:
                        if (flat)
                        {
                            view.cylinder(layer, {s.lo[0], s.lo[1], 0.5 * (zLo + zHi)}, {0.0, 0.0, 0.0, 1.0}, s.radius,
                                          std::max(zHi - zLo, 1e-3));
                        }
                        else
                        {
                            view.sphere(layer, s.lo, s.radius);
                        }
                        break;
                    case Shape::Kind::POINT:
                        view.marker(layer, s.lo, markerRadius);
                        break;
                }
            }
        }

        /** \brief The robot's joint vectors per step and its URDF, posed by RobotModel's FK into a body. */
        void drawRobot(detail::ViewDocument &view, const nlohmann::json &robot, std::size_t frames, const Reader &r,
                       const std::string &folder)
        {
            const detail::RecordedRobot recorded = detail::readRecordedRobot(robot, frames, r, folder);
            std::vector<double> radii;
            std::size_t attached = 0;
            const auto centres =
                detail::robotSphereFrames(*recorded.model, nullptr, recorded.configurations, radii, attached);
            view.body("robot spheres", "#5c6bc0", radii, centres);
        }

        void drawRays(detail::ViewDocument &view, const nlohmann::json &rays, const Reader &r)
        {
            std::vector<std::size_t> steps;
            std::vector<std::vector<std::array<Vec3, 2>>> all;
            for (auto &entry : detail::readRecordedRays(rays, r))
            {
                steps.push_back(entry.step);
                all.push_back(std::move(entry.segments));
            }
            view.rays(steps, all);
        }
    }  // namespace

    nlohmann::json episodeView(const nlohmann::json &recording, const std::string &source, const std::string &folder)
    {
        const Reader r(source);
        const Recording rec = detail::parseRecording(recording, r);
        const nlohmann::json &scene = *rec.scene;
        const double span = std::max({rec.bounds.hi[0] - rec.bounds.lo[0], rec.bounds.hi[1] - rec.bounds.lo[1],
                                      rec.bounds.hi[2] - rec.bounds.lo[2]});
        double robotRadius = 0.01 * span;
        if (scene.contains("robot_radius"))
        {
            robotRadius = r.number(scene["robot_radius"], "scene.robot_radius");
        }
        detail::ViewDocument view(std::max(1e-4, 1e-5 * span));
        auto &doc = view.json();
        const std::size_t frames = rec.paths.front().size();
        if (frames == 0)
        {
            r.fail("key \"trajectory\"", "is empty: nothing to show");
        }
        doc["title"] = rec.title;
        doc["subtitle"] = rec.subtitle;
        doc["source"] = source;
        doc["frames"] = frames;
        doc["frame_seconds"] = 0.1;
        doc["frame_label"] = "step";
        doc["dims"] = rec.dims;

        // 2-D scenes: the floor under the robot at z = -radius, walls and obstacles as blocks, regions as slabs
        const bool flat = rec.dims == 2;
        const double floorZ = flat ? -robotRadius : rec.bounds.lo[2];
        const double blockHeight = std::max(4.0 * robotRadius, 0.03 * span);
        Vec3 lo = rec.bounds.lo, hi = rec.bounds.hi;
        if (flat)
        {
            lo[2] = floorZ;
            hi[2] = floorZ + blockHeight;
        }
        doc["bounds"] = {lo, hi};

        const double marker = std::max(robotRadius, 0.005 * span);
        for (const auto &item : scene.items())
        {
            if (isSetting(item.key()) || !item.value().is_array() || item.value().empty() ||
                !(item.value()[0].is_array() || item.value()[0].is_object()))
            {
                continue;
            }
            const auto shapes = r.shapes(item.value(), "scene." + item.key());
            std::string name = item.key();
            std::replace(name.begin(), name.end(), '_', ' ');
            const bool region = isRegion(item.key());
            const int layer = view.layer(name, detail::layerColour(item.key(), doc["layers"].size()),
                                         region ? 0.3 : (item.key() == "walls" ? 0.9 : 0.7));
            drawShapes(view, layer, shapes, flat, floorZ, floorZ + (region ? 0.02 * blockHeight : blockHeight), marker);
        }
        const auto goals = detail::sceneGoals(scene, r);
        if (!goals.empty())
        {
            drawShapes(view, view.layer("goal", detail::layerColour("goal", 0), 0.35), goals, flat, floorZ,
                       floorZ + 0.05 * blockHeight, marker);
        }
        if (scene.contains("starts"))
        {
            drawShapes(view, view.layer("starts", detail::layerColour("starts", 0), 0.9),
                       r.shapes(scene["starts"], "scene.starts"), false, 0.0, 0.0, 0.5 * marker);
        }

        const bool hasRobot = recording.contains("robot");
        if (hasRobot)
        {
            drawRobot(view, recording["robot"], frames, r, folder);
        }
        for (std::size_t k = 0; k < rec.labels.size(); ++k)
        {
            const std::string colour = detail::labelColour(rec.labels[k], k);
            std::vector<double> centres;
            for (const auto &p : rec.paths[k])
            {
                centres.insert(centres.end(), p.begin(), p.end());
            }
            view.body(rec.labels[k], colour, {hasRobot ? 0.4 * marker : marker}, centres);
            view.path(rec.labels[k], colour, rec.paths[k]);
        }
        if (!rec.beliefs.empty())
        {
            std::vector<std::size_t> steps;
            for (const auto &b : rec.beliefs)
            {
                steps.push_back(b.step);
            }
            for (std::size_t k = 0; k < rec.labels.size(); ++k)
            {
                const bool known = std::all_of(rec.beliefs.begin(), rec.beliefs.end(),
                                               [k](const detail::RecordedBelief &b)
                                               {
                                                   return std::all_of(b.particles.begin(), b.particles.end(),
                                                                      [&](const std::vector<Vec3> &p)
                                                                      { return p[k] == b.particles.front()[k]; });
                                               });
                if (known)
                {
                    continue;  // no uncertainty about this label (the drones of multi-drone): nothing to show
                }
                std::vector<std::vector<Vec3>> points;
                for (const auto &b : rec.beliefs)
                {
                    points.emplace_back();
                    for (const auto &particle : b.particles)
                    {
                        points.back().push_back(particle[k]);
                    }
                }
                const std::string colour = rec.labels[k] == "robot" ? "#f9a825" : detail::labelColour(rec.labels[k], k);
                view.beliefs(rec.labels[k], colour, steps, points);
            }
        }
        if (recording.contains("rays"))
        {
            drawRays(view, recording["rays"], r);
        }
        return doc;
    }
}  // namespace ropras::scenarios
