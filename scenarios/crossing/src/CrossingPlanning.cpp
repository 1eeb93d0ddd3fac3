#include "ropras/scenarios/crossing/CrossingPlanning.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <string>

#include "ropras/core/Error.h"
#include "ropras/scenarios/ScenarioRegistry.h"

namespace ropras::scenarios
{
    namespace
    {
        constexpr const char *URDF_PATH = "robots/stretch/stretch.urdf";
        constexpr double ENTROPY_CELL = 0.2;  ///< m, the pedestrian cells of the belief entropy
        constexpr double PI = 3.14159265358979323846;

        /// a polyline in (x, y) with cumulative arc lengths
        struct Polyline
        {
            std::vector<std::array<double, 2>> points;
            std::vector<double> length;  ///< length[i] = arc length at points[i]

            double total() const { return length.back(); }

            /// arc length of the point of the polyline closest to (x, y)
            double project(double x, double y) const
            {
                double best = std::numeric_limits<double>::infinity(), at = 0.0;
                for (std::size_t i = 0; i + 1 < points.size(); ++i)
                {
                    const double ax = points[i][0], ay = points[i][1];
                    const double dx = points[i + 1][0] - ax, dy = points[i + 1][1] - ay;
                    const double l2 = dx * dx + dy * dy;
                    const double u = l2 > 0.0 ? std::clamp(((x - ax) * dx + (y - ay) * dy) / l2, 0.0, 1.0) : 0.0;
                    const double ex = ax + u * dx - x, ey = ay + u * dy - y;
                    const double d2 = ex * ex + ey * ey;
                    if (d2 < best)
                    {
                        best = d2;
                        at = length[i] + u * (length[i + 1] - length[i]);
                    }
                }
                return at;
            }

            std::array<double, 2> pointAt(double s) const
            {
                for (std::size_t i = 0; i + 1 < points.size(); ++i)
                {
                    if (s <= length[i + 1])
                    {
                        const double l = length[i + 1] - length[i];
                        const double u = l > 0.0 ? (s - length[i]) / l : 0.0;
                        return {points[i][0] + u * (points[i + 1][0] - points[i][0]),
                                points[i][1] + u * (points[i + 1][1] - points[i][1])};
                    }
                }
                return points.back();
            }
        };

        /// the length of the planner's pedestrian capsule (0: a sphere)
        double sweepLength(const CrossingConfig &c)
        {
            return c.planning.pedestrianSweep * std::hypot(c.pedestrianStep[0], c.pedestrianStep[1]);
        }
    }  // namespace

    Eigen::Isometry3d crossingPedestrianPose(const CrossingConfig &c, double px, double py)
    {
        Eigen::Isometry3d pose = Eigen::Isometry3d::Identity();
        pose.translation() = Eigen::Vector3d(px, py, c.pedestrianHeight);
        const double length = sweepLength(c);
        if (length > 0.0)
        {
            // the capsule's axis (local z) along the walking direction, from now to pedestrian_sweep steps ahead
            const Eigen::Vector3d dir = Eigen::Vector3d(c.pedestrianStep[0], c.pedestrianStep[1], 0.0).normalized();
            pose.linear() = Eigen::Quaterniond::FromTwoVectors(Eigen::Vector3d::UnitZ(), dir).toRotationMatrix();
            pose.translation() += 0.5 * length * dir;
        }
        return pose;
    }

    CrossingTargetSpace::CrossingTargetSpace(const CrossingConfig &config)
    {
        goal_ = {config.goal[0], config.goal[1], config.targetYaw};
        for (const auto &l : config.landmarks)
        {
            informative_.push_back({l[0], l[1], config.targetYaw});
        }
        lo_ = config.labLo;
        for (std::size_t k = 0; k < 2; ++k)
        {
            bins_[k] = static_cast<std::size_t>(std::ceil((config.labHi[k] - config.labLo[k]) / ENTROPY_CELL));
        }
    }

    double CrossingTargetSpace::distance(const CrossingState &a, const CrossingTarget &t) const
    {
        return std::hypot(a.x - t[0], a.y - t[1]);
    }

