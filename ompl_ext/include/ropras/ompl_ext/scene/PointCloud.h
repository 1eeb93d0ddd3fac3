#ifndef ROPRAS_OMPL_EXT_POINT_CLOUD_H
#define ROPRAS_OMPL_EXT_POINT_CLOUD_H

#include <Eigen/Core>
#include <memory>
#include <vector>

namespace ropras::ompl_ext
{
    /** \brief An immutable point cloud obstacle (points inflated by a radius) with a uniform-grid index that
        answers sphere queries fast. Shared between Environment copies through shared_ptr<const>. */
    class PointCloud
    {
    public:
        /// \a pointRadius >= 0 inflates every point; \a cellSize <= 0 picks one from the cloud's extent.
        /// Throws ropras::Error on non-finite points or negative radius.
        static std::shared_ptr<const PointCloud> build(const std::vector<Eigen::Vector3f> &points, float pointRadius,
                                                       float cellSize = 0.0f);

        /// true when the sphere (centre in the cloud's frame) touches an inflated point. noexcept, no allocation.
        bool intersectsSphere(float x, float y, float z, float radius) const noexcept;
        /// distance from the sphere surface to the nearest inflated point (negative: penetration);
        /// +infinity for an empty cloud. Exact (brute force over candidate cells, for tests and tools).
        double signedDistance(const Eigen::Vector3d &center, double radius) const;
        /** \brief The first contact of the segment \a a + t \a d, t in [0, \a tMax], with an inflated point
            (cloud frame): true and \a t set when there is one before \a tMax (t = 0 when \a a is inside one).
            Walks the grid cells along the segment, one cell length at a time, and stops at the first chunk
            that holds a contact. Inputs must be finite; noexcept, no allocation. */
        bool firstSegmentHit(const Eigen::Vector3d &a, const Eigen::Vector3d &d, double tMax, double &t) const noexcept;

        std::size_t size() const { return points_.size(); }
        float pointRadius() const { return pointRadius_; }
        const std::vector<Eigen::Vector3f> &points() const { return points_; }
        const Eigen::Vector3f &boundsMin() const { return min_; }
        const Eigen::Vector3f &boundsMax() const { return max_; }

    private:
        PointCloud() = default;
        std::vector<Eigen::Vector3f> points_;  ///< sorted by cell
        float pointRadius_{0.0f};
        float cellSize_{1.0f};
        Eigen::Vector3f min_{Eigen::Vector3f::Zero()}, max_{Eigen::Vector3f::Zero()};
        Eigen::Vector3i cells_{Eigen::Vector3i::Zero()};
        std::vector<unsigned> cellStart_;  ///< CSR offsets into points_, size = number of cells + 1
    };
}  // namespace ropras::ompl_ext

#endif
