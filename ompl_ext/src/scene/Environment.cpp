#include "ropras/ompl_ext/scene/Environment.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <sstream>

#include "ropras/core/Error.h"

namespace ropras::ompl_ext
{
    namespace
    {
        const char *shapeTypeName(ShapeType type)
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

        void validateShape(const std::string &object, std::size_t k, const Shape &shape)
        {
            std::ostringstream where;
            where << "Environment: object '" << object << "' shape " << k << " (" << shapeTypeName(shape.type) << "): ";
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

        /// signed distance from point p (primitive frame) to the primitive's surface, negative inside
        double primitiveDistance(const Shape &shape, const Eigen::Vector3d &p)
        {
            switch (shape.type)
            {
                case ShapeType::Sphere:
                    return p.norm() - shape.radius;
                case ShapeType::Box:
                {
                    const Eigen::Vector3d q = p.cwiseAbs() - 0.5 * shape.extents;
                    return q.cwiseMax(0.0).norm() + std::min(q.maxCoeff(), 0.0);
                }
                case ShapeType::Cylinder:
                {
                    const double dr = std::hypot(p.x(), p.y()) - shape.radius;
                    const double dh = std::abs(p.z()) - 0.5 * shape.length;
                    return std::hypot(std::max(dr, 0.0), std::max(dh, 0.0)) + std::min(std::max(dr, dh), 0.0);
                }
                case ShapeType::Capsule:
                {
                    const double h = 0.5 * shape.length;
                    const double z = std::clamp(p.z(), -h, h);
                    return (p - Eigen::Vector3d(0.0, 0.0, z)).norm() - shape.radius;
                }
                case ShapeType::PointCloud:
                    return shape.cloud->signedDistance(p, 0.0);
            }
            return std::numeric_limits<double>::infinity();
        }
    }  // namespace

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

    int Environment::addObject(const std::string &name, std::vector<Shape> shapes, const Eigen::Isometry3d &pose)
    {
        if (name.empty())
            throw Error("Environment: an object needs a non-empty name");
        if (hasObject(name))
            throw Error("Environment: duplicate object name '" + name + "'");
        if (shapes.empty())
            throw Error("Environment: object '" + name + "' has no shapes");
        const std::string poseError = poseProblem(pose);
        if (!poseError.empty())
            throw Error("Environment: object '" + name + "': " + poseError);
        for (std::size_t k = 0; k < shapes.size(); ++k)
            validateShape(name, k, shapes[k]);

        Object object;
        object.name = name;
        object.pose = pose;
        object.shapes = std::move(shapes);
        object.slots.reserve(object.shapes.size());
        for (const Shape &shape : object.shapes)
        {
            switch (shape.type)
            {
                case ShapeType::Sphere:
                    object.slots.push_back(static_cast<int>(spheres_.size()));
                    spheres_.emplace_back();
                    break;
                case ShapeType::Box:
                    object.slots.push_back(static_cast<int>(boxes_.size()));
                    boxes_.emplace_back();
                    break;
                case ShapeType::Cylinder:
                    object.slots.push_back(static_cast<int>(cylinders_.size()));
                    cylinders_.emplace_back();
                    break;
                case ShapeType::Capsule:
                    object.slots.push_back(static_cast<int>(capsules_.size()));
                    capsules_.emplace_back();
                    break;
                case ShapeType::PointCloud:
                    object.slots.push_back(static_cast<int>(clouds_.size()));
                    clouds_.emplace_back();
                    break;
            }
        }
        index_.emplace(object.name, static_cast<int>(objects_.size()));
        objects_.push_back(std::move(object));
        writeQueryForm(objects_.back());
        return static_cast<int>(objects_.size()) - 1;
    }

    int Environment::addSphere(const std::string &name, const Eigen::Vector3d &center, double radius)
    {
        Eigen::Isometry3d pose = Eigen::Isometry3d::Identity();
        pose.translation() = center;
        return addObject(name, {Shape::sphere(radius)}, pose);
    }

    int Environment::addBox(const std::string &name, const Eigen::Isometry3d &pose, const Eigen::Vector3d &fullExtents)
    {
        return addObject(name, {Shape::box(fullExtents)}, pose);
    }

    int Environment::addCylinder(const std::string &name, const Eigen::Isometry3d &pose, double radius, double length)
    {
        return addObject(name, {Shape::cylinder(radius, length)}, pose);
    }

    int Environment::addCapsule(const std::string &name, const Eigen::Isometry3d &pose, double radius, double length)
    {
        return addObject(name, {Shape::capsule(radius, length)}, pose);
    }

    int Environment::addPointCloud(const std::string &name, std::shared_ptr<const PointCloud> cloud,
                                   const Eigen::Isometry3d &pose)
    {
        return addObject(name, {Shape::pointCloud(std::move(cloud))}, pose);
    }

