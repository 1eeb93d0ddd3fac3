#include "ropras/ompl_ext/scene/Environment.h"

#include <algorithm>
#include <atomic>
#include <cmath>
#include <iterator>
#include <limits>
#include <sstream>

#include "ropras/core/Error.h"
#include "scene/ShapeValidation.h"

namespace ropras::ompl_ext
{
    namespace
    {
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

    int Environment::addObject(const std::string &name, std::vector<Shape> shapes, const Eigen::Isometry3d &pose)
    {
        if (name.empty())
            throw Error("Environment: an object needs a non-empty name");
        if (nameInUse(name))
            throw Error("Environment: duplicate object name '" + name + "'");
        if (shapes.empty())
            throw Error("Environment: object '" + name + "' has no shapes");
        const std::string poseError = detail::poseProblem(pose);
        if (!poseError.empty())
            throw Error("Environment: object '" + name + "': " + poseError);
        for (std::size_t k = 0; k < shapes.size(); ++k)
            detail::validateShape("Environment: object '" + name + "'", k, shapes[k]);

        Layout &layout = ownLayout();
        auto def = std::make_shared<ObjectDefinition>();
        def->name = name;
        def->shapes = std::move(shapes);
        def->firstPrimitive = layout.primitives.size();
        const int id = static_cast<int>(poses_.size());
        const auto append = [](auto &queryVector)
        {
            queryVector.emplace_back();
            return static_cast<int>(queryVector.size()) - 1;
        };
        for (const Shape &shape : def->shapes)
        {
            layout.owners[static_cast<std::size_t>(shape.type)].push_back(id);
            int slot = 0;
            switch (shape.type)
            {
                case ShapeType::Sphere:
                    slot = append(spheres_);
                    break;
                case ShapeType::Box:
                    slot = append(boxes_);
                    break;
                case ShapeType::Cylinder:
                    slot = append(cylinders_);
                    break;
                case ShapeType::Capsule:
                    slot = append(capsules_);
                    break;
                case ShapeType::PointCloud:
                    slot = append(clouds_);
                    break;
            }
            layout.primitives.push_back({shape.type, slot});
        }
        layout.index.emplace(def->name, id);
        layout.objects.push_back(std::move(def));
        poses_.push_back(pose.affine());
        index_.added(layout.primitives.size());  // before the boxes are written: a stale tree is not refitted
        writeQueryForm(id);
        extendBoxChunks();
        return id;
    }

    void Environment::extendBoxChunks()
    {
        const std::size_t n = layout_->primitives.size();
        if (n < static_cast<std::size_t>(OBSTACLE_BOX_LANES))
            return;
        const std::size_t first = boxChunks_.size() * OBSTACLE_BOX_LANES;  // primitives before it have their lanes
        while (boxChunks_.size() * OBSTACLE_BOX_LANES < n)
        {
            // lanes without a primitive: extents -infinity, so that no sphere ever touches them
            ObstacleBoxChunk empty{};
            std::fill(std::begin(empty.ex), std::end(empty.ex), -std::numeric_limits<float>::infinity());
            std::fill(std::begin(empty.ey), std::end(empty.ey), -std::numeric_limits<float>::infinity());
            std::fill(std::begin(empty.ez), std::end(empty.ez), -std::numeric_limits<float>::infinity());
            boxChunks_.push_back(empty);
        }
        for (std::size_t k = first; k < n; ++k)
        {
            const PrimitiveRef &r = layout_->primitives[k];
            const auto i = static_cast<std::size_t>(r.slot);
            switch (r.type)
            {
                case ShapeType::Sphere:
                    setBox(k, spheres_[i].aabb);
                    break;
                case ShapeType::Box:
                    setBox(k, boxes_[i].aabb);
                    break;
                case ShapeType::Cylinder:
                    setBox(k, cylinders_[i].aabb);
                    break;
                case ShapeType::Capsule:
                    setBox(k, capsules_[i].aabb);
                    break;
                case ShapeType::PointCloud:
                    setBox(k, clouds_[i].aabb);
                    break;
            }
        }
    }

    const std::shared_ptr<Environment::Layout> &Environment::emptyLayout()
    {
        static const std::shared_ptr<Layout> empty = std::make_shared<Layout>();
        return empty;
    }

