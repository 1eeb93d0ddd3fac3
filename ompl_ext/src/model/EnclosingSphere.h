#ifndef ROPRAS_OMPL_EXT_SRC_ENCLOSING_SPHERE_H
#define ROPRAS_OMPL_EXT_SRC_ENCLOSING_SPHERE_H

#include <vector>

#include "ropras/ompl_ext/model/Spherizer.h"

namespace ropras::ompl_ext
{
    /** \brief A small sphere that encloses every given sphere (radius 0 spheres are points).
        The best of Ritter's growth pass and a Badoiu-Clarkson refinement; the returned radius is always
        recomputed as max |c - c_i| + r_i, so enclosure holds exactly (up to rounding), and it is within a
        few percent of the minimal enclosing ball. Empty input gives a zero sphere at the origin. */
    Sphere enclosingSphere(const std::vector<Sphere> &spheres, int refineIterations = 2000);
}  // namespace ropras::ompl_ext

#endif
