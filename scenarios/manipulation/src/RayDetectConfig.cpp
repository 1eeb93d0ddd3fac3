#include "ropras/scenarios/manipulation/RayDetectConfig.h"

#include <algorithm>
#include <string>

#include "ropras/scenarios/ConfigReader.h"
#include "ropras/scenarios/manipulation/ArmStartKeys.h"

namespace ropras::scenarios
{
    namespace
    {
        constexpr double PI = 3.14159265358979323846;

        template <std::size_t N>
        std::array<double, N> fixed(const ConfigReader &r, const std::string &key)
        {
            const auto v = r.numbers(key, N);
            std::array<double, N> out{};
            std::copy(v.begin(), v.end(), out.begin());
            return out;
        }

        /// every component must be > 0
        template <std::size_t N>
        std::array<double, N> sizes(const ConfigReader &r, const std::string &key)
        {
            const auto out = fixed<N>(r, key);
            for (double v : out)
            {
                if (!(v > 0.0))
                {
                    r.fail(key, "has a size " + std::to_string(v) + " (every size must be > 0)");
                }
            }
            return out;
        }

        void readObstacles(const ConfigReader &r, RayDetectConfig &c)
        {
            const auto &list = r.at("obstacles");
            if (!list.is_array() || list.size() != RAY_DETECT_OBSTACLES)
            {
                r.fail("obstacles", "must list exactly " + std::to_string(RAY_DETECT_OBSTACLES) +
                                        " boxes {\"pose\": [x, y, z, roll, pitch, yaw], \"extents\": [...]}, not " +
                                        list.dump().substr(0, 200));
            }
            for (std::size_t k = 0; k < RAY_DETECT_OBSTACLES; ++k)
            {
                const ConfigReader b(r.scenario(), list[k], "obstacles[" + std::to_string(k) + "].");
                b.requireKnown({"pose", "extents"});
                c.obstacles[k].pose = fixed<6>(b, "pose");
                c.obstacles[k].extents = sizes<3>(b, "extents");
                for (std::size_t i = 0; i < 3; ++i)
                {
                    if (std::abs(c.obstacles[k].pose[i]) > 10.0 || std::abs(c.obstacles[k].pose[3 + i]) > 2.0 * PI)
                    {
                        b.fail("pose", "is out of range (|position| <= 10 m, |angle| <= 2 pi)");
                    }
                }
            }
        }

        void readPlanning(const ConfigReader &r, RayDetectConfig &c)
        {
            const ConfigReader p = r.sub("planning");
            p.requireKnown({"plan_seconds", "reference_plan_time", "margin", "planner_range", "ik_restarts",
                            "ik_points", "ik_radius_fraction", "look_standoff", "look_from", "look_axis_tolerance"});
            c.planSeconds = p.within("plan_seconds", 1e-6, 3600.0);
            c.referencePlanTime = p.within("reference_plan_time", 1e-6, 60.0);
            c.planningMargin = p.within("margin", 0.0, 0.5);
            c.plannerRange = p.positive("planner_range");
            c.ikRestarts = p.count("ik_restarts", 0, 10000);
            c.ikPoints = p.count("ik_points", 1, 1000);
            c.ikRadiusFraction = p.within("ik_radius_fraction", 0.0, 1.0);
            c.lookStandoff = p.within("look_standoff", 0.05, 2.0);
            c.lookFrom = fixed<3>(p, "look_from");
            c.lookAxisTolerance = p.within("look_axis_tolerance", 1e-6, 1.0);
        }
    }  // namespace

