#include "BulletSupport.h"

#include <utility>

namespace ropras::scenarios::bullet
{
    btCollisionObject *addObject(btCollisionWorld &world, Storage &storage, std::unique_ptr<btCollisionShape> shape,
                                 const btTransform &pose, int userIndex, double margin)
    {
        auto object = std::make_unique<btCollisionObject>();
        object->setCollisionShape(storage.keep(std::move(shape)));
        object->setWorldTransform(pose);
        object->setUserIndex(userIndex);
        object->setContactProcessingThreshold(static_cast<btScalar>(margin));
        world.addCollisionObject(object.get());
        storage.objects.push_back(std::move(object));
        return storage.objects.back().get();
    }

    std::vector<std::unique_ptr<btCompoundShape>> armLinkShapes(const ompl_ext::RobotModel &robot, Storage &storage)
    {
        std::vector<std::unique_ptr<btCompoundShape>> out;
        const auto &spheres = robot.spheres();
        const auto &links = robot.collisionLinks();
        for (const auto &link : links)
        {
            auto compound = std::make_unique<btCompoundShape>(true, link.sphereCount);
            for (int i = link.firstSphere; i < link.firstSphere + link.sphereCount; ++i)
            {
                const auto &sphere = spheres[static_cast<std::size_t>(i)];
                btTransform local;
                local.setIdentity();
                local.setOrigin(toBt(sphere.centerInLink));
                compound->addChildShape(
                    local, storage.keep(std::make_unique<btSphereShape>(static_cast<btScalar>(sphere.radius))));
            }
            out.push_back(std::move(compound));
        }
        return out;
    }
}  // namespace ropras::scenarios::bullet
