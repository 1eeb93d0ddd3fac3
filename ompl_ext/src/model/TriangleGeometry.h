#ifndef ROPRAS_OMPL_EXT_SRC_MODEL_TRIANGLE_GEOMETRY_H
#define ROPRAS_OMPL_EXT_SRC_MODEL_TRIANGLE_GEOMETRY_H

#include <Eigen/Core>
#include <vector>

namespace ropras::ompl_ext
{
    /// Sutherland-Hodgman: keep the part of \a poly with (p[axis] - value) * side <= 0 (\a scratch: reused storage).
    void clipPlane(std::vector<Eigen::Vector3d> &poly, int axis, double value, double side,
                   std::vector<Eigen::Vector3d> &scratch);

    /// closest point of triangle abc to p (Ericson, Real-Time Collision Detection, 5.1.5)
    Eigen::Vector3d closestOnTriangle(const Eigen::Vector3d &p, const Eigen::Vector3d &a, const Eigen::Vector3d &b,
                                      const Eigen::Vector3d &c);
}  // namespace ropras::ompl_ext

#endif