    void Environment::setObjectPose(int id, const Eigen::Isometry3d &pose)
    {
        if (id < 0 || static_cast<std::size_t>(id) >= objects_.size())
            throw Error("Environment::setObjectPose: object id " + std::to_string(id) + " out of range (" +
                        std::to_string(objects_.size()) + " objects)");
        Object &object = objects_[static_cast<std::size_t>(id)];
        const std::string poseError = poseProblem(pose);
        if (!poseError.empty())
            throw Error("Environment::setObjectPose: object '" + object.name + "': " + poseError);
        object.pose = pose;
        writeQueryForm(object);
    }

    const Eigen::Isometry3d &Environment::objectPose(int id) const
    {
        if (id < 0 || static_cast<std::size_t>(id) >= objects_.size())
            throw Error("Environment::objectPose: object id " + std::to_string(id) + " out of range (" +
                        std::to_string(objects_.size()) + " objects)");
        return objects_[static_cast<std::size_t>(id)].pose;
    }

    int Environment::objectId(const std::string &name) const
    {
        const auto it = index_.find(name);
        if (it != index_.end())
            return it->second;
        std::string known;  // the first 20 names (a scene may have 100 000 objects)
        for (std::size_t i = 0; i < objects_.size() && i < 20; ++i)
            known += (known.empty() ? "" : ", ") + objects_[i].name;
        if (objects_.size() > 20)
            known += ", ... (" + std::to_string(objects_.size()) + " objects)";
        throw Error("Environment: unknown object '" + name + "' (objects: " + (known.empty() ? "none" : known) + ")");
    }

    bool Environment::hasObject(const std::string &name) const
    {
        return index_.count(name) != 0;
    }

    const std::string &Environment::objectName(int id) const
    {
        if (id < 0 || static_cast<std::size_t>(id) >= objects_.size())
            throw Error("Environment::objectName: object id " + std::to_string(id) + " out of range (" +
                        std::to_string(objects_.size()) + " objects)");
        return objects_[static_cast<std::size_t>(id)].name;
    }

    const std::vector<Shape> &Environment::objectShapes(int id) const
    {
        if (id < 0 || static_cast<std::size_t>(id) >= objects_.size())
            throw Error("Environment::objectShapes: object id " + std::to_string(id) + " out of range (" +
                        std::to_string(objects_.size()) + " objects)");
        return objects_[static_cast<std::size_t>(id)].shapes;
    }

    void Environment::clear()
    {
        objects_.clear();
        index_.clear();
        spheres_.clear();
        boxes_.clear();
        cylinders_.clear();
        capsules_.clear();
        clouds_.clear();
    }

    Eigen::Isometry3d Environment::shapeWorldPose(int id, std::size_t k) const
    {
        const std::vector<Shape> &shapes = objectShapes(id);
        if (k >= shapes.size())
            throw Error("Environment::shapeWorldPose: object '" + objects_[static_cast<std::size_t>(id)].name +
                        "' has " + std::to_string(shapes.size()) + " shapes, asked for shape " + std::to_string(k));
        return objects_[static_cast<std::size_t>(id)].pose * shapes[k].pose;
    }

    namespace
    {
        ObstacleAabb inflated(float cx, float cy, float cz, float ex, float ey, float ez)
        {
            const auto grow = [](float e) { return e * (1.0f + 1e-5f) + 1e-5f; };
            return {cx, cy, cz, grow(ex), grow(ey), grow(ez)};
        }

        ObstacleAabb worldBox(const SphereObstacle &o)
        {
            return inflated(o.x, o.y, o.z, o.r, o.r, o.r);
        }

        ObstacleAabb worldBox(const BoxObstacle &o)
        {
            // the box axes are the columns of rot: the world half extent along i is sum_j |R_ij| h_j
            const float *r = o.rot;
            return inflated(o.cx, o.cy, o.cz, std::abs(r[0]) * o.hx + std::abs(r[1]) * o.hy + std::abs(r[2]) * o.hz,
                            std::abs(r[3]) * o.hx + std::abs(r[4]) * o.hy + std::abs(r[5]) * o.hz,
                            std::abs(r[6]) * o.hx + std::abs(r[7]) * o.hy + std::abs(r[8]) * o.hz);
        }

        ObstacleAabb worldBox(const CylinderObstacle &o)
        {
            // axis term |a_i| L/2 plus the rim disc's half extent R sqrt(1 - a_i^2)
            const auto e = [&](float a)
            { return std::abs(a) * o.halfLength + o.radius * std::sqrt(std::max(0.0f, 1.0f - a * a)); };
            return inflated(o.cx, o.cy, o.cz, e(o.ax), e(o.ay), e(o.az));
        }

        ObstacleAabb worldBox(const CapsuleObstacle &o)
        {
            return inflated(o.ax + 0.5f * o.dx, o.ay + 0.5f * o.dy, o.az + 0.5f * o.dz,
                            0.5f * std::abs(o.dx) + o.radius, 0.5f * std::abs(o.dy) + o.radius,
                            0.5f * std::abs(o.dz) + o.radius);
        }

