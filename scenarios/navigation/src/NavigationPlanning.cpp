#include "ropras/scenarios/navigation/NavigationPlanning.h"

#include <algorithm>
#include <cmath>
#include <deque>

#include "ropras/core/Error.h"
#include "ropras/scenarios/ScenarioRegistry.h"
#include "ropras/scenarios/navigation/NavigationRecovery.h"
#include "ropras/scenarios/navigation/NavigationWorld.h"

namespace ropras::scenarios
{
    NavigationTargetSpace::NavigationTargetSpace(std::shared_ptr<const NavigationModel> model)
        : model_(std::move(model))
    {
        const auto &c = model_->config();
        goal_ = c.goal.center();
        for (const auto &zone : c.observationZones)
        {
            informative_.push_back(zone.center());
        }
        for (int k = 0; k < 3; ++k)
        {
            goal_[k] = k < c.dims ? goal_[k] : 0.0;
            for (auto &t : informative_)
            {
                t[k] = k < c.dims ? t[k] : 0.0;
            }
            bins_[k] = k < c.dims ? static_cast<std::size_t>(std::ceil(c.bounds.hi[k] - c.bounds.lo[k])) + 1 : 1;
        }
        const auto grown = [&](const std::vector<NavBox> &boxes, double margin)
        {
            for (const NavBox &b : boxes)
            {
                plannerBoxes_.push_back(b.grown(margin, c.dims));
            }
        };
        grown(c.walls, c.obstacleMargin);
        grown(c.obstacles, c.obstacleMargin);
        grown(c.dangerZones, c.dangerMargin);
    }

    double NavigationTargetSpace::distance(const NavState &a, const NavTarget &t) const
    {
        double d2 = 0.0;
        for (int k = 0; k < 3; ++k)
        {
            d2 += (a.p[k] - t[k]) * (a.p[k] - t[k]);
        }
        return std::sqrt(d2);
    }

    std::uint64_t NavigationTargetSpace::entropyBin(const NavState &p) const
    {
        const auto &c = model_->config();
        std::uint64_t bin = 0;
        for (int k = 2; k >= 0; --k)
        {
            const double f = std::floor(p.p[k] - c.bounds.lo[k]);
            const auto i = static_cast<std::uint64_t>(std::clamp(f, 0.0, static_cast<double>(bins_[k] - 1)));
            bin = bin * bins_[k] + i;
        }
        return bin;
    }

    bool NavigationTargetSpace::sampleFree(pomdp::Rng &rng, NavTarget &out) const
    {
        const auto &c = model_->config();
        for (int attempt = 0; attempt < 1000; ++attempt)
        {
            NavState s;
            for (int k = 0; k < c.dims; ++k)
            {
                s.p[k] = rng.uniform(c.bounds.lo[k], c.bounds.hi[k]);
            }
            // the planner's boxes contain the true ones: a clear point is neither blocked nor in danger
            const auto inMargin = [&](const NavBox &b) { return b.distance(s.p) < c.robotRadius; };
            if (std::none_of(plannerBoxes_.begin(), plannerBoxes_.end(), inMargin))
            {
                out = {{s.p[0], s.p[1], s.p[2]}};
                return true;
            }
        }
        return false;
    }

    NavigationPlanningAdapter::NavigationPlanningAdapter(std::shared_ptr<const NavigationModel> model,
                                                         std::size_t macroLength)
        : model_(std::move(model)), macroLength_(macroLength)
    {
        if (macroLength_ == 0)
        {
            throw Error("scenario " + model_->config().scenario + ": parameter macro_length must be >= 1");
        }
    }

    void NavigationPlanningAdapter::configuration(const NavState &state, double *q) const
    {
        for (int k = 0; k < model_->dims(); ++k)
        {
            q[k] = state.p[k];
        }
    }

    bool NavigationPlanningAdapter::targetConfiguration(const NavState &, const NavTarget &target, double *q) const
    {
        bool ok = true;
        for (int k = 0; k < model_->dims(); ++k)
        {
            q[k] = target[k];
            ok = ok && std::isfinite(target[k]);
        }
        return ok;
    }

