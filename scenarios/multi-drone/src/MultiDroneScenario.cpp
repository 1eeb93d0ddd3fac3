// Multi-Drone Tag (the paper's "Multi-Drone with a teleporting target"): registration and assembly.
#include "ropras/scenarios/multi-drone/MultiDroneScenario.h"

#include <cmath>
#include <string>

#include "BuiltinScenarios.h"
#include "ropras/core/Error.h"
#include "ropras/ompl_ext/scene/Environment.h"
#include "ropras/pomdp/OmplReferencePolicy.h"
#include "ropras/scenarios/ConfigReader.h"
#include "ropras/scenarios/multi-drone/MultiDronePlanning.h"
#include "ropras/scenarios/multi-drone/MultiDroneWorld.h"

namespace ropras::scenarios
{
    namespace
    {
        constexpr const char *NAME = "multi-drone";
        constexpr const char *DESCRIPTION =
            "Multi-Drone Tag: 4 drones capture a fleeing, teleporting target in [-15,15]^2 x [-2,2] (H = 400)";

        double planningNumber(const nlohmann::json &planning, const char *key)
        {
            const auto it = planning.find(key);
            if (it == planning.end() || !it->is_number() || !std::isfinite(it->get<double>()) ||
                !(it->get<double>() > 0.0))
            {
                throw Error(std::string("scenario ") + NAME + ": key \"planning." + key + "\" must be a number > 0" +
                            (it == planning.end() ? std::string(" (missing)") : ", not " + it->dump()));
            }
            return it->get<double>();
        }

        nlohmann::json toJson(const std::array<double, 3> &p)
        {
            return nlohmann::json::array({p[0], p[1], p[2]});
        }
    }  // namespace

    ScenarioParts<MultiDroneModel> multiDroneParts(const ScenarioOptions &options)
    {
        const nlohmann::json defaults = nlohmann::json::parse(embeddedFile("multi-drone/default.json"));
        const nlohmann::json json = applyOverrides(NAME, defaults, options);
        const MultiDroneConfig config = MultiDroneConfig::fromJson(json, NAME);
        const auto &planning = json.at("planning");
        for (const auto &item : planning.items())
        {
            if (item.key() != "resolution" && item.key() != "plan_seconds")
            {
                throw Error(std::string("scenario ") + NAME + ": key \"planning." + item.key() + "\" is unknown");
            }
        }
        const double resolution = planningNumber(planning, "resolution");
        const double planSeconds = planningNumber(planning, "plan_seconds");

        ScenarioParts<MultiDroneModel> parts;
        parts.name = NAME;
        parts.description = DESCRIPTION;
        parts.config = json;
        parts.horizon = config.horizon;
        parts.defaultPlanSeconds = planSeconds;
        for (const auto &item : json.at("defaults").items())
        {
            if (!item.value().is_number() || !std::isfinite(item.value().get<double>()))
            {
                throw Error(std::string("scenario ") + NAME + ": key \"defaults." + item.key() +
                            "\" must be a finite number, not " + item.value().dump());
            }
            parts.defaults[item.key()] = item.value().get<double>();
        }
        parts.solverDefaults = ConfigReader(NAME, json).solverDefaults();

        auto model = std::make_shared<const MultiDroneModel>(config);
        parts.model = model;
        auto robot = loadMultiDroneRobot(config);
        auto environment = std::make_shared<const ompl_ext::Environment>();  // an open area: no obstacles
        parts.referencePolicy = [config, robot, environment, resolution](
                                    const RunSettings &settings, const pomdp::ParameterMap &params,
                                    std::uint64_t seed) -> std::unique_ptr<pomdp::ReferencePolicy<MultiDroneModel>>
        {
            auto heuristic = std::make_unique<MultiDroneHeuristic>(
                config, MultiDroneHeuristic::spreadFromName(settings.heuristic), settings.epsilon);
            const std::size_t macroLength = params.getCount("macro_length", 12);
            const double chaseShare = params.get("chase_share", 0.75);
            auto adapter = std::make_shared<const MultiDronePlanningAdapter>(config.stepSize, macroLength, chaseShare);
            const auto plannerSettings = referencePlannerSettings(settings, params, 0.003, resolution, seed);
            return std::make_unique<pomdp::OmplReferencePolicy<MultiDroneModel, MultiDroneTarget>>(
                adapter, std::move(heuristic), robot, environment, plannerSettings);
        };
        parts.world = [model]() -> std::unique_ptr<pomdp::World<MultiDroneModel>>
        { return std::make_unique<MultiDroneWorld>(model); };
        parts.points = [](const MultiDroneModel::State &s, std::vector<Point3> &out)
        {
            for (std::size_t d = 0; d < MULTI_DRONE_COUNT; ++d)
            {
                out.push_back(Point3{s.drone[d][0], s.drone[d][1], s.drone[d][2]});
            }
            out.push_back(Point3{s.target[0], s.target[1], s.target[2]});
        };
        parts.pointLabels = {"drone1", "drone2", "drone3", "drone4", "target"};
        parts.robotUrdf = "multi-drone/drones.urdf";  // joints drone1_x, drone1_y, drone1_z, drone2_x, ...
        parts.configuration = [](const MultiDroneModel::State &s, std::vector<double> &q)
        {
            for (std::size_t d = 0; d < MULTI_DRONE_COUNT; ++d)
            {
                q.insert(q.end(), s.drone[d], s.drone[d] + 3);
            }
        };

        nlohmann::json starts = nlohmann::json::array();
        for (const auto &p : config.starts)
        {
            starts.push_back(toJson(p));
        }
        parts.scene = {{"dims", 3},
                       {"bounds", nlohmann::json::array({toJson(config.lower), toJson(config.upper)})},
                       {"starts", starts},
                       {"robot_radius", config.droneRadius},
                       {"capture_radius", config.captureRadius},
                       {"detection_range", config.detectionRange},
                       {"target_step", config.targetStep},
                       {"teleport_axes", nlohmann::json::array({"x", "y"})},
                       {"walls", nlohmann::json::array()},
                       {"obstacles", nlohmann::json::array()},
                       {"danger_zones", nlohmann::json::array()},
                       {"observation_zones", nlohmann::json::array()}};
        return parts;
    }

    std::unique_ptr<ModelScenario<MultiDroneModel>> makeMultiDroneScenario(const ScenarioOptions &options)
    {
        return std::make_unique<ModelScenario<MultiDroneModel>>(multiDroneParts(options));
    }

    namespace detail
    {
        void addMultiDroneScenario(ScenarioRegistry &registry)
        {
            registry.add({NAME, DESCRIPTION, [](const ScenarioOptions &options) -> std::unique_ptr<Scenario> {
                              return makeMultiDroneScenario(options);
                          }});
        }
    }  // namespace detail
}  // namespace ropras::scenarios
