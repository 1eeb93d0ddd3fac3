#include "ropras/scenarios/manipulation/ArmBulletWorld.h"

#include <BulletCollision/NarrowPhaseCollision/btRaycastCallback.h>
#include <btBulletCollisionCommon.h>

#include <algorithm>
#include <cmath>
#include <set>
#include <string>
#include <utility>
#include <vector>

#include "BulletSupport.h"
#include "ropras/core/Error.h"
#include "ropras/scenarios/manipulation/PandaArm.h"

namespace ropras::scenarios
{
    namespace
    {
        /// user index of obstacles (arm spheres carry their collision link index); HIDDEN: not seen by rays
        constexpr int OBSTACLE = -1;
        constexpr int HIDDEN = -2;
        /// user index of ray-only obstacles (addRayBox): no collision pairs
        constexpr int RAY_ONLY = -3;

        using bullet::toBt;

        /// admits obstacle-arm pairs and arm-arm pairs of self-collision links
        struct PairFilter final : btOverlapFilterCallback
        {
            bool needBroadphaseCollision(btBroadphaseProxy *a, btBroadphaseProxy *b) const override
            {
                const int la = static_cast<const btCollisionObject *>(a->m_clientObject)->getUserIndex();
                const int lb = static_cast<const btCollisionObject *>(b->m_clientObject)->getUserIndex();
                if (la == RAY_ONLY || lb == RAY_ONLY)
                {
                    return false;
                }
                if (la < 0 || lb < 0)
                {
                    return (la < 0) != (lb < 0);
                }
                if (la == lb)
                {
                    return false;
                }
                return selfPairs.count({std::min(la, lb), std::max(la, lb)}) > 0;
            }
            std::set<std::pair<int, int>> selfPairs;
        };

        struct ObstacleRay final : btCollisionWorld::ClosestRayResultCallback
        {
            ObstacleRay(const btVector3 &from, const btVector3 &to) : ClosestRayResultCallback(from, to)
            {
                // GJK rather than the sub-simplex cast against convex shapes (both approximate, GJK less so;
                // addRayBox's triangles are exact)
                m_flags = btTriangleRaycastCallback::kF_UseGjkConvexCastRaytest;
            }
            bool needsCollision(btBroadphaseProxy *proxy) const override
            {
                const int index = static_cast<const btCollisionObject *>(proxy->m_clientObject)->getUserIndex();
                return index == OBSTACLE || index == RAY_ONLY;
            }
        };

        /// the solid obstacles a probe touches
        struct ProbeContact final : btCollisionWorld::ContactResultCallback
        {
            static bool solid(const btCollisionObject *o)
            {
                return o->getUserIndex() == OBSTACLE || o->getUserIndex() == HIDDEN;
            }
            bool needsCollision(btBroadphaseProxy *proxy) const override
            {
                return solid(static_cast<const btCollisionObject *>(proxy->m_clientObject));
            }
            btScalar addSingleResult(btManifoldPoint &cp, const btCollisionObjectWrapper *a, int, int,
                                     const btCollisionObjectWrapper *b, int, int) override
            {
                if (cp.getDistance() <= 0)
                {
                    hits.push_back(solid(a->getCollisionObject()) ? a->getCollisionObject() : b->getCollisionObject());
                }
                return 0;
            }
            std::vector<const btCollisionObject *> hits;
        };
    }  // namespace

    struct ArmBulletWorld::Impl
    {
        Impl(std::shared_ptr<const ompl_ext::RobotModel> r, double m)
            : robot(std::move(r)), margin(m), world(&core.dispatcher, &core.broadphase, &core.configuration)
        {
        }

        btCollisionObject *add(std::unique_ptr<btCollisionShape> shape, const btTransform &pose, int userIndex)
        {
            return bullet::addObject(world, storage, std::move(shape), pose, userIndex, margin);
        }

        bool collides(const double *q)
        {
            // the reference FK of every link; each collision link is one body (its spheres, compound)
            const auto links = robot->linkTransformsReference(q);
            const auto &collisionLinks = robot->collisionLinks();
            for (std::size_t i = 0; i < arm.size(); ++i)
            {
                arm[i]->setWorldTransform(toBt(links[static_cast<std::size_t>(collisionLinks[i].link)]));
            }
            world.updateAabbs();
            world.performDiscreteCollisionDetection();
            const int manifolds = core.dispatcher.getNumManifolds();
            for (int m = 0; m < manifolds; ++m)
            {
                const btPersistentManifold *manifold = core.dispatcher.getManifoldByIndexInternal(m);
                for (int c = 0; c < manifold->getNumContacts(); ++c)
                {
                    if (manifold->getContactPoint(c).getDistance() <= static_cast<btScalar>(margin))
                    {
                        return true;
                    }
                }
            }
            return false;
        }

