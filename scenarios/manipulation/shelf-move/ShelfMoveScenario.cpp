// Shelf-Move (the paper's pick-and-place of a target can from the back of a shelf): registration and assembly.
#include "ropras/scenarios/manipulation/ShelfMoveScenario.h"

#include <string>

#include "BuiltinScenarios.h"
#include "ropras/pomdp/OmplReferencePolicy.h"
#include "ropras/scenarios/manipulation/ShelfMovePlanning.h"
#include "ropras/scenarios/manipulation/ShelfMoveRecovery.h"
#include "ropras/scenarios/manipulation/ShelfMoveWorld.h"

namespace ropras::scenarios
{
    namespace
    {
        constexpr const char *NAME = "shelf-move";
        constexpr const char *DESCRIPTION =
            "Shelf-Move: a 7-DoF Panda clears packed cans off a shelf and places the target can on its reserved "
            "top slot (H = 3000)";

        /** \brief The renderer's format (doc/scenarios.md): the shelf boxes as obstacles, the cans as scene
            objects (held from a "grasp-canK" event until "release-canK-slotJ", carried by the end effector), the
            slots with the reserved one, the goal around it. */
        nlohmann::json shelfMoveScene(const ShelfMoveConfig &config, const ShelfMoveModel &model)
        {
            nlohmann::json boxes = nlohmann::json::array();
            for (const auto &b : config.shelf)
            {
                boxes.push_back({{b[0] - 0.5 * b[3], b[1] - 0.5 * b[4], b[2] - 0.5 * b[5]},
                                 {b[0] + 0.5 * b[3], b[1] + 0.5 * b[4], b[2] + 0.5 * b[5]}});
            }
            nlohmann::json slots = nlohmann::json::array();
            for (const auto &s : config.slots)
            {
                slots.push_back({{"center", {s[0], s[1], s[2]}}, {"radius", config.canRadius}});
            }
            const auto &reserved = config.slots[config.reservedSlot];
            const Eigen::Vector3d ee = model.endEffector(model.trueInitialState());
            nlohmann::json cans = nlohmann::json::array();
            for (std::size_t k = 0; k < SHELF_CANS; ++k)
            {
                cans.push_back("can" + std::to_string(k));
            }
            return {
                {"dims", 3},
                {"bounds", {{-0.2, -0.6, 0.0}, {1.0, 0.6, 1.2}}},
                {"walls", nlohmann::json::array()},
                {"obstacles", boxes},
                {"danger_zones", nlohmann::json::array()},
                {"objects",
                 {{"labels", cans},
                  {"radius", config.canRadius},
                  {"height", config.canLength},
                  {"holder", "end_effector"},
                  {"grasp_event", "grasp-"},
                  {"release_event", "release-"}}},
                {"slots", slots},
                {"reserved_slot", config.reservedSlot},
                {"goal", {{{"center", {reserved[0], reserved[1], reserved[2]}}, {"radius", config.placeTolerance}}}},
                {"starts", {{ee.x(), ee.y(), ee.z()}}},
                {"robot_radius", 0.02}};
        }
    }  // namespace

    std::string shelfMoveEvent(const ShelfMoveModel::State &s)
    {
        std::string name;
        if (s.event == ShelfEvent::Grasped)
        {
            name = "grasp-can" + std::to_string(s.eventCan);
        }
        else if (s.event == ShelfEvent::Released)
        {
            name = "release-can" + std::to_string(s.eventCan) + "-slot" + std::to_string(s.eventSlot);
        }
        const std::pair<std::uint8_t, const char *> reports[] = {{SHELF_REPORT_MOVED, "moved"},
                                                                 {SHELF_REPORT_TIPPED, "tipped"},
                                                                 {SHELF_REPORT_PUSHED, "pushed"},
                                                                 {SHELF_REPORT_VERDICT, "verdict-differs"}};
        for (const auto &[bit, word] : reports)
        {
            if (s.worldReport & bit)
            {
                name += (name.empty() ? "" : "+") + std::string(word);
            }
        }
        return name;
    }

