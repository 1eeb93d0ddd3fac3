#include "ropras/ompl_ext/scene/ShapeIntersection.h"

#include <fcl/narrowphase/collision.h>
#include <fcl/narrowphase/collision_object.h>

#include <cmath>
#include <string>

#include "collision/FclScene.h"
#include "ropras/core/Error.h"

namespace ropras::ompl_ext
{
    namespace
    {
        std::string where(const Shape &s, const char *which)
        {
            return std::string("shapesIntersect: shape ") + which + " (" + shapeTypeName(s.type) + ")";
        }

        std::string numbers(const Shape &s)
        {
            return "radius " + std::to_string(s.radius) + ", length " + std::to_string(s.length) + ", extents (" +
                   std::to_string(s.extents.x()) + ", " + std::to_string(s.extents.y()) + ", " +
                   std::to_string(s.extents.z()) + ")";
        }

        /// the message is built only when a check fails (a valid call does not allocate for it)
        void requirePrimitive(const Shape &s, const Eigen::Isometry3d &pose, const char *which)
        {
            if (s.type == ShapeType::PointCloud)
                throw Error(where(s, which) + ": point clouds are not supported");
            const bool sizes = std::isfinite(s.radius) && s.radius >= 0.0 && std::isfinite(s.length) &&
                               s.length >= 0.0 && s.extents.allFinite() && (s.extents.array() >= 0.0).all();
            if (!sizes)
                throw Error(where(s, which) + ": a size is negative or not finite (" + numbers(s) + ")");
            if (!pose.matrix().allFinite() || !s.pose.matrix().allFinite())
                throw Error(where(s, which) + ": the pose is not finite");
        }
    }  // namespace

    bool shapesIntersect(const Shape &a, const Eigen::Isometry3d &poseA, const Shape &b, const Eigen::Isometry3d &poseB)
    {
        requirePrimitive(a, poseA, "a");
        requirePrimitive(b, poseB, "b");
        const fcl::CollisionObjectd oa(fcl_reference::primitiveGeometry(a), poseA * a.pose);
        const fcl::CollisionObjectd ob(fcl_reference::primitiveGeometry(b), poseB * b.pose);
        fcl::CollisionRequestd request;
        fcl::CollisionResultd result;
        return fcl::collide(&oa, &ob, request, result) > 0;
    }
}  // namespace ropras::ompl_ext