    std::uint64_t CrossingTargetSpace::entropyBin(const CrossingState &p) const
    {
        const auto cell = [&](double v, std::size_t k)
        {
            const double f = std::floor((v - lo_[k]) / ENTROPY_CELL);
            return static_cast<std::uint64_t>(std::clamp(f, 0.0, static_cast<double>(bins_[k] - 1)));
        };
        return cell(p.py, 1) * bins_[0] + cell(p.px, 0);
    }

    CrossingPlanningAdapter::CrossingPlanningAdapter(std::shared_ptr<const CrossingModel> model,
                                                     std::size_t macroLength, int pedestrian)
        : model_(std::move(model)), macroLength_(macroLength), pedestrian_(pedestrian)
    {
        if (!model_)
        {
            throw Error("CrossingPlanningAdapter: null model");
        }
        if (macroLength_ == 0)
        {
            throw Error("scenario " + model_->config().scenario + ": parameter macro_length must be >= 1");
        }
    }

    void CrossingPlanningAdapter::configuration(const CrossingState &state, double *q) const
    {
        q[0] = state.x;
        q[1] = state.y;
        q[2] = CrossingModel::wrapAngle(state.theta);
    }

    bool CrossingPlanningAdapter::targetConfiguration(const CrossingState &, const CrossingTarget &target,
                                                      double *q) const
    {
        for (std::size_t k = 0; k < 3; ++k)
        {
            if (!std::isfinite(target[k]))
            {
                return false;
            }
            q[k] = target[k];
        }
        q[2] = CrossingModel::wrapAngle(q[2]);
        return true;
    }

    bool CrossingPlanningAdapter::poseObstacles(const CrossingState &particle, ompl_ext::Environment &working) const
    {
        working.setObjectPose(pedestrian_, crossingPedestrianPose(model_->config(), particle.px, particle.py));
        return true;
    }

    bool CrossingPlanningAdapter::pathToMacroAction(const CrossingState &start, const double *waypoints,
                                                    std::size_t count, std::vector<CrossingModel::Action> &out) const
    {
        const CrossingConfig &c = model_->config();
        const std::size_t n = std::min(count, c.planning.pathNodes);
        if (n < 2)
        {
            return false;
        }
        Polyline path;
        path.points.reserve(n);
        path.length.reserve(n);
        for (std::size_t i = 0; i < n; ++i)
        {
            path.points.push_back({waypoints[3 * i], waypoints[3 * i + 1]});
            path.length.push_back(i == 0 ? 0.0
                                         : path.length.back() + std::hypot(path.points[i][0] - path.points[i - 1][0],
                                                                           path.points[i][1] - path.points[i - 1][1]));
        }
        if (!(path.total() > 1e-9))
        {
            return false;
        }
        const auto &end = path.points.back();
        CrossingState cur = start;
        std::size_t added = 0;
        while (added < macroLength_ && std::hypot(cur.x - end[0], cur.y - end[1]) >= 0.5 * c.goalTolerance)
        {
            const auto look = path.pointAt(std::min(path.project(cur.x, cur.y) + c.planning.lookahead, path.total()));
            double bestCost = std::numeric_limits<double>::infinity();
            std::size_t best = model_->numActions();
            CrossingState bestState = cur;
            for (std::size_t a = 0; a < model_->numActions(); ++a)
            {
                CrossingState p = cur;
                model_->predict(p, model_->action(a));
                const double dx = look[0] - p.x, dy = look[1] - p.y;
                const double d = std::hypot(dx, dy);
                double heading = 0.0;
                if (d > 1e-6)
                {
                    heading = std::abs(CrossingModel::wrapAngle(p.theta - std::atan2(dy, dx)));
                    heading = std::min(heading, PI - heading);  // forward or backward
                }
                const double cost = c.planning.distanceWeight * d + c.planning.headingWeight * heading;
                if (cost < bestCost)
                {
                    bestCost = cost;
                    best = a;
                    bestState = p;
                }
            }
            if (best == model_->numActions())
            {
                break;
            }
            out.push_back(model_->action(best));
            cur = bestState;
            ++added;
        }
        return added > 0;
    }

