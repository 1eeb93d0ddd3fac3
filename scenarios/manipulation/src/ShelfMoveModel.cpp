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
                // a chain of spheres inside the can, held_clearance from its side and ends, along its axis (z);
                // the planner's chain is grown by the margin like every other shape of its scene: it then keeps
                // 2 margin from the true shelf and cans, which covers the rims of the world's held cylinder
                // (they stick out of the chain's end spheres by (r - c)(sqrt 2 - 1), 9.9 mm at the defaults)
                const double c = config_.heldClearance;
                const double rho = config_.canRadius - c;
                const double span = std::max(0.0, 0.5 * config_.canLength - c - rho);
                const int n = 1 + static_cast<int>(std::ceil(2.0 * span / (0.5 * rho)));
                for (int i = 0; i < n; ++i)
                {
                    Eigen::Isometry3d at = Eigen::Isometry3d::Identity();
                    at.translation().z() = n == 1 ? 0.0 : -span + 2.0 * span * i / (n - 1);
                    body.shapes.push_back(ompl_ext::Shape::sphere(rho + margin, at));
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
        pomdp::Rng probe(0x51e1f00dULL);
        if (config_.graspableLayout && !graspableLayout(s0, probe))
        {
            throw Error(where("cans") +
                        "with graspable_layout true the configured cans must be a graspable layout: no order of "
                        "grasps found that frees the target (doc/scenario-shelf-move.md)");
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

    bool ShelfMoveModel::motionValid(const State &s, const double *target, double *fraction) const noexcept
    {
        // the checker reports 1 for a valid motion, and scans for the last valid sample only when asked
        return arm_->checker()->isMotionValid(scene(s), s.q, target, config_.resolution, fraction);
    }

    pomdp::StepResult<ShelfMoveModel::State, ShelfMoveModel::Observation> ShelfMoveModel::step(
        const State &s, const Action &a, pomdp::Rng &rng) const noexcept
    {
        pomdp::StepResult<State, Observation> out;
        out.next = s;
        out.next.event = ShelfEvent::None;
        out.next.eventCan = out.next.eventSlot = -1;
        out.next.worldReport = 0;
        double target[ARM_DOF];
        proposeMotion(s, a, rng, target);
        double fraction = 1.0;
        motionValid(s, target, &fraction);
        PandaArm::interpolate(s.q, target, fraction, out.next.q);
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
                    n.event = ShelfEvent::Grasped;
                    n.eventCan = static_cast<std::int8_t>(k);
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
                n.event = ShelfEvent::Released;
                n.eventCan = static_cast<std::int8_t>(k);
                n.eventSlot = static_cast<std::int8_t>(slot);
                if (k == static_cast<int>(config_.targetCan) && slot == static_cast<int>(config_.reservedSlot))
                {
                    out.reward += config_.goalReward;
                    out.terminal = true;
                }
            }
        }
        observe(n, rng, out.observation);
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
            if (validState(s) && (!config_.graspableLayout || graspableLayout(s, rng)))
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
        return s.held != static_cast<int>(t) && std::abs(s.can[t][2] - slot[2]) <= 0.01 &&
               std::hypot(s.can[t][0] - slot[0], s.can[t][1] - slot[1], s.can[t][2] - slot[2]) <=
                   config_.placeTolerance;
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
