#ifndef ROPRAS_OMPL_EXT_SPHERIZER_H
#define ROPRAS_OMPL_EXT_SPHERIZER_H

#include <Eigen/Core>
#include <string>
#include <vector>

namespace ropras::ompl_ext
{
    /** \brief Settings of the conservative spherizer (see doc/spherizer.md). */
    struct SpherizerOptions
    {
        /// maximal distance (m) by which the spheres may reach beyond the covered geometry's surface
        double tolerance{0.02};
        /// maximal number of spheres per collision element; if the tolerance cannot be met within it,
        /// the tolerance is relaxed (the cover stays conservative)
        int maxSpheresPerGeometry{32};
    };

    /** \brief A sphere in the geometry's frame. */
    struct Sphere
    {
        Eigen::Vector3d center{Eigen::Vector3d::Zero()};
        double radius{0.0};
    };

    /** \brief A cover with what it achieves. */
    struct SphereCover
    {
        std::vector<Sphere> spheres;
        /// upper bound (m) on how far any sphere reaches beyond the covered solid (see doc/spherizer.md)
        double protrusion{0.0};
        /// false when the tolerance had to be relaxed to stay within maxSpheresPerGeometry
        bool toleranceMet{true};
    };

    /** \brief Conservative sphere covers: every surface point of the input lies inside some sphere.
        Pure functions; inputs are validated (throw ropras::Error naming the geometry). */
    namespace spherizer
    {
        std::vector<Sphere> coverBox(const Eigen::Vector3d &fullExtents, const SpherizerOptions &options);
        /// cylinder along local z, centred at the origin
        std::vector<Sphere> coverCylinder(double radius, double length, const SpherizerOptions &options);
        /// triangle mesh: vertices and triangles (indices into vertices)
        std::vector<Sphere> coverMesh(const std::vector<Eigen::Vector3d> &vertices,
                                      const std::vector<Eigen::Vector3i> &triangles, const SpherizerOptions &options);

        /// the same covers with their protrusion bound and whether the tolerance was met
        SphereCover coverBoxDetailed(const Eigen::Vector3d &fullExtents, const SpherizerOptions &options);
        SphereCover coverCylinderDetailed(double radius, double length, const SpherizerOptions &options);
        SphereCover coverMeshDetailed(const std::vector<Eigen::Vector3d> &vertices,
                                      const std::vector<Eigen::Vector3i> &triangles, const SpherizerOptions &options);
    }  // namespace spherizer
}  // namespace ropras::ompl_ext

#endif
