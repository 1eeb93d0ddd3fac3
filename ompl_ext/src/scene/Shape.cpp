#include "ropras/ompl_ext/scene/Shape.h"

#include <cmath>
#include <sstream>
#include <utility>

#include "ropras/core/Error.h"
#include "scene/ShapeValidation.h"

namespace ropras::ompl_ext
{
    const char *shapeTypeName(ShapeType type) noexcept
    {
        switch (type)
        {
            case ShapeType::Sphere:
                return "sphere";
            case ShapeType::Box:
                return "box";
            case ShapeType::Cylinder:
                return "cylinder";
            case ShapeType::Capsule:
                return "capsule";
            case ShapeType::PointCloud:
                return "point cloud";
        }
        return "unknown";
    }

    namespace detail
    {
        /// empty string when \a pose is a finite rigid transform, otherwise what is wrong with it
        std::string poseProblem(const Eigen::Isometry3d &pose)
        {
            if (!pose.matrix().allFinite())
                return "non-finite pose";
            const Eigen::Matrix3d r = pose.linear();
            if ((r.transpose() * r - Eigen::Matrix3d::Identity()).cwiseAbs().maxCoeff() > 1e-6 || r.determinant() < 0.0)
                return "pose rotation is not a proper rotation (orthonormal, determinant +1)";
            const Eigen::RowVector4d lastRow = pose.matrix().row(3);
            if ((lastRow - Eigen::RowVector4d(0, 0, 0, 1)).cwiseAbs().maxCoeff() > 0.0)
                return "pose is not affine (last row must be 0 0 0 1)";
            return {};
        }

        bool positiveFinite(double x)
        {
            return std::isfinite(x) && x > 0.0;
        }

        void validateShape(const std::string &owner, std::size_t k, const Shape &shape)
        {
            std::ostringstream where;
            where << owner << " shape " << k << " (" << shapeTypeName(shape.type) << "): ";
            const std::string poseError = poseProblem(shape.pose);
            if (!poseError.empty())
                throw Error(where.str() + poseError);
            switch (shape.type)
            {
                case ShapeType::Sphere:
                    if (!positiveFinite(shape.radius))
                        throw Error(where.str() + "radius must be positive and finite, got " +
                                    std::to_string(shape.radius));
                    break;
                case ShapeType::Box:
                    for (int i = 0; i < 3; ++i)
                        if (!positiveFinite(shape.extents[i]))
                        {
                            std::ostringstream msg;
                            msg << where.str() << "extents must be positive and finite, got (" << shape.extents.x()
                                << ", " << shape.extents.y() << ", " << shape.extents.z() << ")";
                            throw Error(msg.str());
                        }
                    break;
                case ShapeType::Cylinder:
                    if (!positiveFinite(shape.radius) || !positiveFinite(shape.length))
                        throw Error(where.str() + "radius and length must be positive and finite, got radius " +
                                    std::to_string(shape.radius) + ", length " + std::to_string(shape.length));
                    break;
                case ShapeType::Capsule:
                    if (!positiveFinite(shape.radius) || !std::isfinite(shape.length) || shape.length < 0.0)
                        throw Error(where.str() +
                                    "radius must be positive and length non-negative, both finite; got radius " +
                                    std::to_string(shape.radius) + ", length " + std::to_string(shape.length));
                    break;
                case ShapeType::PointCloud:
                    if (!shape.cloud)
                        throw Error(where.str() + "no point cloud given (null pointer)");
                    break;
                default:
                    throw Error(where.str() + "unknown shape type");
            }
        }

    }  // namespace detail

    Shape Shape::sphere(double radius, const Eigen::Isometry3d &pose)
    {
        Shape s;
        s.type = ShapeType::Sphere;
        s.radius = radius;
        s.pose = pose;
        return s;
    }

    Shape Shape::box(const Eigen::Vector3d &fullExtents, const Eigen::Isometry3d &pose)
    {
        Shape s;
        s.type = ShapeType::Box;
        s.extents = fullExtents;
        s.pose = pose;
        return s;
    }

    Shape Shape::cylinder(double radius, double length, const Eigen::Isometry3d &pose)
    {
        Shape s;
        s.type = ShapeType::Cylinder;
        s.radius = radius;
        s.length = length;
        s.pose = pose;
        return s;
    }

    Shape Shape::capsule(double radius, double length, const Eigen::Isometry3d &pose)
    {
        Shape s;
        s.type = ShapeType::Capsule;
        s.radius = radius;
        s.length = length;
        s.pose = pose;
        return s;
    }

    Shape Shape::pointCloud(std::shared_ptr<const PointCloud> cloud, const Eigen::Isometry3d &pose)
    {
        Shape s;
        s.type = ShapeType::PointCloud;
        s.cloud = std::move(cloud);
        s.pose = pose;
        return s;
    }

}  // namespace ropras::ompl_ext