        ObstacleAabb worldBox(const CloudObstacle &o)
        {
            return inflated(o.cx, o.cy, o.cz, o.boundRadius, o.boundRadius, o.boundRadius);
        }
    }  // namespace

    void Environment::writeQueryForm(const Object &object)
    {
        for (std::size_t k = 0; k < object.shapes.size(); ++k)
        {
            const Shape &shape = object.shapes[k];
            const Eigen::Isometry3d world = object.pose * shape.pose;
            const Eigen::Vector3d c = world.translation();
            const Eigen::Matrix3d r = world.linear();
            const auto slot = static_cast<std::size_t>(object.slots[k]);
            switch (shape.type)
            {
                case ShapeType::Sphere:
                {
                    SphereObstacle &o = spheres_[slot];
                    o.x = static_cast<float>(c.x());
                    o.y = static_cast<float>(c.y());
                    o.z = static_cast<float>(c.z());
                    o.r = static_cast<float>(shape.radius);
                    o.aabb = worldBox(o);
                    break;
                }
                case ShapeType::Box:
                {
                    BoxObstacle &b = boxes_[slot];
                    b.cx = static_cast<float>(c.x());
                    b.cy = static_cast<float>(c.y());
                    b.cz = static_cast<float>(c.z());
                    for (int i = 0; i < 3; ++i)
                        for (int j = 0; j < 3; ++j)
                            b.rot[3 * i + j] = static_cast<float>(r(i, j));
                    b.hx = static_cast<float>(0.5 * shape.extents.x());
                    b.hy = static_cast<float>(0.5 * shape.extents.y());
                    b.hz = static_cast<float>(0.5 * shape.extents.z());
                    b.boundRadius = static_cast<float>(0.5 * shape.extents.norm());
                    b.aabb = worldBox(b);
                    break;
                }
                case ShapeType::Cylinder:
                {
                    CylinderObstacle &y = cylinders_[slot];
                    const Eigen::Vector3d axis = r.col(2);
                    y.cx = static_cast<float>(c.x());
                    y.cy = static_cast<float>(c.y());
                    y.cz = static_cast<float>(c.z());
                    y.ax = static_cast<float>(axis.x());
                    y.ay = static_cast<float>(axis.y());
                    y.az = static_cast<float>(axis.z());
                    y.halfLength = static_cast<float>(0.5 * shape.length);
                    y.radius = static_cast<float>(shape.radius);
                    y.boundRadius = static_cast<float>(std::hypot(0.5 * shape.length, shape.radius));
                    y.aabb = worldBox(y);
                    break;
                }
                case ShapeType::Capsule:
                {
                    CapsuleObstacle &p = capsules_[slot];
                    const Eigen::Vector3d d = r.col(2) * shape.length;
                    const Eigen::Vector3d a = c - 0.5 * d;
                    p.ax = static_cast<float>(a.x());
                    p.ay = static_cast<float>(a.y());
                    p.az = static_cast<float>(a.z());
                    p.dx = static_cast<float>(d.x());
                    p.dy = static_cast<float>(d.y());
                    p.dz = static_cast<float>(d.z());
                    p.radius = static_cast<float>(shape.radius);
                    p.invLengthSq = shape.length > 0.0 ? static_cast<float>(1.0 / (shape.length * shape.length)) : 0.0f;
                    p.aabb = worldBox(p);
                    break;
                }
                case ShapeType::PointCloud:
                {
                    CloudObstacle &q = clouds_[slot];
                    q.cloud = shape.cloud;
                    q.worldToCloud = world.inverse().cast<float>();
                    if (shape.cloud->size() == 0)
                    {
                        q.cx = q.cy = q.cz = 0.0f;
                        q.boundRadius = -1.0f;  // empty: never touched
                    }
                    else
                    {
                        const Eigen::Vector3d lo = shape.cloud->boundsMin().cast<double>();
                        const Eigen::Vector3d hi = shape.cloud->boundsMax().cast<double>();
                        const Eigen::Vector3d centre = world * (0.5 * (lo + hi));
                        q.cx = static_cast<float>(centre.x());
                        q.cy = static_cast<float>(centre.y());
                        q.cz = static_cast<float>(centre.z());
                        // a little slack for float rounding of the transformed points
                        q.boundRadius = static_cast<float>(0.5 * (hi - lo).norm() + shape.cloud->pointRadius() +
                                                           1e-5 * (1.0 + centre.norm() + (hi - lo).norm()));
                    }
                    q.aabb = worldBox(q);
                    break;
                }
            }
        }
    }

    double Environment::signedDistance(const Eigen::Vector3d &center, double radius) const
    {
        double best = std::numeric_limits<double>::infinity();
        for (const Object &object : objects_)
            for (const Shape &shape : object.shapes)
            {
                const Eigen::Isometry3d world = object.pose * shape.pose;
                const Eigen::Vector3d p = world.inverse(Eigen::Isometry) * center;
                best = std::min(best, primitiveDistance(shape, p) - radius);
            }
        return best;
    }
}  // namespace ropras::ompl_ext
