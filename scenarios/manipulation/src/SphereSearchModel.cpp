#include "ropras/scenarios/manipulation/SphereSearchModel.h"

#include <algorithm>
#include <cmath>
#include <set>
#include <string>
#include <utility>

#include "ropras/core/Error.h"
#include "ropras/scenarios/ConfigReader.h"
#include "ropras/scenarios/manipulation/ArmStartKeys.h"

namespace ropras::scenarios
{
    namespace
    {
        constexpr double PI = 3.14159265358979323846;

        std::array<double, 3> point3(const std::vector<double> &v)
        {
            return {{v[0], v[1], v[2]}};
        }

        std::uint64_t mix(std::uint64_t h, std::int64_t v) noexcept
        {
            h ^= static_cast<std::uint64_t>(v) + 0x9e3779b97f4a7c15ULL + (h << 6) + (h >> 2);
            h *= 0xbf58476d1ce4e5b9ULL;
            return h ^ (h >> 31);
        }
    }  // namespace

    SphereSearchConfig SphereSearchConfig::fromJson(const nlohmann::json &json, const std::string &scenario)
    {
        const ConfigReader r(scenario, json);
        r.requireKnown({"start",
                        "end_effector",
                        "goals",
                        "goal_radius",
                        "light_center",
                        "light_radius",
                        "obstacles",
                        "step",
                        "action_mode",
                        "transition_sigma",
                        "observation_sigma",
                        "initial_sigma",
                        "reinvigorate_sigma",
                        "step_reward",
                        "goal_reward",
                        "fail_reward",
                        "collision_terminal",
                        "discount",
                        "horizon",
                        "resolution",
                        "observation_joint_bin",
                        "heuristic_value",
                        "heuristic_ee_step",
                        "planning",
                        "defaults"});
        SphereSearchConfig c;
        c.json = json;
        readArmStartKeys(r, c.start, c.endEffector);
        const auto goals = r.rows("goals", 3);
        if (goals.size() != 2)
        {
            r.fail("goals", "must list exactly 2 candidate goal centres [x, y, z], not " + r.at("goals").dump());
        }
        c.goals = {{point3(goals[0]), point3(goals[1])}};
        c.goalRadius = r.positive("goal_radius");
        c.light = point3(r.numbers("light_center", 3));
        c.lightRadius = r.positive("light_radius");
        for (const auto &row : r.rows("obstacles", 4))
        {
            if (!(row[3] > 0.0))
            {
                r.fail("obstacles", "has a sphere with radius " + std::to_string(row[3]) + " (must be > 0)");
            }
            c.obstacles.push_back({{row[0], row[1], row[2], row[3]}});
        }
        c.step = r.positive("step");
        const std::string mode = r.choice("action_mode", {"delta", "waypoint"});
        c.waypointActions = mode == "waypoint";
        c.transitionSigma = r.nonNegative("transition_sigma");
        c.observationSigma = r.positive("observation_sigma");
        c.initialSigma = r.nonNegative("initial_sigma");
        c.reinvigorateSigma = r.nonNegative("reinvigorate_sigma");
        c.stepReward = r.number("step_reward");
        c.goalReward = r.number("goal_reward");
        c.failReward = r.number("fail_reward");
        c.collisionTerminal = r.boolean("collision_terminal");
        c.discount = r.within("discount", 1e-9, 1.0);
        c.horizon = r.count("horizon", 1, 10000000);
        c.resolution = r.positive("resolution");
        c.observationJointBin = r.nonNegative("observation_joint_bin");
        c.heuristicValue = r.boolean("heuristic_value");
        c.heuristicEndEffectorStep = r.positive("heuristic_ee_step");
        const ConfigReader p = r.sub("planning");
        p.requireKnown({"plan_seconds", "reference_plan_time", "margin", "planner_range", "ik_restarts", "ik_points",
                        "ik_radius_fraction", "ik_choice"});
        c.planSeconds = p.positive("plan_seconds");
        c.referencePlanTime = p.positive("reference_plan_time");
        c.planningMargin = p.nonNegative("margin");
        c.plannerRange = p.positive("planner_range");
        c.ikRestarts = p.count("ik_restarts", 0, 10000);
        c.ikPoints = p.count("ik_points", 1, 1000);
        c.ikRadiusFraction = p.within("ik_radius_fraction", 0.0, 1.0);
        c.ikNearest = p.choice("ik_choice", {"nearest", "uniform"}) == "nearest";
        const ConfigReader d = r.sub("defaults");
        for (const auto &item : r.at("defaults").items())
        {
            c.defaults[item.key()] = d.number(item.key());
        }
        if (c.step > 2.0 * PI)
        {
            r.fail("step", "= " + std::to_string(c.step) + " rad is larger than a full turn");
        }
        return c;
    }

