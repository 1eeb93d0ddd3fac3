// Forward kinematics and sphere collision kernels, written once for any 8-lane backend V.
// Single configuration: scalar FK, then vectorized over spheres (SingleKernels). Batch: one configuration per lane
// (BatchFrames, BatchKernels). Kernels<V> gathers both; AttachedKernels (included last) adds the attached bodies.
#ifndef ROPRAS_OMPL_EXT_SIMD_KERNELS_H
#define ROPRAS_OMPL_EXT_SIMD_KERNELS_H

#include "BatchFrames.h"
#include "BatchKernels.h"
#include "BroadPhase.h"
#include "FrameRows.h"
#include "KinematicProgram.h"
#include "ObstacleTests.h"
#include "Placed.h"
#include "SingleKernels.h"

namespace ropras::ompl_ext::simd
{
    /// every kernel of backend V: the single-configuration path and the batch path
    template <class V>
    struct Kernels : SingleKernels<V>, BatchFrames<V>, BatchKernels<V>
    {
        using Mask = typename V::Mask;
    };
}  // namespace ropras::ompl_ext::simd

#include "AttachedKernels.h"

#endif
