#ifndef ROPRAS_OMPL_EXT_ATTACHED_BODY_H
#define ROPRAS_OMPL_EXT_ATTACHED_BODY_H

#include <Eigen/Geometry>
#include <cstdint>
#include <memory>
#include <string>
#include <vector>

#include "ropras/ompl_ext/model/Spherizer.h"
#include "ropras/ompl_ext/scene/Shape.h"

namespace ropras::ompl_ext
{
    class RobotModel;

    /** \brief A triangle mesh of an attached body, in the body frame (spherized when attached). */
    struct AttachedMesh
    {
        std::vector<Eigen::Vector3d> vertices;
        std::vector<Eigen::Vector3i> triangles;
        Eigen::Isometry3d pose{Eigen::Isometry3d::Identity()};  ///< mesh frame in the body frame
    };

    /** \brief A body carried rigidly by a robot link (MoveIt's AttachedCollisionObject): a grasped can, a tool.

        It moves with \a link at the fixed transform \a pose (body frame in the link frame). Its geometry is
        \a shapes (spheres, boxes, cylinders, capsules; point clouds are refused) and \a meshes, all in the body
        frame; everything but spheres is covered by the conservative Spherizer when the body is attached. It is
        checked against the obstacles of the Environment, against the robot's collision links except \a link and
        \a touchLinks (the hand holding it, the fingers), and against attached bodies carried by other frames. */
    struct AttachedBody
    {
        std::string name;
        std::string link;
        Eigen::Isometry3d pose{Eigen::Isometry3d::Identity()};
        std::vector<Shape> shapes;
        std::vector<AttachedMesh> meshes;
        std::vector<std::string> touchLinks;
    };

    /// spheres of an attached body's query form are padded to a multiple of this (the SIMD width of the kernels)
    constexpr int ATTACHED_SPHERE_PADDING = 8;

    /** \brief Query form of an AttachedBody for one RobotModel (what the collision kernels read): its spheres in
        the compiled kinematic frame that carries the link (RobotModel::links()[link].frame), float, padded to a
        multiple of ATTACHED_SPHERE_PADDING with copies of its own spheres; a bounding sphere; per collision link
        of the robot whether the body is allowed to touch it. */
    struct AttachedSpheres
    {
        std::shared_ptr<const RobotModel> robot;  ///< the model the frame and link indices refer to
        int link{-1};                             ///< RobotModel::links() index
        int frame{-1};                            ///< RobotModel::frames() index
        int count{0};                             ///< real spheres (x.size() is the padded count)
        std::vector<float> x, y, z, r;            ///< sphere centres in the frame, radii
        float bx{0}, by{0}, bz{0}, br{0};         ///< bounding sphere in the frame
        /// per RobotModel::collisionLinks() entry: 1 when the body may touch it (its own link, touch links)
        std::vector<std::uint8_t> mayTouch;
        /** \brief Per collision link: 1 when the kernels need not test it: it may be touched, or it is carried by the
            body's own frame (their relative pose never changes; a contact with such a link that may not be touched
            is decided once, in alwaysCollides). */
        std::vector<std::uint8_t> skipLink;
        /// true when some link the body may touch is carried by another frame than the body's (skipLink then holds
        /// more than the links of its own frame)
        bool touchesOtherFrames{false};
        /// the body touches a link of its own frame that it may not touch: every configuration is in collision
        bool alwaysCollides{false};
        /// in double, for the references: sphere centres in the link frame and radii
        std::vector<Sphere> spheresInLink;
    };

    /** \brief Checks \a body against \a robot (the link and touch links exist, the pose is a finite rigid
        transform, every shape is valid and not a point cloud, meshes are non-empty with valid indices) and builds
        its query form, covering non-sphere geometry with \a spherizer. Throws ropras::Error naming the body and
        the problem. */
    AttachedSpheres compileAttachedBody(std::shared_ptr<const RobotModel> robot, const AttachedBody &body,
                                        const SpherizerOptions &spherizer = SpherizerOptions());
}  // namespace ropras::ompl_ext

#endif
