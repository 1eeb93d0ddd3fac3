#include "ropras/scenarios/navigation/NavigationConfig.h"

#include <cmath>
#include <sstream>

#include "ropras/core/Error.h"
#include "ropras/scenarios/ConfigReader.h"

namespace ropras::scenarios
{
    namespace
    {
        /// the collision grid's cells (a list of boxes each): Maze2D has 676, Random3D 17 576
        constexpr double MAX_GRID_CELLS = 1e7;
        /// heuristic_value's lattice (2 bytes of distance and 1 of scratch per point): Random3D has 1 030 301 points
        constexpr double MAX_FIELD_POINTS = 5e7;
        /// heuristic_mdp's lattice (a sparse LU of one row per point): Maze2D has 10 201 points
        constexpr double MAX_MDP_POINTS = 250000.0;

        /// "N points (bounds / step), more than MAX"
        std::string tooMany(double points, double most, const char *what)
        {
            return std::to_string(static_cast<long long>(std::min(points, 9e18))) + " " + what + ", more than " +
                   std::to_string(static_cast<long long>(most));
        }

        /// the common reader plus the navigation shapes (points, boxes)
        class Reader : public ConfigReader
        {
        public:
            using ConfigReader::ConfigReader;

            std::array<double, 3> point(const std::string &key, const nlohmann::json &value, int dims) const
            {
                if (!value.is_array() || value.size() != static_cast<std::size_t>(dims))
                {
                    fail(key, "must be an array of " + std::to_string(dims) + " numbers, not " + value.dump());
                }
                std::array<double, 3> p{{0.0, 0.0, 0.0}};
                for (int k = 0; k < dims; ++k)
                {
                    p[k] = number(key, value[k]);
                }
                return p;
            }

            NavBox box(const std::string &key, const nlohmann::json &value, int dims) const
            {
                if (!value.is_array() || value.size() != 2)
                {
                    fail(key, "must be a box [[lo...], [hi...]], not " + value.dump());
                }
                NavBox b;
                b.lo = point(key, value[0], dims);
                b.hi = point(key, value[1], dims);
                if (dims == 2)
                {
                    b.lo[2] = -1.0;
                    b.hi[2] = 1.0;
                }
                for (int k = 0; k < dims; ++k)
                {
                    if (!(b.lo[k] < b.hi[k]))
                    {
                        fail(key, "= " + value.dump() + " has lo >= hi on axis " + std::to_string(k));
                    }
                }
                return b;
            }

            std::vector<NavBox> boxes(const std::string &key, int dims) const
            {
                const auto &list = at(key);
                if (!list.is_array())
                {
                    fail(key, "must be an array of boxes, not " + list.dump());
                }
                std::vector<NavBox> out;
                for (std::size_t i = 0; i < list.size(); ++i)
                {
                    out.push_back(box(key + "[" + std::to_string(i) + "]", list[i], dims));
                }
                return out;
            }
        };

        std::string pointString(const std::array<double, 3> &p, int dims)
        {
            std::ostringstream s;
            s << "(";
            for (int k = 0; k < dims; ++k)
            {
                s << (k ? ", " : "") << p[k];
            }
            s << ")";
            return s.str();
        }

        /// heuristic_value, heuristic_decay, heuristic_mdp: the leaf value of the search
        void readLeafValue(const Reader &r, NavigationConfig &c)
        {
            const auto &heuristic = r.at("heuristic_value");
            if (!heuristic.is_boolean())
            {
                r.fail("heuristic_value", "must be true or false, not " + heuristic.dump());
            }
            c.heuristicValue = heuristic.get<bool>();
            const double points = gridPoints(c, c.stepLength);
            if (c.heuristicValue && points > MAX_FIELD_POINTS)
            {
                r.fail("heuristic_value", "= true builds a distance field over " +
                                              tooMany(points, MAX_FIELD_POINTS, "lattice points (bounds / step)"));
            }
            c.heuristicDecay = r.positive("heuristic_decay");
            if (c.heuristicDecay > 1.0)
            {
                r.fail("heuristic_decay", "= " + nlohmann::json(c.heuristicDecay).dump() + " must be in (0, 1]");
            }
            const auto &mdp = r.at("heuristic_mdp");
            if (!mdp.is_boolean())
            {
                r.fail("heuristic_mdp", "must be true or false, not " + mdp.dump());
            }
            c.heuristicMdp = mdp.get<bool>();
            if (!c.heuristicMdp)
            {
                return;
            }
            if (!c.heuristicValue)
            {
                r.fail("heuristic_mdp",
                       "= true needs heuristic_value true (it replaces the leaf value's distance field)");
            }
            if (c.heuristicDecay != 1.0)
            {
                r.fail("heuristic_mdp",
                       "= true needs heuristic_decay 1 (the decay applies to the shortest path's value), not " +
                           nlohmann::json(c.heuristicDecay).dump());
            }
            if (points > MAX_MDP_POINTS)
            {
                r.fail("heuristic_mdp", "= true solves the problem over " +
                                            tooMany(points, MAX_MDP_POINTS, "lattice points (bounds / step)") +
                                            "; use it in 2-D");
            }
        }
    }  // namespace

