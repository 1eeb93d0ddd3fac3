// Sphere-Search (the paper's arm problem with a light and two goal candidates): registration and assembly.
#include "ropras/scenarios/manipulation/SphereSearchScenario.h"

#include <string>

#include "BuiltinScenarios.h"
#include "ropras/pomdp/OmplReferencePolicy.h"
#include "ropras/scenarios/manipulation/ArmPlanning.h"
#include "ropras/scenarios/manipulation/SphereSearchWorld.h"

namespace ropras::scenarios
{
    namespace
    {
        constexpr const char *NAME = "sphere-search";
        constexpr const char *DESCRIPTION =
            "Sphere-Search: a 7-DoF Panda finds which of two goals is real by reaching into a light (H = 150)";

        nlohmann::json point(const std::array<double, 3> &p)
        {
            return nlohmann::json::array({p[0], p[1], p[2]});
        }

        nlohmann::json sphereSearchScene(const SphereSearchConfig &config, const SphereSearchModel &model)
        {
            nlohmann::json spheres = nlohmann::json::array();
            for (const auto &o : config.obstacles)
            {
                spheres.push_back({{"center", {o[0], o[1], o[2]}}, {"radius", o[3]}});
            }
            SphereSearchModel::State start;
            SphereSearchModel::setJoints(start, config.start.data());
            const Eigen::Vector3d ee = model.endEffector(start);
            // the renderer's format (doc/scenarios.md): discs {"center", "radius"} in the obstacles, light and goal
            // layers, drawn top-down; the trajectory's points are the end effector and the particle's goal
            return {{"dims", 3},
                    {"bounds", {{-1.0, -1.0, 0.0}, {1.0, 1.0, 1.2}}},
                    {"walls", nlohmann::json::array()},
                    {"obstacles", spheres},
                    {"danger_zones", nlohmann::json::array()},
                    {"observation_zones", nlohmann::json::array()},
                    {"light", {{{"center", point(config.light)}, {"radius", config.lightRadius}}}},
                    {"goal",
                     {{{"center", point(config.goals[0])}, {"radius", config.goalRadius}},
                      {{"center", point(config.goals[1])}, {"radius", config.goalRadius}}}},
                    {"starts", {{ee.x(), ee.y(), ee.z()}}},
                    {"robot_radius", 0.02}};
        }
    }  // namespace

    ScenarioParts<SphereSearchModel> sphereSearchParts(const ScenarioOptions &options)
    {
        const nlohmann::json defaults = nlohmann::json::parse(embeddedFile("manipulation/sphere-search/default.json"));
        const nlohmann::json json = applyOverrides(NAME, defaults, options);
        const SphereSearchConfig config = SphereSearchConfig::fromJson(json, NAME);
        auto arm = sharedPandaArm(config.endEffector);
        auto model = std::make_shared<const SphereSearchModel>(config, arm);
        auto planningEnv = sphereSearchEnvironment(config, config.planningMargin);
        if (!arm->checker()->isValid(*planningEnv, config.start.data()))
        {
            throw Error(std::string("scenario ") + NAME +
                        ": key \"planning.margin\" = " + std::to_string(config.planningMargin) +
                        ": the start is in collision with the obstacles grown by the margin");
        }
        auto space = std::make_shared<const SphereSearchTargetSpace>(model, planningEnv);

        ScenarioParts<SphereSearchModel> parts;
        parts.name = NAME;
        parts.description = DESCRIPTION;
        parts.config = json;
        parts.horizon = config.horizon;
        parts.defaultPlanSeconds = config.planSeconds;
        parts.defaults = config.defaults;
        parts.model = model;
        parts.referencePolicy = [config, arm, model, planningEnv, space](
                                    const RunSettings &settings, const pomdp::ParameterMap &params,
                                    std::uint64_t seed) -> std::unique_ptr<pomdp::ReferencePolicy<SphereSearchModel>>
        {
            auto heuristic = makeSamplingHeuristic<SphereSearchModel::State, ArmTarget>(settings, space);
            auto planner = referencePlannerSettings(settings, params, config.referencePlanTime, config.resolution, seed,
                                                    {config.plannerRange});
            planner.checker = arm->checker();  // built once per process (sharedPandaArm), not once per episode
            ArmGoalSampler::Settings ik;
            ik.restarts = config.ikRestarts;
            ik.points = config.ikPoints;
            ik.radiusFraction = config.ikRadiusFraction;
            ik.nearest = config.ikNearest;
            auto sampler = std::make_unique<ArmGoalSampler>(arm, planningEnv, ik, seed ^ 0x5bd1e995ULL);
            const std::size_t macroLength = params.getCount("macro_length", 10);
            auto adapter = std::make_shared<const ArmPlanningAdapter>(std::move(sampler), config.step, macroLength,
                                                                      config.waypointActions);
            auto policy = std::make_unique<pomdp::OmplReferencePolicy<SphereSearchModel, ArmTarget>>(
                adapter, std::move(heuristic), arm->robot(), planningEnv, planner);
            policy->setTrueEnvironment(model->environment());  // particles inside the margin plan in the true cage
            pomdp::PathCache::Settings reuse;
            reuse.radius = params.get("path_reuse", 0.0);
            reuse.pathsPerTarget = params.getCount("path_reuse_paths", reuse.pathsPerTarget);
            // PathToMacroAction reads at most macro_length steps of `step`: only that prefix of a kept path is
            // re-checked in the particle's world (path_reuse_prefix=0 re-checks the whole path)
            if (params.get("path_reuse_prefix", 1.0) != 0.0)
            {
                reuse.prefixStep = config.step;
                reuse.prefixSteps = macroLength;
            }
            policy->setPathCache(reuse);
            return policy;
        };
        parts.world = [model]() -> std::unique_ptr<pomdp::World<SphereSearchModel>>
        { return std::make_unique<SphereSearchWorld>(model); };
        parts.points = [model](const SphereSearchModel::State &s, std::vector<Point3> &out)
        {
            const Eigen::Vector3d ee = model->endEffector(s);
            out.push_back(Point3{ee.x(), ee.y(), ee.z()});
            const auto &g = model->goalCenter(s.goal);
            out.push_back(Point3{g[0], g[1], g[2]});
        };
        parts.pointLabels = {"end_effector", "goal"};
        // the arm itself: `ropras render` and `ropras view` pose its collision spheres from the joints per step
        parts.robotUrdf = "robots/panda/panda.urdf";
        parts.configuration = [](const SphereSearchModel::State &s, std::vector<double> &q)
        { q.assign(s.q, s.q + ARM_DOF); };
        parts.scene = sphereSearchScene(config, *model);
        return parts;
    }

    std::unique_ptr<ModelScenario<SphereSearchModel>> makeSphereSearchScenario(const ScenarioOptions &options)
    {
        return std::make_unique<ModelScenario<SphereSearchModel>>(sphereSearchParts(options));
    }

    namespace detail
    {
        void addSphereSearchScenario(ScenarioRegistry &registry)
        {
            registry.add({NAME, DESCRIPTION, [](const ScenarioOptions &options) -> std::unique_ptr<Scenario> {
                              return makeSphereSearchScenario(options);
                          }});
        }
    }  // namespace detail
}  // namespace ropras::scenarios
