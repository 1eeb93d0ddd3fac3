#include "ropras/ompl_ext/scene/PointCloud.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <sstream>

#include "ropras/core/Error.h"
#include "scene/SegmentTests.h"

namespace ropras::ompl_ext
{
    namespace
    {
        /// cap on the grid size (cells); a denser grid only wastes memory
        constexpr double MAX_CELLS = double(1u << 26);

        double cellCount(const Eigen::Vector3f &extent, double cell)
        {
            double count = 1.0;
            for (int i = 0; i < 3; ++i)
                count *= std::floor(double(extent[i]) / cell) + 1.0;
            return count;
        }

        /// a cell size giving about two points per cell (bisection on the cell count, which falls with the size)
        float autoCellSize(const Eigen::Vector3f &extent, std::size_t points, float pointRadius)
        {
            const double maxExtent = std::max(double(extent.maxCoeff()), 1e-6);
            const double target = std::max(1.0, double(points) / 2.0);
            double lo = maxExtent * 1e-6, hi = maxExtent * 2.0;  // cellCount(hi) == 1 <= target
            for (int iteration = 0; iteration < 60; ++iteration)
            {
                const double mid = std::sqrt(lo * hi);
                if (cellCount(extent, mid) > target)
                    lo = mid;
                else
                    hi = mid;
            }
            // a query visits about ((r + pointRadius) / cell)^3 cells: keep cells no smaller than a point
            double cell = std::max(hi, double(pointRadius));
            while (cellCount(extent, cell) > MAX_CELLS)
                cell *= 1.25;
            return float(cell);
        }
    }  // namespace

    std::shared_ptr<const PointCloud> PointCloud::build(const std::vector<Eigen::Vector3f> &points, float pointRadius,
                                                        float cellSize)
    {
        if (!std::isfinite(pointRadius) || pointRadius < 0.0f)
        {
            std::ostringstream msg;
            msg << "PointCloud::build: point radius must be finite and >= 0, got " << pointRadius;
            throw Error(msg.str());
        }
        if (!std::isfinite(cellSize))
        {
            std::ostringstream msg;
            msg << "PointCloud::build: cell size must be finite, got " << cellSize;
            throw Error(msg.str());
        }
        if (points.size() >= std::numeric_limits<unsigned>::max())
            throw Error("PointCloud::build: too many points (" + std::to_string(points.size()) + ")");
        for (std::size_t i = 0; i < points.size(); ++i)
        {
            if (!points[i].allFinite())
            {
                std::ostringstream msg;
                msg << "PointCloud::build: point " << i << " is not finite (" << points[i].transpose() << ")";
                throw Error(msg.str());
            }
        }

        std::shared_ptr<PointCloud> cloud(new PointCloud());
        cloud->pointRadius_ = pointRadius;
        if (points.empty())
        {
            cloud->cellSize_ = cellSize > 0.0f ? cellSize : 1.0f;
            cloud->cells_ = Eigen::Vector3i::Ones();
            cloud->cellStart_.assign(2, 0u);
            return cloud;
        }

        Eigen::Vector3f lo = points.front(), hi = points.front();
        for (const auto &p : points)
        {
            lo = lo.cwiseMin(p);
            hi = hi.cwiseMax(p);
        }
        const Eigen::Vector3f extent = hi - lo;
        float cell = cellSize;
        if (cell <= 0.0f)
            cell = autoCellSize(extent, points.size(), pointRadius);
        else if (cellCount(extent, cell) > MAX_CELLS)
        {
            std::ostringstream msg;
            msg << "PointCloud::build: cell size " << cellSize << " gives " << cellCount(extent, cell)
                << " cells for a cloud of extent (" << extent.transpose() << "), more than " << MAX_CELLS
                << "; pass a larger cell size or 0 for automatic";
            throw Error(msg.str());
        }
        cloud->cellSize_ = cell;
        cloud->min_ = lo;
        cloud->max_ = hi;
        for (int i = 0; i < 3; ++i)
            cloud->cells_[i] = int(std::floor(double(extent[i]) / cell)) + 1;

        const float inv = 1.0f / cell;
        const Eigen::Vector3i &n = cloud->cells_;
        auto cellOf = [&](const Eigen::Vector3f &p)
        {
            int index[3];
            for (int i = 0; i < 3; ++i)
                index[i] = std::clamp(int((p[i] - lo[i]) * inv), 0, n[i] - 1);
            return (std::size_t(index[2]) * std::size_t(n[1]) + std::size_t(index[1])) * std::size_t(n[0]) +
                   std::size_t(index[0]);
        };

        // counting sort by cell (CSR)
        const std::size_t total = std::size_t(n[0]) * std::size_t(n[1]) * std::size_t(n[2]);
        std::vector<unsigned> &start = cloud->cellStart_;
        start.assign(total + 1, 0u);
        std::vector<std::size_t> cellIndex(points.size());
        for (std::size_t i = 0; i < points.size(); ++i)
        {
            cellIndex[i] = cellOf(points[i]);
            ++start[cellIndex[i] + 1];
        }
        for (std::size_t c = 0; c < total; ++c)
            start[c + 1] += start[c];
        std::vector<unsigned> cursor(start.begin(), start.end() - 1);
        cloud->points_.resize(points.size());
        for (std::size_t i = 0; i < points.size(); ++i)
            cloud->points_[cursor[cellIndex[i]]++] = points[i];
        return cloud;
    }