    bool NavigationPlanningAdapter::pathToMacroAction(const NavState &start, const double *waypoints, std::size_t count,
                                                      std::vector<std::uint8_t> &out) const
    {
        const int dims = model_->dims();
        const double step = model_->config().stepLength;
        thread_local std::vector<double> points;
        points.clear();
        const std::size_t n =
            pomdp::discretizeJointPath(waypoints, count, static_cast<std::size_t>(dims), step, macroLength_, points);
        double cur[3] = {start.p[0], start.p[1], start.p[2]};
        std::size_t added = 0;
        for (std::size_t i = 0; i < n && added < macroLength_; ++i)
        {
            const double *target = points.data() + i * static_cast<std::size_t>(dims);
            while (added < macroLength_)
            {
                int best = -1;
                double bestDiff = 0.5 * step;
                for (int k = 0; k < dims; ++k)
                {
                    const double d = std::abs(target[k] - cur[k]);
                    if (d > bestDiff)
                    {
                        bestDiff = d;
                        best = k;
                    }
                }
                if (best < 0)
                {
                    break;
                }
                const bool positive = target[best] > cur[best];
                out.push_back(static_cast<std::uint8_t>(2 * best + (positive ? 0 : 1)));
                cur[best] += positive ? step : -step;
                ++added;
            }
        }
        return added > 0;
    }

    std::shared_ptr<const ompl_ext::RobotModel> loadNavigationRobot(const NavigationConfig &config,
                                                                    const std::string &folder)
    {
        const std::string path = folder + "/robot.urdf";
        auto robot = ompl_ext::RobotModel::fromUrdfString(embeddedFile(path), ".", path);
        const auto fail = [&](const std::string &problem)
        { throw Error("scenario " + config.scenario + ": " + path + ": " + problem); };
        if (robot->dof() != static_cast<std::size_t>(config.dims))
        {
            fail("has " + std::to_string(robot->dof()) +
                 " joints, the configuration has dims = " + std::to_string(config.dims));
        }
        for (int k = 0; k < config.dims; ++k)
        {
            const auto &j = robot->joints()[static_cast<std::size_t>(k)];
            if (j.type != ompl_ext::JointType::Prismatic || std::abs(j.lower - config.bounds.lo[k]) > 1e-9 ||
                std::abs(j.upper - config.bounds.hi[k]) > 1e-9)
            {
                fail("joint \"" + j.name + "\" (prismatic, limits [" + std::to_string(j.lower) + ", " +
                     std::to_string(j.upper) + "]) does not match the bounds [" + std::to_string(config.bounds.lo[k]) +
                     ", " + std::to_string(config.bounds.hi[k]) + "] on axis " + std::to_string(k));
            }
        }
        if (robot->spheres().size() != 1 || std::abs(robot->spheres()[0].radius - config.robotRadius) > 1e-9)
        {
            fail("must have one collision sphere of radius robot_radius = " + std::to_string(config.robotRadius));
        }
        return robot;
    }

    std::shared_ptr<const ompl_ext::Environment> navigationEnvironment(const NavigationConfig &config,
                                                                       double dangerMargin, double obstacleMargin)
    {
        const double dangerGrow = dangerMargin < 0.0 ? config.dangerMargin : dangerMargin;
        const double obstacleGrow = obstacleMargin < 0.0 ? config.obstacleMargin : obstacleMargin;
        auto env = std::make_shared<ompl_ext::Environment>();
        const auto add = [&](const std::string &prefix, const std::vector<NavBox> &boxes, double grow)
        {
            for (std::size_t i = 0; i < boxes.size(); ++i)
            {
                const NavBox b = boxes[i].grown(grow, config.dims);
                const auto c = b.center();
                const Eigen::Vector3d size(b.hi[0] - b.lo[0], b.hi[1] - b.lo[1], b.hi[2] - b.lo[2]);
                env->addBox(prefix + std::to_string(i), Eigen::Isometry3d(Eigen::Translation3d(c[0], c[1], c[2])),
                            size);
            }
        };
        // grown by obstacle_margin: paths keep off the walls and obstacles that a drifting robot's particles
        // would get stuck on (a belief split along the wall)
        add("wall", config.walls, obstacleGrow);
        add("obstacle", config.obstacles, obstacleGrow);
        // grown by danger_margin: reference paths keep that clearance from danger (the robot drifts)
        add("danger", config.dangerZones, dangerGrow);
        return env;
    }

