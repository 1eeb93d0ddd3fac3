#ifndef ROPRAS_OMPL_EXT_SIMD_SELF_PAIR_PROGRAM_H
#define ROPRAS_OMPL_EXT_SIMD_SELF_PAIR_PROGRAM_H

#include <vector>

#include "collision/simd/KinematicProgram.h"
#include "ropras/ompl_ext/model/RobotModel.h"

namespace ropras::ompl_ext::simd
{
    /// a bounding radius enlarged for float rounding: culling with it may never drop a touching sphere
    float withRoundingSlack(double radius);

    /** \brief The self-collision part of the kinematic program, after its links (compileProgram): the program
        pairs of the model's self pairs with the sphere pairs that can touch within the joint limits and their
        grids of free cells, the link groups, the pairs sorted into one range per group pair, their rows, reach
        and the spheres around the members that can touch. \a linkIndex: the program links of each collision
        link. Throws Error naming the robot for a pair out of range. */
    void compileSelfPairProgram(const RobotModel &model, const std::vector<std::vector<int>> &linkIndex,
                                KinematicProgram &p);
}  // namespace ropras::ompl_ext::simd

#endif