    Environment::Layout &Environment::ownLayout()
    {
        if (layout_.use_count() != 1)
            layout_ = std::make_shared<Layout>(*layout_);  // the shared one never changes
        else
            // sole owner: copies that shared it and were destroyed by other threads have finished reading it
            std::atomic_thread_fence(std::memory_order_acquire);
        return *layout_;
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
        if (id < 0 || static_cast<std::size_t>(id) >= poses_.size())
            throw Error("Environment::setObjectPose: object id " + std::to_string(id) + " out of range (" +
                        std::to_string(poses_.size()) + " objects)");
        const std::string poseError = detail::poseProblem(pose);
        if (!poseError.empty())
            throw Error("Environment::setObjectPose: object '" + definition(id).name + "': " + poseError);
        poses_[static_cast<std::size_t>(id)] = pose.affine();
        writeQueryForm(id);
    }

    Eigen::Isometry3d Environment::objectPose(int id) const
    {
        if (id < 0 || static_cast<std::size_t>(id) >= poses_.size())
            throw Error("Environment::objectPose: object id " + std::to_string(id) + " out of range (" +
                        std::to_string(poses_.size()) + " objects)");
        Eigen::Isometry3d pose = Eigen::Isometry3d::Identity();
        pose.affine() = poses_[static_cast<std::size_t>(id)];
        return pose;
    }

    int Environment::objectId(const std::string &name) const
    {
        const auto it = layout_->index.find(name);
        if (it != layout_->index.end())
            return it->second;
        std::string known;  // the first 20 names (a scene may have 100 000 objects)
        for (std::size_t i = 0; i < layout_->objects.size() && i < 20; ++i)
            known += (known.empty() ? "" : ", ") + layout_->objects[i]->name;
        if (layout_->objects.size() > 20)
            known += ", ... (" + std::to_string(layout_->objects.size()) + " objects)";
        throw Error("Environment: unknown object '" + name + "' (objects: " + (known.empty() ? "none" : known) + ")");
    }

    bool Environment::hasObject(const std::string &name) const
    {
        return layout_->index.count(name) != 0;
    }

    const std::string &Environment::objectName(int id) const
    {
        if (id < 0 || static_cast<std::size_t>(id) >= poses_.size())
            throw Error("Environment::objectName: object id " + std::to_string(id) + " out of range (" +
                        std::to_string(poses_.size()) + " objects)");
        return definition(id).name;
    }

    const std::vector<Shape> &Environment::objectShapes(int id) const
    {
        if (id < 0 || static_cast<std::size_t>(id) >= poses_.size())
            throw Error("Environment::objectShapes: object id " + std::to_string(id) + " out of range (" +
                        std::to_string(poses_.size()) + " objects)");
        return definition(id).shapes;
    }

    bool Environment::nameInUse(const std::string &name) const
    {
        return hasObject(name) || isAttached(name) || (base_ && base_->nameInUse(name));
    }

    Environment::Environment(std::shared_ptr<const Environment> base) : base_(std::move(base)) {}

    int Environment::attach(std::shared_ptr<const RobotModel> robot, AttachedBody body,
                            const SpherizerOptions &spherizer)
    {
        if (body.name.empty())
            throw Error("Environment: an attached body needs a non-empty name");
        if (nameInUse(body.name))
            throw Error("Environment: cannot attach '" + body.name + "': the name is already used by an object or " +
                        "an attached body");
        auto query = std::make_shared<const AttachedSpheres>(compileAttachedBody(std::move(robot), body, spherizer));
        attached_.push_back({std::make_shared<const AttachedBody>(std::move(body)), std::move(query)});
        return static_cast<int>(attached_.size()) - 1;
    }

    void Environment::detach(const std::string &name)
    {
        for (std::size_t i = 0; i < attached_.size(); ++i)
            if (attached_[i].body->name == name)
            {
                attached_.erase(attached_.begin() + static_cast<std::ptrdiff_t>(i));
                return;
            }
        std::string known;
        for (const Attached &a : attached_)
            known += (known.empty() ? "" : ", ") + a.body->name;
        throw Error("Environment::detach: no attached body '" + name +
                    "' (attached: " + (known.empty() ? "none" : known) + ")");
    }

    const AttachedBody &Environment::attachedBody(std::size_t i) const
    {
        if (i >= attached_.size())
            throw Error("Environment::attachedBody: index " + std::to_string(i) + " out of range (" +
                        std::to_string(attached_.size()) + " attached bodies)");
        return *attached_[i].body;
    }

    bool Environment::isAttached(const std::string &name) const
    {
        return std::any_of(attached_.begin(), attached_.end(), [&](const Attached &a) { return a.body->name == name; });
    }

