#ifndef ROPRAS_OMPL_EXT_SHAPE_INTERSECTION_H
#define ROPRAS_OMPL_EXT_SHAPE_INTERSECTION_H

#include <Eigen/Geometry>

#include "ropras/ompl_ext/scene/Shape.h"

namespace ropras::ompl_ext
{
    /** \brief Whether two primitives overlap: shape \a a placed at \a poseA (world from shape, after the shape's own
        pose) and \a b at \a poseB. Spheres, boxes, cylinders and capsules through FCL's narrow phase (its closed
        forms where it has them, libccd's GJK, to its tolerance, for pairs such as box-cylinder; the robot's sphere
        model is not involved). It allocates the two FCL geometries per call. Scenario models use it to keep sampled
       object poses physically possible (boxes that do not interpenetrate each other or a can). Shapes that only touch
       along a face may be reported either way; test with a small gap (shrink one shape) when that matters. Throws
       ropras::Error for a point cloud, a negative or non-finite size or a non-finite pose. */
    bool shapesIntersect(const Shape &a, const Eigen::Isometry3d &poseA, const Shape &b,
                         const Eigen::Isometry3d &poseB);
}  // namespace ropras::ompl_ext

#endif