    std::shared_ptr<const ompl_ext::RobotModel> loadStretchRobot(const CrossingConfig &config)
    {
        ompl_ext::RobotModel::Options options;
        options.planningJoints = {"base_x", "base_y", "base_theta"};
        options.heldJointValues = {{"joint_lift", config.lift}, {"joint_arm", config.arm}};
        std::shared_ptr<const ompl_ext::RobotModel> robot;
        try
        {
            robot = ompl_ext::RobotModel::fromUrdfString(embeddedFile(URDF_PATH), ".", URDF_PATH, "", options);
        }
        catch (const Error &e)
        {
            const std::string what = e.what();
            const std::string key = what.find("joint_lift") != std::string::npos  ? "lift"
                                    : what.find("joint_arm") != std::string::npos ? "arm"
                                                                                  : "";
            throw Error("scenario " + config.scenario + (key.empty() ? "" : ": key \"" + key + "\"") + ": " + what);
        }
        for (std::size_t k = 0; k < 2; ++k)
        {
            const auto &j = robot->joints()[k];
            if (std::abs(j.lower - config.labLo[k]) > 1e-9 || std::abs(j.upper - config.labHi[k]) > 1e-9)
            {
                throw Error("scenario " + config.scenario + ": key \"lab\": " + URDF_PATH + " joint " + j.name +
                            " has limits [" + std::to_string(j.lower) + ", " + std::to_string(j.upper) +
                            "], the lab spans [" + std::to_string(config.labLo[k]) + ", " +
                            std::to_string(config.labHi[k]) + "] (the shipped robot's base joints span the lab)");
            }
        }
        return robot;
    }

    std::vector<CrossingSphere> stretchBaseSpheres(const ompl_ext::RobotModel &robot)
    {
        const double q[3] = {0.0, 0.0, 0.0};
        const auto centres = robot.sphereCentersReference(q);
        std::vector<CrossingSphere> out;
        for (std::size_t i = 0; i < centres.size(); ++i)
        {
            out.push_back({centres[i].x(), centres[i].y(), centres[i].z(), robot.spheres()[i].radius});
        }
        return out;
    }

    std::shared_ptr<const ompl_ext::Environment> crossingLab(const CrossingConfig &c)
    {
        auto env = std::make_shared<ompl_ext::Environment>();
        const double t = c.wallThickness, h = c.wallHeight;
        const double cx = 0.5 * (c.labLo[0] + c.labHi[0]), cy = 0.5 * (c.labLo[1] + c.labHi[1]);
        const double wx = c.labHi[0] - c.labLo[0] + 2.0 * t, wy = c.labHi[1] - c.labLo[1] + 2.0 * t;
        const auto box = [&](const std::string &name, double x, double y, double z, const Eigen::Vector3d &size)
        { env->addBox(name, Eigen::Isometry3d(Eigen::Translation3d(x, y, z)), size); };
        box("wall_south", cx, c.labLo[1] - 0.5 * t, 0.5 * h, {wx, t, h});
        box("wall_north", cx, c.labHi[1] + 0.5 * t, 0.5 * h, {wx, t, h});
        box("wall_west", c.labLo[0] - 0.5 * t, cy, 0.5 * h, {t, wy, h});
        box("wall_east", c.labHi[0] + 0.5 * t, cy, 0.5 * h, {t, wy, h});
        for (std::size_t i = 0; i < c.tables.size(); ++i)
        {
            const auto &tb = c.tables[i];
            box("table" + std::to_string(i), tb.center[0], tb.center[1], tb.center[2],
                {2.0 * tb.halfExtents[0], 2.0 * tb.halfExtents[1], 2.0 * tb.halfExtents[2]});
        }
        return env;
    }

    std::shared_ptr<const ompl_ext::Environment> crossingPlanningScene(const CrossingConfig &config,
                                                                       std::shared_ptr<const ompl_ext::Environment> lab,
                                                                       int &pedestrianId)
    {
        auto scene = std::make_shared<ompl_ext::Environment>(std::move(lab));
        const double radius = config.pedestrianRadius + config.planning.pedestrianMargin;
        const double length = sweepLength(config);
        pedestrianId = length > 0.0 ? scene->addCapsule("pedestrian", Eigen::Isometry3d::Identity(), radius, length)
                                    : scene->addSphere("pedestrian", Eigen::Vector3d::Zero(), radius);
        scene->setObjectPose(pedestrianId,
                             crossingPedestrianPose(config, config.pedestrianStart[0], config.pedestrianStart[1]));
        return scene;
    }
}  // namespace ropras::scenarios
