#include "ropras/scenarios/manipulation/ShelfMoveModel.h"

#include <algorithm>
#include <atomic>
#include <cmath>
#include <string>
#include <utility>

#include "ropras/core/Error.h"

namespace ropras::scenarios
{
    namespace
    {
        constexpr double PI = 3.14159265358979323846;
        /// what the held can may touch: the hand holding it and its fingers
        const char *const TOUCH_LINKS[] = {"panda_hand", "panda_leftfinger", "panda_rightfinger"};

        std::uint64_t mix(std::uint64_t h, std::int64_t v) noexcept
        {
            h ^= static_cast<std::uint64_t>(v) + 0x9e3779b97f4a7c15ULL + (h << 6) + (h >> 2);
            h *= 0xbf58476d1ce4e5b9ULL;
            return h ^ (h >> 31);
        }

        std::int64_t cell(double v, double bin) noexcept
        {
            const double c = std::floor(v / bin);
            return static_cast<std::int64_t>(std::isfinite(c) ? std::fmax(-1e15, std::fmin(1e15, c)) : 0.0);
        }

        /// the object id of can k in the prototype for held state h (0: nothing held, 1 + j: can j held)
        int objectOf(int h, std::size_t k) noexcept
        {
            const int ki = static_cast<int>(k);
            return h == 0 || ki < h - 1 ? ki : ki - 1;
        }

        std::atomic<std::uint64_t> nextModelId{1};
    }  // namespace

    /// the calling thread's copies of the prototypes (re-made when another model used the thread last)
    struct ShelfMoveModel::Scenes
    {
        std::uint64_t owner{0};
        std::array<ompl_ext::Environment, SHELF_CANS + 1> envs;
    };

    Eigen::Isometry3d ShelfMoveModel::graspTransform() const
    {
        Eigen::Isometry3d t = Eigen::Isometry3d::Identity();
        t.translation() = Eigen::Vector3d(0.0, 0.0, config_.graspOffset);
        t.linear() = Eigen::AngleAxisd(PI / 2.0, Eigen::Vector3d::UnitY()).toRotationMatrix();
        return t;
    }

