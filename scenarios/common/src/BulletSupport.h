#ifndef ROPRAS_SCENARIOS_BULLET_SUPPORT_H
#define ROPRAS_SCENARIOS_BULLET_SUPPORT_H

// Private to the scenarios library (its public headers keep Bullet out): what the scenarios' Bullet worlds share —
// Eigen <-> Bullet conversions, the collision core, ownership of shapes and objects, the arm's link bodies.
#include <btBulletCollisionCommon.h>

#include <Eigen/Core>
#include <Eigen/Geometry>
#include <memory>
#include <vector>

#include "ropras/ompl_ext/model/RobotModel.h"

namespace ropras::scenarios::bullet
{
    inline btVector3 toBt(const Eigen::Vector3d &v)
    {
        return btVector3(static_cast<btScalar>(v.x()), static_cast<btScalar>(v.y()), static_cast<btScalar>(v.z()));
    }

    inline btTransform toBt(const Eigen::Isometry3d &pose)
    {
        const Eigen::Matrix3d r = pose.rotation();
        btTransform t;
        t.setBasis(btMatrix3x3(
            static_cast<btScalar>(r(0, 0)), static_cast<btScalar>(r(0, 1)), static_cast<btScalar>(r(0, 2)),
            static_cast<btScalar>(r(1, 0)), static_cast<btScalar>(r(1, 1)), static_cast<btScalar>(r(1, 2)),
            static_cast<btScalar>(r(2, 0)), static_cast<btScalar>(r(2, 1)), static_cast<btScalar>(r(2, 2))));
        t.setOrigin(toBt(Eigen::Vector3d(pose.translation())));
        return t;
    }

    inline Eigen::Vector3d fromBt(const btVector3 &v)
    {
        return Eigen::Vector3d(v.x(), v.y(), v.z());
    }

    inline Eigen::Isometry3d fromBt(const btTransform &t)
    {
        Eigen::Isometry3d pose = Eigen::Isometry3d::Identity();
        const btMatrix3x3 &b = t.getBasis();
        for (int i = 0; i < 3; ++i)
        {
            for (int j = 0; j < 3; ++j)
            {
                pose.linear()(i, j) = b[i][j];
            }
        }
        pose.translation() = fromBt(t.getOrigin());
        return pose;
    }

    /** \brief The collision configuration, dispatcher and broadphase of one Bullet world: declare it before the
        world built on it. */
    struct CollisionCore
    {
        btDefaultCollisionConfiguration configuration;
        btCollisionDispatcher dispatcher{&configuration};
        btDbvtBroadphase broadphase;
    };

    /** \brief What must outlive a world's objects: declare it before the world, which is then destroyed first
        and releases the objects' broadphase proxies itself. (No removeCollisionObject() per object: Bullet finds
        each one by a linear search, so tearing down n objects would cost O(n^2).) */
    struct Storage
    {
        std::vector<std::unique_ptr<btTriangleMesh>> meshes;  ///< triangles of mesh shapes (outlive them)
        std::vector<std::unique_ptr<btCollisionShape>> shapes;
        std::vector<std::unique_ptr<btMotionState>> motionStates;
        std::vector<std::unique_ptr<btCollisionObject>> objects;

        template <class S>
        S *keep(std::unique_ptr<S> shape)
        {
            S *raw = shape.get();
            shapes.push_back(std::move(shape));
            return raw;
        }
    };

    /** \brief A new static collision object of \a shape at \a pose in \a world (kept in \a storage), with user
        index \a userIndex and contact processing threshold \a margin. */
    btCollisionObject *addObject(btCollisionWorld &world, Storage &storage, std::unique_ptr<btCollisionShape> shape,
                                 const btTransform &pose, int userIndex, double margin);

    /** \brief One compound shape per collision link of \a robot (RobotModel::collisionLinks order): the link's
        spheres in its frame (children kept in \a storage), to be posed by the link's reference FK. */
    std::vector<std::unique_ptr<btCompoundShape>> armLinkShapes(const ompl_ext::RobotModel &robot, Storage &storage);
}  // namespace ropras::scenarios::bullet

#endif
