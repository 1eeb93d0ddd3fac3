// A small continuous toy POMDP for the OMPL reference policy: a disc robot in the unit square (URDF with
// two prismatic joints and one sphere), a wall with two gaps, one of which a door blocks (hidden), a
// sensing spot where the door's side can be heard.
#ifndef ROPRAS_TEST_POMDP_POINT_ROBOT_MODEL_H
#define ROPRAS_TEST_POMDP_POINT_ROBOT_MODEL_H

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <memory>
#include <string>
#include <vector>

#include "ropras/core/Error.h"
#include "ropras/ompl_ext/model/RobotModel.h"
#include "ropras/ompl_ext/scene/Environment.h"
#include "ropras/pomdp/Model.h"
#include "ropras/pomdp/OmplReferencePolicy.h"
#include "ropras/pomdp/SolverFactory.h"
#include "ropras/pomdp/TargetSpace.h"

namespace ropras::pomdp::test
{
    /// motion-check resolution for the toy robot (the default 1/32 is about its radius)
    constexpr double POINT_RESOLUTION = 0.005;

    struct Point2
    {
        double x{0.0}, y{0.0};
    };

    /** \brief Disc robot (radius 0.03) in [0, 1]^2. A wall at x = 0.5 spans y in [0.25, 0.75]; the door (a box
        of the same width) blocks the bottom gap (door = 0) or the top gap (door = 1), uniformly at first.
        Actions are displacements of length <= STEP; motion is deterministic and clamped to the square.
        Reward: -1 per step, +100 and terminal within GOAL_RADIUS of the goal, -100 and terminal on a
        collision (checked analytically along the motion). Observation: within SENSE_RADIUS of the sensing
        spot, the door's side with probability 0.9; elsewhere 2 ("nothing"). */
    struct PointRobotModel
    {
        struct State
        {
            double x{0.15}, y{0.5};
            std::uint8_t door{0};
        };
        struct Action
        {
            double dx{0.0}, dy{0.0};
        };
        using Observation = std::uint8_t;

        static constexpr double RADIUS = 0.03;
        static constexpr double STEP = 0.05;
        static constexpr double GOAL_RADIUS = 0.06;
        static constexpr double SENSE_RADIUS = 0.08;
        static constexpr double WALL_X = 0.5, WALL_HALF_WIDTH = 0.03;
        static constexpr Point2 START{0.15, 0.5};
        static constexpr Point2 GOAL{0.85, 0.5};
        static constexpr Point2 SENSE{0.15, 0.2};

        /// door box centre y for \a door (0: bottom gap blocked, 1: top gap blocked)
        static double doorY(std::uint8_t door) { return door == 0 ? 0.125 : 0.875; }

        /// exact: does the disc at (x, y) touch the wall, the door of \a door, or leave the square?
        static bool collides(double x, double y, std::uint8_t door) noexcept
        {
            const auto boxDistance = [&](double cy, double hy)
            {
                const double ex = std::max(0.0, std::abs(x - WALL_X) - WALL_HALF_WIDTH);
                const double ey = std::max(0.0, std::abs(y - cy) - hy);
                return std::sqrt(ex * ex + ey * ey);
            };
            return boxDistance(0.5, 0.25) < RADIUS || boxDistance(doorY(door), 0.125) < RADIUS;
        }

        StepResult<State, Observation> step(const State &s, const Action &a, Rng &rng) const noexcept
        {
            StepResult<State, Observation> out;
            double dx = a.dx, dy = a.dy;
            const double length = std::sqrt(dx * dx + dy * dy);
            if (!(length <= STEP))
            {
                const double scale = std::isfinite(length) && length > 0.0 ? STEP / length : 0.0;
                dx *= scale;
                dy *= scale;
            }
            out.next = s;
            out.next.x = std::clamp(s.x + dx, 0.0, 1.0);
            out.next.y = std::clamp(s.y + dy, 0.0, 1.0);
            out.reward = -1.0;
            constexpr int SUB = 8;
            for (int k = 1; k <= SUB; ++k)
            {
                const double t = static_cast<double>(k) / SUB;
                if (collides(s.x + t * (out.next.x - s.x), s.y + t * (out.next.y - s.y), s.door))
                {
                    out.reward = -100.0;
                    out.terminal = true;
                    out.observation = 2;
                    return out;
                }
            }
            if (std::hypot(out.next.x - GOAL.x, out.next.y - GOAL.y) <= GOAL_RADIUS)
            {
                out.reward = 100.0;
                out.terminal = true;
            }
            if (std::hypot(out.next.x - SENSE.x, out.next.y - SENSE.y) <= SENSE_RADIUS)
                out.observation = rng.bernoulli(0.9) ? s.door : static_cast<Observation>(1 - s.door);
            else
                out.observation = 2;
            return out;
        }