    void Environment::clear()
    {
        attached_.clear();
        layout_ = emptyLayout();
        poses_.clear();
        spheres_.clear();
        boxes_.clear();
        cylinders_.clear();
        capsules_.clear();
        clouds_.clear();
        boxChunks_.clear();
        index_.clear();
    }

    Eigen::Isometry3d Environment::shapeWorldPose(int id, std::size_t k) const
    {
        const std::vector<Shape> &shapes = objectShapes(id);
        if (k >= shapes.size())
            throw Error("Environment::shapeWorldPose: object '" + definition(id).name + "' has " +
                        std::to_string(shapes.size()) + " shapes, asked for shape " + std::to_string(k));
        return objectPose(id) * shapes[k].pose;
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

    const ObstacleAabb &Environment::primitiveBox(std::size_t i) const noexcept
    {
        const PrimitiveRef &r = layout_->primitives[i];
        const auto slot = static_cast<std::size_t>(r.slot);
        switch (r.type)
        {
            case ShapeType::Sphere:
                return spheres_[slot].aabb;
            case ShapeType::Box:
                return boxes_[slot].aabb;
            case ShapeType::Cylinder:
                return cylinders_[slot].aabb;
            case ShapeType::Capsule:
                return capsules_[slot].aabb;
            case ShapeType::PointCloud:
                break;
        }
        return clouds_[slot].aabb;
    }

    void Environment::setBox(std::size_t primitive, const ObstacleAabb &box)
    {
        ObstacleBoxChunk &chunk = boxChunks_[primitive / OBSTACLE_BOX_LANES];
        const std::size_t lane = primitive % OBSTACLE_BOX_LANES;
        chunk.cx[lane] = box.cx;
        chunk.cy[lane] = box.cy;
        chunk.cz[lane] = box.cz;
        chunk.ex[lane] = box.ex;
        chunk.ey[lane] = box.ey;
        chunk.ez[lane] = box.ez;
    }

    void Environment::writeQueryForm(int id)
    {
        const ObjectDefinition &def = definition(id);
        const Eigen::Isometry3d pose = objectPose(id);
        const std::size_t chunked = boxChunks_.size() * OBSTACLE_BOX_LANES;  // primitives with a lane
        for (std::size_t k = 0; k < def.shapes.size(); ++k)
        {
            const Shape &shape = def.shapes[k];
            const Eigen::Isometry3d world = pose * shape.pose;
            const Eigen::Vector3d c = world.translation();
            const Eigen::Matrix3d r = world.linear();
            const std::size_t primitive = def.firstPrimitive + k;
            const auto slot = static_cast<std::size_t>(layout_->primitives[primitive].slot);
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
                    if (primitive < chunked)
                        setBox(primitive, o.aabb);
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
                    if (primitive < chunked)
                        setBox(primitive, b.aabb);
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
                    y.boundRadius =
                        static_cast<float>(std::sqrt(0.25 * shape.length * shape.length + shape.radius * shape.radius));
                    y.aabb = worldBox(y);
                    if (primitive < chunked)
                        setBox(primitive, y.aabb);
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
                    if (primitive < chunked)
                        setBox(primitive, p.aabb);
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
                    if (primitive < chunked)
                        setBox(primitive, q.aabb);
                    break;
                }
            }
            index_.moved(primitive, primitiveBox(primitive));
        }
    }

    double Environment::signedDistance(const Eigen::Vector3d &center, double radius) const
    {
        double best = std::numeric_limits<double>::infinity();
        for (std::size_t id = 0; id < poses_.size(); ++id)
            best = std::min(best, objectSignedDistance(static_cast<int>(id), center, radius));
        if (base_)
            best = std::min(best, base_->signedDistance(center, radius));
        return best;
    }

    double Environment::objectSignedDistance(int id, const Eigen::Vector3d &center, double radius) const
    {
        const std::vector<Shape> &shapes = objectShapes(id);
        const Eigen::Isometry3d pose = objectPose(id);
        double best = std::numeric_limits<double>::infinity();
        for (const Shape &shape : shapes)
        {
            const Eigen::Isometry3d world = pose * shape.pose;
            const Eigen::Vector3d p = world.inverse(Eigen::Isometry) * center;
            best = std::min(best, primitiveDistance(shape, p) - radius);
        }
        return best;
    }
}  // namespace ropras::ompl_ext
