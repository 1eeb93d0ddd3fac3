// Random3D #1-#4 (paper, Tables "POMDP Summary" / "Spaces and Discounts" / "Functions and Horizons"): a sphere
// robot in [-25, 25]^3 among randomly placed obstacles and danger zones (100/15, 200/10, 300/10, 400/5), landmarks,
// and a goal far from the start. Every layout comes from a fixed seed; a layout whose goal is not reachable from
// the start without entering a danger zone (BFS on the action lattice) is redrawn with the next seed.
// Generation documented in doc/scenario-random3d.md.
#include <algorithm>
#include <cmath>

#include "BuiltinScenarios.h"
#include "ropras/core/Error.h"
#include "ropras/scenarios/navigation/NavigationPlanning.h"

namespace ropras::scenarios::detail
{
    namespace
    {
        struct Variant
        {
            const char *name;
            int seed;
            int obstacles;
            int danger;
        };
        constexpr Variant VARIANTS[] = {{"random3d-1", 1, 100, 15},
                                        {"random3d-2", 2, 200, 10},
                                        {"random3d-3", 3, 300, 10},
                                        {"random3d-4", 4, 400, 5}};

        bool overlaps(const NavBox &a, const NavBox &b, double margin)
        {
            for (int k = 0; k < 3; ++k)
            {
                if (a.lo[k] > b.hi[k] + margin || b.lo[k] > a.hi[k] + margin)
                {
                    return false;
                }
            }
            return true;
        }

        /// a box of half sizes uniform in [lo, hi] per axis, centred at \a c, shifted to lie inside the bounds
        NavBox boxAt(pomdp::Rng &rng, std::array<double, 3> c, double lo, double hi, double bound)
        {
            NavBox b;
            for (int k = 0; k < 3; ++k)
            {
                const double h = rng.uniform(lo, hi);
                c[k] = std::clamp(c[k], -bound + h, bound - h);
                b.lo[k] = c[k] - h;
                b.hi[k] = c[k] + h;
            }
            return b;
        }

        std::array<double, 3> uniformPoint(pomdp::Rng &rng, double range)
        {
            return {{rng.uniform(-range, range), rng.uniform(-range, range), rng.uniform(-range, range)}};
        }

        nlohmann::json point(const std::array<double, 3> &p)
        {
            return nlohmann::json::array({p[0], p[1], p[2]});
        }

        double readNumber(const std::string &scenario, const nlohmann::json &g, const std::string &key)
        {
            const auto it = g.find(key);
            if (it == g.end() || !it->is_number() || !std::isfinite(it->get<double>()))
            {
                throw Error("scenario " + scenario + ": key \"generator." + key + "\" must be a finite number");
            }
            return it->get<double>();
        }

        std::pair<double, double> readRange(const std::string &scenario, const nlohmann::json &g,
                                            const std::string &key)
        {
            const auto it = g.find(key);
            if (it == g.end() || !it->is_array() || it->size() != 2 || !(*it)[0].is_number() || !(*it)[1].is_number())
            {
                throw Error("scenario " + scenario + ": key \"generator." + key + "\" must be [min, max]");
            }
            const double lo = (*it)[0].get<double>(), hi = (*it)[1].get<double>();
            if (!(lo > 0.0) || !(hi >= lo) || !std::isfinite(hi))
            {
                throw Error("scenario " + scenario + ": key \"generator." + key + "\" = " + it->dump() +
                            " must satisfy 0 < min <= max");
            }
            return {lo, hi};
        }

        std::size_t readCount(const std::string &scenario, const nlohmann::json &g, const std::string &key)
        {
            const double v = readNumber(scenario, g, key);
            if (!(v >= 0.0) || v != std::floor(v) || v > 100000.0)
            {
                throw Error("scenario " + scenario + ": key \"generator." + key + "\" = " + std::to_string(v) +
                            " must be a count >= 0");
            }
            return static_cast<std::size_t>(v);
        }

