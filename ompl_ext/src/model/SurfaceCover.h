#ifndef ROPRAS_OMPL_EXT_SRC_MODEL_SURFACE_COVER_H
#define ROPRAS_OMPL_EXT_SRC_MODEL_SURFACE_COVER_H

#include <vector>

#include "ropras/ompl_ext/model/Spherizer.h"

namespace ropras::ompl_ext
{
    /** \brief The spherizer's core: spheres that cover the closed triangle surface (\a vertices, \a triangles),
        each grown by \a slack. Shrinks the block size until the protrusion bound meets options.tolerance or the
        sphere budget runs out (then the best cover within the budget, toleranceMet false). Inputs are checked by
        the callers (spherizer::cover*Detailed). */
    SphereCover coverTriangles(const std::vector<Eigen::Vector3d> &vertices,
                               const std::vector<Eigen::Vector3i> &triangles, const SpherizerOptions &options,
                               double slack);
}  // namespace ropras::ompl_ext

#endif
