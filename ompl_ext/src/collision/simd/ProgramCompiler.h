#ifndef ROPRAS_OMPL_EXT_SIMD_PROGRAM_COMPILER_H
#define ROPRAS_OMPL_EXT_SIMD_PROGRAM_COMPILER_H

#include "collision/simd/KinematicProgram.h"
#include "ropras/ompl_ext/model/RobotModel.h"

namespace ropras::ompl_ext::simd
{
    /** \brief The kinematic program of \a model: its frames with their offsets folded, its collision links as
        program links (large links split, spheres padded into vector blocks), the self pairs that can touch within
        the joint limits with their grids, link groups and rows, and the scratch layouts of the single and batch
        paths. Throws Error naming the robot when the model is inconsistent (frame order, ranges). */
    KinematicProgram compileProgram(const RobotModel &model);
}  // namespace ropras::ompl_ext::simd

#endif
