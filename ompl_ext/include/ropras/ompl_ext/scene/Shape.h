#ifndef ROPRAS_OMPL_EXT_SHAPE_H
#define ROPRAS_OMPL_EXT_SHAPE_H

#include <Eigen/Geometry>
#include <memory>

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
    /// "sphere", "box", "cylinder", "capsule", "point cloud"
    const char *shapeTypeName(ShapeType type) noexcept;

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

}  // namespace ropras::ompl_ext

#endif