    bool PointCloud::intersectsSphere(float x, float y, float z, float radius) const noexcept
    {
        if (points_.empty())
            return false;
        const float reach = radius + pointRadius_;
        // non-finite input: report contact (the conservative answer) rather than a silent "free"
        if (!(std::isfinite(x) && std::isfinite(y) && std::isfinite(z) && std::isfinite(reach)))
            return true;
        if (reach < 0.0f)
            return false;
        // the candidate cells use a slightly widened reach so that float rounding never drops a point the
        // distance test below would accept
        const float margin = reach * 1e-5f + 1e-6f;
        const float wide = reach + margin;
        if (x + wide < min_.x() || x - wide > max_.x() || y + wide < min_.y() || y - wide > max_.y() ||
            z + wide < min_.z() || z - wide > max_.z())
            return false;

        const float inv = 1.0f / cellSize_;
        const float c[3] = {x, y, z};
        int lo[3], hi[3];
        for (int i = 0; i < 3; ++i)
        {
            const float last = float(cells_[i] - 1);
            lo[i] = int(std::clamp(std::floor((c[i] - wide - min_[i]) * inv), 0.0f, last));
            hi[i] = int(std::clamp(std::floor((c[i] + wide - min_[i]) * inv), 0.0f, last));
        }
        const float reachSq = reach * reach;
        const Eigen::Vector3f *pts = points_.data();
        for (int iz = lo[2]; iz <= hi[2]; ++iz)
        {
            for (int iy = lo[1]; iy <= hi[1]; ++iy)
            {
                // the cells lo[0]..hi[0] of one row are contiguous in points_
                const std::size_t row =
                    (std::size_t(iz) * std::size_t(cells_[1]) + std::size_t(iy)) * std::size_t(cells_[0]);
                const unsigned begin = cellStart_[row + std::size_t(lo[0])];
                const unsigned end = cellStart_[row + std::size_t(hi[0]) + 1];
                for (unsigned k = begin; k < end; ++k)
                {
                    const float dx = pts[k].x() - x, dy = pts[k].y() - y, dz = pts[k].z() - z;
                    if (dx * dx + dy * dy + dz * dz <= reachSq)
                        return true;
                }
            }
        }
        return false;
    }

