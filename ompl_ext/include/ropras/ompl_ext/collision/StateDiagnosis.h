#ifndef ROPRAS_OMPL_EXT_STATE_DIAGNOSIS_H
#define ROPRAS_OMPL_EXT_STATE_DIAGNOSIS_H

#include <string>

#include "ropras/ompl_ext/collision/CollisionChecker.h"
#include "ropras/ompl_ext/scene/Environment.h"

namespace ropras::ompl_ext
{
    /** \brief Why \a q (dof() planning-joint values) is not a valid state for \a checker in \a env; "" when
        CollisionChecker::isValid accepts it.

        The verdict is the checker's own; the explanation names the cause: every planning joint that is not finite
        or lies outside its limits (name, value, limits), else the first colliding pair as the double-precision FCL
        reference on the same spheres finds it (a link against an obstacle, or two links), else — when only the
        float kernels see a contact — the FCL signed distance. For messages (`ropras plan`, `bench-mbm`): it
        allocates and builds an FclSphereChecker, so it is no hot-path call. */
    std::string explainInvalidState(const CollisionChecker &checker, const Environment &env, const double *q);
}  // namespace ropras::ompl_ext

#endif