    ShelfMoveModel::ShelfMoveModel(const ShelfMoveConfig &config, std::shared_ptr<const PandaArm> arm)
        : config_(config), arm_(std::move(arm)), id_(nextModelId++)
    {
        if (!arm_)
        {
            throw Error("ShelfMoveModel: null arm");
        }
        const auto where = [](const std::string &key) { return "scenario shelf-move: key \"" + key + "\" "; };
        auto makeShelf = [&](double margin)
        {
            auto env = std::make_shared<ompl_ext::Environment>();
            for (std::size_t i = 0; i < config_.shelf.size(); ++i)
            {
                const auto &b = config_.shelf[i];
                Eigen::Isometry3d pose = Eigen::Isometry3d::Identity();
                pose.translation() = Eigen::Vector3d(b[0], b[1], b[2]);
                env->addBox("shelf" + std::to_string(i), pose,
                            Eigen::Vector3d(b[3], b[4], b[5]) + Eigen::Vector3d::Constant(2.0 * margin));
            }
            return std::shared_ptr<const ompl_ext::Environment>(std::move(env));
        };
        shelf_ = makeShelf(0.0);
        planningShelf_ = makeShelf(config_.planningMargin);
        auto makePrototype = [&](const std::shared_ptr<const ompl_ext::Environment> &shelf, int h, double margin)
        {
            auto env = std::make_shared<ompl_ext::Environment>(shelf);
            for (std::size_t k = 0; k < SHELF_CANS; ++k)
            {
                if (static_cast<int>(k) == h - 1)
                {
                    continue;
                }
                Eigen::Isometry3d pose = Eigen::Isometry3d::Identity();
                pose.translation() = Eigen::Vector3d(config_.cans[k][0], config_.cans[k][1], config_.cans[k][2]);
                env->addCylinder("can" + std::to_string(k), pose, config_.canRadius + margin,
                                 config_.canLength + 2.0 * margin);
            }
            if (h > 0)
            {
                ompl_ext::AttachedBody body;
                body.name = "held_can";
                body.link = config_.endEffector;
                body.pose = graspTransform();
                // a chain of spheres inside the can, held_clearance from its side and ends, along its axis (z)
                const double c = config_.heldClearance;
                const double rho = config_.canRadius - c;
                const double span = std::max(0.0, 0.5 * config_.canLength - c - rho);
                const int n = 1 + static_cast<int>(std::ceil(2.0 * span / (0.5 * rho)));
                for (int i = 0; i < n; ++i)
                {
                    Eigen::Isometry3d at = Eigen::Isometry3d::Identity();
                    at.translation().z() = n == 1 ? 0.0 : -span + 2.0 * span * i / (n - 1);
                    body.shapes.push_back(ompl_ext::Shape::sphere(rho, at));
                }
                for (const char *link : TOUCH_LINKS)
                {
                    body.touchLinks.emplace_back(link);
                }
                env->attach(arm_->robot(), body);
            }
            return std::shared_ptr<const ompl_ext::Environment>(std::move(env));
        };
        for (int h = 0; h <= static_cast<int>(SHELF_CANS); ++h)
        {
            prototypes_[static_cast<std::size_t>(h)] = makePrototype(shelf_, h, 0.0);
            planningPrototypes_[static_cast<std::size_t>(h)] = makePrototype(planningShelf_, h, config_.planningMargin);
        }
        arm_->requireWithinLimits(config_.start.data(), where("start"));
        const State s0 = trueInitialState();
        for (std::size_t k = 0; k < SHELF_CANS; ++k)
        {
            if (supportingBox(s0.can[k]) < 0)
            {
                throw Error(where("cans") + "can " + std::to_string(k) +
                            " does not stand on a shelf box (its bottom must lie on a box top, within its footprint)");
            }
            if (!canPlacementValid(s0, k))
            {
                throw Error(where("cans") + "can " + std::to_string(k) + " overlaps another can or a shelf box");
            }
        }
        for (std::size_t i = 0; i < config_.slots.size(); ++i)
        {
            if (supportingBox(config_.slots[i].data()) < 0)
            {
                throw Error(where("slots") + "slot " + std::to_string(i) + " is not on a shelf box top");
            }
        }
        if (!arm_->checker()->isValid(scene(s0), s0.q))
        {
            throw Error(where("start") + "is in collision (with the shelf, a can or itself)");
        }
        logNorm_ = -static_cast<double>(ARM_DOF) * std::log(std::sqrt(2.0 * PI) * config_.observationSigma);
    }

    ShelfMoveModel::State ShelfMoveModel::trueInitialState() const noexcept
    {
        State s;
        setJoints(s, config_.start.data());
        for (std::size_t k = 0; k < SHELF_CANS; ++k)
        {
            for (int a = 0; a < 3; ++a)
            {
                s.can[k][a] = config_.cans[k][static_cast<std::size_t>(a)];
            }
        }
        return s;
    }

    const ShelfMoveModel::Scenes &ShelfMoveModel::threadScenes() const noexcept
    {
        thread_local Scenes scenes;
        if (scenes.owner != id_)
        {
            for (std::size_t h = 0; h <= SHELF_CANS; ++h)
            {
                scenes.envs[h] = *prototypes_[h];
            }
            scenes.owner = id_;
        }
        return scenes;
    }

    void ShelfMoveModel::poseScene(ompl_ext::Environment &env, int held, const State &s) const noexcept
    {
        const int h = held + 1;
        for (std::size_t k = 0; k < SHELF_CANS; ++k)
        {
            if (static_cast<int>(k) == held)
            {
                continue;
            }
            Eigen::Isometry3d pose = Eigen::Isometry3d::Identity();
            pose.translation() = Eigen::Vector3d(s.can[k][0], s.can[k][1], s.can[k][2]);
            if (pose.translation().allFinite())
            {
                env.setObjectPose(objectOf(h, k), pose);
            }
        }
    }

    const ompl_ext::Environment &ShelfMoveModel::scene(const State &s) const noexcept
    {
        auto &scenes = const_cast<Scenes &>(threadScenes());
        const int held = s.held >= 0 && s.held < static_cast<int>(SHELF_CANS) ? s.held : -1;
        auto &env = scenes.envs[static_cast<std::size_t>(held + 1)];
        poseScene(env, held, s);
        return env;
    }

    std::shared_ptr<ompl_ext::Environment> ShelfMoveModel::makeScene(const State &s, bool planning) const
    {
        const int held = s.held >= 0 && s.held < static_cast<int>(SHELF_CANS) ? s.held : -1;
        const auto &proto = (planning ? planningPrototypes_ : prototypes_)[static_cast<std::size_t>(held + 1)];
        auto env = std::make_shared<ompl_ext::Environment>(*proto);
        poseScene(*env, held, s);
        return env;
    }

