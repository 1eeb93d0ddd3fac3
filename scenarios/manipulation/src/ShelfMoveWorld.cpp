#include "ropras/scenarios/manipulation/ShelfMoveWorld.h"

#include <algorithm>
#include <cmath>
#include <string>
#include <utility>
#include <vector>

#include "ShelfDynamics.h"
#include "ropras/core/Error.h"

namespace ropras::scenarios
{
    namespace
    {
        using bullet::fromBt;
        using bullet::toBt;
        using shelf_dynamics::CAN0;
        using shelf_dynamics::HELD;
        using shelf_dynamics::Touch;
    }  // namespace

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
