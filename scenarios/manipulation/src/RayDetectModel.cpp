#include "ropras/scenarios/manipulation/RayDetectModel.h"

#include <algorithm>
#include <atomic>
#include <cmath>
#include <string>
#include <utility>

#include "ropras/core/Error.h"
#include "ropras/ompl_ext/kinematics/CollisionFreePredicate.h"
#include "ropras/ompl_ext/scene/EnvironmentQueries.h"
#include "ropras/ompl_ext/scene/ShapeIntersection.h"
#include "ropras/scenarios/manipulation/BallIk.h"

namespace ropras::scenarios
{
    namespace
    {
        constexpr double PI = 3.14159265358979323846;

        std::atomic<std::uint64_t> nextInstance{1};

        Eigen::Vector3d vec(const std::array<double, 3> &v)
        {
            return Eigen::Vector3d(v[0], v[1], v[2]);
        }

        std::uint64_t mix(std::uint64_t h, std::uint64_t v) noexcept
        {
            h ^= v + 0x9e3779b97f4a7c15ULL + (h << 6) + (h >> 2);
            h *= 0xbf58476d1ce4e5b9ULL;
            return h ^ (h >> 31);
        }

        /// the calling thread's overlay of one model instance, with the poses it last set
        struct ThreadScene
        {
            std::uint64_t instance{0};
            std::unique_ptr<ompl_ext::Environment> env;
            double poses[RAY_DETECT_OBSTACLES][6]{};
        };
    }  // namespace

    Eigen::Isometry3d rayDetectPose(const double *pose) noexcept
    {
        Eigen::Isometry3d t = Eigen::Isometry3d::Identity();
        t.translation() = Eigen::Vector3d(pose[0], pose[1], pose[2]);
        t.linear() = (Eigen::AngleAxisd(pose[5], Eigen::Vector3d::UnitZ()) *
                      Eigen::AngleAxisd(pose[4], Eigen::Vector3d::UnitY()) *
                      Eigen::AngleAxisd(pose[3], Eigen::Vector3d::UnitX()))
                         .toRotationMatrix();
        return t;
    }

    std::shared_ptr<const ompl_ext::Environment> rayDetectStaticScene(const RayDetectConfig &config, double margin)
    {
        auto env = std::make_shared<ompl_ext::Environment>();
        env->addBox("table", Eigen::Isometry3d(Eigen::Translation3d(vec(config.tableCenter))),
                    vec(config.tableExtents) + Eigen::Vector3d::Constant(2.0 * margin));
        env->addCylinder("target", Eigen::Isometry3d(Eigen::Translation3d(vec(config.targetCenter))),
                         config.targetRadius + margin, config.targetLength + 2.0 * margin);
        return env;
    }

    std::shared_ptr<ompl_ext::Environment> rayDetectObstacleScene(const RayDetectConfig &config,
                                                                  std::shared_ptr<const ompl_ext::Environment> base,
                                                                  double margin)
    {
        auto env = std::make_shared<ompl_ext::Environment>(std::move(base));
        for (std::size_t k = 0; k < RAY_DETECT_OBSTACLES; ++k)
        {
            const auto &b = config.obstacles[k];
            env->addBox("obstacle" + std::to_string(k), rayDetectPose(b.pose.data()),
                        vec(b.extents) + Eigen::Vector3d::Constant(2.0 * margin));
        }
        return env;
    }

    void poseRayDetectObstacles(const RayDetectModel::State &s, ompl_ext::Environment &env)
    {
        for (std::size_t k = 0; k < RAY_DETECT_OBSTACLES; ++k)
        {
            env.setObjectPose(static_cast<int>(k), rayDetectPose(s.poses[k]));
        }
    }