    int ShelfMoveModel::supportingBox(const double *c) const noexcept
    {
        const double bottom = c[2] - 0.5 * config_.canLength;
        const double r = config_.canRadius;
        for (std::size_t i = 0; i < config_.shelf.size(); ++i)
        {
            const auto &b = config_.shelf[i];
            if (std::abs(b[2] + 0.5 * b[5] - bottom) <= 1e-3 && std::abs(c[0] - b[0]) <= 0.5 * b[3] - r &&
                std::abs(c[1] - b[1]) <= 0.5 * b[4] - r)
            {
                return static_cast<int>(i);
            }
        }
        return -1;
    }

    bool ShelfMoveModel::canPlacementValid(const State &s, std::size_t k) const noexcept
    {
        const double *c = s.can[k];
        if (!(std::isfinite(c[0]) && std::isfinite(c[1]) && std::isfinite(c[2])))
        {
            return false;
        }
        const int support = supportingBox(c);
        if (support < 0)
        {
            return false;
        }
        const double r = config_.canRadius;
        const double half = 0.5 * config_.canLength;
        for (std::size_t i = 0; i < config_.shelf.size(); ++i)
        {
            if (static_cast<int>(i) == support)
            {
                continue;
            }
            const auto &b = config_.shelf[i];
            if (c[2] + half <= b[2] - 0.5 * b[5] || c[2] - half + 1e-4 >= b[2] + 0.5 * b[5])
            {
                continue;  // no overlap in z
            }
            const double dx = std::max(0.0, std::abs(c[0] - b[0]) - 0.5 * b[3]);
            const double dy = std::max(0.0, std::abs(c[1] - b[1]) - 0.5 * b[4]);
            if (dx * dx + dy * dy < r * r)
            {
                return false;
            }
        }
        for (std::size_t j = 0; j < SHELF_CANS; ++j)
        {
            if (j == k || static_cast<int>(j) == s.held)
            {
                continue;
            }
            const double *o = s.can[j];
            if (std::abs(o[2] - c[2]) < 2.0 * half && std::hypot(o[0] - c[0], o[1] - c[1]) < 2.0 * r)
            {
                return false;
            }
        }
        return true;
    }

    bool ShelfMoveModel::validState(const State &s) const noexcept
    {
        for (std::size_t k = 0; k < SHELF_CANS; ++k)
        {
            if (static_cast<int>(k) != s.held && !canPlacementValid(s, k))
            {
                return false;
            }
        }
        return arm_->checker()->isValid(scene(s), s.q);
    }

    void ShelfMoveModel::followHand(State &s) const noexcept
    {
        if (s.held < 0 || s.held >= static_cast<int>(SHELF_CANS))
        {
            return;
        }
        const Eigen::Vector3d p = graspPoint(s);
        for (int a = 0; a < 3; ++a)
        {
            s.can[s.held][a] = p[a];
        }
    }

    int ShelfMoveModel::graspableCan(const State &s) const noexcept
    {
        if (s.held >= 0)
        {
            return -1;
        }
        const Eigen::Isometry3d ee = arm_->endEffectorPose(s.q);
        if (std::abs(ee.linear().col(0).z()) < std::cos(config_.graspAxisTolerance))
        {
            return -1;
        }
        const Eigen::Vector3d p = ee * Eigen::Vector3d(0.0, 0.0, config_.graspOffset);
        const double half = 0.5 * config_.canLength;
        int best = -1;
        double bestDistance = config_.graspTolerance;
        for (std::size_t k = 0; k < SHELF_CANS; ++k)
        {
            const double *c = s.can[k];
            const double dz = std::max(0.0, std::abs(p.z() - c[2]) - half);
            const double d = std::sqrt((p.x() - c[0]) * (p.x() - c[0]) + (p.y() - c[1]) * (p.y() - c[1]) + dz * dz);
            if (d <= bestDistance)
            {
                bestDistance = d;
                best = static_cast<int>(k);
            }
        }
        return best;
    }

