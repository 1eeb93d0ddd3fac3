// A test-only Scenario: the 2-D toy of test/pomdp/PointRobotModel.h (a disc robot, a wall with a door in one of
// two gaps, a sensing spot) behind the type-erased Scenario interface, with the OMPL reference policy
// (VectorizedRRTConnect, seeded, iteration-limited: deterministic) and the model as its own world.
#ifndef ROPRAS_TEST_SCENARIOS_TOY_SCENARIO_H
#define ROPRAS_TEST_SCENARIOS_TOY_SCENARIO_H

#include <cmath>
#include <functional>
#include <memory>
#include <string>
#include <vector>

#include "pomdp/PointRobotModel.h"
#include "ropras/scenarios/ModelScenario.h"

namespace ropras::scenarios::test
{
    /** \brief PointRobotModel with a goal test (success = the robot ended within the goal radius). */
    struct ToyModel : pomdp::test::PointRobotModel
    {
        bool reachedGoal(const State &s) const noexcept
        {
            return std::hypot(s.x - GOAL.x, s.y - GOAL.y) <= GOAL_RADIUS;
        }
    };

    /** \brief A world that throws in its first step (to test that episode errors reach the caller). */
    class ThrowingWorld final : public pomdp::World<ToyModel>
    {
    public:
        void reset(const State &initial) override { state_ = initial; }
        const State &state() const override { return state_; }
        pomdp::StepResult<State, Observation> step(const Action &, pomdp::Rng &) override
        {
            throw Error("ThrowingWorld: the world broke");
        }

    private:
        State state_{};
    };

    /** \brief The toy as a Scenario named "toy": horizon \a horizon, default planning time 0.01 s. With
        \a brokenWorld every episode throws in its first step. */
    inline std::unique_ptr<Scenario> makeToyScenario(std::size_t horizon = 30, bool brokenWorld = false)
    {
        using pomdp::test::Point2;
        ScenarioParts<ToyModel> parts;
        parts.name = "toy";
        parts.description = "test toy: a disc robot, a wall with a hidden door, a sensing spot";
        auto model = std::make_shared<const ToyModel>();
        parts.model = model;
        auto robot = pomdp::test::pointRobot();
        auto environment = pomdp::test::pointEnvironment();
        std::shared_ptr<const pomdp::TargetSpace<ToyModel::State, Point2>> space =
            std::make_shared<const pomdp::test::PointTargetSpace>();
        auto adapter = std::make_shared<const pomdp::test::PointPlanningAdapter>();
        parts.referencePolicy = [=](const RunSettings &settings, const pomdp::ParameterMap &params,
                                    std::uint64_t seed) -> std::unique_ptr<pomdp::ReferencePolicy<ToyModel>>
        {
            auto heuristic = makeSamplingHeuristic<ToyModel::State, Point2>(settings, space);
            const auto planner = referencePlannerSettings(settings, params, 1.0, pomdp::test::POINT_RESOLUTION, seed);
            return std::make_unique<pomdp::OmplReferencePolicy<ToyModel, Point2>>(adapter, std::move(heuristic), robot,
                                                                                  environment, planner);
        };
        if (brokenWorld)
        {
            parts.world = [] { return std::make_unique<ThrowingWorld>(); };
        }
        else
        {
            parts.world = [model] { return std::make_unique<pomdp::SimulatedWorld<ToyModel>>(model); };
        }
        parts.points = [](const ToyModel::State &s, std::vector<Point3> &out) { out.push_back({s.x, s.y, 0.0}); };
        parts.pointLabels = {"robot"};
        parts.defaults = {{"depth", 3}, {"rollout_steps", 0}, {"particles", 100}, {"plan_iterations", 3000}};
        parts.horizon = horizon;
        parts.defaultPlanSeconds = 0.01;
        parts.config = {{"horizon", horizon}, {"goal_radius", ToyModel::GOAL_RADIUS}};
        using nlohmann::json;
        const auto box = [](double x0, double y0, double x1, double y1) {
            return json::array({json::array({x0, y0}), json::array({x1, y1})});
        };
        const auto disc = [](double x, double y, double r) {
            return json{{"center", json::array({x, y})}, {"radius", r}};
        };
        parts.scene = json::object();
        parts.scene["dims"] = 2;
        parts.scene["bounds"] = box(0.0, 0.0, 1.0, 1.0);
        parts.scene["walls"] = json::array({box(0.47, 0.25, 0.53, 0.75)});
        parts.scene["obstacles"] = json::array({box(0.47, 0.0, 0.53, 0.25)});
        parts.scene["danger_zones"] = json::array();
        parts.scene["observation_zones"] = json::array({disc(0.15, 0.2, ToyModel::SENSE_RADIUS)});
        parts.scene["goal"] = disc(0.85, 0.5, ToyModel::GOAL_RADIUS);
        parts.scene["starts"] = json::array({json::array({0.15, 0.5})});
        parts.scene["robot_radius"] = ToyModel::RADIUS;
        parts.scene["unknown_key_for_render"] = "ignored";
        return std::make_unique<ModelScenario<ToyModel>>(std::move(parts));
    }
}  // namespace ropras::scenarios::test

#endif
