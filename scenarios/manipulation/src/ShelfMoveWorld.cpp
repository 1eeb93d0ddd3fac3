#include "ropras/scenarios/manipulation/ShelfMoveWorld.h"

#include <btBulletDynamicsCommon.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <set>
#include <string>
#include <utility>
#include <vector>

#include "BulletSupport.h"
#include "ropras/core/Error.h"

namespace ropras::scenarios
{
    namespace
    {
        using bullet::fromBt;
        using bullet::toBt;

        /// user indices: arm collision links 0.., the shelf's boxes, the floor, the held can, can k = CAN0 + k
        constexpr int SHELF = -1;
        constexpr int FLOOR = -2;
        constexpr int HELD = -3;
        constexpr int CAN0 = 1000;
        /// what the held can may touch (as in the model): the hand holding it and its fingers
        const char *const TOUCH_LINKS[] = {"panda_hand", "panda_leftfinger", "panda_rightfinger"};
        /// consecutive quiet physics steps that count as settled
        constexpr int QUIET_STEPS = 12;

        bool isCan(int user)
        {
            return user >= CAN0;
        }

        bool isArm(int user)
        {
            return user >= 0 && user < CAN0;
        }

        int userOf(const btBroadphaseProxy *proxy)
        {
            return static_cast<const btCollisionObject *>(proxy->m_clientObject)->getUserIndex();
        }

        /// the pairs the dynamics simulates: a can with the shelf, the floor and the other cans; with the arm and
        /// the held can only when the arm pushes cans
        struct DynamicsFilter final : btOverlapFilterCallback
        {
            bool needBroadphaseCollision(btBroadphaseProxy *a, btBroadphaseProxy *b) const override
            {
                const int ua = userOf(a), ub = userOf(b);
                if (!isCan(ua) && !isCan(ub))
                {
                    return false;
                }
                const int other = isCan(ua) ? ub : ua;
                return (isArm(other) || other == HELD) ? push : true;
            }
            bool push{false};
        };

        /// one body's contact query: whether an admitted object comes within the threshold
        struct Touch final : btCollisionWorld::ContactResultCallback
        {
            enum class Arm
            {
                None,         ///< no arm link
                SelfPairs,    ///< the links forming a self-collision pair with link \a self
                NotTouching,  ///< every link but the held can's touch links
                All
            };
            Touch(int selfUser, bool cans, Arm arm, const std::set<std::pair<int, int>> &pairs,
                  const std::vector<bool> &touchLinks, double threshold)
                : self_(selfUser), cans_(cans), arm_(arm), pairs_(pairs), touch_(touchLinks)
            {
                m_closestDistanceThreshold = static_cast<btScalar>(threshold);
            }
            bool needsCollision(btBroadphaseProxy *proxy) const override
            {
                const int u = userOf(proxy);
                if (u == SHELF)
                {
                    return shelf_;
                }
                if (isCan(u))
                {
                    return cans_;
                }
                if (!isArm(u))
                {
                    return false;  // the floor, the held can
                }
                switch (arm_)
                {
                    case Arm::SelfPairs:
                        return pairs_.count({std::min(self_, u), std::max(self_, u)}) > 0;
                    case Arm::NotTouching:
                        return !touch_[static_cast<std::size_t>(u)];
                    case Arm::All:
                        return true;
                    case Arm::None:
                        break;
                }
                return false;
            }
            btScalar addSingleResult(btManifoldPoint &cp, const btCollisionObjectWrapper *, int, int,
                                     const btCollisionObjectWrapper *, int, int) override
            {
                if (cp.getDistance() <= m_closestDistanceThreshold)
                {
                    hit = true;
                }
                return 0;
            }
            bool hit{false};
            bool shelf_{true};

        private:
            int self_;
            bool cans_;
            Arm arm_;
            const std::set<std::pair<int, int>> &pairs_;
            const std::vector<bool> &touch_;
        };
    }  // namespace

    struct ShelfMoveWorld::Impl
    {
        explicit Impl(const ShelfMoveModel &m)
            : model(m), config(m.config()), world(&core.dispatcher, &core.broadphase, &solver, &core.configuration)
        {
            filter.push = config.pushCans;
            world.getPairCache()->setOverlapFilterCallback(&filter);
            world.setGravity(btVector3(0, 0, static_cast<btScalar>(-config.gravity)));
            grasp = m.graspTransform();
            addShelf();
            addCans();
            addArm();
        }