        std::shared_ptr<const ompl_ext::RobotModel> robot;
        double margin;
        PairFilter filter;
        bullet::CollisionCore core;
        bullet::Storage storage;
        btCollisionWorld world;  // after the storage: destroyed before it (releases the proxies itself)
        std::vector<btCollisionObject *> arm;
        std::size_t obstacles{0};
    };

    ArmBulletWorld::ArmBulletWorld(std::shared_ptr<const ompl_ext::RobotModel> robot, double contactMargin)
    {
        if (!robot)
        {
            throw Error("ArmBulletWorld: null robot");
        }
        if (!(contactMargin >= 0.0) || !std::isfinite(contactMargin))
        {
            throw Error("ArmBulletWorld: contact margin " + std::to_string(contactMargin) +
                        " is not a finite value >= 0");
        }
        impl_ = std::make_unique<Impl>(std::move(robot), contactMargin);
        for (const auto &pair : impl_->robot->selfCollisionPairs())
        {
            impl_->filter.selfPairs.insert(pair);
        }
        impl_->world.getPairCache()->setOverlapFilterCallback(&impl_->filter);
        btTransform identity;
        identity.setIdentity();
        int link = 0;
        for (auto &shape : bullet::armLinkShapes(*impl_->robot, impl_->storage))
        {
            impl_->arm.push_back(impl_->add(std::move(shape), identity, link++));
        }
    }

    ArmBulletWorld::~ArmBulletWorld() = default;

    std::size_t ArmBulletWorld::addSphere(const Eigen::Vector3d &center, double radius, bool detectable)
    {
        if (!center.allFinite() || !(radius > 0.0) || !std::isfinite(radius))
        {
            throw Error("ArmBulletWorld::addSphere: the centre and radius (" + std::to_string(radius) +
                        ") must be finite with radius > 0");
        }
        impl_->add(std::make_unique<btSphereShape>(static_cast<btScalar>(radius)),
                   toBt(Eigen::Isometry3d(Eigen::Translation3d(center))), detectable ? OBSTACLE : HIDDEN);
        return impl_->obstacles++;
    }

    std::size_t ArmBulletWorld::addBox(const Eigen::Isometry3d &pose, const Eigen::Vector3d &fullExtents,
                                       bool detectable)
    {
        if (!pose.matrix().allFinite() || !fullExtents.allFinite() || !(fullExtents.minCoeff() > 0.0))
        {
            throw Error("ArmBulletWorld::addBox: the pose and extents must be finite with extents > 0");
        }
        auto shape = std::make_unique<btBoxShape>(toBt(Eigen::Vector3d(0.5 * fullExtents)));
        shape->setMargin(0);  // exact corners
        impl_->add(std::move(shape), toBt(pose), detectable ? OBSTACLE : HIDDEN);
        return impl_->obstacles++;
    }

    std::size_t ArmBulletWorld::addCylinder(const Eigen::Isometry3d &pose, double radius, double length,
                                            bool detectable)
    {
        if (!pose.matrix().allFinite() || !(radius > 0.0) || !(length > 0.0) || !std::isfinite(radius) ||
            !std::isfinite(length))
        {
            throw Error("ArmBulletWorld::addCylinder: the pose, radius and length must be finite with sizes > 0");
        }
        auto shape = std::make_unique<btCylinderShapeZ>(btVector3(
            static_cast<btScalar>(radius), static_cast<btScalar>(radius), static_cast<btScalar>(0.5 * length)));
        shape->setMargin(0);
        impl_->add(std::move(shape), toBt(pose), detectable ? OBSTACLE : HIDDEN);
        return impl_->obstacles++;
    }

    std::size_t ArmBulletWorld::addRayBox(const Eigen::Isometry3d &pose, const Eigen::Vector3d &fullExtents)
    {
        if (!pose.matrix().allFinite() || !fullExtents.allFinite() || !(fullExtents.minCoeff() > 0.0))
        {
            throw Error("ArmBulletWorld::addRayBox: the pose and extents must be finite with extents > 0");
        }
        auto mesh = std::make_unique<btTriangleMesh>();
        const Eigen::Vector3d h = 0.5 * fullExtents;
        const auto corner = [&](int i)
        { return toBt(Eigen::Vector3d((i & 1) ? h.x() : -h.x(), (i & 2) ? h.y() : -h.y(), (i & 4) ? h.z() : -h.z())); };
        // two triangles per face: the faces normal to x (bit 1), y (bit 2), z (bit 4), at -h and +h
        for (int axis = 0; axis < 3; ++axis)
        {
            const int bit = 1 << axis, u = 1 << ((axis + 1) % 3), v = 1 << ((axis + 2) % 3);
            for (int side = 0; side < 2; ++side)
            {
                const int base = side ? bit : 0;
                mesh->addTriangle(corner(base), corner(base | u), corner(base | u | v));
                mesh->addTriangle(corner(base), corner(base | u | v), corner(base | v));
            }
        }
        auto shape = std::make_unique<btBvhTriangleMeshShape>(mesh.get(), true);
        impl_->storage.meshes.push_back(std::move(mesh));
        impl_->add(std::move(shape), toBt(pose), RAY_ONLY);
        return impl_->obstacles++;
    }