    ScenarioParts<NavigationModel> navigationParts(const std::string &name, const std::string &description,
                                                   const std::string &folder, const nlohmann::json &json)
    {
        NavigationConfig config = parseNavigationConfig(name, json);
        auto model = std::make_shared<const NavigationModel>(config);
        auto robot = loadNavigationRobot(config, folder);
        auto env = navigationEnvironment(config);
        auto tight = config.dangerMargin > 0.0 || config.obstacleMargin > 0.0 ? navigationEnvironment(config, 0.0, 0.0)
                                                                              : nullptr;
        auto space = std::make_shared<const NavigationTargetSpace>(model);

        ScenarioParts<NavigationModel> parts;
        parts.name = name;
        parts.description = description;
        parts.model = model;
        const double planTime = config.referencePlanTime;
        const double resolution = config.planResolution;
        const PlannerScale scale{config.plannerRange, config.plannerDdRadius};
        parts.referencePolicy = [model, robot, env, tight, space, planTime, resolution, scale](
                                    const RunSettings &settings, const pomdp::ParameterMap &params,
                                    std::uint64_t seed) -> std::unique_ptr<pomdp::ReferencePolicy<NavigationModel>>
        {
            auto heuristic = makeSamplingHeuristic<NavState, NavTarget>(settings, space);
            // the extension step and dynamic-domain radius in metres (the planner's defaults are for radians)
            auto planner = referencePlannerSettings(settings, params, planTime, resolution, seed, scale);
            const std::size_t macroLength = params.getCount("macro_length", 15);
            auto adapter = std::make_shared<const NavigationPlanningAdapter>(model, macroLength);
            auto policy = std::make_unique<pomdp::OmplReferencePolicy<NavigationModel, NavTarget>>(
                adapter, std::move(heuristic), robot, env, planner);
            // a particle inside a margin (not in the zone: that ends the episode) plans its way out with the
            // danger zones, walls and obstacles at their true size instead of failing with an invalid start
            policy->setTrueEnvironment(tight);
            return policy;
        };
        if (config.recoverFromObservation)
        {
            parts.recovery = []() -> std::unique_ptr<pomdp::DepletionRecovery<NavigationModel>>
            { return std::make_unique<NavigationRecovery>(); };
        }
        parts.world = [model]() -> std::unique_ptr<pomdp::World<NavigationModel>>
        { return std::make_unique<NavigationWorld>(model); };
        parts.points = [](const NavState &s, std::vector<Point3> &out) { out.push_back({{s.p[0], s.p[1], s.p[2]}}); };
        parts.pointLabels = {"robot"};
        parts.robotUrdf = folder + "/robot.urdf";
        parts.configuration = [dims = config.dims](const NavState &s, std::vector<double> &q)
        { q.insert(q.end(), s.p, s.p + dims); };
        parts.defaults = config.defaults;
        parts.solverDefaults = config.solverDefaults;
        parts.horizon = config.horizon;
        parts.defaultPlanSeconds = config.planSeconds;
        parts.config = config.json;
        parts.scene = navigationScene(config);
        return parts;
    }

    std::unique_ptr<Scenario> makeNavigationScenario(const std::string &name, const std::string &description,
                                                     const std::string &folder, const nlohmann::json &json)
    {
        return std::make_unique<ModelScenario<NavigationModel>>(navigationParts(name, description, folder, json));
    }

    std::size_t shortestGoalSteps(const NavigationModel &model, const NavState &start, bool avoidDanger)
    {
        const auto &c = model.config();
        const double step = c.stepLength;
        long lo[3] = {0, 0, 0}, size[3] = {1, 1, 1};
        for (int k = 0; k < c.dims; ++k)
        {
            lo[k] = static_cast<long>(std::ceil((c.bounds.lo[k] - start.p[k]) / step - 1e-9));
            const long hi = static_cast<long>(std::floor((c.bounds.hi[k] - start.p[k]) / step + 1e-9));
            size[k] = hi - lo[k] + 1;
        }
        const auto index = [&](const long *k)
        { return static_cast<std::size_t>(((k[2] - lo[2]) * size[1] + (k[1] - lo[1])) * size[0] + (k[0] - lo[0])); };
        std::vector<std::uint32_t> depth(static_cast<std::size_t>(size[0] * size[1] * size[2]), 0);
        std::deque<std::array<long, 3>> queue;
        queue.push_back({{0, 0, 0}});
        depth[index(queue.front().data())] = 1;
        while (!queue.empty())
        {
            const auto cur = queue.front();
            queue.pop_front();
            const std::uint32_t d = depth[index(cur.data())];
            for (int a = 0; a < 2 * c.dims; ++a)
            {
                auto next = cur;
                next[a / 2] += a % 2 == 0 ? 1 : -1;
                if (next[a / 2] < lo[a / 2] || next[a / 2] >= lo[a / 2] + size[a / 2])
                {
                    continue;
                }
                auto &nd = depth[index(next.data())];
                if (nd != 0)
                {
                    continue;
                }
                NavState s;
                for (int k = 0; k < 3; ++k)
                {
                    s.p[k] = start.p[k] + static_cast<double>(next[k]) * step;
                }
                nd = d + 1;
                if (model.blocked(s.p) || (avoidDanger && model.inDanger(s.p)))
                {
                    continue;
                }
                if (model.reachedGoal(s))
                {
                    return d;
                }
                queue.push_back(next);
            }
        }
        return 0;
    }
}  // namespace ropras::scenarios