    RayDetectConfig RayDetectConfig::fromJson(const nlohmann::json &json, const std::string &scenario)
    {
        const ConfigReader r(scenario, json);
        r.requireKnown({"start",
                        "end_effector",
                        "table",
                        "target",
                        "obstacles",
                        "goal_point",
                        "goal_radius",
                        "ray_length",
                        "step",
                        "action_mode",
                        "transition_sigma",
                        "observation_sigma",
                        "observation_position_noise",
                        "observation_angle_noise",
                        "mismatch_likelihood",
                        "initial_sigma_joints",
                        "initial_sigma_pose",
                        "reinvigorate_sigma",
                        "reinvigorate_position_sigma",
                        "reinvigorate_angle_sigma",
                        "step_reward",
                        "goal_reward",
                        "discount",
                        "horizon",
                        "resolution",
                        "observation_distance_bin",
                        "entropy_cell",
                        "heuristic_value",
                        "heuristic_ee_step",
                        "reachable_goal",
                        "planning",
                        "defaults"});
        RayDetectConfig c;
        c.json = json;
        readArmStartKeys(r, c.start, c.endEffector);
        const ConfigReader table = r.sub("table");
        table.requireKnown({"center", "extents"});
        c.tableCenter = fixed<3>(table, "center");
        c.tableExtents = sizes<3>(table, "extents");
        const ConfigReader target = r.sub("target");
        target.requireKnown({"center", "radius", "length"});
        c.targetCenter = fixed<3>(target, "center");
        c.targetRadius = target.within("radius", 1e-4, 1.0);
        c.targetLength = target.within("length", 1e-4, 2.0);
        readObstacles(r, c);
        c.goalPoint = fixed<3>(r, "goal_point");
        c.goalRadius = r.within("goal_radius", 1e-4, 1.0);
        c.rayLength = r.within("ray_length", 1e-3, 10.0);
        c.step = r.within("step", 1e-4, 2.0 * PI);
        const std::string mode = r.choice("action_mode", {"delta", "waypoint"});
        c.waypointActions = mode == "waypoint";
        c.transitionSigma = r.within("transition_sigma", 0.0, 1.0);
        c.observationSigma = r.within("observation_sigma", 1e-6, 1.0);
        c.positionNoise = r.within("observation_position_noise", 1e-6, 1.0);
        c.angleNoise = r.within("observation_angle_noise", 1e-6, PI);
        c.mismatchLikelihood = r.within("mismatch_likelihood", 0.0, 1.0);
        c.initialSigmaJoints = r.within("initial_sigma_joints", 0.0, 1.0);
        c.initialSigmaPose = fixed<6>(r, "initial_sigma_pose");
        for (double s : c.initialSigmaPose)
        {
            if (!(s >= 0.0 && s <= 1.0))
            {
                r.fail("initial_sigma_pose", "has " + std::to_string(s) + " (each must be in [0, 1])");
            }
        }
        c.reinvigorateSigma = r.within("reinvigorate_sigma", 0.0, 1.0);
        c.reinvigoratePositionSigma = r.within("reinvigorate_position_sigma", 0.0, 1.0);
        c.reinvigorateAngleSigma = r.within("reinvigorate_angle_sigma", 0.0, 1.0);
        c.stepReward = r.within("step_reward", -1e6, 1e6);
        c.goalReward = r.within("goal_reward", -1e9, 1e9);
        c.discount = r.within("discount", 1e-9, 1.0);
        c.horizon = r.count("horizon", 1, 10000000);
        c.resolution = r.within("resolution", 1e-5, 1.0);
        c.observationDistanceBin = r.within("observation_distance_bin", 1e-4, 100.0);
        c.entropyCell = r.within("entropy_cell", 1e-4, 10.0);
        c.heuristicValue = r.boolean("heuristic_value");
        c.heuristicEndEffectorStep = r.within("heuristic_ee_step", 1e-5, 1.0);
        c.reachableGoal = r.boolean("reachable_goal");
        readPlanning(r, c);
        const ConfigReader d = r.sub("defaults");
        for (const auto &item : r.at("defaults").items())
        {
            c.defaults[item.key()] = d.number(item.key());
        }
        return c;
    }
}  // namespace ropras::scenarios