    std::shared_ptr<const ompl_ext::Environment> sphereSearchEnvironment(const SphereSearchConfig &config,
                                                                         double margin)
    {
        auto env = std::make_shared<ompl_ext::Environment>();
        for (std::size_t i = 0; i < config.obstacles.size(); ++i)
        {
            const auto &o = config.obstacles[i];
            env->addSphere("obstacle" + std::to_string(i), Eigen::Vector3d(o[0], o[1], o[2]), o[3] + margin);
        }
        return env;
    }

    SphereSearchModel::SphereSearchModel(const SphereSearchConfig &config, std::shared_ptr<const PandaArm> arm)
        : config_(config), arm_(std::move(arm))
    {
        if (!arm_)
        {
            throw Error("SphereSearchModel: null arm");
        }
        environment_ = sphereSearchEnvironment(config_, 0.0);
        const auto where = [](const std::string &key) { return "scenario sphere-search: key \"" + key + "\" "; };
        arm_->requireWithinLimits(config_.start.data(), where("start"));
        if (!arm_->checker()->isValid(*environment_, config_.start.data()))
        {
            throw Error(where("start") + "is in collision (with an obstacle or itself)");
        }
        const auto inside = [&](const std::array<double, 3> &p)
        {
            for (const auto &o : config_.obstacles)
            {
                if (std::hypot(p[0] - o[0], p[1] - o[1], p[2] - o[2]) < o[3])
                {
                    return true;
                }
            }
            return false;
        };
        if (inside(config_.goals[0]) || inside(config_.goals[1]))
        {
            throw Error(where("goals") + "has a goal centre inside an obstacle");
        }
        if (inside(config_.light))
        {
            throw Error(where("light_center") + "is inside an obstacle");
        }
        const double s = config_.observationSigma;
        logNorm_ = -static_cast<double>(ARM_DOF) * std::log(std::sqrt(2.0 * PI) * s);
    }

    void SphereSearchModel::finishStep(pomdp::StepResult<State, Observation> &out, bool collided,
                                       pomdp::Rng &rng) const noexcept
    {
        out.reward = config_.stepReward;
        if (collided && config_.collisionTerminal)
        {
            out.reward += config_.failReward;
            out.terminal = true;
        }
        else if (reachedGoal(out.next))
        {
            out.reward += config_.goalReward;
            out.terminal = true;
        }
        for (std::size_t j = 0; j < ARM_DOF; ++j)
        {
            out.observation.q[j] = out.next.q[j] + config_.observationSigma * rng.normal();
        }
        const bool lit = inLight(out.next);
        out.next.seen = out.next.seen || lit;
        out.observation.goal = lit ? out.next.goal : -1;
    }

    bool SphereSearchModel::inLight(const State &s) const noexcept
    {
        const Eigen::Vector3d p = endEffector(s);
        const auto &c = config_.light;
        return (p - Eigen::Vector3d(c[0], c[1], c[2])).squaredNorm() <= config_.lightRadius * config_.lightRadius;
    }