    NavigationConfig parseNavigationConfig(const std::string &scenario, const nlohmann::json &json)
    {
        Reader r(scenario, json);
        NavigationConfig c;
        c.scenario = scenario;
        c.json = json;
        const double dims = r.number("dims");
        if (dims != 2.0 && dims != 3.0)
        {
            r.fail("dims", "= " + std::to_string(dims) + " must be 2 or 3");
        }
        c.dims = static_cast<int>(dims);
        c.bounds = r.box("bounds", r.at("bounds"), c.dims);
        if (c.dims == 2)
        {
            c.bounds.lo[2] = 0.0;
            c.bounds.hi[2] = 0.0;
        }
        c.stepLength = r.positive("step");
        c.slip = r.nonNegative("slip");
        if (c.slip > 1.0)
        {
            r.fail("slip", "= " + nlohmann::json(c.slip).dump() + " must be in [0, 1]");
        }
        c.robotRadius = r.positive("robot_radius");
        if (gridPoints(c, collisionGridCell(c)) > MAX_GRID_CELLS)
        {
            r.fail("bounds", "= " + boxToJson(c.bounds, c.dims).dump() + " needs a collision grid of " +
                                 tooMany(gridPoints(c, collisionGridCell(c)), MAX_GRID_CELLS,
                                         "cells (max(2 m, 4 robot radii) wide)"));
        }
        c.stepReward = r.number("step_reward");
        c.goalReward = r.number("goal_reward");
        c.dangerReward = r.number("danger_reward");
        c.goal = r.box("goal", r.at("goal"), c.dims);
        c.walls = r.boxes("walls", c.dims);
        c.obstacles = r.boxes("obstacles", c.dims);
        c.dangerZones = r.boxes("danger_zones", c.dims);
        c.observationZones = r.boxes("observation_zones", c.dims);
        c.observationSigma = r.positive("observation_sigma");
        c.observationCutoff = r.nonNegative("observation_cutoff");
        if (c.observationCutoff > 0.0 && c.observationCutoff < 3.0)
        {
            // below 3 sigma the truth itself is cut too often (1 - (1 - 2 Q(k))^dims per seen step: 9 % at k = 2)
            r.fail("observation_cutoff", "= " + nlohmann::json(c.observationCutoff).dump() +
                                             " must be 0 (off) or >= 3 (observation_sigma units)");
        }
        c.observationBin = r.positive("observation_bin");
        c.initialSigma = r.nonNegative("initial_sigma");
        c.reinvigorateSigma = r.nonNegative("reinvigorate_sigma");
        c.discount = r.positive("discount");
        if (!(c.discount < 1.0))
        {
            r.fail("discount", "= " + nlohmann::json(c.discount).dump() + " must be in (0, 1)");
        }
        const double horizon = r.positive("horizon");
        if (horizon != std::floor(horizon) || horizon > 1e7)
        {
            r.fail("horizon", "= " + std::to_string(horizon) + " must be a positive integer");
        }
        c.horizon = static_cast<std::size_t>(horizon);
        c.planSeconds = r.positive("plan_seconds");
        c.referencePlanTime = r.positive("reference_plan_time");
        c.planResolution = r.positive("plan_resolution");
        c.plannerRange = r.positive("planner_range");
        c.plannerDdRadius = r.nonNegative("planner_dd_radius");
        c.dangerMargin = r.nonNegative("danger_margin");
        c.obstacleMargin = r.nonNegative("obstacle_margin");
        c.recoverFromObservation = r.choice("depletion_recovery", {"ignore", "observation"}) == "observation";
        readLeafValue(r, c);
        const auto &evidence = r.at("termination_evidence");
        if (!evidence.is_boolean())
        {
            r.fail("termination_evidence", "must be true or false, not " + evidence.dump());
        }
        c.terminationEvidence = evidence.get<bool>();

        const auto &defaults = r.at("defaults");
        if (!defaults.is_object())
        {
            r.fail("defaults", "must be an object of solver parameters, not " + defaults.dump());
        }
        for (const auto &item : defaults.items())
        {
            c.defaults[item.key()] = r.number("defaults." + item.key(), item.value());
        }
        c.solverDefaults = r.solverDefaults();  // per solver (names checked by ModelScenario)

        // Boxes inside the bounds (the goal and every zone; walls and obstacles may touch the border).
        const auto inside = [&](const std::string &key, const NavBox &b)
        {
            for (int k = 0; k < c.dims; ++k)
            {
                if (b.lo[k] < c.bounds.lo[k] || b.hi[k] > c.bounds.hi[k])
                {
                    r.fail(key, "= " + boxToJson(b, c.dims).dump() + " lies outside the bounds " +
                                    boxToJson(c.bounds, c.dims).dump());
                }
            }
        };
        inside("goal", c.goal);
        const std::pair<const char *, const std::vector<NavBox> *> lists[] = {
            {"walls", &c.walls},
            {"obstacles", &c.obstacles},
            {"danger_zones", &c.dangerZones},
            {"observation_zones", &c.observationZones}};
        for (const auto &list : lists)
        {
            for (std::size_t i = 0; i < list.second->size(); ++i)
            {
                inside(std::string(list.first) + "[" + std::to_string(i) + "]", (*list.second)[i]);
            }
        }

        const auto &starts = r.at("starts");
        if (!starts.is_array() || starts.empty())
        {
            r.fail("starts", "must be a non-empty array of positions, not " + starts.dump());
        }
        for (std::size_t i = 0; i < starts.size(); ++i)
        {
            const std::string key = "starts[" + std::to_string(i) + "]";
            auto p = r.point(key, starts[i], c.dims);
            for (int k = 0; k < c.dims; ++k)
            {
                if (p[k] < c.bounds.lo[k] || p[k] > c.bounds.hi[k])
                {
                    r.fail(key, "= " + pointString(p, c.dims) + " lies outside the bounds");
                }
            }
            for (const auto *list : {&c.walls, &c.obstacles})
            {
                for (const auto &b : *list)
                {
                    if (b.distance(p.data()) < c.robotRadius)
                    {
                        r.fail(key, "= " + pointString(p, c.dims) + " is in collision (robot_radius " +
                                        nlohmann::json(c.robotRadius).dump() + ") with the box " +
                                        boxToJson(b, c.dims).dump());
                    }
                }
            }
            for (const auto &b : c.dangerZones)
            {
                if (b.contains(p.data()))
                {
                    r.fail(key,
                           "= " + pointString(p, c.dims) + " lies in the danger zone " + boxToJson(b, c.dims).dump());
                }
            }
            if (c.goal.contains(p.data()))
            {
                r.fail(key, "= " + pointString(p, c.dims) + " lies in the goal");
            }
            c.starts.push_back(p);
        }
        return c;
    }

