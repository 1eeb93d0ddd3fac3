#ifndef ROPRAS_SCENARIOS_MANIPULATION_SRC_SHELF_DYNAMICS_H
#define ROPRAS_SCENARIOS_MANIPULATION_SRC_SHELF_DYNAMICS_H

#include <btBulletDynamicsCommon.h>

#include <algorithm>
#include <array>
#include <set>
#include <utility>
#include <vector>

#include "BulletSupport.h"
#include "ropras/scenarios/manipulation/ShelfMoveWorld.h"

// Shelf-Move's Bullet dynamics world (btDiscreteDynamicsWorld): the static shelf and floor, the cans as dynamic
// bodies, the arm's links and the held can as kinematic bodies, contact queries and settling. ShelfMoveWorld.cpp
// decides the POMDP step on top of it (doc/scenario-shelf-move.md, "World").

namespace ropras::scenarios
{
    /// the pieces of Shelf-Move's Bullet world that ShelfMoveWorld's steps use too
    namespace shelf_dynamics
    {
        /// user indices: arm collision links 0.., the shelf's boxes, the floor, the held can, can k = CAN0 + k
        constexpr int SHELF = -1;
        constexpr int FLOOR = -2;
        constexpr int HELD = -3;
        constexpr int CAN0 = 1000;

        inline bool isCan(int user)
        {
            return user >= CAN0;
        }

        inline bool isArm(int user)
        {
            return user >= 0 && user < CAN0;
        }

        inline int userOf(const btBroadphaseProxy *proxy)
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
    }  // namespace shelf_dynamics

    /// The Bullet world of one episode, built from the model's configuration (its bodies' user indices as above)
    struct ShelfMoveWorld::Impl
    {
        explicit Impl(const ShelfMoveModel &m);
        /// a kinematic body is flagged before it joins the world (Bullet then keeps it among the moving bodies,
        /// whose velocity it derives from the pose change of each step)
        btRigidBody *addBody(btCollisionShape *shape, double mass, const btTransform &pose, int user, bool inWorld,
                             bool kinematic = false);
        void addShelf();  ///< the shelf's static boxes and the floor
        void addCans();   ///< the dynamic cans and the kinematic held-can query body (out of the world)
        void addArm();    ///< one kinematic body per collision link
        /// moves a body and refreshes its broadphase bounds
        void setPose(btRigidBody *body, const btTransform &pose);
        /// the arm's links at \a q, and the held-can body at the hand
        void poseArm(const double *q);
        /// whether \a body comes within \a threshold of what the query admits (cans if \a cansBlock, arm links by
        /// \a armMode, the shelf)
        bool touches(btCollisionObject *body, int user, bool cansBlock, shelf_dynamics::Touch::Arm armMode,
                     double threshold = 0.0);
        /// the arm as posed (and the held can) touching the shelf, the cans in the world (\a cansBlock) or itself
        bool posedCollides(bool cansBlock, double within = 0.0);
        /// can \a k leaves the dynamics and travels with the hand (the held-can body joins the world)
        void hold(int k);
        /// the held can's dynamic body rejoins the world, its pose the caller's to set (no-op when nothing is held)
        void unhold();
        /// steps the dynamics until every can in the world is quiet for QUIET_STEPS steps (or settle_seconds)
        std::pair<double, bool> settle();
        /// kinematic bodies start a physics pass at rest (Bullet derives their velocity from the pose change)
        void restKinematic();

        const ShelfMoveModel &model;
        const ShelfMoveConfig &config;
        Eigen::Isometry3d grasp{Eigen::Isometry3d::Identity()};
        bullet::CollisionCore core;
        btSequentialImpulseConstraintSolver solver;
        bullet::Storage storage;
        shelf_dynamics::DynamicsFilter filter;
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
}  // namespace ropras::scenarios

#endif
