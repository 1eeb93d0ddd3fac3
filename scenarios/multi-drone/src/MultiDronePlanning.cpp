#include "ropras/scenarios/multi-drone/MultiDronePlanning.h"

#include <array>
#include <cmath>
#include <set>
#include <string>
#include <utility>

#include "ropras/core/Error.h"
#include "ropras/scenarios/ScenarioRegistry.h"

namespace ropras::scenarios
{
    namespace
    {
        constexpr const char *URDF_PATH = "multi-drone/drones.urdf";
        /// clearance between two drone goals beyond touching (m)
        constexpr double GOAL_CLEARANCE = 0.1;
        constexpr int PLACEMENT_DRAWS = 64;
    }  // namespace

    MultiDroneHeuristic::MultiDroneHeuristic(const MultiDroneConfig &config, Spread spread, double epsilon)
        : config_(config), spread_(spread), epsilon_(epsilon)
    {
        if (!(epsilon >= 0.0 && epsilon <= 1.0))
        {
            throw Error("multi-drone heuristic: epsilon = " + std::to_string(epsilon) + " is not in [0, 1]");
        }
    }

    MultiDroneHeuristic::Spread MultiDroneHeuristic::spreadFromName(const std::string &heuristic)
    {
        if (heuristic == "uniform")
        {
            return Spread::Uniform;
        }
        if (heuristic == "dynamic")
        {
            return Spread::Belief;
        }
        throw Error("multi-drone: unknown sampling heuristic \"" + heuristic + "\" (known: uniform, dynamic)");
    }

    std::string MultiDroneHeuristic::name() const
    {
        const std::string inner = spread_ == Spread::Uniform ? "chase+uniform-spread" : "chase+belief-spread";
        return epsilon_ > 0.0 ? "epsilon-greedy(" + inner + ")" : inner;
    }

    void MultiDroneHeuristic::uniformPoint(pomdp::Rng &rng, double *p) const
    {
        for (int k = 0; k < 3; ++k)
        {
            p[k] = rng.uniform(config_.lower[k], config_.upper[k]);
        }
    }

    bool MultiDroneHeuristic::place(std::size_t d, const double *p, std::size_t placedMask,
                                    const MultiDroneTarget &out) const
    {
        const double minDistance = 2.0 * config_.droneRadius + GOAL_CLEARANCE;
        for (std::size_t j = 0; j < MULTI_DRONE_COUNT; ++j)
        {
            if (j != d && (placedMask & (std::size_t{1} << j)) != 0 &&
                MultiDroneModel::squaredDistance(p, &out.q[3 * j]) < minDistance * minDistance)
            {
                return false;
            }
        }
        return true;
    }

    bool MultiDroneHeuristic::sample(const MultiDroneModel::State &agent,
                                     pomdp::BeliefView<MultiDroneModel::State> belief, pomdp::Rng &rng,
                                     MultiDroneTarget &out)
    {
        std::size_t mask = 0;
        double p[3];
        const auto setGoal = [&](std::size_t d, const double *q)
        {
            for (int k = 0; k < 3; ++k)
            {
                out.q[3 * d + static_cast<std::size_t>(k)] = q[k];
            }
            mask |= std::size_t{1} << d;
        };
        const bool explore = epsilon_ > 0.0 && rng.bernoulli(epsilon_);
        std::size_t chaser = MULTI_DRONE_COUNT;
        if (!explore)
        {
            const auto &particle = belief.empty() ? agent : belief[rng.uniformIndex(belief.size)];
            double best = 0.0;
            for (std::size_t d = 0; d < MULTI_DRONE_COUNT; ++d)
            {
                const double d2 = MultiDroneModel::squaredDistance(agent.drone[d], particle.target);
                if (chaser == MULTI_DRONE_COUNT || d2 < best)
                {
                    best = d2;
                    chaser = d;
                }
            }
            setGoal(chaser, particle.target);
        }
        out.chaser = chaser;
        for (std::size_t d = 0; d < MULTI_DRONE_COUNT; ++d)
        {
            if (d == chaser)
            {
                continue;
            }
            bool placed = false;
            for (int draw = 0; draw < PLACEMENT_DRAWS && !placed; ++draw)
            {
                const bool fromBelief =
                    !explore && spread_ == Spread::Belief && !belief.empty() && draw < PLACEMENT_DRAWS / 2;
                if (fromBelief)
                {
                    const auto &other = belief[rng.uniformIndex(belief.size)];
                    for (int k = 0; k < 3; ++k)
                    {
                        p[k] = other.target[k];
                    }
                }
                else
                {
                    uniformPoint(rng, p);
                }
                if (place(d, p, mask, out))
                {
                    setGoal(d, p);
                    placed = true;
                }
            }
            if (!placed)
            {
                return false;
            }
        }
        return true;
    }