    std::size_t gridPointsAlong(const NavigationConfig &c, double cell, int axis)
    {
        return axis < c.dims ? static_cast<std::size_t>(std::floor((c.bounds.hi[axis] - c.bounds.lo[axis]) / cell)) + 1
                             : 1;
    }

    double gridPoints(const NavigationConfig &c, double cell)
    {
        double points = 1.0;
        for (int k = 0; k < c.dims; ++k)
            points *= std::floor((c.bounds.hi[k] - c.bounds.lo[k]) / cell) + 1.0;
        return points;
    }

    nlohmann::json boxToJson(const NavBox &box, int dims)
    {
        nlohmann::json lo = nlohmann::json::array(), hi = nlohmann::json::array();
        for (int k = 0; k < dims; ++k)
        {
            lo.push_back(box.lo[k]);
            hi.push_back(box.hi[k]);
        }
        return nlohmann::json::array({lo, hi});
    }

    nlohmann::json navigationScene(const NavigationConfig &c)
    {
        const auto list = [&](const std::vector<NavBox> &boxes)
        {
            nlohmann::json out = nlohmann::json::array();
            for (const auto &b : boxes)
            {
                out.push_back(boxToJson(b, c.dims));
            }
            return out;
        };
        nlohmann::json starts = nlohmann::json::array();
        for (const auto &s : c.starts)
        {
            nlohmann::json p = nlohmann::json::array();
            for (int k = 0; k < c.dims; ++k)
            {
                p.push_back(s[k]);
            }
            starts.push_back(p);
        }
        return {{"dims", c.dims},
                {"bounds", boxToJson(c.bounds, c.dims)},
                {"walls", list(c.walls)},
                {"obstacles", list(c.obstacles)},
                {"danger_zones", list(c.dangerZones)},
                {"observation_zones", list(c.observationZones)},
                {"goal", boxToJson(c.goal, c.dims)},
                {"starts", starts},
                {"robot_radius", c.robotRadius}};
    }
}  // namespace ropras::scenarios
