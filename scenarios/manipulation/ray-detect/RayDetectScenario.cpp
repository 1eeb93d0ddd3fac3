// Ray-Detect (the paper's arm problem with an end-effector ray detector and four uncertain obstacles):
// registration and assembly.
#include "ropras/scenarios/manipulation/RayDetectScenario.h"

#include <string>

#include "BuiltinScenarios.h"
#include "ropras/pomdp/OmplReferencePolicy.h"
#include "ropras/scenarios/manipulation/RayDetectPlanning.h"
#include "ropras/scenarios/manipulation/RayDetectWorld.h"

namespace ropras::scenarios
{
    namespace
    {
        constexpr const char *NAME = "ray-detect";
        constexpr const char *DESCRIPTION =
            "Ray-Detect: a 7-DoF Panda with an end-effector ray detector reaches a "
            "can among 4 obstacles of uncertain pose (H = 800)";

        nlohmann::json box(const Eigen::Isometry3d &pose, const std::array<double, 3> &extents)
        {
            // the world axis-aligned bounds of the box (the renderer's boxes are axis-aligned)
            const Eigen::Vector3d half(0.5 * extents[0], 0.5 * extents[1], 0.5 * extents[2]);
            const Eigen::Vector3d reach = pose.linear().cwiseAbs() * half;
            const Eigen::Vector3d lo = pose.translation() - reach, hi = pose.translation() + reach;
            return nlohmann::json::array({{lo.x(), lo.y(), lo.z()}, {hi.x(), hi.y(), hi.z()}});
        }

        nlohmann::json rayDetectScene(const RayDetectConfig &config)
        {
            nlohmann::json obstacles = nlohmann::json::array();
            for (const auto &o : config.obstacles)
            {
                obstacles.push_back(box(rayDetectPose(o.pose.data()), o.extents));
            }
            const auto &t = config.tableCenter;
            const auto &c = config.targetCenter;
            const double r = config.targetRadius;
            const auto &g = config.goalPoint;
            return {
                {"dims", 3},
                {"bounds", {{-0.3, -0.8, 0.0}, {1.3, 0.8, 1.2}}},
                {"walls", {box(Eigen::Isometry3d(Eigen::Translation3d(t[0], t[1], t[2])), config.tableExtents)}},
                {"obstacles", obstacles},
                {"target",
                 {box(Eigen::Isometry3d(Eigen::Translation3d(c[0], c[1], c[2])), {2 * r, 2 * r, config.targetLength})}},
                {"danger_zones", nlohmann::json::array()},
                {"observation_zones", nlohmann::json::array()},
                {"goal", {{{"center", {g[0], g[1], g[2]}}, {"radius", config.goalRadius}}}},
                {"robot_radius", 0.02}};
        }
    }  // namespace

    ScenarioParts<RayDetectModel> rayDetectParts(const ScenarioOptions &options)
    {
        const nlohmann::json defaults = nlohmann::json::parse(embeddedFile("manipulation/ray-detect/default.json"));
        const nlohmann::json json = applyOverrides(NAME, defaults, options);
        const RayDetectConfig config = RayDetectConfig::fromJson(json, NAME);
        auto arm = sharedPandaArm(config.endEffector);
        auto model = std::make_shared<const RayDetectModel>(config, arm);
        std::shared_ptr<const ompl_ext::Environment> planningScene =
            rayDetectObstacleScene(config, rayDetectStaticScene(config, config.planningMargin), config.planningMargin);
        if (!arm->checker()->isValid(*planningScene, config.start.data()))
        {
            throw Error(std::string("scenario ") + NAME +
                        ": key \"planning.margin\" = " + std::to_string(config.planningMargin) +
                        ": the start is in collision with the obstacles grown by the margin");
        }
        auto space = std::make_shared<const RayDetectTargetSpace>(model, planningScene);

        ScenarioParts<RayDetectModel> parts;
        parts.name = NAME;
        parts.description = DESCRIPTION;
        parts.config = json;
        parts.horizon = config.horizon;
        parts.defaultPlanSeconds = config.planSeconds;
        parts.defaults = config.defaults;
        parts.model = model;
        parts.referencePolicy = [config, arm, model, planningScene, space](
                                    const RunSettings &settings, const pomdp::ParameterMap &params,
                                    std::uint64_t seed) -> std::unique_ptr<pomdp::ReferencePolicy<RayDetectModel>>
        {
            auto heuristic = makeSamplingHeuristic<RayDetectModel::State, RayDetectTarget>(settings, space);
            auto planner = referencePlannerSettings(settings, params, config.referencePlanTime, config.resolution, seed,
                                                    {config.plannerRange});
            planner.checker = arm->checker();  // built once per process (sharedPandaArm), not once per episode
            auto sampler = std::make_unique<RayDetectGoalSampler>(model, planningScene, seed ^ 0x5bd1e995ULL);
            const std::size_t macroLength = params.getCount("macro_length", 10);
            auto adapter = std::make_shared<const RayDetectPlanningAdapter>(std::move(sampler), config.step,
                                                                            macroLength, config.waypointActions);
            auto policy = std::make_unique<pomdp::OmplReferencePolicy<RayDetectModel, RayDetectTarget>>(
                adapter, std::move(heuristic), arm->robot(), planningScene, planner);
            // particles inside the planning margin plan in their true scene (the obstacles posed the same way)
            policy->setTrueEnvironment(model->nominalScene());
            return policy;
        };
        parts.world = [model]() -> std::unique_ptr<pomdp::World<RayDetectModel>>
        { return std::make_unique<RayDetectWorld>(model); };
        parts.points = [model](const RayDetectModel::State &s, std::vector<Point3> &out)
        {
            const Eigen::Vector3d ee = model->endEffector(s);
            out.push_back(Point3{ee.x(), ee.y(), ee.z()});
            for (const auto &p : s.poses)
            {
                out.push_back(Point3{p[0], p[1], p[2]});
            }
        };
        parts.pointLabels = {"end_effector", "obstacle0", "obstacle1", "obstacle2", "obstacle3"};
        parts.robotUrdf = "robots/panda/panda.urdf";
        parts.configuration = [](const RayDetectModel::State &s, std::vector<double> &q)
        { q.assign(s.q, s.q + ARM_DOF); };
        parts.rays = [model](const RayDetectModel::State &s, std::vector<std::array<Point3, 2>> &out)
        {
            const auto d = model->detect(s);
            out.push_back({Point3{d.origin.x(), d.origin.y(), d.origin.z()}, Point3{d.end.x(), d.end.y(), d.end.z()}});
        };
        parts.scene = rayDetectScene(config);
        return parts;
    }

    std::unique_ptr<ModelScenario<RayDetectModel>> makeRayDetectScenario(const ScenarioOptions &options)
    {
        return std::make_unique<ModelScenario<RayDetectModel>>(rayDetectParts(options));
    }

    namespace detail
    {
        void addRayDetectScenario(ScenarioRegistry &registry)
        {
            registry.add({NAME, DESCRIPTION, [](const ScenarioOptions &options) -> std::unique_ptr<Scenario> {
                              return makeRayDetectScenario(options);
                          }});
        }
    }  // namespace detail
}  // namespace ropras::scenarios
