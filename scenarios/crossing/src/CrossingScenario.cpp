// stretch-crossing (the paper's physical demonstration, reproduced in simulation): registration and assembly.
#include "ropras/scenarios/crossing/CrossingScenario.h"

#include <algorithm>
#include <string>

#include "BuiltinScenarios.h"
#include "ropras/core/Error.h"
#include "ropras/pomdp/OmplReferencePolicy.h"
#include "ropras/scenarios/crossing/CrossingPlanning.h"
#include "ropras/scenarios/crossing/CrossingWorld.h"

namespace ropras::scenarios
{
    namespace
    {
        constexpr const char *NAME = "stretch-crossing";
        constexpr const char *DESCRIPTION =
            "Stretch crossing: a diff-drive Stretch crosses a 3.8 x 4 m lab past a pedestrian it cannot see "
            "(45 twists of 0.7 s, H = 75)";

        nlohmann::json box2(double x0, double y0, double x1, double y1)
        {
            return nlohmann::json::array({nlohmann::json::array({x0, y0}), nlohmann::json::array({x1, y1})});
        }

        nlohmann::json crossingScene(const CrossingConfig &c, const CrossingModel &model)
        {
            nlohmann::json tables = nlohmann::json::array();
            for (const auto &t : c.tables)
            {
                tables.push_back(box2(t.center[0] - t.halfExtents[0], t.center[1] - t.halfExtents[1],
                                      t.center[0] + t.halfExtents[0], t.center[1] + t.halfExtents[1]));
            }
            nlohmann::json landmarks = nlohmann::json::array();
            for (const auto &l : c.landmarks)
            {
                landmarks.push_back({l[0], l[1]});
            }
            // the footprint: the xy bounding rectangle of the robot's spheres in the base frame
            double lo[2] = {1e9, 1e9}, hi[2] = {-1e9, -1e9};
            for (const auto &s : model.spheres())
            {
                lo[0] = std::min(lo[0], s.x - s.radius);
                lo[1] = std::min(lo[1], s.y - s.radius);
                hi[0] = std::max(hi[0], s.x + s.radius);
                hi[1] = std::max(hi[1], s.y + s.radius);
            }
            const nlohmann::json polygon = {{lo[0], lo[1]}, {hi[0], lo[1]}, {hi[0], hi[1]}, {lo[0], hi[1]}};
            return {{"dims", 2},
                    {"bounds", box2(c.labLo[0], c.labLo[1], c.labHi[0], c.labHi[1])},
                    {"walls", nlohmann::json::array()},
                    {"obstacles", tables},
                    {"danger_zones", nlohmann::json::array()},
                    {"observation_zones", nlohmann::json::array()},
                    {"landmarks", landmarks},
                    {"goal", {{"center", {c.goal[0], c.goal[1]}}, {"radius", c.goalTolerance}}},
                    {"starts", nlohmann::json::array({nlohmann::json::array({c.start[0], c.start[1]})})},
                    {"robot_radius", 0.0},
                    {"footprint", {{"label", "robot"}, {"polygon", polygon}}},
                    {"discs", {{"pedestrian", c.pedestrianRadius}}}};
        }
    }  // namespace

    const char *crossingEventName(CrossingEvent event)
    {
        switch (event)
        {
            case CrossingEvent::TooClose:
                return "too-close";
            case CrossingEvent::Goal:
                return "goal";
            case CrossingEvent::Pedestrian:
                return "pedestrian-collision";
            case CrossingEvent::Obstacle:
                return "obstacle-collision";
            case CrossingEvent::None:
                break;
        }
        return "";
    }

    ScenarioParts<CrossingModel> crossingParts(const ScenarioOptions &options)
    {
        const nlohmann::json defaults = nlohmann::json::parse(embeddedFile("crossing/stretch-crossing/default.json"));
        const nlohmann::json json = applyOverrides(NAME, defaults, options);
        const CrossingConfig config = CrossingConfig::fromJson(json, NAME);
        auto robot = loadStretchRobot(config);
        auto model = std::make_shared<const CrossingModel>(config, stretchBaseSpheres(*robot));
        auto lab = crossingLab(config);
        int pedestrianId = -1;
        auto scene = crossingPlanningScene(config, lab, pedestrianId);
        auto space = std::make_shared<const CrossingTargetSpace>(config);

        ScenarioParts<CrossingModel> parts;
        parts.name = NAME;
        parts.description = DESCRIPTION;
        parts.model = model;
        parts.config = json;
        parts.horizon = config.horizon;
        parts.defaultPlanSeconds = config.planning.planSeconds;
        parts.defaults = config.defaults;
        const CrossingPlanningConfig planning = config.planning;
        parts.referencePolicy = [model, robot, scene, space, planning, pedestrianId](
                                    const RunSettings &settings, const pomdp::ParameterMap &params,
                                    std::uint64_t seed) -> std::unique_ptr<pomdp::ReferencePolicy<CrossingModel>>
        {
            auto heuristic = makeSamplingHeuristic<CrossingState, CrossingTarget>(settings, space);
            auto planner = referencePlannerSettings(settings, params, planning.referencePlanTime, planning.resolution,
                                                    seed, {planning.plannerRange});
            const std::size_t macroLength = params.getCount("macro_length", 5);
            auto adapter = std::make_shared<const CrossingPlanningAdapter>(model, macroLength, pedestrianId);
            return std::make_unique<pomdp::OmplReferencePolicy<CrossingModel, CrossingTarget>>(
                adapter, std::move(heuristic), robot, scene, planner);
        };
        parts.world = [model]() -> std::unique_ptr<pomdp::World<CrossingModel>>
        { return std::make_unique<CrossingWorld>(model); };
        parts.points = [](const CrossingState &s, std::vector<Point3> &out)
        {
            out.push_back({{s.x, s.y, s.theta}});  // z = heading (the scene's footprint reads it)
            out.push_back({{s.px, s.py, 0.0}});
        };
        parts.pointLabels = {"robot", "pedestrian"};
        parts.event = [](const CrossingState &s) -> std::string { return crossingEventName(s.event); };
        parts.scene = crossingScene(config, *model);
        return parts;
    }

    std::unique_ptr<ModelScenario<CrossingModel>> makeCrossingScenario(const ScenarioOptions &options)
    {
        return std::make_unique<ModelScenario<CrossingModel>>(crossingParts(options));
    }

    namespace detail
    {
        void addCrossingScenario(ScenarioRegistry &registry)
        {
            registry.add({NAME, DESCRIPTION, [](const ScenarioOptions &options) -> std::unique_ptr<Scenario> {
                              return makeCrossingScenario(options);
                          }});
        }
    }  // namespace detail
}  // namespace ropras::scenarios