        /// a kinematic body is flagged before it joins the world (Bullet then keeps it among the moving bodies,
        /// whose velocity it derives from the pose change of each step)
        btRigidBody *addBody(btCollisionShape *shape, double mass, const btTransform &pose, int user, bool inWorld,
                             bool kinematic = false)
        {
            btVector3 inertia(0, 0, 0);
            if (mass > 0.0)
            {
                shape->calculateLocalInertia(static_cast<btScalar>(mass), inertia);
            }
            btRigidBody::btRigidBodyConstructionInfo info(static_cast<btScalar>(mass), nullptr, shape, inertia);
            info.m_startWorldTransform = pose;
            auto body = std::make_unique<btRigidBody>(info);
            body->setUserIndex(user);
            btRigidBody *raw = body.get();
            storage.objects.push_back(std::move(body));
            if (kinematic)
            {
                raw->setCollisionFlags(raw->getCollisionFlags() | btCollisionObject::CF_KINEMATIC_OBJECT);
                raw->setActivationState(DISABLE_DEACTIVATION);
            }
            if (inWorld)
            {
                world.addRigidBody(raw);
            }
            return raw;
        }

        void addShelf()
        {
            for (const auto &b : config.shelf)
            {
                btTransform pose;
                pose.setIdentity();
                pose.setOrigin(
                    btVector3(static_cast<btScalar>(b[0]), static_cast<btScalar>(b[1]), static_cast<btScalar>(b[2])));
                auto *shape = storage.keep(std::make_unique<btBoxShape>(btVector3(static_cast<btScalar>(0.5 * b[3]),
                                                                                  static_cast<btScalar>(0.5 * b[4]),
                                                                                  static_cast<btScalar>(0.5 * b[5]))));
                btRigidBody *body = addBody(shape, 0.0, pose, SHELF, true);
                body->setFriction(static_cast<btScalar>(config.shelfFriction));
                body->setRestitution(static_cast<btScalar>(config.canRestitution));
            }
            btTransform identity;
            identity.setIdentity();
            auto *floor = storage.keep(std::make_unique<btStaticPlaneShape>(btVector3(0, 0, 1), btScalar(0)));
            addBody(floor, 0.0, identity, FLOOR, true)->setFriction(static_cast<btScalar>(config.shelfFriction));
        }

        void addCans()
        {
            const auto r = static_cast<btScalar>(config.canRadius);
            canShape = storage.keep(
                std::make_unique<btCylinderShapeZ>(btVector3(r, r, static_cast<btScalar>(0.5 * config.canLength))));
            // the held can's query shape: held_clearance inside the can (the model's sphere chain lies inside it)
            const auto rh = static_cast<btScalar>(config.canRadius - config.heldClearance);
            heldShape = storage.keep(std::make_unique<btCylinderShapeZ>(
                btVector3(rh, rh, static_cast<btScalar>(0.5 * config.canLength - config.heldClearance))));
            btTransform identity;
            identity.setIdentity();
            for (std::size_t k = 0; k < SHELF_CANS; ++k)
            {
                btRigidBody *body = addBody(canShape, config.canMass, identity, CAN0 + static_cast<int>(k), true);
                body->setFriction(static_cast<btScalar>(config.canFriction));
                body->setRestitution(static_cast<btScalar>(config.canRestitution));
                body->setActivationState(DISABLE_DEACTIVATION);  // settling is decided here, not by sleeping
                cans[k] = body;
                inWorld[k] = true;
            }
            held = addBody(heldShape, 0.0, identity, HELD, false, true);
        }

        void addArm()
        {
            const auto &robot = *model.arm().robot();
            const auto &links = robot.collisionLinks();
            btTransform identity;
            identity.setIdentity();
            int l = 0;
            for (auto &shape : bullet::armLinkShapes(robot, storage))
            {
                arm.push_back(addBody(storage.keep(std::move(shape)), 0.0, identity, l, true, true));
                const std::string &name = links[static_cast<std::size_t>(l)].name;
                touch.push_back(std::find_if(std::begin(TOUCH_LINKS), std::end(TOUCH_LINKS),
                                             [&](const char *t) { return name == t; }) != std::end(TOUCH_LINKS));
                ++l;
            }
            for (const auto &pair : robot.selfCollisionPairs())
            {
                selfPairs.insert(pair);
            }
        }

