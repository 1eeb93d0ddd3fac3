#include "ropras/scenarios/BulletCollisionWorld.h"

#include <btBulletCollisionCommon.h>

#include <cmath>
#include <string>
#include <vector>

#include "ropras/core/Error.h"

namespace ropras::scenarios
{
    namespace
    {
        btVector3 toBt(const Eigen::Vector3d &v)
        {
            return btVector3(static_cast<btScalar>(v.x()), static_cast<btScalar>(v.y()), static_cast<btScalar>(v.z()));
        }

        bool finite(const Eigen::Vector3d &v)
        {
            return v.allFinite();
        }

        std::string str(const Eigen::Vector3d &v)
        {
            return "(" + std::to_string(v.x()) + ", " + std::to_string(v.y()) + ", " + std::to_string(v.z()) + ")";
        }

        /// Records whether any contact point is within the margin (distance <= margin).
        struct AnyContact final : btCollisionWorld::ContactResultCallback
        {
            explicit AnyContact(btScalar margin) : margin_(margin) {}
            btScalar addSingleResult(btManifoldPoint &cp, const btCollisionObjectWrapper *, int, int,
                                     const btCollisionObjectWrapper *, int, int) override
            {
                if (cp.getDistance() <= margin_)
                {
                    hit = true;
                }
                return 0;
            }
            bool hit{false};
            btScalar margin_;
        };
    }  // namespace

    struct BulletCollisionWorld::Impl
    {
        explicit Impl(double margin)
            : margin(margin), dispatcher(&configuration), world(&dispatcher, &broadphase, &configuration)
        {
        }
        // No removeCollisionObject() per object: Bullet finds each one by a linear search, so tearing down n
        // objects cost O(n^2) (100 000 obstacles: seconds). The world is declared after the objects and shapes, so
        // it is destroyed first and releases their broadphase proxies itself; then the objects are freed.

        btCollisionObject *addObject(std::unique_ptr<btCollisionShape> shape, const Eigen::Vector3d &position)
        {
            auto object = std::make_unique<btCollisionObject>();
            object->setCollisionShape(shape.get());
            btTransform t;
            t.setIdentity();
            t.setOrigin(toBt(position));
            object->setWorldTransform(t);
            object->setContactProcessingThreshold(static_cast<btScalar>(margin));
            world.addCollisionObject(object.get());
            shapes.push_back(std::move(shape));
            objects.push_back(std::move(object));
            return objects.back().get();
        }

        double margin;
        btDefaultCollisionConfiguration configuration;
        btCollisionDispatcher dispatcher;
        btDbvtBroadphase broadphase;
        std::vector<std::unique_ptr<btCollisionShape>> shapes;
        std::vector<std::unique_ptr<btCollisionObject>> objects;
        btCollisionWorld world;  // after the objects: destroyed before them
        std::size_t obstacles{0};
        std::vector<btCollisionObject *> agents;
    };

    BulletCollisionWorld::BulletCollisionWorld(double contactMargin)
    {
        if (!(contactMargin >= 0.0) || !std::isfinite(contactMargin))
        {
            throw Error("BulletCollisionWorld: contact margin " + std::to_string(contactMargin) +
                        " is not a finite value >= 0");
        }
        impl_ = std::make_unique<Impl>(contactMargin);
    }

    BulletCollisionWorld::~BulletCollisionWorld() = default;

    std::size_t BulletCollisionWorld::addBox(const Eigen::Vector3d &center, const Eigen::Vector3d &halfExtents)
    {
        if (!finite(center) || !finite(halfExtents) || !(halfExtents.minCoeff() > 0.0))
        {
            throw Error("BulletCollisionWorld::addBox: centre " + str(center) + " / half extents " + str(halfExtents) +
                        " must be finite with half extents > 0");
        }
        // Zero margin: the box is exact (Bullet otherwise rounds its corners by the margin).
        auto shape = std::make_unique<btBoxShape>(toBt(halfExtents));
        shape->setMargin(0);
        impl_->addObject(std::move(shape), center);
        return impl_->obstacles++;
    }

    std::size_t BulletCollisionWorld::addSphere(const Eigen::Vector3d &center, double radius)
    {
        if (!finite(center) || !(radius > 0.0) || !std::isfinite(radius))
        {
            throw Error("BulletCollisionWorld::addSphere: centre " + str(center) + " / radius " +
                        std::to_string(radius) + " must be finite with radius > 0");
        }
        impl_->addObject(std::make_unique<btSphereShape>(static_cast<btScalar>(radius)), center);
        return impl_->obstacles++;
    }

    std::size_t BulletCollisionWorld::addAgent(double radius, const Eigen::Vector3d &position)
    {
        if (!finite(position) || !(radius > 0.0) || !std::isfinite(radius))
        {
            throw Error("BulletCollisionWorld::addAgent: position " + str(position) + " / radius " +
                        std::to_string(radius) + " must be finite with radius > 0");
        }
        impl_->agents.push_back(
            impl_->addObject(std::make_unique<btSphereShape>(static_cast<btScalar>(radius)), position));
        return impl_->agents.size() - 1;
    }

    void BulletCollisionWorld::setAgentPosition(std::size_t agent, const Eigen::Vector3d &position)
    {
        if (agent >= impl_->agents.size() || !finite(position))
        {
            throw Error("BulletCollisionWorld::setAgentPosition: agent " + std::to_string(agent) + " of " +
                        std::to_string(impl_->agents.size()) + " / position " + str(position) + " is invalid");
        }
        btCollisionObject *object = impl_->agents[agent];
        object->getWorldTransform().setOrigin(toBt(position));
        impl_->world.updateSingleAabb(object);
    }

    Eigen::Vector3d BulletCollisionWorld::agentPosition(std::size_t agent) const
    {
        if (agent >= impl_->agents.size())
        {
            throw Error("BulletCollisionWorld::agentPosition: agent " + std::to_string(agent) + " of " +
                        std::to_string(impl_->agents.size()) + " does not exist");
        }
        const btVector3 &p = impl_->agents[agent]->getWorldTransform().getOrigin();
        return Eigen::Vector3d(p.x(), p.y(), p.z());
    }

    bool BulletCollisionWorld::collides(std::size_t agent, const Eigen::Vector3d &position) const
    {
        if (agent >= impl_->agents.size() || !finite(position))
        {
            throw Error("BulletCollisionWorld::collides: agent " + std::to_string(agent) + " of " +
                        std::to_string(impl_->agents.size()) + " / position " + str(position) + " is invalid");
        }
        btCollisionObject *object = impl_->agents[agent];
        const btTransform saved = object->getWorldTransform();
        object->getWorldTransform().setOrigin(toBt(position));
        // contactTest computes the probe's AABB from its (temporary) transform and skips the object itself.
        AnyContact callback(static_cast<btScalar>(impl_->margin));
        impl_->world.contactTest(object, callback);
        object->setWorldTransform(saved);
        return callback.hit;
    }

    std::size_t BulletCollisionWorld::obstacleCount() const
    {
        return impl_->obstacles;
    }

    std::size_t BulletCollisionWorld::agentCount() const
    {
        return impl_->agents.size();
    }
}  // namespace ropras::scenarios
