#ifndef ROPRAS_OMPL_EXT_FCL_REFERENCE_CHECKER_H
#define ROPRAS_OMPL_EXT_FCL_REFERENCE_CHECKER_H

#include <memory>
#include <string>

#include "ropras/ompl_ext/model/RobotModel.h"
#include "ropras/ompl_ext/scene/Environment.h"

namespace ropras::ompl_ext
{
    /** \brief Independent reference collision checkers built on FCL 0.7 (double precision), for tests and
        tools: they share no code with CollisionChecker's float kernels. The robot is posed by the
        RobotModel's reference FK (RobotModel::sphereCentersReference / linkTransformsReference), the
        obstacles are built from the Environment's authoring form (Shape, in double): boxes, cylinders,
        spheres and capsules as FCL primitives, point clouds as one sphere per point.

        A configuration is valid when it is finite, within the joint limits, touches no obstacle and no
        RobotModel::selfCollisionPairs() pair touches. Obstacle candidates are found by FCL's dynamic AABB
        tree and self pairs by an AABB overlap test (both exact: disjoint boxes cannot hold touching shapes);
        every verdict comes from FCL's narrow phase.

        The FCL objects of the last Environment seen are cached (rebuilt when any shape, pose or cloud
        differs). The const methods are thread-safe: calls on one checker are serialized by a mutex. They
        allocate and are meant for tests and tools, not hot paths (tens of microseconds per check). */
    class FclSphereChecker
    {
    public:
        /// the robot's collision spheres (RobotModel::spheres()) as fcl::Sphere
        explicit FclSphereChecker(std::shared_ptr<const RobotModel> robot);
        ~FclSphereChecker();
        FclSphereChecker(const FclSphereChecker &) = delete;
        FclSphereChecker &operator=(const FclSphereChecker &) = delete;

        const RobotModel &robot() const { return *robot_; }

        /// false when \a q is non-finite, out of limits, or in collision
        bool isValid(const Environment &env, const double *q) const;
        /** \brief Signed minimum distance over every robot sphere vs obstacle pair and every self pair:
            negative when penetrating (minus the deepest penetration), +infinity when there is no pair.
            Exact for the sphere model. Throws ropras::Error when \a q is non-finite. */
        double distance(const Environment &env, const double *q) const;
        /// "" when \a q is collision-free (limits are not considered), else which spheres touch what
        std::string describeCollision(const Environment &env, const double *q) const;

    private:
        struct Impl;
        std::shared_ptr<const RobotModel> robot_;
        std::unique_ptr<Impl> impl_;
    };

    /** \brief The same reference for the URDF's own collision geometry (RobotModel::collisionGeometries()):
        meshes (loadMesh) as FCL BVH models with OBBRSS bounding volumes, boxes, cylinders and spheres as FCL
        primitives, posed at RobotModel::linkTransformsReference(q); self-collision over the link pairs of
        RobotModel::selfCollisionPairs(). Use it with the mesh URDF to measure how conservative a sphere
        model is. Loading the meshes happens in the constructor (throws ropras::Error naming the file).

        distance(): positive values are FCL's exact minimum distance; for penetrating pairs involving a mesh
        the negative value is FCL's contact penetration estimate (the depth reported at triangle contacts). */
    class FclMeshChecker
    {
    public:
        explicit FclMeshChecker(std::shared_ptr<const RobotModel> robot);
        ~FclMeshChecker();
        FclMeshChecker(const FclMeshChecker &) = delete;
        FclMeshChecker &operator=(const FclMeshChecker &) = delete;

        const RobotModel &robot() const { return *robot_; }
        /// number of collision geometries (meshes and primitives) posed per check
        std::size_t geometryCount() const;
        /// total number of mesh triangles
        std::size_t triangleCount() const;

        bool isValid(const Environment &env, const double *q) const;
        double distance(const Environment &env, const double *q) const;
        std::string describeCollision(const Environment &env, const double *q) const;

    private:
        struct Impl;
        std::shared_ptr<const RobotModel> robot_;
        std::unique_ptr<Impl> impl_;
    };
}  // namespace ropras::ompl_ext

#endif
