#include "ropras/scenarios/crossing/CrossingConfig.h"

#include <cmath>
#include <set>

#include "ropras/core/Error.h"
#include "ropras/scenarios/ConfigReader.h"

namespace ropras::scenarios
{
    namespace
    {
        /** \brief The shared ConfigReader with the crossing's fixed-size arrays, sigma triples and speed lists
            (errors name the scenario and the dotted key). */
        class KeyReader : public ConfigReader
        {
        public:
            KeyReader(const nlohmann::json &json, std::string scenario, std::string prefix = "")
                : ConfigReader(std::move(scenario), json, std::move(prefix))
            {
            }

            using ConfigReader::number;
            double number(const nlohmann::json &v, const std::string &key) const
            {
                return ConfigReader::number(key, v);
            }
            /// a number > 0 (or >= 0 when \a zeroOk)
            double positive(const std::string &key, bool zeroOk = false) const
            {
                return zeroOk ? nonNegative(key) : ConfigReader::positive(key);
            }
            template <std::size_t N>
            std::array<double, N> array(const nlohmann::json &v, const std::string &key) const
            {
                if (!v.is_array() || v.size() != N)
                {
                    fail(key, "must be an array of " + std::to_string(N) + " numbers, not " + v.dump());
                }
                std::array<double, N> out{};
                for (std::size_t i = 0; i < N; ++i)
                {
                    out[i] = number(v[i], key);
                }
                return out;
            }
            template <std::size_t N>
            std::array<double, N> array(const std::string &key) const
            {
                return array<N>(at(key), key);
            }
            template <std::size_t N>
            std::array<double, N> sigmas(const std::string &key) const
            {
                const auto out = array<N>(key);
                for (const double s : out)
                {
                    if (!(s >= 0.0))
                    {
                        fail(key, "= " + at(key).dump() + " must have entries >= 0");
                    }
                }
                return out;
            }
            /// 1 to 64 numbers (the twist set is their product)
            std::vector<double> list(const std::string &key) const
            {
                const auto &v = at(key);
                if (!v.is_array() || v.empty() || v.size() > 64)
                {
                    fail(key, "must be an array of 1 to 64 numbers, not " + v.dump());
                }
                return numbers(key, 0);
            }
        };

        bool insideLab(const CrossingConfig &c, double x, double y, double margin)
        {
            return x - margin >= c.labLo[0] && x + margin <= c.labHi[0] && y - margin >= c.labLo[1] &&
                   y + margin <= c.labHi[1];
        }

        bool inTable(const CrossingConfig &c, double x, double y, double margin)
        {
            for (const auto &t : c.tables)
            {
                if (std::abs(x - t.center[0]) < t.halfExtents[0] + margin &&
                    std::abs(y - t.center[1]) < t.halfExtents[1] + margin)
                {
                    return true;
                }
            }
            return false;
        }

        void readPlanning(const KeyReader &top, CrossingConfig &c)
        {
            const KeyReader r(top.at("planning"), c.scenario, "planning.");
            r.requireKnown({"plan_seconds", "reference_plan_time", "resolution", "planner_range", "pedestrian_margin",
                            "pedestrian_sweep", "path_nodes", "lookahead", "distance_weight", "heading_weight"});
            auto &p = c.planning;
            p.planSeconds = r.positive("plan_seconds");
            p.referencePlanTime = r.positive("reference_plan_time");
            p.resolution = r.positive("resolution");
            p.plannerRange = r.positive("planner_range");
            p.pedestrianMargin = r.positive("pedestrian_margin", true);
            p.pedestrianSweep = r.positive("pedestrian_sweep", true);
            if (p.pedestrianSweep > 1000.0)
            {
                r.fail("pedestrian_sweep", "= " + r.at("pedestrian_sweep").dump() + " must be at most 1000 steps");
            }
            const double nodes = r.number("path_nodes");
            if (!(nodes >= 2.0) || nodes != std::floor(nodes) || nodes > 1e6)
            {
                r.fail("path_nodes", "= " + r.at("path_nodes").dump() + " must be an integer >= 2");
            }
            p.pathNodes = static_cast<std::size_t>(nodes);
            p.lookahead = r.positive("lookahead");
            p.distanceWeight = r.positive("distance_weight", true);
            p.headingWeight = r.positive("heading_weight", true);
        }
    }  // namespace

