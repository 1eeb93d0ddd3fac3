#ifndef ROPRAS_OMPL_EXT_COLLISION_FREE_PREDICATE_H
#define ROPRAS_OMPL_EXT_COLLISION_FREE_PREDICATE_H

#include "ropras/ompl_ext/collision/CollisionChecker.h"
#include "ropras/ompl_ext/kinematics/InverseKinematics.h"
#include "ropras/ompl_ext/scene/Environment.h"

namespace ropras::ompl_ext
{
    /** \brief The ready-made InverseKinematics predicate: CollisionChecker::isValid in \a env (self-collision and
        obstacles, with whatever the checker's robot carries). Both are held by reference and must outlive the
        predicate; the checker's robot must be the chain's robot (same planning joints). A scene with
        attachments, or any other test, plugs in the same way: any ConfigurationPredicate will do. */
    inline ConfigurationPredicate collisionFreePredicate(const CollisionChecker &checker, const Environment &env)
    {
        return [&checker, &env](const double *q) { return checker.isValid(env, q); };
    }
}  // namespace ropras::ompl_ext

#endif