    ScenarioParts<ShelfMoveModel> shelfMoveParts(const ScenarioOptions &options)
    {
        const nlohmann::json defaults = nlohmann::json::parse(embeddedFile("manipulation/shelf-move/default.json"));
        const nlohmann::json json = applyOverrides(NAME, defaults, options);
        const ShelfMoveConfig config = ShelfMoveConfig::fromJson(json, NAME);
        auto arm = sharedPandaArm(config.endEffector);
        auto model = std::make_shared<const ShelfMoveModel>(config, arm);
        if (!arm->checker()->isValid(*model->makeScene(model->trueInitialState(), true), config.start.data()))
        {
            throw Error(std::string("scenario ") + NAME +
                        ": key \"planning.margin\" = " + std::to_string(config.planningMargin) +
                        ": the start is in collision with the shelf and cans grown by the margin");
        }
        auto space = std::make_shared<const ShelfMoveTargetSpace>(model);

        ScenarioParts<ShelfMoveModel> parts;
        parts.name = NAME;
        parts.description = DESCRIPTION;
        parts.config = json;
        parts.horizon = config.horizon;
        parts.defaultPlanSeconds = config.planSeconds;
        parts.defaults = config.defaults;
        parts.model = model;
        parts.referencePolicy = [config, model, space](
                                    const RunSettings &settings, const pomdp::ParameterMap &params,
                                    std::uint64_t seed) -> std::unique_ptr<pomdp::ReferencePolicy<ShelfMoveModel>>
        {
            auto heuristic = makeSamplingHeuristic<ShelfMoveModel::State, ShelfTarget>(settings, space);
            auto planner = referencePlannerSettings(settings, params, config.referencePlanTime, config.resolution, seed,
                                                    {config.plannerRange});
            auto ik = std::make_unique<ShelfMoveIk>(model, config.ikRestarts, seed ^ 0x5bd1e995ULL);
            auto adapter = std::make_shared<const ShelfMoveAdapter>(model, std::move(ik));
            return std::make_unique<pomdp::OmplReferencePolicy<ShelfMoveModel, ShelfTarget>>(
                adapter, std::move(heuristic), model->arm().robot(), model->shelf(), planner);
        };
        if (config.repairOnDepletion)
        {
            parts.recovery = []() -> std::unique_ptr<pomdp::DepletionRecovery<ShelfMoveModel>>
            { return std::make_unique<ShelfMoveRecovery>(); };
        }
        parts.world = [model]() -> std::unique_ptr<pomdp::World<ShelfMoveModel>>
        {
            if (model->config().bulletWorld)
            {
                return std::make_unique<ShelfMoveWorld>(model);
            }
            return std::make_unique<pomdp::SimulatedWorld<ShelfMoveModel>>(model);
        };
        parts.points = [model](const ShelfMoveModel::State &s, std::vector<Point3> &out)
        {
            const Eigen::Vector3d ee = model->endEffector(s);
            out.push_back(Point3{ee.x(), ee.y(), ee.z()});
            for (std::size_t k = 0; k < SHELF_CANS; ++k)
            {
                out.push_back(Point3{s.can[k][0], s.can[k][1], s.can[k][2]});
            }
        };
        parts.pointLabels = {"end_effector", "can0", "can1", "can2", "can3"};
        parts.robotUrdf = "robots/panda/panda.urdf";
        parts.configuration = [](const ShelfMoveModel::State &s, std::vector<double> &q)
        { q.assign(s.q, s.q + ARM_DOF); };
        parts.event = shelfMoveEvent;
        parts.scene = shelfMoveScene(config, *model);
        return parts;
    }

    std::unique_ptr<ModelScenario<ShelfMoveModel>> makeShelfMoveScenario(const ScenarioOptions &options)
    {
        return std::make_unique<ModelScenario<ShelfMoveModel>>(shelfMoveParts(options));
    }

    namespace detail
    {
        void addShelfMoveScenario(ScenarioRegistry &registry)
        {
            registry.add({NAME, DESCRIPTION, [](const ScenarioOptions &options) -> std::unique_ptr<Scenario> {
                              return makeShelfMoveScenario(options);
                          }});
        }
    }  // namespace detail
}  // namespace ropras::scenarios
