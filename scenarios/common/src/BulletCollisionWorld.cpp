#include "ropras/scenarios/BulletCollisionWorld.h"

#include <cmath>
#include <string>
#include <utility>
#include <vector>

#include "BulletSupport.h"
#include "ropras/core/Error.h"

namespace ropras::scenarios
{
    namespace
    {
        using bullet::toBt;

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

        /// Records which objects are within the margin of the probe: obstacles (user index -1) and agents (their
        /// index, set as the user index).
        struct WhichContacts final : btCollisionWorld::ContactResultCallback
        {
            WhichContacts(const btCollisionObject *probe, btScalar margin) : probe_(probe), margin_(margin) {}
            btScalar addSingleResult(btManifoldPoint &cp, const btCollisionObjectWrapper *a, int, int,
                                     const btCollisionObjectWrapper *b, int, int) override
            {
                if (cp.getDistance() > margin_)
                {
                    return 0;
                }
                const btCollisionObject *other =
                    a->getCollisionObject() == probe_ ? b->getCollisionObject() : a->getCollisionObject();
                const int index = other->getUserIndex();
                if (index < 0)
                {
                    result.obstacle = true;
                }
                else if (index < 64)
                {
                    result.agents |= std::uint64_t{1} << index;
                }
                return 0;
            }
            BulletCollisionWorld::Touching result;
            const btCollisionObject *probe_;
            btScalar margin_;
        };

        bool finite(const Eigen::Isometry3d &pose)
        {
            return pose.matrix().allFinite();
        }
    }  // namespace

    struct BulletCollisionWorld::Impl
    {
        explicit Impl(double m) : margin(m), world(&core.dispatcher, &core.broadphase, &core.configuration) {}

        btCollisionObject *addObject(std::unique_ptr<btCollisionShape> shape, const Eigen::Vector3d &position)
        {
            return bullet::addObject(world, storage, std::move(shape),
                                     toBt(Eigen::Isometry3d(Eigen::Translation3d(position))), -1, margin);
        }

        double margin;
        bullet::CollisionCore core;
        bullet::Storage storage;
        btCollisionWorld world;  // after the storage: destroyed before it
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
        impl_->agents.back()->setUserIndex(static_cast<int>(impl_->agents.size() - 1));
        return impl_->agents.size() - 1;
    }

    std::size_t BulletCollisionWorld::addRigidAgent(const std::vector<std::pair<Eigen::Vector3d, double>> &spheres,
                                                    const Eigen::Isometry3d &pose)
    {
        if (spheres.empty() || !finite(pose))
        {
            throw Error("BulletCollisionWorld::addRigidAgent: " +
                        std::string(spheres.empty() ? "no spheres" : "a non-finite pose"));
        }
        auto compound = std::make_unique<btCompoundShape>(true, static_cast<int>(spheres.size()));
        for (const auto &[centre, radius] : spheres)
        {
            if (!finite(centre) || !(radius > 0.0) || !std::isfinite(radius))
            {
                throw Error("BulletCollisionWorld::addRigidAgent: sphere " + str(centre) + " / radius " +
                            std::to_string(radius) + " must be finite with radius > 0");
            }
            auto child = std::make_unique<btSphereShape>(static_cast<btScalar>(radius));
            btTransform t;
            t.setIdentity();
            t.setOrigin(toBt(centre));
            compound->addChildShape(t, child.get());
            impl_->storage.shapes.push_back(std::move(child));
        }
        btCollisionObject *object = impl_->addObject(std::move(compound), Eigen::Vector3d::Zero());
        object->setWorldTransform(toBt(pose));
        impl_->world.updateSingleAabb(object);
        impl_->agents.push_back(object);
        object->setUserIndex(static_cast<int>(impl_->agents.size() - 1));
        return impl_->agents.size() - 1;
    }

    void BulletCollisionWorld::setAgentPose(std::size_t agent, const Eigen::Isometry3d &pose)
    {
        if (agent >= impl_->agents.size() || !finite(pose))
        {
            throw Error("BulletCollisionWorld::setAgentPose: agent " + std::to_string(agent) + " of " +
                        std::to_string(impl_->agents.size()) + " / its pose is invalid");
        }
        btCollisionObject *object = impl_->agents[agent];
        object->setWorldTransform(toBt(pose));
        impl_->world.updateSingleAabb(object);
    }

    BulletCollisionWorld::Touching BulletCollisionWorld::touching(std::size_t agent,
                                                                  const Eigen::Isometry3d &pose) const
    {
        if (agent >= impl_->agents.size() || !finite(pose))
        {
            throw Error("BulletCollisionWorld::touching: agent " + std::to_string(agent) + " of " +
                        std::to_string(impl_->agents.size()) + " / its pose is invalid");
        }
        btCollisionObject *object = impl_->agents[agent];
        const btTransform saved = object->getWorldTransform();
        object->setWorldTransform(toBt(pose));
        WhichContacts callback(object, static_cast<btScalar>(impl_->margin));
        impl_->world.contactTest(object, callback);
        object->setWorldTransform(saved);
        return callback.result;
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
