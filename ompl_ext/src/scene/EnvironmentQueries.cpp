#include "ropras/ompl_ext/scene/EnvironmentQueries.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <sstream>

#include "ropras/core/Error.h"
#include "scene/SegmentTests.h"

namespace ropras::ompl_ext
{
    namespace
    {
        std::string format(const Eigen::Vector3d &p)
        {
            std::ostringstream s;
            s << "(" << p.x() << ", " << p.y() << ", " << p.z() << ")";
            return s.str();
        }

        void checkSphere(const char *function, const Eigen::Vector3d &center, double radius)
        {
            if (!center.allFinite())
                throw Error(std::string(function) + ": non-finite point " + format(center));
            if (!std::isfinite(radius) || radius < 0.0)
                throw Error(std::string(function) + ": the radius must be finite and >= 0, got " +
                            std::to_string(radius));
        }

        /// the best contact so far and the cull segment shortened to it
        struct Search
        {
            Eigen::Vector3d a, d;
            double t{1.0};
            bool found{false};
            ShapeType type{ShapeType::Sphere};
            std::size_t index{0};
            segment::FloatSegment cull{};

            void offer(double ti, ShapeType ty, std::size_t i) noexcept
            {
                if (found && !(ti < t))
                    return;
                t = ti;
                found = true;
                type = ty;
                index = i;
                cull.set(a, d, t);
            }
        };

        /// culls every primitive of \a list by its AABB, then runs \a exact(primitive, tMax, t) on the rest
        template <class List, class Exact>
        void scan(const List &list, ShapeType type, Search &s, Exact &&exact) noexcept
        {
            for (std::size_t i = 0; i < list.size(); ++i)
            {
                if (!s.cull.overlaps(list[i].aabb))
                    continue;
                double ti = 0.0;
                if (exact(list[i], s.t, ti))
                    s.offer(ti, type, i);
            }
        }
    }  // namespace

    SegmentHit firstHit(const Environment &env, const Eigen::Vector3d &a, const Eigen::Vector3d &b)
    {
        if (!a.allFinite() || !b.allFinite())
            throw Error("firstHit: non-finite segment " + format(a) + " -> " + format(b));
        const Eigen::Vector3d d = b - a;
        const double length = d.norm();
        if (!(length > 0.0) || !std::isfinite(length))
            throw Error("firstHit: the segment " + format(a) + " -> " + format(b) + " has length " +
                        std::to_string(length) + " (must be positive and finite)");

        Search s;
        s.a = a;
        s.d = d;
        s.cull.set(a, d, 1.0);
        scan(env.spheres(), ShapeType::Sphere, s,
             [&](const SphereObstacle &o, double tMax, double &t)
             { return segment::sphere(a, d, Eigen::Vector3d(o.x, o.y, o.z), o.r, tMax, t); });
        scan(env.boxes(), ShapeType::Box, s,
             [&](const BoxObstacle &o, double tMax, double &t)
             {
                 // box frame: R^T (p - c); rot is R row-major
                 const Eigen::Matrix3d r =
                     Eigen::Map<const Eigen::Matrix<float, 3, 3, Eigen::RowMajor>>(o.rot).cast<double>();
                 const Eigen::Vector3d c(o.cx, o.cy, o.cz);
                 return segment::localBox(r.transpose() * (a - c), r.transpose() * d, Eigen::Vector3d(o.hx, o.hy, o.hz),
                                          tMax, t);
             });
        scan(env.cylinders(), ShapeType::Cylinder, s,
             [&](const CylinderObstacle &o, double tMax, double &t)
             {
                 return segment::cylinder(a, d, Eigen::Vector3d(o.cx, o.cy, o.cz), Eigen::Vector3d(o.ax, o.ay, o.az),
                                          o.halfLength, o.radius, tMax, t);
             });
        scan(env.capsules(), ShapeType::Capsule, s,
             [&](const CapsuleObstacle &o, double tMax, double &t) { return segment::capsule(a, d, o, tMax, t); });
        scan(env.clouds(), ShapeType::PointCloud, s,
             [&](const CloudObstacle &o, double tMax, double &t)
             {
                 if (o.boundRadius < 0.0f)  // empty cloud
                     return false;
                 const Eigen::Isometry3d toCloud = o.worldToCloud.cast<double>();
                 return o.cloud->firstSegmentHit(toCloud * a, toCloud.linear() * d, tMax, t);
             });

        SegmentHit hit;
        if (!s.found)
            return hit;
        hit.hit = true;
        hit.type = s.type;
        hit.primitive = s.index;
        hit.object = env.primitiveObjects(s.type)[s.index];
        hit.name = env.objectName(hit.object);
        hit.fraction = s.t;
        hit.distance = s.t * length;
        hit.point = a + s.t * d;
        return hit;
    }