    RayDetectModel::RayDetectModel(const RayDetectConfig &config, std::shared_ptr<const PandaArm> arm)
        : config_(config), arm_(std::move(arm)), instance_(nextInstance++)
    {
        if (!arm_)
        {
            throw Error("RayDetectModel: null arm");
        }
        static_ = rayDetectStaticScene(config_, 0.0);
        nominal_ = rayDetectObstacleScene(config_, static_, 0.0);
        const auto where = [](const std::string &key) { return "scenario ray-detect: key \"" + key + "\" "; };
        arm_->requireWithinLimits(config_.start.data(), where("start"));
        if (!arm_->checker()->isValid(*nominal_, config_.start.data()))
        {
            throw Error(where("start") + "is in collision (with the table, the can, an obstacle or itself)");
        }
        if (nominal_->signedDistance(vec(config_.goalPoint), 0.0) <= 0.0)
        {
            throw Error(where("goal_point") + "is inside an obstacle");
        }
        for (std::size_t k = 0; k < RAY_DETECT_OBSTACLES; ++k)
        {
            boxShapes_[k] = ompl_ext::Shape::box(vec(config_.obstacles[k].extents));
        }
        canShape_ = ompl_ext::Shape::cylinder(config_.targetRadius, config_.targetLength);
        canPose_ = Eigen::Translation3d(vec(config_.targetCenter));
        ballShape_ = ompl_ext::Shape::sphere(config_.goalRadius);
        ballPose_ = Eigen::Translation3d(vec(config_.goalPoint));
        int first = -1, second = -1;
        if (layoutConflict(nominalState(), first, second))
        {
            const std::string what = second == CAN         ? "the can (target)"
                                     : second == GOAL_BALL ? "the goal ball (goal_point, goal_radius " +
                                                                 std::to_string(config_.goalRadius) + " m)"
                                     : second >= 0 ? "obstacle " + std::to_string(second)
                                                   : "nothing (its pose is not finite)";
            throw Error(where("obstacles") + "at their nominal poses: obstacle " + std::to_string(first) +
                        " overlaps " + what);
        }
        ik_ = std::make_shared<const ompl_ext::InverseKinematics>(arm_->endEffectorChain());
        goalIk_.restarts = 100;
        goalIk_.positionTolerance = 1e-4;
        goalIk_.validate();
        pomdp::Rng probe(1);
        if (config_.reachableGoal && !goalReachable(nominalState(), probe))
        {
            const auto &g = config_.goalPoint;
            throw Error(where("goal_point") + "(" + std::to_string(g[0]) + ", " + std::to_string(g[1]) + ", " +
                        std::to_string(g[2]) + ") has no collision-free configuration within " +
                        std::to_string(config_.ikRadiusFraction * config_.goalRadius) +
                        " m of it at the nominal obstacle poses (position IK, " + std::to_string(config_.ikPoints) +
                        " points x 100 restarts)");
        }
        const double s = config_.observationSigma;
        logNorm_ = -static_cast<double>(ARM_DOF) * std::log(std::sqrt(2.0 * PI) * s);
        // the softened uniform: a Gaussian of the uniform's standard deviation (half-width / sqrt 3)
        for (std::size_t i = 0; i < 6; ++i)
        {
            kernelSigma_[i] = (i < 3 ? config_.positionNoise : config_.angleNoise) / std::sqrt(3.0);
        }
    }

    const ompl_ext::Environment &RayDetectModel::scene(const State &s) const noexcept
    {
        thread_local ThreadScene cache;
        if (cache.instance != instance_ || !cache.env)
        {
            cache.env = std::make_unique<ompl_ext::Environment>(*nominal_);
            cache.instance = instance_;
            for (auto &p : cache.poses)
            {
                std::fill(p, p + 6, std::nan(""));
            }
        }
        for (std::size_t k = 0; k < RAY_DETECT_OBSTACLES; ++k)
        {
            if (!std::equal(s.poses[k], s.poses[k] + 6, cache.poses[k]))
            {
                cache.env->setObjectPose(static_cast<int>(k), rayDetectPose(s.poses[k]));
                std::copy(s.poses[k], s.poses[k] + 6, cache.poses[k]);
            }
        }
        return *cache.env;
    }

    void RayDetectModel::ray(const double *q, Eigen::Vector3d &origin, Eigen::Vector3d &direction) const noexcept
    {
        const Eigen::Isometry3d pose = arm_->endEffectorPose(q);
        origin = pose.translation();
        direction = pose.linear().col(2);
    }

    RayDetectModel::Detection RayDetectModel::detect(const State &s) const noexcept
    {
        Detection d;
        Eigen::Vector3d direction;
        ray(s.q, d.origin, direction);
        d.end = d.origin + config_.rayLength * direction;
        d.distance = config_.rayLength;
        const ompl_ext::SegmentHit hit = ompl_ext::firstHit(scene(s), d.origin, d.end);
        if (hit.hit)
        {
            d.object = hit.object;
            d.distance = hit.distance;
            d.end = hit.point;
        }
        return d;
    }

    pomdp::StepResult<RayDetectModel::State, RayDetectModel::Observation> RayDetectModel::step(
        const State &s, const Action &a, pomdp::Rng &rng) const noexcept
    {
        pomdp::StepResult<State, Observation> out;
        out.next = s;
        double target[ARM_DOF];
        proposeMotion(s, a, rng, target);
        double fraction = 1.0;
        const ompl_ext::Environment &env = scene(s);
        // blocked: the last valid checked configuration (not terminal, no penalty)
        arm_->checker()->isMotionValid(env, s.q, target, config_.resolution, &fraction);
        PandaArm::interpolate(s.q, target, fraction, out.next.q);
        finishStep(out, detect(out.next), rng);
        return out;
    }

