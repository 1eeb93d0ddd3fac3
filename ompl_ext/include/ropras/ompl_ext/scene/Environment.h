#ifndef ROPRAS_OMPL_EXT_ENVIRONMENT_H
#define ROPRAS_OMPL_EXT_ENVIRONMENT_H

#include <Eigen/Geometry>
#include <memory>
#include <string>
#include <unordered_map>
#include <vector>

#include "ropras/ompl_ext/scene/PointCloud.h"

namespace ropras::ompl_ext
{
    /** \brief Kinds of obstacle primitives. */
    enum class ShapeType
    {
        Sphere,
        Box,
        Cylinder,
        Capsule,
        PointCloud
    };

    /** \brief An obstacle primitive in its object's frame (the authoring form).
        Sphere: radius. Box: full extents (x, y, z). Cylinder and capsule: radius and length along local z
        (for a capsule the length is that of the segment between the two cap centres). */
    struct Shape
    {
        ShapeType type{ShapeType::Sphere};
        Eigen::Isometry3d pose{Eigen::Isometry3d::Identity()};  ///< primitive pose in the object frame
        double radius{0.0};
        double length{0.0};
        Eigen::Vector3d extents{Eigen::Vector3d::Zero()};
        std::shared_ptr<const PointCloud> cloud;  ///< for ShapeType::PointCloud

        static Shape sphere(double radius, const Eigen::Isometry3d &pose = Eigen::Isometry3d::Identity());
        static Shape box(const Eigen::Vector3d &fullExtents,
                         const Eigen::Isometry3d &pose = Eigen::Isometry3d::Identity());
        static Shape cylinder(double radius, double length,
                              const Eigen::Isometry3d &pose = Eigen::Isometry3d::Identity());
        static Shape capsule(double radius, double length,
                             const Eigen::Isometry3d &pose = Eigen::Isometry3d::Identity());
        static Shape pointCloud(std::shared_ptr<const PointCloud> cloud,
                                const Eigen::Isometry3d &pose = Eigen::Isometry3d::Identity());
    };

    // Query form: float, world frame, what the collision kernels read.

    /** \brief World axis-aligned box around a primitive (centre, half extents), enlarged by 1e-5 (relative) +
        1e-5 m so that float rounding can never make it cull a contact the exact test finds. Computed with the rest
        of the query form (when an object is added or moved), read by every check. */
    struct ObstacleAabb
    {
        float cx, cy, cz, ex, ey, ez;
    };

    struct SphereObstacle
    {
        float x, y, z, r;
        ObstacleAabb aabb;
    };
    struct BoxObstacle  ///< p_box = R^T (p - c); rot is R row-major (columns are the box axes in the world)
    {
        float cx, cy, cz;
        float rot[9];
        float hx, hy, hz;
        float boundRadius;  ///< radius of the box's bounding sphere around c
        ObstacleAabb aabb;
    };
    struct CylinderObstacle  ///< exact solid cylinder: centre, unit axis, half length, radius
    {
        float cx, cy, cz;
        float ax, ay, az;
        float halfLength, radius;
        float boundRadius;
        ObstacleAabb aabb;
    };
    struct CapsuleObstacle  ///< segment from a to a + d (d not unit), radius
    {
        float ax, ay, az;
        float dx, dy, dz;
        float radius;
        float invLengthSq;  ///< 1 / |d|^2, 0 for a degenerate (sphere) capsule
        ObstacleAabb aabb;
    };
    struct CloudObstacle
    {
        std::shared_ptr<const PointCloud> cloud;
        Eigen::Isometry3f worldToCloud;
        float cx, cy, cz, boundRadius;  ///< world bounding sphere of the inflated cloud
        ObstacleAabb aabb;
    };

    /** \brief A set of named obstacles. Value type: copying is cheap (primitives are a few floats each,
        point clouds are shared), and setObjectPose() moves one object in O(its primitives) — the POMDP
        layer keeps one Environment per belief particle when obstacle poses are uncertain.

        Errors (duplicate or unknown names, non-positive or non-finite sizes, non-finite poses) throw
        ropras::Error naming the object. */
    class Environment
    {
    public:
        /// adds an object made of \a shapes at \a pose; returns its id (ids are dense, from 0)
        int addObject(const std::string &name, std::vector<Shape> shapes,
                      const Eigen::Isometry3d &pose = Eigen::Isometry3d::Identity());
        int addSphere(const std::string &name, const Eigen::Vector3d &center, double radius);
        int addBox(const std::string &name, const Eigen::Isometry3d &pose, const Eigen::Vector3d &fullExtents);
        int addCylinder(const std::string &name, const Eigen::Isometry3d &pose, double radius, double length);
        int addCapsule(const std::string &name, const Eigen::Isometry3d &pose, double radius, double length);
        int addPointCloud(const std::string &name, std::shared_ptr<const PointCloud> cloud,
                          const Eigen::Isometry3d &pose = Eigen::Isometry3d::Identity());

        void setObjectPose(int id, const Eigen::Isometry3d &pose);
        void setObjectPose(const std::string &name, const Eigen::Isometry3d &pose)
        {
            setObjectPose(objectId(name), pose);
        }
        const Eigen::Isometry3d &objectPose(int id) const;
        int objectId(const std::string &name) const;  ///< throws Error listing the object names if unknown
        bool hasObject(const std::string &name) const;
        std::size_t objectCount() const { return objects_.size(); }
        const std::string &objectName(int id) const;
        const std::vector<Shape> &objectShapes(int id) const;
        void clear();

        /// world pose of primitive \a k of object \a id
        Eigen::Isometry3d shapeWorldPose(int id, std::size_t k) const;

        // query form
        const std::vector<SphereObstacle> &spheres() const { return spheres_; }
        const std::vector<BoxObstacle> &boxes() const { return boxes_; }
        const std::vector<CylinderObstacle> &cylinders() const { return cylinders_; }
        const std::vector<CapsuleObstacle> &capsules() const { return capsules_; }
        const std::vector<CloudObstacle> &clouds() const { return clouds_; }

        /// exact signed distance (double) from a sphere to the nearest obstacle surface: negative when
        /// penetrating, +infinity for an empty environment. Reference computation for tests and tools.
        double signedDistance(const Eigen::Vector3d &center, double radius) const;

    private:
        struct Object
        {
            std::string name;
            Eigen::Isometry3d pose;
            std::vector<Shape> shapes;
            std::vector<int> slots;  ///< per shape: index into the query vector of its type
        };
        void writeQueryForm(const Object &object);
        std::vector<Object> objects_;
        /// object name -> index into objects_ (so adding n objects costs O(n), not O(n^2) name comparisons)
        std::unordered_map<std::string, int> index_;
        std::vector<SphereObstacle> spheres_;
        std::vector<BoxObstacle> boxes_;
        std::vector<CylinderObstacle> cylinders_;
        std::vector<CapsuleObstacle> capsules_;
        std::vector<CloudObstacle> clouds_;
    };
}  // namespace ropras::ompl_ext

#endif
