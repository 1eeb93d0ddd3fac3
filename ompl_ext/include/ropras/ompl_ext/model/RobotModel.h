#ifndef ROPRAS_OMPL_EXT_ROBOT_MODEL_H
#define ROPRAS_OMPL_EXT_ROBOT_MODEL_H

#include <Eigen/Geometry>
#include <cstddef>
#include <cstdint>
#include <map>
#include <memory>
#include <string>
#include <utility>
#include <vector>

#include "ropras/ompl_ext/model/Spherizer.h"

namespace ropras::ompl_ext
{
    /** \brief URDF joint types we accept. Floating and planar joints are rejected with an Error. */
    enum class JointType
    {
        Fixed,
        Revolute,
        Continuous,
        Prismatic
    };

    /** \brief How a compiled kinematic frame moves relative to its joint frame: every movable joint is
        re-expressed so that it rotates about, or slides along, its local +z axis. */
    enum class JointMotion
    {
        None,
        RotateZ,
        TranslateZ
    };

    /** \brief A planning variable: one movable URDF joint chosen for planning. */
    struct PlanningJoint
    {
        std::string name;
        JointType type{JointType::Revolute};
        double lower{0.0};  ///< from the URDF limits; continuous joints get [-pi, pi]
        double upper{0.0};
        int urdfJoint{-1};  ///< index into RobotModel::urdfJoints()
    };

    /** \brief A joint exactly as the URDF states it (the reference FK walks these). */
    struct UrdfJoint
    {
        std::string name;
        JointType type{JointType::Fixed};
        int parentLink{-1};  ///< index into RobotModel::links()
        int childLink{-1};
        Eigen::Isometry3d origin{Eigen::Isometry3d::Identity()};  ///< parent link frame -> joint frame
        Eigen::Vector3d axis{Eigen::Vector3d::UnitZ()};           ///< unit axis in the joint frame
        int variable{-1};     ///< planning-variable index, or -1 when the joint is fixed or held
        double heldValue{0};  ///< value used when the joint is movable but not planned
    };

    /** \brief A URDF link, with where it sits in the compiled kinematic frames. */
    struct Link
    {
        std::string name;
        int parentJoint{-1};                                       ///< index into urdfJoints(), -1 for the root link
        int frame{-1};                                             ///< compiled frame that carries this link rigidly
        Eigen::Isometry3d inFrame{Eigen::Isometry3d::Identity()};  ///< link frame expressed in that frame
    };

    /** \brief A compiled kinematic frame: fixed and held joints folded away, motion about local z.
        World pose: T = T_parent * offset * Motion(q[variable]), frames in topological order
        (parent < index), frame 0 is the root carrying the base pose. */
    struct KinematicFrame
    {
        std::string name;  ///< name of the URDF link that opens the frame
        int parent{-1};
        int variable{-1};
        JointMotion motion{JointMotion::None};
        Eigen::Isometry3d offset{Eigen::Isometry3d::Identity()};
    };

    /** \brief One collision sphere of a link. */
    struct CollisionSphere
    {
        Eigen::Vector3d centerInLink{Eigen::Vector3d::Zero()};   ///< as the URDF (or the spherizer) gives it
        Eigen::Vector3d centerInFrame{Eigen::Vector3d::Zero()};  ///< in the compiled kinematic frame
        double radius{0.0};
        int collisionLink{-1};
    };

    /** \brief A URDF `<collision>` element as written (what the FCL mesh baseline and the spherizer read). */
    struct CollisionGeometry
    {
        enum class Type
        {
            Sphere,
            Box,
            Cylinder,
            Mesh
        };
        Type type{Type::Sphere};
        int link{-1};                                             ///< index into links()
        Eigen::Isometry3d origin{Eigen::Isometry3d::Identity()};  ///< in the link frame
        double radius{0.0};                                       ///< sphere, cylinder
        double length{0.0};                                       ///< cylinder
        Eigen::Vector3d extents{Eigen::Vector3d::Zero()};         ///< box full extents
        Eigen::Vector3d scale{Eigen::Vector3d::Ones()};           ///< mesh
        std::string meshPath;                                     ///< mesh, resolved absolute path
        /// upper bound (m) on how far this element's spheres reach beyond it (0 for spheres; see Spherizer)
        double coverProtrusion{0.0};
    };