    void objectDistances(const Environment &env, const Eigen::Vector3d &center, double radius,
                         std::vector<ObjectDistance> &out)
    {
        checkSphere("objectDistances", center, radius);
        out.resize(env.objectCount());
        for (std::size_t id = 0; id < env.objectCount(); ++id)
        {
            const int i = static_cast<int>(id);
            out[id] = ObjectDistance{i, env.objectName(i), env.objectSignedDistance(i, center, radius)};
        }
    }

    ObjectDistance nearestObject(const Environment &env, const Eigen::Vector3d &center, double radius)
    {
        checkSphere("nearestObject", center, radius);
        ObjectDistance best;
        best.distance = std::numeric_limits<double>::infinity();
        for (std::size_t id = 0; id < env.objectCount(); ++id)
        {
            const int i = static_cast<int>(id);
            const double distance = env.objectSignedDistance(i, center, radius);
            if (distance < best.distance)
                best = ObjectDistance{i, env.objectName(i), distance};
        }
        return best;
    }

    namespace
    {
        /// pushes the owner of every primitive whose AABB comes within \a reach of \a c
        template <class List>
        void nearAabbs(const Environment &env, const List &list, ShapeType type, const Eigen::Vector3d &c, double reach,
                       std::vector<int> &out)
        {
            const std::vector<int> &owners = env.primitiveObjects(type);
            for (std::size_t i = 0; i < list.size(); ++i)
            {
                const ObstacleAabb &b = list[i].aabb;
                const Eigen::Vector3d q =
                    ((c - Eigen::Vector3d(b.cx, b.cy, b.cz)).cwiseAbs() - Eigen::Vector3d(b.ex, b.ey, b.ez))
                        .cwiseMax(0.0);
                if (q.squaredNorm() <= reach * reach)
                    out.push_back(owners[i]);
            }
        }
    }  // namespace

    void objectsWithin(const Environment &env, const Eigen::Vector3d &center, double radius, double distance,
                       std::vector<int> &out)
    {
        checkSphere("objectsWithin", center, radius);
        if (!std::isfinite(distance) || distance < 0.0)
            throw Error("objectsWithin: the distance must be finite and >= 0, got " + std::to_string(distance));
        out.clear();
        // candidates: a primitive's AABB holds it, so the AABB is at least as near (slack for rounding)
        const double reach = (radius + distance) * (1.0 + 1e-9) + 1e-9;
        nearAabbs(env, env.spheres(), ShapeType::Sphere, center, reach, out);
        nearAabbs(env, env.boxes(), ShapeType::Box, center, reach, out);
        nearAabbs(env, env.cylinders(), ShapeType::Cylinder, center, reach, out);
        nearAabbs(env, env.capsules(), ShapeType::Capsule, center, reach, out);
        nearAabbs(env, env.clouds(), ShapeType::PointCloud, center, reach, out);
        std::sort(out.begin(), out.end());
        out.erase(std::unique(out.begin(), out.end()), out.end());
        out.erase(std::remove_if(out.begin(), out.end(),
                                 [&](int id) { return env.objectSignedDistance(id, center, radius) > distance; }),
                  out.end());
    }
}  // namespace ropras::ompl_ext
