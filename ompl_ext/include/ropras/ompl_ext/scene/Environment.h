#ifndef ROPRAS_OMPL_EXT_ENVIRONMENT_H
#define ROPRAS_OMPL_EXT_ENVIRONMENT_H

#include <Eigen/Geometry>
#include <memory>
#include <string>
#include <unordered_map>
#include <vector>

#include "ropras/ompl_ext/scene/AttachedBody.h"
#include "ropras/ompl_ext/scene/ObstacleIndex.h"
#include "ropras/ompl_ext/scene/PointCloud.h"
#include "ropras/ompl_ext/scene/Shape.h"

namespace ropras::ompl_ext
{
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

    /// primitives per ObstacleBoxChunk (the SIMD width of the collision kernels)
    constexpr int OBSTACLE_BOX_LANES = 8;

    /** \brief The world boxes (ObstacleAabb) of eight primitives side by side, so that a kernel culls eight
        obstacles with one vector test. Lanes past the last primitive have extents -infinity: nothing touches them. */
    struct ObstacleBoxChunk
    {
        float cx[OBSTACLE_BOX_LANES], cy[OBSTACLE_BOX_LANES], cz[OBSTACLE_BOX_LANES];
        float ex[OBSTACLE_BOX_LANES], ey[OBSTACLE_BOX_LANES], ez[OBSTACLE_BOX_LANES];
    };

    /// a primitive of the query form: its type and its index into that type's query vector (spheres(), boxes(), ...)
    struct PrimitiveRef
    {
        ShapeType type;
        int slot;
    };

    /** \brief A set of named obstacles, optionally over a shared base, with the bodies attached to the robot.

        Value type: copying is cheap. What only addObject() and clear() change (names, shapes, the name index, which
        object owns each primitive) is shared by the copies and copied only when a copy adds an object; a copy owns
        just the object poses and the query form (a few floats per primitive); point clouds and the base are shared.
        setObjectPose() moves one object in O(its primitives).

        **Per-particle scenes.** An Environment made with a base (Environment(base)) checks the base's obstacles
        too without copying them: the static scene is one shared, immutable Environment, and each belief particle
        owns a small Environment over it holding only its movable objects (their poses differ per particle) and
        its attached bodies (what the hand holds). Object names are unique across an Environment and its bases;
        ids, objectCount() and the query form refer to this Environment's own objects (the base's are reached
        through base()). Const use is thread-safe: several threads may check against one Environment, and
        particles may share one base.

        **Attached bodies** (attach(), detach()) move with a robot link; the collision checker of the same
        RobotModel checks them in every path (see AttachedBody). A checker of another model ignores nothing: it
        calls every configuration invalid while such bodies are attached, rather than guess their frames.

        Errors (duplicate or unknown names, non-positive or non-finite sizes, non-finite poses, unknown links)
        throw ropras::Error naming the object. */
    class Environment
    {
    public:
        Environment() = default;
        /// an overlay: \a base's obstacles and attached bodies are part of this Environment (null: none)
        explicit Environment(std::shared_ptr<const Environment> base);

        /// the shared base, or nullptr
        const Environment *base() const { return base_.get(); }
        const std::shared_ptr<const Environment> &basePtr() const { return base_; }

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
        Eigen::Isometry3d objectPose(int id) const;
        int objectId(const std::string &name) const;  ///< throws Error listing the object names if unknown
        /// an object of this Environment (not of its base)
        bool hasObject(const std::string &name) const;
        /// an object or attached body of this Environment or of a base has this name
        bool nameInUse(const std::string &name) const;
        std::size_t objectCount() const { return poses_.size(); }
        const std::string &objectName(int id) const;
        const std::vector<Shape> &objectShapes(int id) const;
        /// removes this Environment's objects and attached bodies (the base stays)
        void clear();

        /// world pose of primitive \a k of object \a id
        Eigen::Isometry3d shapeWorldPose(int id, std::size_t k) const;