    double PointCloud::signedDistance(const Eigen::Vector3d &center, double radius) const
    {
        if (!center.allFinite() || !std::isfinite(radius))
        {
            std::ostringstream msg;
            msg << "PointCloud::signedDistance: non-finite query (centre " << center.transpose() << ", radius "
                << radius << ")";
            throw Error(msg.str());
        }
        if (points_.empty())
            return std::numeric_limits<double>::infinity();

        const Eigen::Vector3d lo = min_.cast<double>(), hi = max_.cast<double>();
        const double cell = cellSize_;
        // Every point within distance h of the centre lies in the cells overlapping the cube [c - h, c + h].
        // Search growing cubes until the nearest point found is within the cube's half width h.
        const double toBounds = (center.cwiseMax(lo).cwiseMin(hi) - center).norm();
        const double maxHalf = (hi - lo).norm() + toBounds + cell;
        double h = toBounds + cell;
        while (true)
        {
            int a[3], b[3];
            for (int i = 0; i < 3; ++i)
            {
                a[i] = int(std::clamp(std::floor((center[i] - h - lo[i]) / cell), 0.0, double(cells_[i] - 1)));
                b[i] = int(std::clamp(std::floor((center[i] + h - lo[i]) / cell), 0.0, double(cells_[i] - 1)));
            }
            double bestSq = std::numeric_limits<double>::infinity();
            for (int iz = a[2]; iz <= b[2]; ++iz)
            {
                for (int iy = a[1]; iy <= b[1]; ++iy)
                {
                    const std::size_t row =
                        (std::size_t(iz) * std::size_t(cells_[1]) + std::size_t(iy)) * std::size_t(cells_[0]);
                    for (unsigned k = cellStart_[row + std::size_t(a[0])]; k < cellStart_[row + std::size_t(b[0]) + 1];
                         ++k)
                        bestSq = std::min(bestSq, (points_[k].cast<double>() - center).squaredNorm());
                }
            }
            const double best = std::sqrt(bestSq);
            if (best <= h || h >= maxHalf)
                return best - radius - double(pointRadius_);
            h *= 2.0;
        }
    }

    bool PointCloud::firstSegmentHit(const Eigen::Vector3d &a, const Eigen::Vector3d &d, double tMax,
                                     double &t) const noexcept
    {
        if (points_.empty() || !(tMax >= 0.0))
            return false;
        const double r = pointRadius_;
        // widened a little so that rounding never drops a cell holding a point the exact test accepts
        const double reach = r * (1.0 + 1e-6) + 1e-6;
        const Eigen::Vector3d lo = min_.cast<double>(), hi = max_.cast<double>();
        double tNear = 0.0, tFar = tMax;
        for (int i = 0; i < 3; ++i)
            if (!segment::clipSlab(a[i], d[i], lo[i] - reach, hi[i] + reach, tNear, tFar))
                return false;

        const double length = d.norm();
        const double chunk = length > 0.0 ? double(cellSize_) / length : tFar - tNear + 1.0;
        const double inv = 1.0 / double(cellSize_);
        double best = tMax;
        bool found = false;
        // chunks of one cell length: a point whose first contact lies in a chunk is within `reach` of that
        // chunk, so it is in the cells of the chunk's box widened by reach; once a chunk ends after the best
        // contact found so far, no later chunk can hold an earlier one
        for (double t0 = tNear; t0 <= tFar; t0 += chunk)
        {
            const double t1 = std::min(t0 + chunk, tFar);
            const Eigen::Vector3d p0 = a + t0 * d, p1 = a + t1 * d;
            int c0[3], c1[3];
            for (int i = 0; i < 3; ++i)
            {
                const double last = double(cells_[i] - 1);
                c0[i] = int(std::clamp(std::floor((std::min(p0[i], p1[i]) - reach - lo[i]) * inv), 0.0, last));
                c1[i] = int(std::clamp(std::floor((std::max(p0[i], p1[i]) + reach - lo[i]) * inv), 0.0, last));
            }
            for (int iz = c0[2]; iz <= c1[2]; ++iz)
            {
                for (int iy = c0[1]; iy <= c1[1]; ++iy)
                {
                    const std::size_t row =
                        (std::size_t(iz) * std::size_t(cells_[1]) + std::size_t(iy)) * std::size_t(cells_[0]);
                    const unsigned begin = cellStart_[row + std::size_t(c0[0])];
                    const unsigned end = cellStart_[row + std::size_t(c1[0]) + 1];
                    for (unsigned k = begin; k < end; ++k)
                    {
                        double tk = 0.0;
                        if (segment::sphere(a, d, points_[k].cast<double>(), r, best, tk) && (!found || tk < best))
                        {
                            best = tk;
                            found = true;
                        }
                    }
                }
            }
            if (found && best <= t1)
                break;
            if (t1 >= tFar)
                break;
        }
        if (found)
            t = best;
        return found;
    }
}  // namespace ropras::ompl_ext