    std::size_t ArmBulletWorld::obstacleCount() const
    {
        return impl_->obstacles;
    }

    bool ArmBulletWorld::collides(const double *q)
    {
        return impl_->collides(q);
    }

    bool ArmBulletWorld::motionValid(const double *q0, const double *q1, double resolution, double *lastValidFraction)
    {
        const std::size_t dof = impl_->robot->dof();
        const std::size_t n = PandaArm::motionSamples(q0, q1, resolution);
        std::vector<double> q(dof);
        for (std::size_t k = 1; k <= n; ++k)
        {
            const double t = static_cast<double>(k) / static_cast<double>(n);
            for (std::size_t j = 0; j < dof; ++j)
            {
                q[j] = q0[j] + t * (q1[j] - q0[j]);
            }
            if (impl_->collides(q.data()))
            {
                if (lastValidFraction != nullptr)
                {
                    *lastValidFraction = static_cast<double>(k - 1) / static_cast<double>(n);
                }
                return false;
            }
        }
        if (lastValidFraction != nullptr)
        {
            *lastValidFraction = 1.0;
        }
        return true;
    }

    int ArmBulletWorld::rayTest(const Eigen::Vector3d &from, const Eigen::Vector3d &to, double *fraction) const
    {
        ObstacleRay ray(toBt(from), toBt(to));
        impl_->world.rayTest(toBt(from), toBt(to), ray);
        if (!ray.hasHit())
        {
            return -1;
        }
        if (fraction != nullptr)
        {
            *fraction = ray.m_closestHitFraction;
        }
        int index = 0;
        for (const auto &object : impl_->storage.objects)
        {
            if (object.get() == ray.m_collisionObject)
            {
                return index - static_cast<int>(impl_->arm.size());
            }
            ++index;
        }
        return -1;
    }

    int ArmBulletWorld::containing(const Eigen::Vector3d &p) const
    {
        // Boxes and z cylinders (the world's solid obstacles) from their Bullet shapes, exactly: contactTest's GJK
        // misses a probe sphere a fraction of a millimetre inside a box without margin. Other shapes: contactTest.
        btSphereShape probeShape(static_cast<btScalar>(1e-4));
        btCollisionObject probe;
        probe.setCollisionShape(&probeShape);
        probe.setWorldTransform(toBt(Eigen::Isometry3d(Eigen::Translation3d(p))));
        ProbeContact contact;
        bool probed = false;
        int index = 0;
        for (const auto &object : impl_->storage.objects)
        {
            const int at = index++;
            if (!ProbeContact::solid(object.get()))
            {
                continue;
            }
            const btVector3 local = object->getWorldTransform().invXform(toBt(p));
            const btCollisionShape *shape = object->getCollisionShape();
            bool inside = false;
            if (shape->getShapeType() == BOX_SHAPE_PROXYTYPE)
            {
                const btVector3 h = static_cast<const btBoxShape *>(shape)->getHalfExtentsWithMargin();
                inside = std::abs(local.x()) <= h.x() && std::abs(local.y()) <= h.y() && std::abs(local.z()) <= h.z();
            }
            else if (shape->getShapeType() == CYLINDER_SHAPE_PROXYTYPE &&
                     static_cast<const btCylinderShape *>(shape)->getUpAxis() == 2)
            {
                const btVector3 h = static_cast<const btCylinderShape *>(shape)->getHalfExtentsWithMargin();
                inside = local.x() * local.x() + local.y() * local.y() <= h.x() * h.x() && std::abs(local.z()) <= h.z();
            }
            else
            {
                if (!probed)
                {
                    impl_->world.contactTest(&probe, contact);
                    probed = true;
                }
                inside = std::find(contact.hits.begin(), contact.hits.end(), object.get()) != contact.hits.end();
            }
            if (inside)
            {
                return at - static_cast<int>(impl_->arm.size());
            }
        }
        return -1;
    }
}  // namespace ropras::scenarios