    MultiDronePlanningAdapter::MultiDronePlanningAdapter(double stepSize, std::size_t macroLength, double chaseShare)
        : step_(stepSize), macroLength_(macroLength), chaseShare_(chaseShare)
    {
        if (!(chaseShare > 0.0 && chaseShare <= 1.0))
        {
            throw Error("multi-drone: parameter chase_share = " + std::to_string(chaseShare) + " is not in (0, 1]");
        }
        if (!(stepSize > 0.0) || !std::isfinite(stepSize))
        {
            throw Error("multi-drone: step size " + std::to_string(stepSize) + " must be > 0");
        }
        if (macroLength == 0)
        {
            throw Error("multi-drone: parameter macro_length must be >= 1");
        }
    }

    void MultiDronePlanningAdapter::configuration(const MultiDroneModel::State &state, double *q) const
    {
        for (std::size_t d = 0; d < MULTI_DRONE_COUNT; ++d)
        {
            for (std::size_t k = 0; k < 3; ++k)
            {
                q[3 * d + k] = state.drone[d][k];
            }
        }
    }

    bool MultiDronePlanningAdapter::targetConfiguration(const MultiDroneModel::State &, const MultiDroneTarget &target,
                                                        double *q) const
    {
        chaser_ = target.chaser;
        for (std::size_t i = 0; i < target.q.size(); ++i)
        {
            if (!std::isfinite(target.q[i]))
            {
                return false;
            }
            q[i] = target.q[i];
        }
        return true;
    }

    bool MultiDronePlanningAdapter::pathToMacroAction(const MultiDroneModel::State &start, const double *waypoints,
                                                      std::size_t count,
                                                      std::vector<MultiDroneModel::Action> &out) const
    {
        constexpr std::size_t DOF = 3 * MULTI_DRONE_COUNT;
        std::vector<double> points;
        const std::size_t n = pomdp::discretizeJointPath(waypoints, count, DOF, step_, 0, points);
        // Each drone's staircase along its part of the points.
        std::array<std::vector<MultiDroneModel::Action>, MULTI_DRONE_COUNT> moves;
        const double half = 0.5 * step_;
        for (std::size_t d = 0; d < MULTI_DRONE_COUNT; ++d)
        {
            double current[3] = {start.drone[d][0], start.drone[d][1], start.drone[d][2]};
            for (std::size_t i = 0; i < n; ++i)
            {
                const double *point = &points[i * DOF + 3 * d];
                for (;;)
                {
                    std::size_t axis = 0;
                    double largest = -1.0;
                    for (std::size_t k = 0; k < 3; ++k)
                    {
                        const double diff = std::abs(point[k] - current[k]);
                        if (diff > largest)
                        {
                            largest = diff;
                            axis = k;
                        }
                    }
                    if (!(largest > half))
                    {
                        break;
                    }
                    const bool negative = point[axis] < current[axis];
                    moves[d].push_back(static_cast<MultiDroneModel::Action>(6 * d + 2 * axis + (negative ? 1 : 0)));
                    current[axis] += negative ? -step_ : step_;
                }
            }
        }
        // Interleave: the chaser takes its share, the others take turns.
        std::array<std::size_t, MULTI_DRONE_COUNT> next{};
        const std::size_t chaser = chaser_;
        std::size_t emitted = 0, chased = 0, turn = 0;
        while (emitted < macroLength_)
        {
            const bool chaserHas = chaser < MULTI_DRONE_COUNT && next[chaser] < moves[chaser].size();
            std::size_t other = MULTI_DRONE_COUNT;
            for (std::size_t j = 0; j < MULTI_DRONE_COUNT; ++j)
            {
                const std::size_t d = (turn + j) % MULTI_DRONE_COUNT;
                if (d != chaser && next[d] < moves[d].size())
                {
                    other = d;
                    break;
                }
            }
            if (!chaserHas && other == MULTI_DRONE_COUNT)
            {
                break;
            }
            const bool takeChaser =
                chaserHas && (other == MULTI_DRONE_COUNT ||
                              static_cast<double>(chased) < chaseShare_ * static_cast<double>(emitted + 1));
            const std::size_t d = takeChaser ? chaser : other;
            out.push_back(moves[d][next[d]++]);
            ++emitted;
            if (takeChaser)
            {
                ++chased;
            }
            else
            {
                turn = d + 1;
            }
        }
        return emitted > 0;
    }

