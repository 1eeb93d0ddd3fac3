#ifndef ROPRAS_OMPL_EXT_ENVIRONMENT_QUERIES_H
#define ROPRAS_OMPL_EXT_ENVIRONMENT_QUERIES_H

#include <Eigen/Core>
#include <cstddef>
#include <string_view>
#include <vector>

#include "ropras/ompl_ext/scene/Environment.h"

namespace ropras::ompl_ext
{
    /** \brief Where a segment first touches an obstacle (see firstHit). \a name views the Environment's own
        string: it stays valid while that object exists. */
    struct SegmentHit
    {
        bool hit{false};
        int object{-1};         ///< object id (Environment::objectName(object) == name)
        std::string_view name;  ///< object name
        ShapeType type{ShapeType::Sphere};
        std::size_t primitive{0};  ///< index into the query vector of \a type (spheres(), boxes(), ...)
        double fraction{1.0};      ///< t in [0, 1] of the first contact along a + t (b - a)
        double distance{0.0};      ///< t |b - a|: metres from the segment's start to the contact
        Eigen::Vector3d point{Eigen::Vector3d::Zero()};  ///< a + t (b - a)
    };

    /** \brief The first obstacle the segment \a a -> \a b touches, in the Environment's float query form
        (spheres, boxes, cylinders, capsules and point clouds, each a solid). A segment that starts inside (or
        on) an obstacle hits it at fraction 0; a tangent segment hits at the touching point. No hit: hit false,
        object -1. Ties (the same fraction) go to the first in the order spheres, boxes, cylinders, capsules,
        clouds, then by index.

        Each primitive is culled first by its world AABB against the segment shortened to the best contact so
        far, then tested exactly (double arithmetic on the float primitive). A point cloud is walked cell by
        cell along the segment in its grid. noexcept after the argument check, allocation-free, thread-safe.
        Throws ropras::Error naming the value for a non-finite end point or a zero-length segment. */
    SegmentHit firstHit(const Environment &env, const Eigen::Vector3d &a, const Eigen::Vector3d &b);

    /** \brief The signed distance from a sphere (a point: \a radius 0) to one object. */
    struct ObjectDistance
    {
        int object{-1};
        std::string_view name;  ///< views the Environment's string (valid while the object exists)
        double distance{0.0};   ///< from the sphere's surface to the object's; negative when they overlap
    };

    /** \brief One entry per object, in id order (\a out is overwritten; its capacity is reused): the signed
        distance from the sphere (\a center, \a radius >= 0; 0 for a point) to the object's nearest primitive,
        computed exactly in double from the object's shapes (Environment::objectSignedDistance). Throws
        ropras::Error naming the value for a non-finite centre or a negative or non-finite radius. */
    void objectDistances(const Environment &env, const Eigen::Vector3d &center, double radius,
                         std::vector<ObjectDistance> &out);

    /** \brief The nearest object to the sphere (\a center, \a radius): object -1 and distance +infinity for an
        empty environment. Same checks as objectDistances. */
    ObjectDistance nearestObject(const Environment &env, const Eigen::Vector3d &center, double radius = 0.0);

    /** \brief The ids (ascending, \a out overwritten) of the objects whose signed distance from the sphere
        (\a center, \a radius) is at most \a distance (>= 0; 0 gives the objects the sphere touches).
        Objects are culled by their primitives' AABBs first. Throws ropras::Error naming the value for a
        non-finite centre, a negative or non-finite radius or distance. */
    void objectsWithin(const Environment &env, const Eigen::Vector3d &center, double radius, double distance,
                       std::vector<int> &out);
}  // namespace ropras::ompl_ext

#endif