    /** \brief A link that has collision geometry: its spheres (contiguous) and a bounding sphere. */
    struct CollisionLink
    {
        std::string name;
        int link{-1};   ///< index into links()
        int frame{-1};  ///< compiled frame
        int firstSphere{0};
        int sphereCount{0};
        Eigen::Vector3d boundCenterInFrame{Eigen::Vector3d::Zero()};  ///< encloses all the link's spheres
        double boundRadius{0.0};
    };

    /** \brief Options of RobotModel::fromUrdfFile / fromUrdfString (also reachable as RobotModel::Options). */
    struct RobotModelOptions
    {
        std::vector<std::string> planningJoints;                    ///< empty: all movable joints in URDF order
        std::map<std::string, double> heldJointValues;              ///< values of movable joints not planned
        Eigen::Isometry3d basePose{Eigen::Isometry3d::Identity()};  ///< root link pose in the world
        SpherizerOptions spherizer;
        /** \brief MoveIt Setup Assistant's "Always" rule: drop the self-collision pairs whose spheres are in
            contact in EVERY one of \a alwaysCollidingSamples configurations drawn uniformly within the joint
            limits (seed \a alwaysCollidingSeed; reference centres in double). Such pairs are in contact by
            design (e.g. a sensor flange modelled inside the wrist); left enabled they make every configuration
            invalid. The dropped pairs are listed by RobotModel::alwaysCollidingPairs(). */
        bool disableAlwaysColliding{true};
        std::size_t alwaysCollidingSamples{1000};  ///< must be > 0 when disableAlwaysColliding is on
        std::uint64_t alwaysCollidingSeed{20240601};
        /// more pairs to disable, by link name, exactly as if listed in the SRDF's disable_collisions
        std::vector<std::pair<std::string, std::string>> disabledPairs;
        /// an SRDF `<group>` whose movable joints are planned (MoveIt's planning group); not with planningJoints
        std::string group;
        /** \brief The group a request names (MotionPlanRequest::group): planned like \a group when the SRDF defines
            it and neither \a group nor \a planningJoints is given; otherwise every movable joint is planned. */
        std::string requestGroup;
        /** \brief A whole joint state (e.g. a request's start state): the held value of every movable joint that is
            not planned, unless heldJointValues gives one. Its planning joints are ignored; names the URDF lacks are
            ignored with a warning (an error when \a strict). */
        std::map<std::string, double> jointState;
        /// joint values at most this far outside a limit (rad or m) are clamped into it with a warning
        double limitTolerance{DEFAULT_LIMIT_TOLERANCE};
        /** \brief Refuse what MoveIt accepts with a warning: SRDF names the URDF lacks (disable_collisions, groups),
            request joints the robot lacks, values outside a limit (no clamping, no wrapping). */
        bool strict{false};

        static constexpr double DEFAULT_LIMIT_TOLERANCE = 1e-4;
    };

    /** \brief Immutable robot description for collision checking, loaded from URDF (+ SRDF) at run time.

        Planning joints are, by default, all movable joints in URDF document order; Options may name a
        subset (the others are held at given values, default 0 clamped into their limits). Collision
        geometry: `<sphere>` elements are taken as they are; boxes, cylinders and meshes are covered by
        the Spherizer. Self-collision pairs are all pairs of collision links that can move relative to each
        other, minus SRDF `disable_collisions` (and Options::disabledPairs), minus links adjacent through one joint,
        minus (by default) pairs in contact in every sampled configuration (alwaysCollidingPairs()).

        Every error (unreadable or malformed file, unsupported joint, unknown name, missing mesh, bad radius)
        throws ropras::Error naming the file and the problem. */
    class RobotModel
    {
    public:
        /// loading options (defined outside the class so it can be a default argument with member initializers)
        using Options = RobotModelOptions;

        static std::shared_ptr<const RobotModel> fromUrdfFile(const std::string &urdfPath,
                                                              const std::string &srdfPath = "",
                                                              const Options &options = Options());
        /** \brief \a sourceName names the document in error messages; meshes resolve against \a baseDir. */
        static std::shared_ptr<const RobotModel> fromUrdfString(const std::string &urdfXml, const std::string &baseDir,
                                                                const std::string &sourceName,
                                                                const std::string &srdfXml = "",
                                                                const Options &options = Options());