        double observationProbability(Observation o, const State &next, const Action &) const noexcept
        {
            if (std::hypot(next.x - SENSE.x, next.y - SENSE.y) <= SENSE_RADIUS)
                return o == 2 ? 0.0 : (o == next.door ? 0.9 : 0.1);
            return o == 2 ? 1.0 : 0.0;
        }

        State sampleInitialState(Rng &rng) const noexcept
        {
            State s;
            s.x = START.x;
            s.y = START.y;
            s.door = static_cast<std::uint8_t>(rng.uniformIndex(2));
            return s;
        }

        double discount() const noexcept { return 0.98; }
        std::size_t numActions() const noexcept { return 8; }
        Action action(std::size_t i) const noexcept
        {
            const double angle = 0.7853981633974483 * static_cast<double>(i);
            return Action{STEP * std::cos(angle), STEP * std::sin(angle)};
        }
    };

    /** \brief Radius of the planning sphere: the disc padded by the motion-check resolution. A motion the
        checker validates at samples POINT_RESOLUTION apart (max-norm, so at most POINT_RESOLUTION * sqrt(2) / 2
        from any point of the segment) is then collision-free everywhere for the true disc, as PointRobotModel's
        exact check sees it; without the pad a path may graze an obstacle between two samples. */
    constexpr double PLANNING_RADIUS = PointRobotModel::RADIUS + POINT_RESOLUTION;

