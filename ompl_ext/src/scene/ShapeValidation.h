// Checks shared by Environment objects and attached bodies (private).
#ifndef ROPRAS_OMPL_EXT_SHAPE_VALIDATION_H
#define ROPRAS_OMPL_EXT_SHAPE_VALIDATION_H

#include <Eigen/Geometry>
#include <cstddef>
#include <string>

#include "ropras/ompl_ext/scene/Shape.h"

namespace ropras::ompl_ext::detail
{
    /// empty string when \a pose is a finite rigid transform, otherwise what is wrong with it
    std::string poseProblem(const Eigen::Isometry3d &pose);
    bool positiveFinite(double x);
    /// throws Error "<owner> shape <k> (<type>): <problem>"
    void validateShape(const std::string &owner, std::size_t k, const Shape &shape);
}  // namespace ropras::ompl_ext::detail

#endif