    void RayDetectModel::finishStep(pomdp::StepResult<State, Observation> &out, const Detection &detection,
                                    pomdp::Rng &rng) const noexcept
    {
        out.reward = config_.stepReward;
        if (reachedGoal(out.next))
        {
            out.reward += config_.goalReward;
            out.terminal = true;
        }
        for (std::size_t j = 0; j < ARM_DOF; ++j)
        {
            out.observation.q[j] = out.next.q[j] + config_.observationSigma * rng.normal();
        }
        out.observation.object = detection.object;
        if (detection.object >= 0)
        {
            const double *pose = out.next.poses[detection.object];
            for (std::size_t i = 0; i < 6; ++i)
            {
                const double a = i < 3 ? config_.positionNoise : config_.angleNoise;
                out.observation.pose[i] = pose[i] + rng.uniform(-a, a);
            }
        }
    }

    bool RayDetectModel::reachedGoal(const State &s) const noexcept
    {
        return (endEffector(s) - vec(config_.goalPoint)).squaredNorm() <= config_.goalRadius * config_.goalRadius;
    }

    double RayDetectModel::observationProbability(const Observation &o, const State &next,
                                                  const Action &) const noexcept
    {
        double q = 0.0;
        for (std::size_t j = 0; j < ARM_DOF; ++j)
        {
            const double d = (o.q[j] - next.q[j]) / config_.observationSigma;
            q += d * d;
        }
        const double joints = std::exp(logNorm_ - 0.5 * q);
        const int expected = detect(next).object;
        if (o.object != expected)
        {
            return joints * config_.mismatchLikelihood;
        }
        if (o.object < 0)
        {
            return joints;
        }
        // the same object: a kernel on the pose (1 at the exact pose; the normalisation is common to every state)
        const double *pose = next.poses[o.object];
        double e = 0.0;
        for (std::size_t i = 0; i < 6; ++i)
        {
            double d = o.pose[i] - pose[i];
            if (i >= 3)
            {
                d = std::remainder(d, 2.0 * PI);
            }
            d /= kernelSigma_[i];
            e += d * d;
        }
        return joints * std::exp(-0.5 * e);
    }

    RayDetectModel::State RayDetectModel::nominalState() const noexcept
    {
        State s;
        setJoints(s, config_.start.data());
        for (std::size_t k = 0; k < RAY_DETECT_OBSTACLES; ++k)
        {
            std::copy(config_.obstacles[k].pose.begin(), config_.obstacles[k].pose.end(), s.poses[k]);
        }
        return s;
    }

    bool RayDetectModel::layoutConflict(const State &s, int &first, int &second) const noexcept
    {
        first = second = -1;
        try
        {
            for (std::size_t k = 0; k < RAY_DETECT_OBSTACLES; ++k)
            {
                if (!std::all_of(s.poses[k], s.poses[k] + 6, [](double v) { return std::isfinite(v); }))
                {
                    first = static_cast<int>(k);
                    second = NON_FINITE;
                    return true;
                }
            }
            Eigen::Isometry3d poses[RAY_DETECT_OBSTACLES];
            const auto &boxes = boxShapes_;
            for (std::size_t k = 0; k < RAY_DETECT_OBSTACLES; ++k)
            {
                first = static_cast<int>(k);
                poses[k] = rayDetectPose(s.poses[k]);
                second = CAN;
                if (ompl_ext::shapesIntersect(boxes[k], poses[k], canShape_, canPose_))
                {
                    return true;
                }
                // the goal ball against the obstacles (the constructor checks the goal point against the table
                // and the can, which do not move)
                second = GOAL_BALL;
                if (ompl_ext::shapesIntersect(boxes[k], poses[k], ballShape_, ballPose_))
                {
                    return true;
                }
                for (std::size_t j = 0; j < k; ++j)
                {
                    second = static_cast<int>(j);
                    if (ompl_ext::shapesIntersect(boxes[k], poses[k], boxes[j], poses[j]))
                    {
                        return true;
                    }
                }
            }
            first = second = -1;
            return false;
        }
        catch (const std::exception &)
        {
            second = NON_FINITE;  // not reached for finite poses (bad_alloc aside): not shown possible
            return true;
        }
    }

    bool RayDetectModel::physicallyPossible(const State &s) const noexcept
    {
        int first = -1, second = -1;
        return !layoutConflict(s, first, second);
    }

    bool RayDetectModel::goalReachable(const State &s, pomdp::Rng &rng) const noexcept
    {
        return physicallyPossible(s) && reachableLayout(s, rng);  // a non-finite pose never reaches the IK
    }