    int ShelfMoveModel::releaseSlot(const State &s) const noexcept
    {
        if (s.held < 0 || s.held >= static_cast<int>(SHELF_CANS))
        {
            return -1;
        }
        const Eigen::Vector3d p = graspPoint(s);
        int best = -1;
        double bestDistance = 1e300;
        for (std::size_t i = 0; i < config_.slots.size(); ++i)
        {
            const auto &slot = config_.slots[i];
            const double d = (p - Eigen::Vector3d(slot[0], slot[1], slot[2])).norm();
            if (d > config_.placeTolerance || d >= bestDistance)
            {
                continue;
            }
            State placed = s;
            for (int a = 0; a < 3; ++a)
            {
                placed.can[s.held][a] = slot[static_cast<std::size_t>(a)];
            }
            placed.held = -1;
            if (canPlacementValid(placed, static_cast<std::size_t>(s.held)) &&
                arm_->checker()->isValid(scene(placed), placed.q))
            {
                best = static_cast<int>(i);
                bestDistance = d;
            }
        }
        return best;
    }

    void ShelfMoveModel::proposeMotion(const State &s, const Action &a, pomdp::Rng &rng, double *target) const noexcept
    {
        for (std::size_t j = 0; j < ARM_DOF; ++j)
        {
            target[j] = (a.waypoint ? 0.0 : s.q[j]) + a.dq[j] + config_.transitionSigma * rng.normal();
        }
        arm_->clamp(target);
    }

    pomdp::StepResult<ShelfMoveModel::State, ShelfMoveModel::Observation> ShelfMoveModel::step(
        const State &s, const Action &a, pomdp::Rng &rng) const noexcept
    {
        pomdp::StepResult<State, Observation> out;
        out.next = s;
        double target[ARM_DOF];
        proposeMotion(s, a, rng, target);
        double fraction = 1.0;
        if (arm_->checker()->isMotionValid(scene(s), s.q, target, config_.resolution, &fraction))
        {
            setJoints(out.next, target);
        }
        else
        {
            for (std::size_t j = 0; j < ARM_DOF; ++j)
            {
                out.next.q[j] = s.q[j] + fraction * (target[j] - s.q[j]);
            }
        }
        followHand(out.next);
        finishStep(out, a.event, rng);
        return out;
    }

    void ShelfMoveModel::finishStep(pomdp::StepResult<State, Observation> &out, GripperEvent event,
                                    pomdp::Rng &rng) const noexcept
    {
        State &n = out.next;
        out.reward = config_.stepReward;
        if (event == GripperEvent::Close)
        {
            const int k = graspableCan(n);
            if (k >= 0)
            {
                State grasped = n;
                grasped.held = k;
                followHand(grasped);
                if (arm_->checker()->isValid(scene(grasped), grasped.q))
                {
                    n = grasped;
                }
            }
        }
        else if (event == GripperEvent::Open)
        {
            const int slot = releaseSlot(n);
            if (slot >= 0)
            {
                const int k = n.held;
                for (int a = 0; a < 3; ++a)
                {
                    n.can[k][a] = config_.slots[static_cast<std::size_t>(slot)][static_cast<std::size_t>(a)];
                }
                n.held = -1;
                if (k == static_cast<int>(config_.targetCan) && slot == static_cast<int>(config_.reservedSlot))
                {
                    out.reward += config_.goalReward;
                    out.terminal = true;
                }
            }
        }
        Observation &o = out.observation;
        for (std::size_t j = 0; j < ARM_DOF; ++j)
        {
            o.q[j] = n.q[j] + config_.observationSigma * rng.normal();
        }
        o.held = n.held;
        o.detected = 0;
        const Eigen::Vector3d p = endEffector(n);
        const double w = config_.canObservationNoise;
        for (std::size_t k = 0; k < SHELF_CANS; ++k)
        {
            const Eigen::Vector3d c(n.can[k][0], n.can[k][1], n.can[k][2]);
            if (static_cast<int>(k) == n.held || (c - p).norm() > config_.senseDistance)
            {
                continue;
            }
            o.detected = static_cast<std::uint8_t>(o.detected | (1u << k));
            for (int a = 0; a < 3; ++a)
            {
                o.can[k][a] = c[a] + w * (2.0 * rng.uniform01() - 1.0);
            }
        }
    }