        void setPose(btRigidBody *body, const btTransform &pose)
        {
            body->setWorldTransform(pose);
            if (body->getBroadphaseHandle() != nullptr)
            {
                world.updateSingleAabb(body);
            }
        }

        void poseArm(const double *q)
        {
            const auto transforms = model.arm().robot()->linkTransformsReference(q);
            const auto &links = model.arm().robot()->collisionLinks();
            for (std::size_t l = 0; l < arm.size(); ++l)
            {
                setPose(arm[l], toBt(transforms[static_cast<std::size_t>(links[l].link)]));
            }
            setPose(held, toBt(model.arm().endEffectorPose(q) * grasp));
        }

        bool touches(btCollisionObject *body, int user, bool cansBlock, Touch::Arm armMode, double threshold = 0.0)
        {
            Touch touchQuery(user, cansBlock, armMode, selfPairs, touch, threshold);
            world.contactTest(body, touchQuery);
            return touchQuery.hit;
        }

        /// the arm as posed (and the held can) touching the shelf, the cans in the world (\a cansBlock) or itself
        bool posedCollides(bool cansBlock, double within = 0.0)
        {
            for (std::size_t l = 0; l < arm.size(); ++l)
            {
                if (touches(arm[l], static_cast<int>(l), cansBlock, Touch::Arm::SelfPairs, within))
                {
                    return true;
                }
            }
            return heldCan >= 0 && touches(held, HELD, cansBlock, Touch::Arm::NotTouching, within);
        }

        void hold(int k)
        {
            const auto i = static_cast<std::size_t>(k);
            if (inWorld[i])
            {
                world.removeRigidBody(cans[i]);
                inWorld[i] = false;
            }
            if (heldCan < 0)
            {
                world.addRigidBody(held);
            }
            heldCan = k;
        }

        void unhold()
        {
            if (heldCan < 0)
            {
                return;
            }
            world.removeRigidBody(held);
            const auto i = static_cast<std::size_t>(heldCan);
            heldCan = -1;
            if (!inWorld[i])
            {
                world.addRigidBody(cans[i]);
                inWorld[i] = true;
            }
        }

        /// steps the dynamics until every can in the world is quiet for QUIET_STEPS steps (or settle_seconds)
        std::pair<double, bool> settle()
        {
            const double dt = config.timeStep;
            const auto steps = static_cast<int>(std::ceil(config.settleSeconds / dt));
            int quiet = 0;
            int i = 0;
            for (; i < steps && quiet < QUIET_STEPS; ++i)
            {
                world.stepSimulation(static_cast<btScalar>(dt), 0);
                double v = 0.0, w = 0.0;
                for (std::size_t k = 0; k < SHELF_CANS; ++k)
                {
                    if (inWorld[k])
                    {
                        v = std::max(v, static_cast<double>(cans[k]->getLinearVelocity().length()));
                        w = std::max(w, static_cast<double>(cans[k]->getAngularVelocity().length()));
                    }
                }
                quiet = v < config.settleSpeed && w < config.settleAngularSpeed ? quiet + 1 : 0;
            }
            for (auto *can : cans)
            {
                can->setLinearVelocity(btVector3(0, 0, 0));
                can->setAngularVelocity(btVector3(0, 0, 0));
            }
            return {i * dt, quiet >= QUIET_STEPS};
        }

        /// kinematic bodies start a physics pass at rest (Bullet derives their velocity from the pose change)
        void restKinematic()
        {
            for (auto *link : arm)
            {
                link->setInterpolationWorldTransform(link->getWorldTransform());
            }
            held->setInterpolationWorldTransform(held->getWorldTransform());
        }

        const ShelfMoveModel &model;
        const ShelfMoveConfig &config;
        Eigen::Isometry3d grasp{Eigen::Isometry3d::Identity()};
        bullet::CollisionCore core;
        btSequentialImpulseConstraintSolver solver;
        bullet::Storage storage;
        DynamicsFilter filter;
        btDiscreteDynamicsWorld world;  // after the storage: destroyed before it (releases the proxies itself)
        btCollisionShape *canShape{nullptr};
        btCollisionShape *heldShape{nullptr};
        std::array<btRigidBody *, SHELF_CANS> cans{};
        std::array<bool, SHELF_CANS> inWorld{};
        btRigidBody *held{nullptr};
        int heldCan{-1};
        std::vector<btRigidBody *> arm;
        std::vector<bool> touch;
        std::set<std::pair<int, int>> selfPairs;
    };