        // query form
        const std::vector<SphereObstacle> &spheres() const { return spheres_; }
        const std::vector<BoxObstacle> &boxes() const { return boxes_; }
        const std::vector<CylinderObstacle> &cylinders() const { return cylinders_; }
        const std::vector<CapsuleObstacle> &capsules() const { return capsules_; }
        const std::vector<CloudObstacle> &clouds() const { return clouds_; }
        /// the object id owning each entry of the query vector of \a type (indexed like spheres(), boxes(), ...)
        const std::vector<int> &primitiveObjects(ShapeType type) const
        {
            return layout_->owners[static_cast<std::size_t>(type)];
        }
        /** \brief The world boxes of this Environment's primitives (every type, in the order they were added),
            eight per chunk: lane i of chunk c is primitiveRef(OBSTACLE_BOX_LANES * c + i). Empty while the
            Environment has fewer than OBSTACLE_BOX_LANES primitives (a particle's few movable objects cost no
            chunk; the kernels test such primitives one at a time). */
        const std::vector<ObstacleBoxChunk> &obstacleBoxChunks() const { return boxChunks_; }
        std::size_t primitiveCount() const noexcept { return layout_->primitives.size(); }
        /// primitive \a i (< primitiveCount()) of that order
        const PrimitiveRef &primitiveRef(std::size_t i) const noexcept { return layout_->primitives[i]; }
        /// the world box (ObstacleAabb) of primitive \a i (< primitiveCount())
        const ObstacleAabb &primitiveBox(std::size_t i) const noexcept;
        /** \brief The broad phase over this Environment's primitives (not its base's; see ObstacleIndex), built
            by the first call after objects were added; nullptr below ObstacleIndex::MIN_PRIMITIVES primitives. */
        const ObstacleTree *obstacleTree() const noexcept { return index_.tree(*this); }

        /** \brief Attaches \a body to a link of \a robot (see AttachedBody; non-sphere geometry is spherized with
            \a spherizer); returns its index (attachedBody(i)). The name must be unique among objects and attached
            bodies. Throws Error naming the body for an unknown link or touch link, a bad pose or shape. */
        int attach(std::shared_ptr<const RobotModel> robot, AttachedBody body,
                   const SpherizerOptions &spherizer = SpherizerOptions());
        /// removes the attached body \a name (of this Environment, not of its base); throws Error if unknown
        void detach(const std::string &name);
        bool isAttached(const std::string &name) const;
        /// this Environment's attached bodies (not its base's); copies of an Environment share them
        std::size_t attachedCount() const { return attached_.size(); }
        /// attached body \a i in authoring form; throws Error if out of range
        const AttachedBody &attachedBody(std::size_t i) const;
        /// its query form (what the kernels read), i < attachedCount()
        const AttachedSpheres &attachedSpheres(std::size_t i) const noexcept { return *attached_[i].spheres; }
        /// true when this Environment or a base has attached bodies
        bool hasAttachedBodies() const { return !attached_.empty() || (base_ && base_->hasAttachedBodies()); }

        /// exact signed distance (double) from a sphere to the nearest obstacle surface (the base's included):
        /// negative when penetrating, +infinity for an empty environment. Reference computation for tests and tools.
        double signedDistance(const Eigen::Vector3d &center, double radius) const;
        /// the same for the primitives of object \a id alone (throws Error for an unknown id)
        double objectSignedDistance(int id, const Eigen::Vector3d &center, double radius) const;

    private:
        /// what never changes about an object
        struct ObjectDefinition
        {
            std::string name;
            std::vector<Shape> shapes;
            std::size_t firstPrimitive{0};  ///< its shapes are primitives firstPrimitive, firstPrimitive + 1, ...
        };
        /** \brief What only addObject() and clear() change, shared by the copies of an Environment (a particle's
            copy costs a pointer, not the names, shapes and name index) and copied on write (ownLayout()). */
        struct Layout
        {
            std::vector<std::shared_ptr<const ObjectDefinition>> objects;
            /// object name -> id (so adding n objects costs O(n), not O(n^2) name comparisons)
            std::unordered_map<std::string, int> index;
            std::vector<PrimitiveRef> primitives;
            std::vector<int> owners[5];  ///< per ShapeType: object id of each query-form entry
        };
        struct Attached
        {
            std::shared_ptr<const AttachedBody> body;
            std::shared_ptr<const AttachedSpheres> spheres;
        };
        /// the layout shared by every Environment that has no object (never changed: it is never unique)
        static const std::shared_ptr<Layout> &emptyLayout();
        /// the layout, first copied when another Environment shares it
        Layout &ownLayout();
        const ObjectDefinition &definition(int id) const { return *layout_->objects[static_cast<std::size_t>(id)]; }
        void writeQueryForm(int id);
        void setBox(std::size_t primitive, const ObstacleAabb &box);
        /// adds the chunks that primitives past the last chunk need (none below OBSTACLE_BOX_LANES primitives)
        void extendBoxChunks();
        std::shared_ptr<Layout> layout_{emptyLayout()};  ///< never null
        /// per object id: the top three rows of its pose (the last row is 0 0 0 1)
        std::vector<Eigen::Matrix<double, 3, 4>> poses_;
        std::vector<SphereObstacle> spheres_;
        std::vector<BoxObstacle> boxes_;
        std::vector<CylinderObstacle> cylinders_;
        std::vector<CapsuleObstacle> capsules_;
        std::vector<CloudObstacle> clouds_;
        std::vector<ObstacleBoxChunk> boxChunks_;
        ObstacleIndex index_;
        std::shared_ptr<const Environment> base_;
        std::vector<Attached> attached_;
    };
}  // namespace ropras::ompl_ext

#endif