        /** \brief The effective Random3D configuration: \a config (default.json with the variant's counts and the
            user's overrides) plus the generated goal, start, obstacles, danger zones and landmarks. */
        nlohmann::json generateRandom3D(const std::string &scenario, nlohmann::json config)
        {
            const auto &g = config.at("generator");
            const std::uint64_t seed = readCount(scenario, g, "seed");
            const std::size_t numObstacles = readCount(scenario, g, "obstacles");
            const std::size_t numDanger = readCount(scenario, g, "danger_zones");
            const std::size_t numLandmarks = readCount(scenario, g, "landmarks");
            const auto obstacleHalf = readRange(scenario, g, "obstacle_half_size");
            const auto dangerHalf = readRange(scenario, g, "danger_half_size");
            const auto landmarkHalf = readRange(scenario, g, "landmark_half_size");
            const double goalHalf = readNumber(scenario, g, "goal_half_size");
            const double startRange = readNumber(scenario, g, "start_range");
            const double distance = readNumber(scenario, g, "start_goal_distance");
            const double clearance = readNumber(scenario, g, "clearance");
            const std::size_t maxAttempts = readCount(scenario, g, "max_attempts");
            const double corridorFraction = readNumber(scenario, g, "corridor_fraction");
            const double corridorRadius = readNumber(scenario, g, "corridor_radius");
            if (!(corridorFraction >= 0.0 && corridorFraction <= 1.0) || !(corridorRadius > 0.0))
            {
                throw Error(
                    "scenario " + scenario + ": generator.corridor_fraction = " + std::to_string(corridorFraction) +
                    " must be in [0, 1] and generator.corridor_radius = " + std::to_string(corridorRadius) + " > 0");
            }
            const double radius = readNumber(scenario, config, "robot_radius");
            const double bound = 25.0;
            if (!(goalHalf > 0.0) || !(startRange > 0.0) || startRange > bound - 2.0 || !(distance > 0.0) ||
                !(clearance >= 0.0) || maxAttempts == 0)
            {
                throw Error("scenario " + scenario +
                            ": generator.goal_half_size, start_range (< 23), start_goal_distance must be > 0, "
                            "clearance >= 0, max_attempts >= 1");
            }
            for (std::size_t attempt = 0; attempt < maxAttempts; ++attempt)
            {
                pomdp::Rng rng(seed * 1000003ULL + attempt);
                // Start uniform in [-start_range, start_range]^3; goal at Manhattan distance start_goal_distance, the
                // distance split between the axes at random, each sign flipped if the goal would leave the bounds.
                const auto start = uniformPoint(rng, startRange);
                double w[3] = {rng.uniform(0.2, 1.0), rng.uniform(0.2, 1.0), rng.uniform(0.2, 1.0)};
                const double sum = w[0] + w[1] + w[2];
                std::array<double, 3> goal{};
                for (int k = 0; k < 3; ++k)
                {
                    const double offset = distance * w[k] / sum * (rng.bernoulli(0.5) ? 1.0 : -1.0);
                    goal[k] = start[k] + offset;
                    if (std::abs(goal[k]) > bound - goalHalf - 1.0)
                    {
                        goal[k] = start[k] - offset;
                    }
                }
                NavBox goalBox;
                for (int k = 0; k < 3; ++k)
                {
                    goalBox.lo[k] = goal[k] - goalHalf;
                    goalBox.hi[k] = goal[k] + goalHalf;
                }
                // Landmarks: half near the straight line from the start to the goal, the others anywhere.
                std::vector<NavBox> landmarks;
                for (std::size_t i = 0; i < numLandmarks; ++i)
                {
                    std::array<double, 3> c{};
                    if (i % 2 == 0)
                    {
                        const double t = rng.uniform(0.15, 0.85);
                        for (int k = 0; k < 3; ++k)
                        {
                            c[k] = start[k] + t * (goal[k] - start[k]) + rng.uniform(-4.0, 4.0);
                        }
                    }
                    else
                    {
                        c = uniformPoint(rng, bound - 3.0);
                    }
                    landmarks.push_back(boxAt(rng, c, landmarkHalf.first, landmarkHalf.second, bound));
                }
                // Obstacles and danger zones: a fraction corridor_fraction centred near the straight line from the
                // start to the goal (within corridor_radius per axis), the others uniform; rejected when near the
                // start, the goal or a landmark centre.
                const auto acceptable = [&](const NavBox &b)
                {
                    if (b.distance(start.data()) < clearance + radius || overlaps(b, goalBox, clearance))
                    {
                        return false;
                    }
                    for (const auto &l : landmarks)
                    {
                        if (b.distance(l.center().data()) < radius + 0.5)
                        {
                            return false;
                        }
                    }
                    return true;
                };
                const auto place = [&](std::size_t count, std::pair<double, double> half)
                {
                    std::vector<NavBox> out;
                    for (std::size_t tries = 0; out.size() < count && tries < 100 * count + 100; ++tries)
                    {
                        std::array<double, 3> c{};
                        if (rng.bernoulli(corridorFraction))
                        {
                            const double t = rng.uniform(0.1, 0.9);
                            for (int k = 0; k < 3; ++k)
                            {
                                c[k] = std::clamp(
                                    start[k] + t * (goal[k] - start[k]) + rng.uniform(-corridorRadius, corridorRadius),
                                    -bound, bound);
                            }
                        }
                        else
                        {
                            c = uniformPoint(rng, bound);
                        }
                        const NavBox b = boxAt(rng, c, half.first, half.second, bound);
                        if (acceptable(b))
                        {
                            out.push_back(b);
                        }
                    }
                    return out;
                };
                const auto obstacles = place(numObstacles, obstacleHalf);
                const auto danger = place(numDanger, dangerHalf);
                if (obstacles.size() < numObstacles || danger.size() < numDanger)
                {
                    continue;
                }
                nlohmann::json out = config;
                const auto list = [](const std::vector<NavBox> &boxes)
                {
                    nlohmann::json j = nlohmann::json::array();
                    for (const auto &b : boxes)
                    {
                        j.push_back(boxToJson(b, 3));
                    }
                    return j;
                };
                out["obstacles"] = list(obstacles);
                out["danger_zones"] = list(danger);
                out["observation_zones"] = list(landmarks);
                out["goal"] = boxToJson(goalBox, 3);
                out["starts"] = nlohmann::json::array({point(start)});
                out["generator"]["attempt"] = attempt;
                const NavigationModel model(parseNavigationConfig(scenario, out));
                NavState s;
                std::copy(start.begin(), start.end(), s.p);
                if (shortestGoalSteps(model, s, true) == 0)
                {
                    continue;  // not solvable without entering a danger zone: next seed
                }
                return out;
            }
            throw Error("scenario " + scenario + ": no solvable layout in generator.max_attempts = " +
                        std::to_string(maxAttempts) + " attempts from generator.seed = " + std::to_string(seed));
        }
    }  // namespace

    void addRandom3DScenarios(ScenarioRegistry &registry)
    {
        for (const auto &variant : VARIANTS)
        {
            ScenarioEntry entry;
            entry.name = variant.name;
            entry.description = "Random3D: " + std::to_string(variant.obstacles) + " obstacles, " +
                                std::to_string(variant.danger) +
                                " danger zones, landmarks in [-25,25]^3 (seeded); 20% slip";
            entry.factory = [variant, description = entry.description](const ScenarioOptions &options)
            {
                auto defaults = nlohmann::json::parse(embeddedFile("navigation/random3d/default.json"));
                defaults["generator"]["seed"] = variant.seed;
                defaults["generator"]["obstacles"] = variant.obstacles;
                defaults["generator"]["danger_zones"] = variant.danger;
                const auto config = generateRandom3D(variant.name, applyOverrides(variant.name, defaults, options));
                return makeNavigationScenario(variant.name, description, "navigation/random3d", config);
            };
            registry.add(std::move(entry));
        }
    }
}  // namespace ropras::scenarios::detail