    ShelfMoveWorld::ShelfMoveWorld(std::shared_ptr<const ShelfMoveModel> model) : model_(std::move(model))
    {
        if (!model_)
        {
            throw Error("ShelfMoveWorld: null model");
        }
        reset(model_->trueInitialState());
    }

    ShelfMoveWorld::~ShelfMoveWorld() = default;

    void ShelfMoveWorld::reset(const State &initial)
    {
        impl_ = std::make_unique<Impl>(*model_);
        state_ = initial;
        state_.event = ShelfEvent::None;
        state_.eventCan = state_.eventSlot = -1;
        state_.worldReport = 0;
        for (std::size_t k = 0; k < SHELF_CANS; ++k)
        {
            const Eigen::Vector3d c(initial.can[k][0], initial.can[k][1], initial.can[k][2]);
            if (!c.allFinite())
            {
                throw Error("ShelfMoveWorld::reset: can " + std::to_string(k) + " has a non-finite centre");
            }
            impl_->setPose(impl_->cans[k], toBt(Eigen::Isometry3d(Eigen::Translation3d(c))));
        }
        if (initial.held >= 0 && initial.held < static_cast<int>(SHELF_CANS))
        {
            impl_->hold(initial.held);
        }
        impl_->poseArm(state_.q);
        readCans();
        settling_ = Settling();
    }

    void ShelfMoveWorld::readCans()
    {
        for (std::size_t k = 0; k < SHELF_CANS; ++k)
        {
            const btRigidBody *body = static_cast<int>(k) == impl_->heldCan ? impl_->held : impl_->cans[k];
            const btVector3 &c = body->getWorldTransform().getOrigin();
            state_.can[k][0] = c.x();
            state_.can[k][1] = c.y();
            state_.can[k][2] = c.z();
        }
        state_.held = impl_->heldCan;
    }

    Eigen::Isometry3d ShelfMoveWorld::canPose(std::size_t k) const
    {
        if (k >= SHELF_CANS)
        {
            throw Error("ShelfMoveWorld::canPose: can " + std::to_string(k) + " of " + std::to_string(SHELF_CANS));
        }
        const btRigidBody *body = static_cast<int>(k) == impl_->heldCan ? impl_->held : impl_->cans[k];
        return fromBt(body->getWorldTransform());
    }

    double ShelfMoveWorld::canTilt(std::size_t k) const
    {
        const double z = std::abs(canPose(k).linear()(2, 2));
        return std::acos(std::min(1.0, z));
    }

    bool ShelfMoveWorld::collides(const double *q, double within)
    {
        impl_->poseArm(q);
        const bool hit = impl_->posedCollides(!model_->config().pushCans, within);
        impl_->poseArm(state_.q);
        return hit;
    }

    bool ShelfMoveWorld::motionValid(const double *target, double *fraction, double within)
    {
        const double *q0 = state_.q;
        const std::size_t n = PandaArm::motionSamples(q0, target, model_->config().resolution);
        const bool cansBlock = !model_->config().pushCans;
        double q[ARM_DOF];
        bool valid = true;
        std::size_t k = 1;
        for (; k <= n; ++k)
        {
            PandaArm::interpolate(q0, target, static_cast<double>(k) / static_cast<double>(n), q);
            impl_->poseArm(q);
            if (impl_->posedCollides(cansBlock, within))
            {
                valid = false;
                break;
            }
        }
        impl_->poseArm(q0);
        if (fraction != nullptr)
        {
            *fraction = valid ? 1.0 : static_cast<double>(k - 1) / static_cast<double>(n);
        }
        return valid;
    }

    void ShelfMoveWorld::pushAlong(const double *target, double *fraction)
    {
        const ShelfMoveConfig &c = model_->config();
        double q0[ARM_DOF];
        std::copy(state_.q, state_.q + ARM_DOF, q0);
        double largest = 0.0;
        for (std::size_t j = 0; j < ARM_DOF; ++j)
        {
            largest = std::max(largest, std::abs(target[j] - q0[j]));
        }
        const auto steps =
            std::max<std::size_t>(PandaArm::motionSamples(q0, target, c.resolution),
                                  static_cast<std::size_t>(std::ceil(largest / c.pushJointSpeed / c.timeStep)));
        impl_->restKinematic();
        double q[ARM_DOF];
        *fraction = 1.0;
        for (std::size_t i = 1; i <= steps; ++i)
        {
            const double t = static_cast<double>(i) / static_cast<double>(steps);
            PandaArm::interpolate(q0, target, t, q);
            impl_->poseArm(q);
            if (impl_->posedCollides(false))
            {
                *fraction = static_cast<double>(i - 1) / static_cast<double>(steps);
                break;
            }
            impl_->world.stepSimulation(static_cast<btScalar>(c.timeStep), 0);
        }
        PandaArm::interpolate(q0, target, *fraction, q);
        impl_->poseArm(q);
        impl_->restKinematic();
        impl_->settle();
    }