    bool SphereSearchModel::reachedGoal(const State &s) const noexcept
    {
        const Eigen::Vector3d p = endEffector(s);
        const auto &c = goalCenter(s.goal);
        return (p - Eigen::Vector3d(c[0], c[1], c[2])).squaredNorm() <= config_.goalRadius * config_.goalRadius;
    }

    double SphereSearchModel::observationProbability(const Observation &o, const State &next,
                                                     const Action &) const noexcept
    {
        const int expected = inLight(next) ? next.goal : -1;
        if (o.goal != expected)
        {
            return 0.0;
        }
        double q = 0.0;
        for (std::size_t j = 0; j < ARM_DOF; ++j)
        {
            const double d = (o.q[j] - next.q[j]) / config_.observationSigma;
            q += d * d;
        }
        return std::exp(logNorm_ - 0.5 * q);
    }

    SphereSearchModel::State SphereSearchModel::sampleInitialState(pomdp::Rng &rng) const noexcept
    {
        State s;
        s.goal = rng.bernoulli(0.5) ? 1 : 0;
        // redrawn while in collision (the validated start is the fallback)
        for (int attempt = 0; attempt < 100; ++attempt)
        {
            for (std::size_t j = 0; j < ARM_DOF; ++j)
            {
                s.q[j] = config_.start[j] + config_.initialSigma * rng.normal();
            }
            arm_->clamp(s.q);
            if (arm_->checker()->isValid(*environment_, s.q))
            {
                return s;
            }
        }
        setJoints(s, config_.start.data());
        return s;
    }

    SphereSearchModel::Action SphereSearchModel::action(std::size_t i) const noexcept
    {
        Action a;
        i %= 2 * ARM_DOF;
        a.dq[i / 2] = (i % 2 == 0 ? 1.0 : -1.0) * config_.step;
        return a;
    }

    std::uint64_t SphereSearchModel::observationKey(const Observation &o) const noexcept
    {
        std::uint64_t key = static_cast<std::uint64_t>(o.goal + 1);
        if (config_.observationJointBin > 0.0)
        {
            std::uint64_t h = 0x9e3779b97f4a7c15ULL;
            for (std::size_t j = 0; j < ARM_DOF; ++j)
            {
                const double cell = std::floor(o.q[j] / config_.observationJointBin);
                h = mix(h,
                        static_cast<std::int64_t>(std::isfinite(cell) ? std::fmax(-1e15, std::fmin(1e15, cell)) : 0.0));
            }
            key = (h << 2) | key;
        }
        return key;
    }

    void SphereSearchModel::reinvigorate(State &s, pomdp::Rng &rng) const noexcept
    {
        if (!s.seen)
        {
            s.goal = rng.bernoulli(0.5) ? 1 : 0;
        }
        if (config_.reinvigorateSigma <= 0.0)
        {
            return;
        }
        double q[ARM_DOF];
        for (std::size_t j = 0; j < ARM_DOF; ++j)
        {
            q[j] = s.q[j] + config_.reinvigorateSigma * rng.normal();
        }
        arm_->clamp(q);
        if (arm_->checker()->isValid(*environment_, q))
        {
            setJoints(s, q);
        }
    }

    double SphereSearchModel::heuristicValue(const State &s) const noexcept
    {
        if (!config_.heuristicValue)
        {
            return 0.0;
        }
        const Eigen::Vector3d p = endEffector(s);
        const auto &c = goalCenter(s.goal);
        const double gap = std::max(0.0, (p - Eigen::Vector3d(c[0], c[1], c[2])).norm() - config_.goalRadius);
        const double d = std::ceil(gap / config_.heuristicEndEffectorStep);
        const double g = config_.discount;
        const double gd = std::pow(g, d);
        const double steps = g < 1.0 ? (1.0 - gd) / (1.0 - g) : d;
        return config_.goalReward * gd + config_.stepReward * steps;
    }
}  // namespace ropras::scenarios