    double ShelfMoveModel::observationProbability(const Observation &o, const State &next,
                                                  const Action &) const noexcept
    {
        if (o.held != next.held)
        {
            return 0.0;
        }
        const Eigen::Vector3d p = endEffector(next);
        const double w = config_.canObservationNoise;
        double log = logNorm_;
        for (std::size_t j = 0; j < ARM_DOF; ++j)
        {
            const double d = (o.q[j] - next.q[j]) / config_.observationSigma;
            log -= 0.5 * d * d;
        }
        for (std::size_t k = 0; k < SHELF_CANS; ++k)
        {
            const Eigen::Vector3d c(next.can[k][0], next.can[k][1], next.can[k][2]);
            const bool expected = static_cast<int>(k) != next.held && (c - p).norm() <= config_.senseDistance;
            const bool seen = (o.detected >> k) & 1u;
            if (expected != seen)
            {
                return 0.0;
            }
            if (!seen)
            {
                continue;
            }
            for (int a = 0; a < 3; ++a)
            {
                // U(-w, w), softened outside the box by a Gaussian tail (no 0/1 likelihoods)
                const double excess = std::max(0.0, std::abs(o.can[k][a] - c[a]) - w) / config_.observationSoftening;
                log += -std::log(2.0 * w) - 0.5 * excess * excess;
            }
        }
        return std::exp(log);
    }

    ShelfMoveModel::State ShelfMoveModel::sampleInitialState(pomdp::Rng &rng) const noexcept
    {
        const State truth = trueInitialState();
        for (int attempt = 0; attempt < 100; ++attempt)
        {
            State s = truth;
            for (std::size_t j = 0; j < ARM_DOF; ++j)
            {
                s.q[j] += config_.initialSigma * rng.normal();
            }
            arm_->clamp(s.q);
            for (std::size_t k = 0; k < SHELF_CANS; ++k)
            {
                s.can[k][0] += config_.initialCanSigma * rng.normal();
                s.can[k][1] += config_.initialCanSigma * rng.normal();
            }
            if (validState(s))
            {
                return s;
            }
        }
        return truth;
    }

    bool ShelfMoveModel::reachedGoal(const State &s) const noexcept
    {
        const auto t = config_.targetCan;
        const auto &slot = config_.slots[config_.reservedSlot];
        return s.held != static_cast<int>(t) && std::hypot(s.can[t][0] - slot[0], s.can[t][1] - slot[1],
                                                           s.can[t][2] - slot[2]) <= config_.placeTolerance;
    }

    ShelfMoveModel::Action ShelfMoveModel::action(std::size_t i) const noexcept
    {
        Action a;
        i %= numActions();
        if (i < 2 * ARM_DOF)
        {
            a.dq[i / 2] = (i % 2 == 0 ? 1.0 : -1.0) * config_.step;
        }
        else
        {
            a.event = i == 2 * ARM_DOF ? GripperEvent::Close : GripperEvent::Open;
        }
        return a;
    }

    std::uint64_t ShelfMoveModel::observationKey(const Observation &o) const noexcept
    {
        std::uint64_t h = mix(0x9e3779b97f4a7c15ULL, o.held + 1);
        h = mix(h, o.detected);
        for (std::size_t k = 0; k < SHELF_CANS; ++k)
        {
            if ((o.detected >> k) & 1u)
            {
                for (int a = 0; a < 3; ++a)
                {
                    h = mix(h, cell(o.can[k][a], config_.observationCanBin));
                }
            }
        }
        if (config_.observationJointBin > 0.0)
        {
            for (std::size_t j = 0; j < ARM_DOF; ++j)
            {
                h = mix(h, cell(o.q[j], config_.observationJointBin));
            }
        }
        return h;
    }

    void ShelfMoveModel::reinvigorate(State &s, pomdp::Rng &rng) const noexcept
    {
        if (!rng.bernoulli(config_.reinvigorateProbability))
        {
            return;
        }
        State j = s;
        for (std::size_t i = 0; i < ARM_DOF; ++i)
        {
            j.q[i] += config_.reinvigorateSigma * rng.normal();
        }
        arm_->clamp(j.q);
        for (std::size_t k = 0; k < SHELF_CANS; ++k)
        {
            if (static_cast<int>(k) != s.held)
            {
                j.can[k][0] += config_.reinvigorateCanSigma * rng.normal();
                j.can[k][1] += config_.reinvigorateCanSigma * rng.normal();
            }
        }
        followHand(j);
        if (validState(j))
        {
            s = j;
        }
    }
}  // namespace ropras::scenarios