    int ShelfMoveWorld::graspableCan()
    {
        if (impl_->heldCan >= 0)
        {
            return -1;
        }
        const ShelfMoveConfig &c = model_->config();
        const Eigen::Isometry3d ee = model_->arm().endEffectorPose(state_.q);
        const Eigen::Vector3d p = ee * Eigen::Vector3d(0.0, 0.0, c.graspOffset);
        const Eigen::Vector3d x = ee.linear().col(0);
        int best = -1;
        double bestDistance = c.graspTolerance;
        for (std::size_t k = 0; k < SHELF_CANS; ++k)
        {
            const Eigen::Isometry3d pose = canPose(k);
            const Eigen::Vector3d axis = pose.linear().col(2);
            if (std::abs(axis.dot(x)) < std::cos(c.graspAxisTolerance))
            {
                continue;
            }
            const double t = std::clamp((p - pose.translation()).dot(axis), -0.5 * c.canLength, 0.5 * c.canLength);
            const double d = (p - (pose.translation() + t * axis)).norm();
            if (d <= bestDistance)
            {
                bestDistance = d;
                best = static_cast<int>(k);
            }
        }
        return best;
    }

    bool ShelfMoveWorld::grasp(int k)
    {
        impl_->hold(k);
        impl_->poseArm(state_.q);  // the can snaps into the hand: its pose is the grasp transform's
        if (impl_->touches(impl_->held, HELD, true, Touch::Arm::NotTouching))
        {
            impl_->unhold();
            return false;
        }
        return true;
    }

    int ShelfMoveWorld::releaseSlot()
    {
        const int h = impl_->heldCan;
        if (h < 0)
        {
            return -1;
        }
        const ShelfMoveConfig &c = model_->config();
        const Eigen::Vector3d centre = fromBt(impl_->held->getWorldTransform().getOrigin());
        int best = -1;
        double bestDistance = c.placeTolerance;
        for (std::size_t i = 0; i < c.slots.size(); ++i)
        {
            const Eigen::Vector3d slot(c.slots[i][0], c.slots[i][1], c.slots[i][2]);
            const double d = (centre - slot).norm();
            if (d > bestDistance)
            {
                continue;
            }
            bool free = true;
            for (std::size_t j = 0; j < SHELF_CANS && free; ++j)
            {
                const Eigen::Vector3d o = canPose(j).translation();
                free = static_cast<int>(j) == h || std::abs(o.z() - slot.z()) >= c.canLength ||
                       std::hypot(o.x() - slot.x(), o.y() - slot.y()) >= 2.0 * c.canRadius;
            }
            if (free)
            {
                best = static_cast<int>(i);
                bestDistance = d;
            }
        }
        if (best < 0)
        {
            return -1;
        }
        // the open hand must be clear of the whole can where it is let go
        btRigidBody *can = impl_->cans[static_cast<std::size_t>(h)];
        can->setWorldTransform(impl_->held->getWorldTransform());
        Touch handQuery(CAN0 + h, false, Touch::Arm::All, impl_->selfPairs, impl_->touch, 0.0);
        handQuery.shelf_ = false;
        impl_->world.contactTest(can, handQuery);
        return handQuery.hit ? -1 : best;
    }

    ShelfMoveWorld::Settling ShelfMoveWorld::drop(std::size_t k, const Eigen::Isometry3d &pose)
    {
        if (k >= SHELF_CANS || !pose.matrix().allFinite())
        {
            throw Error("ShelfMoveWorld::drop: can " + std::to_string(k) + " of " + std::to_string(SHELF_CANS) +
                        " / its pose must be finite");
        }
        if (static_cast<int>(k) == impl_->heldCan)
        {
            impl_->unhold();
        }
        btRigidBody *can = impl_->cans[k];
        can->setWorldTransform(toBt(pose));
        can->setInterpolationWorldTransform(can->getWorldTransform());
        can->setLinearVelocity(btVector3(0, 0, 0));
        can->setAngularVelocity(btVector3(0, 0, 0));
        can->clearForces();
        impl_->world.updateSingleAabb(can);
        impl_->restKinematic();
        const auto [seconds, settled] = impl_->settle();
        settling_.can = static_cast<int>(k);
        settling_.from = pose.translation();
        settling_.to = canPose(k).translation();
        settling_.tilt = canTilt(k);
        settling_.seconds = seconds;
        settling_.settled = settled;
        readCans();
        return settling_;
    }