    CrossingConfig CrossingConfig::fromJson(const nlohmann::json &json, const std::string &scenario)
    {
        CrossingConfig c;
        c.scenario = scenario;
        c.json = json;
        const KeyReader r(json, scenario);
        r.requireKnown({"lab",
                        "wall_thickness",
                        "wall_height",
                        "tables",
                        "lift",
                        "arm",
                        "start",
                        "start_sigma",
                        "goal",
                        "goal_tolerance",
                        "pedestrian_start",
                        "pedestrian_sigma",
                        "pedestrian_radius",
                        "pedestrian_height",
                        "pedestrian_step",
                        "world_pedestrian_speed_noise",
                        "action_duration",
                        "substep",
                        "wheel_base",
                        "wheel_acceleration",
                        "wheel_speed_limit",
                        "linear_speeds",
                        "angular_speeds",
                        "straight_speed",
                        "speed_noise",
                        "observation_sigma",
                        "observation_bin",
                        "goal_reward",
                        "collision_reward",
                        "close_reward",
                        "close_distance",
                        "step_reward",
                        "discount",
                        "horizon",
                        "reinvigorate_sigma",
                        "heuristic_value",
                        "heuristic_speed",
                        "landmarks",
                        "target_yaw",
                        "planning",
                        "defaults"});
        const auto &lab = r.at("lab");
        if (!lab.is_array() || lab.size() != 2)
        {
            r.fail("lab", "must be [[xmin, ymin], [xmax, ymax]], not " + lab.dump());
        }
        c.labLo = r.array<2>(lab[0], "lab");
        c.labHi = r.array<2>(lab[1], "lab");
        if (!(c.labHi[0] > c.labLo[0]) || !(c.labHi[1] > c.labLo[1]) || c.labHi[0] - c.labLo[0] > 1000.0 ||
            c.labHi[1] - c.labLo[1] > 1000.0)
        {
            r.fail("lab", "= " + lab.dump() + " must have max > min (and sides of at most 1000 m)");
        }
        c.wallThickness = r.positive("wall_thickness");
        c.wallHeight = r.positive("wall_height");
        const auto &tables = r.at("tables");
        if (!tables.is_array() || tables.size() > 1000)
        {
            r.fail("tables", "must be an array of at most 1000 {\"center\": [x, y, z], \"half_extents\": [...]}");
        }
        for (const auto &t : tables)
        {
            if (!t.is_object() || t.size() != 2 || !t.contains("center") || !t.contains("half_extents"))
            {
                r.fail("tables",
                       "entry " + t.dump() + " must be {\"center\": [x, y, z], \"half_extents\": [hx, hy, hz]}");
            }
            CrossingTable table{r.array<3>(t.at("center"), "tables"), r.array<3>(t.at("half_extents"), "tables")};
            for (const double h : table.halfExtents)
            {
                if (!(h > 0.0))
                {
                    r.fail("tables", "entry " + t.dump() + " must have half extents > 0");
                }
            }
            c.tables.push_back(table);
        }
        c.lift = r.number("lift");
        c.arm = r.number("arm");
        c.start = r.array<3>("start");
        c.startSigma = r.sigmas<3>("start_sigma");
        c.goal = r.array<2>("goal");
        c.goalTolerance = r.positive("goal_tolerance");
        c.pedestrianStart = r.array<2>("pedestrian_start");
        c.pedestrianSigma = r.positive("pedestrian_sigma", true);
        c.pedestrianRadius = r.positive("pedestrian_radius");
        c.pedestrianHeight = r.number("pedestrian_height");
        c.pedestrianStep = r.array<2>("pedestrian_step");
        c.worldPedestrianSpeedNoise = r.positive("world_pedestrian_speed_noise", true);
        if (c.worldPedestrianSpeedNoise > 1.0)
        {
            r.fail("world_pedestrian_speed_noise",
                   "= " + r.at("world_pedestrian_speed_noise").dump() + " must be <= 1");
        }
        c.actionDuration = r.positive("action_duration");
        c.substep = r.positive("substep");
        if (c.actionDuration / c.substep > 1000.0 || c.substep > c.actionDuration)
        {
            r.fail("substep", "= " + r.at("substep").dump() +
                                  " must be at most action_duration and at least action_duration / 1000");
        }
        c.wheelBase = r.positive("wheel_base");
        c.wheelAcceleration = r.positive("wheel_acceleration");
        c.wheelSpeedLimit = r.positive("wheel_speed_limit");
        c.linearSpeeds = r.list("linear_speeds");
        for (const double v : c.linearSpeeds)
        {
            if (!(v > 0.0))
            {
                r.fail("linear_speeds", "= " + r.at("linear_speeds").dump() + " must list speeds > 0");
            }
        }
        c.angularSpeeds = r.list("angular_speeds");
        c.straightSpeed = r.positive("straight_speed");
        c.speedNoise = r.sigmas<2>("speed_noise");
        c.observationSigma = r.array<3>("observation_sigma");
        for (const double s : c.observationSigma)
        {
            if (!(s > 0.0))
            {
                r.fail("observation_sigma", "= " + r.at("observation_sigma").dump() + " must have entries > 0");
            }
        }
        c.observationBin = r.array<3>("observation_bin");
        for (const double s : c.observationBin)
        {
            if (!(s > 0.0))
            {
                r.fail("observation_bin", "= " + r.at("observation_bin").dump() + " must have entries > 0");
            }
        }
        c.goalReward = r.number("goal_reward");
        c.collisionReward = r.number("collision_reward");
        c.closeReward = r.number("close_reward");
        c.closeDistance = r.positive("close_distance");
        c.stepReward = r.number("step_reward");
        c.discount = r.number("discount");
        if (!(c.discount > 0.0 && c.discount < 1.0))
        {
            r.fail("discount", "= " + r.at("discount").dump() + " must be in (0, 1)");
        }
        const double horizon = r.number("horizon");
        if (!(horizon >= 1.0) || horizon != std::floor(horizon) || horizon > 1e7)
        {
            r.fail("horizon", "= " + r.at("horizon").dump() + " must be a positive integer (<= 1e7)");
        }
        c.horizon = static_cast<std::size_t>(horizon);
        c.reinvigorateSigma = r.sigmas<4>("reinvigorate_sigma");
        c.heuristicValue = r.boolean("heuristic_value");
        c.heuristicSpeed = r.positive("heuristic_speed");
        const auto &landmarks = r.at("landmarks");
        if (!landmarks.is_array() || landmarks.size() > 1000)
        {
            r.fail("landmarks", "must be an array of at most 1000 points [x, y], not " + landmarks.dump());
        }
        for (const auto &l : landmarks)
        {
            c.landmarks.push_back(r.array<2>(l, "landmarks"));
        }
        c.targetYaw = r.number("target_yaw");
        readPlanning(r, c);
        const KeyReader d(r.at("defaults"), scenario, "defaults.");
        for (const auto &item : r.at("defaults").items())
        {
            c.defaults[item.key()] = d.number(item.key());
        }

        // places
        if (!insideLab(c, c.start[0], c.start[1], 0.0) || inTable(c, c.start[0], c.start[1], 0.0))
        {
            r.fail("start", "= " + r.at("start").dump() + " is outside the lab or in a table");
        }
        if (!insideLab(c, c.goal[0], c.goal[1], 0.0) || inTable(c, c.goal[0], c.goal[1], 0.0))
        {
            r.fail("goal", "= " + r.at("goal").dump() + " is outside the lab or in a table");
        }
        if (!insideLab(c, c.pedestrianStart[0], c.pedestrianStart[1], c.pedestrianRadius))
        {
            r.fail("pedestrian_start",
                   "= " + r.at("pedestrian_start").dump() + " does not leave the pedestrian sphere inside the lab");
        }
        for (std::size_t i = 0; i < c.landmarks.size(); ++i)
        {
            if (!insideLab(c, c.landmarks[i][0], c.landmarks[i][1], 0.0) ||
                inTable(c, c.landmarks[i][0], c.landmarks[i][1], 0.0))
            {
                r.fail("landmarks", "entry " + std::to_string(i) + " = " + landmarks[i].dump() +
                                        " is outside the lab or in a table");
            }
        }
        return c;
    }
}  // namespace ropras::scenarios
