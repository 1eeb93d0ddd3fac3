#ifndef ROPRAS_OMPL_EXT_SRC_COLLISION_FCL_SCENE_H
#define ROPRAS_OMPL_EXT_SRC_COLLISION_FCL_SCENE_H

// Only the FCL headers we use: <fcl/fcl.h> alone takes seconds to compile.
#include <fcl/broadphase/broadphase_dynamic_AABB_tree.h>
#include <fcl/narrowphase/collision_object.h>

#include <cstddef>
#include <memory>
#include <string>
#include <vector>

#include "ropras/ompl_ext/scene/Environment.h"
#include "ropras/ompl_ext/scene/Shape.h"

// The obstacles of an Environment (and its bases) as FCL objects, for the FCL reference checkers.

namespace ropras::ompl_ext::fcl_reference
{
    using GeometryPtr = std::shared_ptr<fcl::CollisionGeometryd>;

    /// the FCL objects of one Environment, never modified after construction
    struct ObstacleScene
    {
        std::vector<double> signature;
        std::vector<const void *> clouds;
        std::vector<std::unique_ptr<fcl::CollisionObjectd>> objects;
        std::vector<std::string> labels;  ///< per object: "object 'name'" (+ primitive / point index)
        std::unique_ptr<fcl::DynamicAABBTreeCollisionManagerd> manager;
    };

    /// the FCL geometry of a primitive (sphere, box, cylinder, capsule; nullptr for a point cloud)
    GeometryPtr primitiveGeometry(const Shape &shape);

    /// the index into ObstacleScene::labels of one of its objects
    std::size_t tagLabel(const fcl::CollisionObjectd *object);

    /// Caches the scene of the last Environment seen: rebuilt when any shape, pose or point cloud differs (a renamed
    /// object alone keeps the cached labels; the checkers only quote them in describeCollision).
    class SceneCache
    {
    public:
        const ObstacleScene &get(const Environment &env);

    private:
        std::vector<double> numbers_;
        std::vector<const void *> clouds_;
        std::shared_ptr<const ObstacleScene> scene_;
    };
}  // namespace ropras::ompl_ext::fcl_reference

#endif
