#include "ShelfDynamics.h"

#include <algorithm>
#include <cmath>
#include <iterator>
#include <memory>
#include <string>

namespace ropras::scenarios
{
    namespace
    {
        using bullet::toBt;
        using shelf_dynamics::CAN0;
        using shelf_dynamics::FLOOR;
        using shelf_dynamics::HELD;
        using shelf_dynamics::SHELF;
        using shelf_dynamics::Touch;

        /// what the held can may touch (as in the model): the hand holding it and its fingers
        const char *const TOUCH_LINKS[] = {"panda_hand", "panda_leftfinger", "panda_rightfinger"};
        /// consecutive quiet physics steps that count as settled
        constexpr int QUIET_STEPS = 12;
    }  // namespace

    ShelfMoveWorld::Impl::Impl(const ShelfMoveModel &m)
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
    btRigidBody *ShelfMoveWorld::Impl::addBody(btCollisionShape *shape, double mass, const btTransform &pose, int user,
                                               bool inWorld, bool kinematic)
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

    void ShelfMoveWorld::Impl::addShelf()
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

    void ShelfMoveWorld::Impl::addCans()
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

    void ShelfMoveWorld::Impl::addArm()
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

    void ShelfMoveWorld::Impl::setPose(btRigidBody *body, const btTransform &pose)
    {
        body->setWorldTransform(pose);
        if (body->getBroadphaseHandle() != nullptr)
        {
            world.updateSingleAabb(body);
        }
    }

    void ShelfMoveWorld::Impl::poseArm(const double *q)
    {
        const auto transforms = model.arm().robot()->linkTransformsReference(q);
        const auto &links = model.arm().robot()->collisionLinks();
        for (std::size_t l = 0; l < arm.size(); ++l)
        {
            setPose(arm[l], toBt(transforms[static_cast<std::size_t>(links[l].link)]));
        }
        setPose(held, toBt(model.arm().endEffectorPose(q) * grasp));
    }

    bool ShelfMoveWorld::Impl::touches(btCollisionObject *body, int user, bool cansBlock, Touch::Arm armMode,
                                       double threshold)
    {
        Touch touchQuery(user, cansBlock, armMode, selfPairs, touch, threshold);
        world.contactTest(body, touchQuery);
        return touchQuery.hit;
    }

    /// the arm as posed (and the held can) touching the shelf, the cans in the world (\a cansBlock) or itself
    bool ShelfMoveWorld::Impl::posedCollides(bool cansBlock, double within)
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

    void ShelfMoveWorld::Impl::hold(int k)
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

    void ShelfMoveWorld::Impl::unhold()
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
    std::pair<double, bool> ShelfMoveWorld::Impl::settle()
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
    void ShelfMoveWorld::Impl::restKinematic()
    {
        for (auto *link : arm)
        {
            link->setInterpolationWorldTransform(link->getWorldTransform());
        }
        held->setInterpolationWorldTransform(held->getWorldTransform());
    }
}  // namespace ropras::scenarios
