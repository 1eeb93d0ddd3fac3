#ifndef ROPRAS_SCENARIOS_MANIPULATION_ARM_BULLET_WORLD_H
#define ROPRAS_SCENARIOS_MANIPULATION_ARM_BULLET_WORLD_H

#include <Eigen/Geometry>
#include <cstddef>
#include <memory>

#include "ropras/ompl_ext/model/RobotModel.h"

namespace ropras::scenarios
{
    /** \brief The physics side of the arm scenarios: a Bullet collision world (btCollisionWorld, dynamic AABB
        tree broadphase) holding static obstacles and the arm as its collision bodies: one body per collision
        link of the RobotModel (a btCompoundShape of the link's btSphereShapes), moved kinematically to each
        configuration asked about.

        The sphere centres come from the model's double-precision reference FK (RobotModel::
        linkTransformsReference, which walks the URDF joints, independently of the SIMD checker's compiled
        frames). A configuration collides when a link touches an obstacle, or two links of a self-collision
        pair (RobotModel::selfCollisionPairs) touch: Bullet's broadphase filter admits exactly those pairs, its
        narrowphase (compound against sphere, box, cylinder or compound) decides. Bullet stays private (pimpl). Not
       thread-safe: one instance per episode. */
    class ArmBulletWorld
    {
    public:
        /** \brief \a contactMargin: shapes closer than this (m) count as touching (>= 0, finite). */
        explicit ArmBulletWorld(std::shared_ptr<const ompl_ext::RobotModel> robot, double contactMargin = 0.0);
        ~ArmBulletWorld();
        ArmBulletWorld(const ArmBulletWorld &) = delete;
        ArmBulletWorld &operator=(const ArmBulletWorld &) = delete;

        /** \brief Static obstacles; each returns its index. Throw ropras::Error for non-finite values or
            non-positive sizes. A \a detectable obstacle is seen by rayTest; every obstacle blocks the arm. */
        std::size_t addSphere(const Eigen::Vector3d &center, double radius, bool detectable = true);
        std::size_t addBox(const Eigen::Isometry3d &pose, const Eigen::Vector3d &fullExtents, bool detectable = true);
        std::size_t addCylinder(const Eigen::Isometry3d &pose, double radius, double length, bool detectable = true);
        /** \brief A box that only rays see (a btBvhTriangleMeshShape of its 12 triangles: rayTest is exact
            against triangles, while Bullet's ray cast against convex shapes is off by up to cm); it blocks
            nothing. Pair it with a non-detectable box of the same pose for collisions. Returns its index. */
        std::size_t addRayBox(const Eigen::Isometry3d &pose, const Eigen::Vector3d &fullExtents);
        std::size_t obstacleCount() const;

        /** \brief Whether the arm at \a q (dof() values) touches an obstacle or itself. */
        bool collides(const double *q);

        /** \brief The straight motion q0 -> q1 checked at the configurations q0 + (k/n)(q1 - q0), k = 1..n,
            n = PandaArm::motionSamples (the SIMD checker's rule). True when none collides; otherwise
            \a lastValidFraction (if non-null) gets (k-1)/n for the first colliding k. */
        bool motionValid(const double *q0, const double *q1, double resolution, double *lastValidFraction = nullptr);

        /** \brief btCollisionWorld::rayTest from \a from to \a to against the detectable obstacles only (the
            arm and the other obstacles are neither hit nor occlude): the index of the closest obstacle hit, or -1; \a
           fraction gets the hit's fraction along the segment. */
        int rayTest(const Eigen::Vector3d &from, const Eigen::Vector3d &to, double *fraction = nullptr) const;

        /** \brief The smallest index of a solid obstacle (not a ray box) that contains the point \a p, or -1:
            rayTest does not report the shape a ray starts inside. Boxes and z cylinders are tested exactly in
            their Bullet shapes' frames; other shapes with contactTest of a 0.1 mm probe sphere. */
        int containing(const Eigen::Vector3d &p) const;

    private:
        struct Impl;
        std::unique_ptr<Impl> impl_;
    };
}  // namespace ropras::scenarios

#endif