    std::shared_ptr<const ompl_ext::RobotModel> loadMultiDroneRobot(const MultiDroneConfig &config)
    {
        auto robot = ompl_ext::RobotModel::fromUrdfString(embeddedFile(URDF_PATH), ".", URDF_PATH);
        const std::string where = std::string("multi-drone: ") + URDF_PATH;
        if (robot->dof() != 3 * MULTI_DRONE_COUNT)
        {
            throw Error(where + " has " + std::to_string(robot->dof()) + " planning joints, expected " +
                        std::to_string(3 * MULTI_DRONE_COUNT));
        }
        const char *axes = "xyz";
        for (std::size_t d = 0; d < MULTI_DRONE_COUNT; ++d)
        {
            for (std::size_t k = 0; k < 3; ++k)
            {
                const auto &joint = robot->joints()[3 * d + k];
                const std::string expected = "drone" + std::to_string(d + 1) + "_" + axes[k];
                if (joint.name != expected)
                {
                    throw Error(where + ": planning joint " + std::to_string(3 * d + k) + " is \"" + joint.name +
                                "\", expected \"" + expected + "\"");
                }
                if (std::abs(joint.lower - config.lower[k]) > 1e-9 || std::abs(joint.upper - config.upper[k]) > 1e-9)
                {
                    throw Error(where + ": joint " + joint.name + " limits [" + std::to_string(joint.lower) + ", " +
                                std::to_string(joint.upper) + "] differ from the configuration key \"bounds\" [" +
                                std::to_string(config.lower[k]) + ", " + std::to_string(config.upper[k]) +
                                "] (the shipped robot fixes the box)");
                }
            }
        }
        if (robot->spheres().size() != MULTI_DRONE_COUNT || robot->collisionLinks().size() != MULTI_DRONE_COUNT)
        {
            throw Error(where + ": expected one collision sphere per drone, found " +
                        std::to_string(robot->spheres().size()) + " spheres on " +
                        std::to_string(robot->collisionLinks().size()) + " links");
        }
        for (const auto &sphere : robot->spheres())
        {
            if (std::abs(sphere.radius - config.droneRadius) > 1e-9)
            {
                throw Error(where + ": sphere radius " + std::to_string(sphere.radius) +
                            " differs from the configuration key \"drone_radius\" = " +
                            std::to_string(config.droneRadius) + " (the shipped robot fixes it)");
            }
        }
        std::set<std::pair<int, int>> pairs(robot->selfCollisionPairs().begin(), robot->selfCollisionPairs().end());
        for (int i = 0; i < static_cast<int>(MULTI_DRONE_COUNT); ++i)
        {
            for (int j = i + 1; j < static_cast<int>(MULTI_DRONE_COUNT); ++j)
            {
                if (pairs.count({i, j}) == 0)
                {
                    throw Error(where + ": drones " + robot->collisionLinks()[static_cast<std::size_t>(i)].name +
                                " and " + robot->collisionLinks()[static_cast<std::size_t>(j)].name +
                                " are not a self-collision pair");
                }
            }
        }
        return robot;
    }
}  // namespace ropras::scenarios