    void ShelfMoveWorld::release(int slot, pomdp::StepResult<State, Observation> &out)
    {
        const ShelfMoveConfig &c = model_->config();
        const int k = impl_->heldCan;
        const Eigen::Isometry3d pose = fromBt(impl_->held->getWorldTransform());
        const Settling s = drop(static_cast<std::size_t>(k), pose);
        const auto &slotCentre = c.slots[static_cast<std::size_t>(slot)];
        const double off = (s.to - Eigen::Vector3d(slotCentre[0], slotCentre[1], slotCentre[2])).norm();
        state_.event = ShelfEvent::Released;
        state_.eventCan = static_cast<std::int8_t>(k);
        state_.eventSlot = static_cast<std::int8_t>(slot);
        ++statistics_.releases;
        if (off > c.reportDistance)
        {
            state_.worldReport |= SHELF_REPORT_MOVED;
            ++statistics_.movedReleases;
        }
        if (s.tilt > c.tipAngle)
        {
            state_.worldReport |= SHELF_REPORT_TIPPED;
            ++statistics_.tippedReleases;
        }
        if (k == static_cast<int>(c.targetCan) && slot == static_cast<int>(c.reservedSlot) && s.tilt <= c.tipAngle &&
            off <= c.placeTolerance)
        {
            out.reward += c.goalReward;
            out.terminal = true;
        }
    }

    pomdp::StepResult<ShelfMoveModel::State, ShelfMoveModel::Observation> ShelfMoveWorld::step(const Action &action,
                                                                                               pomdp::Rng &rng)
    {
        const ShelfMoveConfig &c = model_->config();
        pomdp::StepResult<State, Observation> out;
        state_.event = ShelfEvent::None;
        state_.eventCan = state_.eventSlot = -1;
        state_.worldReport = 0;
        ++statistics_.steps;
        double target[ARM_DOF];
        model_->proposeMotion(state_, action, rng, target);
        const State before = state_;
        double fraction = 1.0;
        if (c.pushCans)
        {
            pushAlong(target, &fraction);
        }
        else
        {
            motionValid(target, &fraction);
        }
        // the model's verdict on the same motion from the same (world) state
        const bool worldValid = fraction >= 1.0;
        if (!worldValid)
        {
            ++statistics_.blockedSteps;
        }
        if (model_->motionValid(before, target, nullptr) != worldValid)
        {
            state_.worldReport |= SHELF_REPORT_VERDICT;
            ++statistics_.verdictDisagreements;
        }
        PandaArm::interpolate(before.q, target, fraction, state_.q);
        impl_->poseArm(state_.q);
        out.reward = c.stepReward;
        if (action.event == GripperEvent::Close)
        {
            const int k = graspableCan();
            if (k >= 0 && grasp(k))
            {
                state_.event = ShelfEvent::Grasped;
                state_.eventCan = static_cast<std::int8_t>(k);
                ++statistics_.grasps;
            }
        }
        else if (action.event == GripperEvent::Open)
        {
            const int slot = releaseSlot();
            if (slot >= 0)
            {
                release(slot, out);
            }
        }
        readCans();
        for (std::size_t k = 0; k < SHELF_CANS; ++k)
        {
            const bool moves = static_cast<int>(k) != before.held && static_cast<int>(k) != state_.eventCan;
            if (moves && std::hypot(state_.can[k][0] - before.can[k][0], state_.can[k][1] - before.can[k][1],
                                    state_.can[k][2] - before.can[k][2]) > c.reportDistance)
            {
                state_.worldReport |= SHELF_REPORT_PUSHED;
            }
        }
        if (state_.worldReport & SHELF_REPORT_PUSHED)
        {
            ++statistics_.pushedSteps;
        }
        model_->observe(state_, rng, out.observation);
        out.next = state_;
        return out;
    }
}  // namespace ropras::scenarios