    /** \brief The robot of PointRobotModel as URDF: joints x, y (prismatic, [0, 1]) and one sphere of
        \a radius (the planning radius by default, PointRobotModel::RADIUS for the exact disc). */
    inline std::shared_ptr<const ompl_ext::RobotModel> pointRobot(double radius = PLANNING_RADIUS)
    {
        const std::string urdf = R"(<robot name="point2d">
  <link name="world"/>
  <link name="slider"/>
  <link name="body"><collision><geometry><sphere radius=")" +
                                 std::to_string(radius) + R"("/></geometry></collision></link>
  <joint name="x" type="prismatic"><parent link="world"/><child link="slider"/><axis xyz="1 0 0"/>
    <limit lower="0" upper="1" effort="1" velocity="1"/></joint>
  <joint name="y" type="prismatic"><parent link="slider"/><child link="body"/><axis xyz="0 1 0"/>
    <limit lower="0" upper="1" effort="1" velocity="1"/></joint>
</robot>)";
        return ompl_ext::RobotModel::fromUrdfString(urdf, ".", "point2d.urdf");
    }

    /** \brief The obstacles: "wall" and "door" (at the bottom gap; particles move it). */
    inline std::shared_ptr<const ompl_ext::Environment> pointEnvironment()
    {
        auto env = std::make_shared<ompl_ext::Environment>();
        env->addBox("wall", Eigen::Isometry3d(Eigen::Translation3d(0.5, 0.5, 0.0)), Eigen::Vector3d(0.06, 0.5, 0.2));
        env->addBox("door", Eigen::Isometry3d(Eigen::Translation3d(0.5, PointRobotModel::doorY(0), 0.0)),
                    Eigen::Vector3d(0.06, 0.25, 0.2));
        return env;
    }

    /** \brief Targets: the goal, the sensing spot (informative), uniform free points. */
    class PointTargetSpace final : public TargetSpace<PointRobotModel::State, Point2>
    {
    public:
        Point2 goal(const PointRobotModel::State &) const override { return PointRobotModel::GOAL; }
        std::size_t numInformative(const PointRobotModel::State &) const override { return 1; }
        Point2 informative(const PointRobotModel::State &, std::size_t) const override
        {
            return PointRobotModel::SENSE;
        }
        double distance(const PointRobotModel::State &a, const Point2 &t) const override
        {
            return std::hypot(a.x - t.x, a.y - t.y);
        }
        std::uint64_t entropyBin(const PointRobotModel::State &p) const override { return p.door; }
        std::size_t numEntropyBins() const override { return 2; }
        bool sampleFree(Rng &rng, Point2 &out) const override
        {
            out = Point2{rng.uniform01(), rng.uniform01()};
            return true;
        }
    };

    /** \brief The OMPL adapter: configuration = (x, y); the particle's door moves the "door" object;
        PathToMacroAction = displacements between points STEP apart along the path, at most maxLength. */
    class PointPlanningAdapter final
        : public OmplPlanningAdapter<PointRobotModel::State, PointRobotModel::Action, Point2>
    {
    public:
        explicit PointPlanningAdapter(std::size_t maxLength = 40) : maxLength_(maxLength) {}

        void configuration(const PointRobotModel::State &s, double *q) const override
        {
            q[0] = s.x;
            q[1] = s.y;
        }
        bool targetConfiguration(const PointRobotModel::State &, const Point2 &t, double *q) const override
        {
            q[0] = t.x;
            q[1] = t.y;
            return std::isfinite(t.x) && std::isfinite(t.y);
        }
        bool pathToMacroAction(const PointRobotModel::State &start, const double *waypoints, std::size_t count,
                               std::vector<PointRobotModel::Action> &out) const override
        {
            std::vector<double> points;
            const std::size_t n = discretizeJointPath(waypoints, count, 2, PointRobotModel::STEP, maxLength_, points);
            double x = start.x, y = start.y;
            for (std::size_t i = 0; i < n; ++i)
            {
                out.push_back(PointRobotModel::Action{points[2 * i] - x, points[2 * i + 1] - y});
                x = points[2 * i];
                y = points[2 * i + 1];
            }
            return n > 0;
        }
        bool poseObstacles(const PointRobotModel::State &particle, ompl_ext::Environment &working) const override
        {
            working.setObjectPose(
                "door", Eigen::Isometry3d(Eigen::Translation3d(0.5, PointRobotModel::doorY(particle.door), 0.0)));
            return true;
        }

    private:
        std::size_t maxLength_;
    };

    /** \brief ModelComponents for the runner: the OMPL reference policy with \a planner; parameters
        heuristic (0 uniform, 1 dynamic), epsilon, plan_time, plan_iterations, shortcut, planner_seed. */
    inline ModelComponents<PointRobotModel> pointComponents(const std::string &planner = "VectorizedRRTConnect")
    {
        ModelComponents<PointRobotModel> c;
        c.model = std::make_shared<const PointRobotModel>();
        auto robot = pointRobot();
        auto env = pointEnvironment();
        auto space = std::make_shared<const PointTargetSpace>();
        auto adapter = std::make_shared<const PointPlanningAdapter>();
        c.referencePolicy = [=](const ParameterMap &p) -> std::unique_ptr<ReferencePolicy<PointRobotModel>>
        {
            std::unique_ptr<SamplingHeuristic<PointRobotModel::State, Point2>> h;
            const std::size_t kind = p.getCount("heuristic", 1);
            if (kind > 1)
                throw Error("point2d: parameter heuristic = " + std::to_string(kind) +
                            " is unknown (0 = uniform, 1 = dynamic)");
            if (kind == 0)
                h = std::make_unique<UniformHeuristic<PointRobotModel::State, Point2>>(space);
            else
                h = std::make_unique<DynamicHeuristic<PointRobotModel::State, Point2>>(space);
            const double epsilon = p.get("epsilon", 0.0);
            if (epsilon > 0.0)
                h = std::make_unique<EpsilonGreedyHeuristic<PointRobotModel::State, Point2>>(space, std::move(h),
                                                                                             epsilon);
            OmplPathPlannerSettings settings;
            settings.planner = planner;
            settings.resolution = POINT_RESOLUTION;
            settings.readParameters(p);
            const std::size_t seed = p.getCount("planner_seed", 0);
            if (seed != 0)
                settings.plannerParams["seed"] = std::to_string(seed);
            return std::make_unique<OmplReferencePolicy<PointRobotModel, Point2>>(adapter, std::move(h), robot, env,
                                                                                  settings);
        };
        c.defaults = {{"depth", 3}, {"rollout_steps", 0}};
        return c;
    }
}  // namespace ropras::pomdp::test

#endif