        const std::string &name() const { return name_; }
        std::size_t dof() const { return joints_.size(); }
        const std::vector<PlanningJoint> &joints() const { return joints_; }
        const std::vector<UrdfJoint> &urdfJoints() const { return urdfJoints_; }
        const std::vector<Link> &links() const { return links_; }
        const std::vector<KinematicFrame> &frames() const { return frames_; }
        const std::vector<CollisionLink> &collisionLinks() const { return collisionLinks_; }
        const std::vector<CollisionSphere> &spheres() const { return spheres_; }
        const std::vector<CollisionGeometry> &collisionGeometries() const { return geometries_; }
        /// pairs of collisionLinks() indices (first < second) checked for self-collision
        const std::vector<std::pair<int, int>> &selfCollisionPairs() const { return selfPairs_; }
        /// link-name pairs removed by Options::disableAlwaysColliding (in contact in every sampled configuration)
        const std::vector<std::pair<std::string, std::string>> &alwaysCollidingPairs() const { return alwaysPairs_; }
        /** \brief Link-name pairs of selfCollisionPairs() in contact at defaultConfiguration() (MoveIt's "Default"
            rule). Reported only, never disabled: a hint that the SRDF may miss pairs in contact by design. */
        const std::vector<std::pair<std::string, std::string>> &defaultCollidingPairs() const { return defaultPairs_; }
        /// every planning joint at 0 clamped into its limits (what defaultCollidingPairs() is computed at)
        std::vector<double> defaultConfiguration() const;
        const Eigen::Isometry3d &basePose() const { return basePose_; }

        /// planning-variable index of a joint; throws Error listing the planning joints if unknown
        int jointIndex(const std::string &name) const;
        /// link index; throws Error if unknown
        int linkIndex(const std::string &name) const;
        /// true when every value is finite and within its joint's limits (continuous joints: any finite)
        bool withinBounds(const double *q) const noexcept;
        /** \brief The planning-joint values (dof(), in planning order) from a name -> value map such as a MoveIt
            request's start state or goal. Joints of the URDF that are not planned are ignored (they stay held);
            a planning joint the map does not give throws Error naming \a context (e.g. "request0001.yaml: goal").
            As MoveIt does (unless the model is strict(), when they are errors or left as given): names the URDF
            does not have are ignored, values within limitTolerance() outside a limit are clamped and continuous
            joints are wrapped into [-pi, pi], each with a message appended to \a warnings (when given). */
        std::vector<double> planningValues(const std::map<std::string, double> &jointValues, const std::string &context,
                                           std::vector<std::string> *warnings = nullptr) const;

        /// what loading accepted with a warning (SRDF names the URDF lacks, clamped held values, ...), in order
        const std::vector<std::string> &warnings() const { return warnings_; }
        /// the SRDF's groups that resolve on this URDF: name -> their movable, non-mimic joints in URDF order
        const std::map<std::string, std::vector<std::string>> &groups() const { return groups_; }
        /// the SRDF group whose joints are planned ("" when the planning joints were not chosen by group)
        const std::string &group() const { return group_; }
        double limitTolerance() const { return limitTolerance_; }
        bool strict() const { return strict_; }

        // Reference computations in double precision. They walk the URDF joints (origin, axis-angle),
        // independently of the compiled frames, and allocate: for tests and tools, not hot paths.
        /// world pose of every URDF link, indexed like links()
        std::vector<Eigen::Isometry3d> linkTransformsReference(const double *q) const;
        /// world centre of every sphere, indexed like spheres()
        std::vector<Eigen::Vector3d> sphereCentersReference(const double *q) const;

        /// the file the model came from (for messages)
        const std::string &source() const { return source_; }
        /// folder that relative and package:// mesh paths resolve against
        const std::string &baseDir() const { return baseDir_; }

    private:
        RobotModel() = default;
        friend class RobotModelBuilder;

        std::string name_, source_, baseDir_;
        Eigen::Isometry3d basePose_{Eigen::Isometry3d::Identity()};
        std::vector<PlanningJoint> joints_;
        std::vector<UrdfJoint> urdfJoints_;
        std::vector<Link> links_;
        std::vector<KinematicFrame> frames_;
        std::vector<CollisionLink> collisionLinks_;
        std::vector<CollisionSphere> spheres_;
        std::vector<CollisionGeometry> geometries_;
        std::vector<std::pair<int, int>> selfPairs_;
        std::vector<std::pair<std::string, std::string>> alwaysPairs_, defaultPairs_;
        std::vector<std::string> warnings_;
        std::map<std::string, std::vector<std::string>> groups_;
        std::string group_;
        double limitTolerance_{RobotModelOptions::DEFAULT_LIMIT_TOLERANCE};
        bool strict_{false};
    };
}  // namespace ropras::ompl_ext

#endif