    bool RayDetectModel::reachableLayout(const State &s, pomdp::Rng &rng) const noexcept
    {
        struct ThreadIk
        {
            std::uint64_t instance{0};
            std::unique_ptr<ompl_ext::IkWorkspace> workspace;
        };
        thread_local ThreadIk cache;
        try
        {
            if (cache.instance != instance_ || !cache.workspace)
            {
                cache.workspace = std::make_unique<ompl_ext::IkWorkspace>(ik_->makeWorkspace());
                cache.instance = instance_;
            }
            const ompl_ext::ConfigurationPredicate free = ompl_ext::collisionFreePredicate(*arm_->checker(), scene(s));
            double q[ARM_DOF];
            return solvePositionInBall(*ik_, vec(config_.goalPoint), config_.ikRadiusFraction * config_.goalRadius,
                                       config_.ikPoints, config_.start.data(), rng, *cache.workspace, goalIk_, &free,
                                       q);
        }
        catch (const std::exception &)
        {
            // out of memory for the workspace or the predicate: not shown reachable
        }
        return false;
    }

    RayDetectModel::State RayDetectModel::sampleInitialState(pomdp::Rng &rng) const noexcept
    {
        State s = nominalState();
        // redrawn while the layout is not physically possible, the arm collides in the drawn scene or (reachable_goal)
        // no configuration reaches the goal (the validated nominal state is the fallback)
        for (int attempt = 0; attempt < 100; ++attempt)
        {
            for (std::size_t j = 0; j < ARM_DOF; ++j)
            {
                s.q[j] = config_.start[j] + config_.initialSigmaJoints * rng.normal();
            }
            arm_->clamp(s.q);
            for (std::size_t k = 0; k < RAY_DETECT_OBSTACLES; ++k)
            {
                for (std::size_t i = 0; i < 6; ++i)
                {
                    s.poses[k][i] = config_.obstacles[k].pose[i] + config_.initialSigmaPose[i] * rng.normal();
                }
            }
            if (physicallyPossible(s) && arm_->checker()->isValid(scene(s), s.q) &&
                (!config_.reachableGoal || reachableLayout(s, rng)))
            {
                return s;
            }
        }
        return nominalState();
    }

    RayDetectModel::Action RayDetectModel::action(std::size_t i) const noexcept
    {
        Action a;
        i %= 2 * ARM_DOF;
        a.dq[i / 2] = (i % 2 == 0 ? 1.0 : -1.0) * config_.step;
        return a;
    }

    std::uint64_t RayDetectModel::observationKey(const Observation &o) const noexcept
    {
        if (o.object < 0)
        {
            return 0;
        }
        const Eigen::Vector3d ee = arm_->endEffectorPosition(o.q);
        const double distance = (Eigen::Vector3d(o.pose[0], o.pose[1], o.pose[2]) - ee).norm();
        const double cell = std::floor(distance / config_.observationDistanceBin);
        const auto bin = static_cast<std::uint64_t>(std::isfinite(cell) ? std::fmax(0.0, std::fmin(1e6, cell)) : 0.0);
        return mix(static_cast<std::uint64_t>(o.object + 1), bin) | 1ULL;
    }

    void RayDetectModel::reinvigorate(State &s, pomdp::Rng &rng) const noexcept
    {
        State j = s;
        for (std::size_t i = 0; i < ARM_DOF; ++i)
        {
            j.q[i] += config_.reinvigorateSigma * rng.normal();
        }
        arm_->clamp(j.q);
        for (std::size_t k = 0; k < RAY_DETECT_OBSTACLES; ++k)
        {
            for (std::size_t i = 0; i < 6; ++i)
            {
                if (config_.initialSigmaPose[i] > 0.0)
                {
                    j.poses[k][i] +=
                        (i < 3 ? config_.reinvigoratePositionSigma : config_.reinvigorateAngleSigma) * rng.normal();
                }
            }
        }
        if (physicallyPossible(j) && arm_->checker()->isValid(scene(j), j.q))
        {
            s = j;
        }
    }

    double RayDetectModel::heuristicValue(const State &s) const noexcept
    {
        if (!config_.heuristicValue)
        {
            return 0.0;
        }
        const double gap = std::max(0.0, (endEffector(s) - vec(config_.goalPoint)).norm() - config_.goalRadius);
        const double d = std::ceil(gap / config_.heuristicEndEffectorStep);
        const double g = config_.discount;
        const double gd = std::pow(g, d);
        const double steps = g < 1.0 ? (1.0 - gd) / (1.0 - g) : d;
        return config_.goalReward * gd + config_.stepReward * steps;
    }
}  // namespace ropras::scenarios
