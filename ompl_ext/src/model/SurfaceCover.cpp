#include "model/SurfaceCover.h"

#include <Eigen/Eigenvalues>
#include <algorithm>
#include <array>
#include <cmath>
#include <deque>
#include <limits>
#include <map>

#include "model/EnclosingSphere.h"
#include "model/TriangleGeometry.h"

// Algorithm (doc/spherizer.md): a fine grid over the surface gives surface cells, an inside/outside flood fill and
// exact surface distances. The bounding box is split into blocks of about s x s x s; every triangle is clipped to
// the blocks it touches and each block gets one sphere containing every vertex of its clipped pieces (a ball around
// a convex polygon's vertices contains the polygon, so every surface point is covered). The centre is pushed inward
// when that lowers the protrusion bound r - d (d: exact distance from an inside centre to the surface). s shrinks
// from the longest extent until the bound meets the tolerance; partitions with a better bound but too many spheres
// are greedily merged down to the budget; if the budget runs out, the best cover within it is returned (tolerance
// relaxed).

namespace ropras::ompl_ext
{
    namespace
    {
        constexpr int MAX_FINE_CELLS_PER_AXIS = 64;
        constexpr int BALL_REFINE_ITERATIONS = 120;
        constexpr int MERGE_REFINE_ITERATIONS = 40;

        struct FineCell
        {
            Eigen::Vector3i ijk;
            std::vector<Eigen::Vector3d> points;  ///< vertices of the triangle pieces clipped to the cell
            std::vector<int> triangles;           ///< triangles that reach into the cell
        };

        class SurfaceCover
        {
        public:
            SurfaceCover(const std::vector<Eigen::Vector3d> &vertices, const std::vector<Eigen::Vector3i> &triangles,
                         double tolerance, double slack)
                : vertices_(vertices), triangles_(triangles), slack_(slack)
            {
                Eigen::Vector3d lo = Eigen::Vector3d::Constant(std::numeric_limits<double>::infinity());
                Eigen::Vector3d hi = -lo;
                for (const Eigen::Vector3i &t : triangles)
                {
                    for (int k = 0; k < 3; ++k)
                    {
                        lo = lo.cwiseMin(vertices[t[k]]);
                        hi = hi.cwiseMax(vertices[t[k]]);
                    }
                }
                const double longest = std::max((hi - lo).maxCoeff(), 1e-9);
                cell_ = std::max(std::min(0.5 * tolerance, 0.25 * longest), longest / MAX_FINE_CELLS_PER_AXIS);
                lo_ = lo;
                hi_ = hi;
                for (int a = 0; a < 3; ++a)
                {
                    dims_[a] = static_cast<int>(std::floor((hi[a] - lo[a]) / cell_)) + 3;
                }
                // centre the box in the grid (one free cell around it for the outside flood fill)
                origin_ = 0.5 * (lo + hi) - 0.5 * cell_ * Eigen::Vector3d(dims_[0], dims_[1], dims_[2]);
                voxelize();
                classify();
            }

            /// one sphere per occupied block of an n[0] x n[1] x n[2] partition of the bounding box
            SphereCover cover(const Eigen::Vector3i &n, std::vector<std::vector<Eigen::Vector3d>> *pieces = nullptr,
                              std::vector<double> *bounds = nullptr) const
            {
                const Eigen::Vector3d size = (hi_ - lo_).cwiseQuotient(n.cast<double>());
                std::map<long, std::vector<Eigen::Vector3d>> blocks;
                std::vector<Eigen::Vector3d> poly, scratch;
                for (const Eigen::Vector3i &t : triangles_)
                {
                    const Eigen::Vector3d &a = vertices_[t[0]], &b = vertices_[t[1]], &c = vertices_[t[2]];
                    const Eigen::Vector3d tlo = a.cwiseMin(b).cwiseMin(c), thi = a.cwiseMax(b).cwiseMax(c);
                    Eigen::Vector3i i0, i1;
                    for (int ax = 0; ax < 3; ++ax)
                    {
                        const double w = size[ax] > 0.0 ? size[ax] : 1.0;
                        i0[ax] = std::clamp(static_cast<int>(std::floor((tlo[ax] - lo_[ax]) / w)), 0, n[ax] - 1);
                        i1[ax] = std::clamp(static_cast<int>(std::floor((thi[ax] - lo_[ax]) / w)), 0, n[ax] - 1);
                    }
                    for (int z = i0.z(); z <= i1.z(); ++z)
                    {
                        for (int y = i0.y(); y <= i1.y(); ++y)
                        {
                            for (int x = i0.x(); x <= i1.x(); ++x)
                            {
                                const Eigen::Vector3i ijk(x, y, z);
                                poly.assign({a, b, c});
                                for (int ax = 0; ax < 3 && !poly.empty(); ++ax)
                                {
                                    // outer faces of the partition are open so that nothing is clipped away
                                    if (ijk[ax] + 1 < n[ax])
                                    {
                                        clipPlane(poly, ax, lo_[ax] + size[ax] * (ijk[ax] + 1), 1.0, scratch);
                                    }
                                    if (ijk[ax] > 0 && !poly.empty())
                                    {
                                        clipPlane(poly, ax, lo_[ax] + size[ax] * ijk[ax], -1.0, scratch);
                                    }
                                }
                                if (!poly.empty())
                                {
                                    auto &pts = blocks[(static_cast<long>(z) * n[1] + y) * n[0] + x];
                                    pts.insert(pts.end(), poly.begin(), poly.end());
                                }
                            }
                        }
                    }
                }
                SphereCover out;
                for (auto &entry : blocks)
                {
                    auto less = [](const Eigen::Vector3d &x, const Eigen::Vector3d &y)
                    { return std::lexicographical_compare(x.data(), x.data() + 3, y.data(), y.data() + 3); };
                    std::sort(entry.second.begin(), entry.second.end(), less);
                    entry.second.erase(std::unique(entry.second.begin(), entry.second.end()), entry.second.end());
                    double bound = 0.0;
                    out.spheres.push_back(blockSphere(entry.second, bound));
                    out.protrusion = std::max(out.protrusion, bound);
                    if (bounds != nullptr)
                    {
                        bounds->push_back(bound);
                    }
                    if (pieces != nullptr)
                    {
                        pieces->push_back(std::move(entry.second));
                    }
                }
                return out;
            }

            /** \brief Greedy merging: starting from a cover with too many spheres, repeatedly replace the two
                touching spheres whose merged sphere (around the union of their piece vertices) has the smallest
                protrusion bound, until \a budget spheres remain. Coverage is kept: every merged sphere contains
                all piece vertices of both. */
            SphereCover merge(std::vector<std::vector<Eigen::Vector3d>> pieces, SphereCover cover,
                              std::vector<double> bounds, int budget) const
            {
                const std::size_t n = pieces.size();
                std::vector<bool> alive(n, true);
                struct Candidate
                {
                    double bound;  ///< worst of the merged sphere and the two it replaces (greedy key)
                    double own;    ///< the merged sphere's bound
                    Sphere sphere;
                };
                std::map<std::pair<std::size_t, std::size_t>, Candidate> candidates;
                auto touching = [&](std::size_t i, std::size_t j)
                {
                    const Sphere &a = cover.spheres[i], &b = cover.spheres[j];
                    return (a.center - b.center).norm() <= a.radius + b.radius;
                };
                auto evaluate = [&](std::size_t i, std::size_t j)
                {
                    std::vector<Eigen::Vector3d> both = pieces[i];
                    both.insert(both.end(), pieces[j].begin(), pieces[j].end());
                    double bound = 0.0;
                    const Sphere merged = blockSphere(both, bound, MERGE_REFINE_ITERATIONS);
                    candidates[{i, j}] = Candidate{std::max({bound, bounds[i], bounds[j]}), bound, merged};
                };
                for (std::size_t i = 0; i < n; ++i)
                {
                    for (std::size_t j = i + 1; j < n; ++j)
                    {
                        if (touching(i, j))
                        {
                            evaluate(i, j);
                        }
                    }
                }
                std::size_t count = n;
                while (static_cast<int>(count) > budget && !candidates.empty())
                {
                    auto best = candidates.begin();
                    for (auto it = candidates.begin(); it != candidates.end(); ++it)
                    {
                        if (it->second.bound < best->second.bound)
                        {
                            best = it;
                        }
                    }
                    const auto [i, j] = best->first;
                    const Candidate chosen = best->second;
                    pieces[i].insert(pieces[i].end(), pieces[j].begin(), pieces[j].end());
                    pieces[j].clear();
                    cover.spheres[i] = chosen.sphere;
                    bounds[i] = chosen.own;
                    alive[j] = false;
                    --count;
                    for (auto it = candidates.begin(); it != candidates.end();)
                    {
                        it = (it->first.first == i || it->first.second == i || it->first.first == j ||
                              it->first.second == j)
                                 ? candidates.erase(it)
                                 : std::next(it);
                    }
                    for (std::size_t k = 0; k < n; ++k)
                    {
                        if (k != i && alive[k] && touching(std::min(i, k), std::max(i, k)))
                        {
                            evaluate(std::min(i, k), std::max(i, k));
                        }
                    }
                }
                SphereCover out;
                for (std::size_t i = 0; i < n; ++i)
                {
                    if (alive[i])
                    {
                        out.spheres.push_back(cover.spheres[i]);
                        out.protrusion = std::max(out.protrusion, bounds[i]);
                    }
                }
                return out;
            }

            Eigen::Vector3d extent() const { return hi_ - lo_; }
            double fineCell() const { return cell_; }

        private:
            long flat(int i, int j, int k) const { return (static_cast<long>(k) * dims_[1] + j) * dims_[0] + i; }

            void voxelize()
            {
                const long total = static_cast<long>(dims_[0]) * dims_[1] * dims_[2];
                std::vector<int> slot(static_cast<std::size_t>(total), -1);
                std::vector<Eigen::Vector3d> poly, scratch;
                const double eps = 1e-12 * cell_;
                for (const Eigen::Vector3i &t : triangles_)
                {
                    const Eigen::Vector3d &a = vertices_[t[0]], &b = vertices_[t[1]], &c = vertices_[t[2]];
                    const Eigen::Vector3d lo = a.cwiseMin(b).cwiseMin(c), hi = a.cwiseMax(b).cwiseMax(c);
                    Eigen::Vector3i i0, i1;
                    for (int ax = 0; ax < 3; ++ax)
                    {
                        i0[ax] =
                            std::clamp(static_cast<int>(std::floor((lo[ax] - origin_[ax]) / cell_)), 0, dims_[ax] - 1);
                        i1[ax] =
                            std::clamp(static_cast<int>(std::floor((hi[ax] - origin_[ax]) / cell_)), 0, dims_[ax] - 1);
                    }
                    for (int z = i0.z(); z <= i1.z(); ++z)
                    {
                        for (int y = i0.y(); y <= i1.y(); ++y)
                        {
                            for (int x = i0.x(); x <= i1.x(); ++x)
                            {
                                const Eigen::Vector3d cmin = origin_ + cell_ * Eigen::Vector3d(x, y, z);
                                const Eigen::Vector3d cmax = cmin + Eigen::Vector3d::Constant(cell_);
                                poly.assign({a, b, c});
                                for (int ax = 0; ax < 3 && !poly.empty(); ++ax)
                                {
                                    clipPlane(poly, ax, cmax[ax] + eps, 1.0, scratch);
                                    if (!poly.empty())
                                    {
                                        clipPlane(poly, ax, cmin[ax] - eps, -1.0, scratch);
                                    }
                                }
                                if (poly.empty())
                                {
                                    continue;
                                }
                                int &s = slot[static_cast<std::size_t>(flat(x, y, z))];
                                if (s < 0)
                                {
                                    s = static_cast<int>(cells_.size());
                                    cells_.push_back(FineCell{Eigen::Vector3i(x, y, z), {}, {}});
                                }
                                auto &cell = cells_[static_cast<std::size_t>(s)];
                                cell.points.insert(cell.points.end(), poly.begin(), poly.end());
                                cell.triangles.push_back(static_cast<int>(&t - triangles_.data()));
                            }
                        }
                    }
                }
                // Clipped pieces share vertices: keep each point once per cell.
                for (FineCell &cell : cells_)
                {
                    auto less = [](const Eigen::Vector3d &x, const Eigen::Vector3d &y)
                    { return std::lexicographical_compare(x.data(), x.data() + 3, y.data(), y.data() + 3); };
                    std::sort(cell.points.begin(), cell.points.end(), less);
                    cell.points.erase(std::unique(cell.points.begin(), cell.points.end()), cell.points.end());
                }
                slot_ = std::move(slot);
                surface_.assign(static_cast<std::size_t>(total), 0);
                for (const FineCell &cell : cells_)
                {
                    surface_[static_cast<std::size_t>(flat(cell.ijk.x(), cell.ijk.y(), cell.ijk.z()))] = 1;
                }
            }

            // Flood the outside from the padded corner through cells without surface; what stays is inside.
            void classify()
            {
                state_ = surface_;  // 1 surface, 2 outside, 0 inside
                std::deque<Eigen::Vector3i> queue{Eigen::Vector3i(0, 0, 0)};
                state_[0] = 2;
                const int steps[6][3] = {{1, 0, 0}, {-1, 0, 0}, {0, 1, 0}, {0, -1, 0}, {0, 0, 1}, {0, 0, -1}};
                while (!queue.empty())
                {
                    const Eigen::Vector3i c = queue.front();
                    queue.pop_front();
                    for (const auto &s : steps)
                    {
                        const Eigen::Vector3i n = c + Eigen::Vector3i(s[0], s[1], s[2]);
                        if ((n.array() < 0).any() || n.x() >= dims_[0] || n.y() >= dims_[1] || n.z() >= dims_[2])
                        {
                            continue;
                        }
                        char &st = state_[static_cast<std::size_t>(flat(n.x(), n.y(), n.z()))];
                        if (st == 0)
                        {
                            st = 2;
                            queue.push_back(n);
                        }
                    }
                }
                // Chebyshev distance (in cells) from every cell to the nearest surface cell: a multi-source
                // breadth-first search over the 26 neighbours. The ring search starts there.
                ringStart_.assign(state_.size(), -1);
                std::deque<Eigen::Vector3i> frontier;
                for (const FineCell &cell : cells_)
                {
                    ringStart_[static_cast<std::size_t>(flat(cell.ijk.x(), cell.ijk.y(), cell.ijk.z()))] = 0;
                    frontier.push_back(cell.ijk);
                }
                while (!frontier.empty())
                {
                    const Eigen::Vector3i c = frontier.front();
                    frontier.pop_front();
                    const int d = ringStart_[static_cast<std::size_t>(flat(c.x(), c.y(), c.z()))];
                    for (int dz = -1; dz <= 1; ++dz)
                    {
                        for (int dy = -1; dy <= 1; ++dy)
                        {
                            for (int dx = -1; dx <= 1; ++dx)
                            {
                                const Eigen::Vector3i n = c + Eigen::Vector3i(dx, dy, dz);
                                if ((n.array() < 0).any() || n.x() >= dims_[0] || n.y() >= dims_[1] ||
                                    n.z() >= dims_[2])
                                {
                                    continue;
                                }
                                int &r = ringStart_[static_cast<std::size_t>(flat(n.x(), n.y(), n.z()))];
                                if (r < 0)
                                {
                                    r = d + 1;
                                    frontier.push_back(n);
                                }
                            }
                        }
                    }
                }
            }

            /// exact distance from \a p to the surface (ring search over the fine grid); \a inside tells whether p
            /// lies in a cell the flood fill did not reach (inside the solid)
            double surfaceDistance(const Eigen::Vector3d &p, bool &inside) const
            {
                Eigen::Vector3i c;
                bool inGrid = true;
                for (int a = 0; a < 3; ++a)
                {
                    c[a] = static_cast<int>(std::floor((p[a] - origin_[a]) / cell_));
                    inGrid = inGrid && c[a] >= 0 && c[a] < dims_[a];
                }
                inside = inGrid && state_[static_cast<std::size_t>(flat(c.x(), c.y(), c.z()))] == 0;
                double best = std::numeric_limits<double>::infinity();
                if (!inside)
                {
                    return best;  // callers bound outside centres differently
                }
                const int maxRing = std::max({dims_[0], dims_[1], dims_[2]});
                const int firstRing = std::max(0, ringStart_[static_cast<std::size_t>(flat(c.x(), c.y(), c.z()))]);
                for (int ring = firstRing; ring <= maxRing; ++ring)
                {
                    // every cell of this ring is at least (ring - 1) cells away from p
                    const double reach = std::max(0, ring - 1) * cell_;
                    if (reach * reach > best)
                    {
                        break;
                    }
                    for (int z = c.z() - ring; z <= c.z() + ring; ++z)
                    {
                        for (int y = c.y() - ring; y <= c.y() + ring; ++y)
                        {
                            // on the shell's faces in z or y every x; inside them only the two x ends
                            const bool face = std::abs(z - c.z()) == ring || std::abs(y - c.y()) == ring;
                            const int step = face || ring == 0 ? 1 : 2 * ring;
                            for (int x = c.x() - ring; x <= c.x() + ring; x += step)
                            {
                                if (x < 0 || y < 0 || z < 0 || x >= dims_[0] || y >= dims_[1] || z >= dims_[2])
                                {
                                    continue;
                                }
                                const int s = slot_[static_cast<std::size_t>(flat(x, y, z))];
                                if (s < 0)
                                {
                                    continue;
                                }
                                const Eigen::Vector3d cmin = origin_ + cell_ * Eigen::Vector3d(x, y, z);
                                const Eigen::Vector3d gap =
                                    (cmin - p).cwiseMax(p - cmin - Eigen::Vector3d::Constant(cell_)).cwiseMax(0.0);
                                if (gap.squaredNorm() >= best)
                                {
                                    continue;
                                }
                                for (int ti : cells_[static_cast<std::size_t>(s)].triangles)
                                {
                                    const Eigen::Vector3i &t = triangles_[static_cast<std::size_t>(ti)];
                                    best = std::min(
                                        best,
                                        (closestOnTriangle(p, vertices_[t[0]], vertices_[t[1]], vertices_[t[2]]) - p)
                                            .squaredNorm());
                                }
                            }
                        }
                    }
                }
                return std::sqrt(best);
            }

            /// one sphere for a block of fine cells; \a bound receives its protrusion bound
            Sphere blockSphere(const std::vector<Eigen::Vector3d> &blockPoints, double &bound,
                               int refineIterations = BALL_REFINE_ITERATIONS) const
            {
                std::vector<Sphere> points;
                points.reserve(blockPoints.size());
                Eigen::Vector3d mean = Eigen::Vector3d::Zero();
                for (const Eigen::Vector3d &p : blockPoints)
                {
                    points.push_back(Sphere{p, 0.0});
                    mean += p;
                }
                mean /= static_cast<double>(points.size());
                Eigen::Matrix3d cov = Eigen::Matrix3d::Zero();
                for (const Sphere &p : points)
                {
                    cov += (p.center - mean) * (p.center - mean).transpose();
                }
                const Sphere base =
                    enclosingSphere(points, points.size() > 20000 ? refineIterations / 4 : refineIterations);
                Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> eig(cov);
                const Eigen::Vector3d normal = eig.eigenvectors().col(0);  // smallest spread: the patch normal

                // the ball around the piece vertices contains the convex hull of each clipped (convex) piece
                auto radiusAt = [&](const Eigen::Vector3d &c)
                {
                    double r = 0.0;
                    for (const Sphere &p : points)
                    {
                        r = std::max(r, (p.center - c).squaredNorm());
                    }
                    return std::sqrt(r) * (1.0 + 1e-12) + 1e-12 + slack_;
                };
                // protrusion <= r - d when the centre is inside at distance d from the surface, else <= r + d
                auto boundAt = [&](const Eigen::Vector3d &c, double r)
                {
                    bool inside = false;
                    const double d = surfaceDistance(c, inside);
                    if (inside)
                    {
                        return r - d;
                    }
                    // the nearest piece vertex is a surface point: the distance to the surface is at most that
                    double nearest = std::numeric_limits<double>::infinity();
                    for (const Sphere &q : points)
                    {
                        nearest = std::min(nearest, (q.center - c).squaredNorm());
                    }
                    return r + std::sqrt(nearest);
                };
                Sphere best{base.center, radiusAt(base.center)};
                bound = boundAt(best.center, best.radius);
                std::vector<Eigen::Vector3d> directions;
                if (normal.allFinite())
                {
                    directions.push_back(normal);
                    directions.push_back(-normal);
                }
                directions.push_back(mean - base.center);  // toward the bulk of the piece points
                for (const Eigen::Vector3d &dir : directions)
                {
                    if (dir.norm() < 1e-12)
                    {
                        continue;
                    }
                    for (const double depth : {0.25, 0.5, 1.0, 1.5, 2.0, 3.0})
                    {
                        const Eigen::Vector3d c = base.center + depth * base.radius * dir.normalized();
                        const double r = radiusAt(c);
                        const double b = boundAt(c, r);
                        if (b < bound)
                        {
                            bound = b;
                            best = Sphere{c, r};
                        }
                    }
                }
                return best;
            }

            const std::vector<Eigen::Vector3d> &vertices_;
            const std::vector<Eigen::Vector3i> &triangles_;
            double slack_;
            double cell_{0.0};
            Eigen::Vector3d origin_, lo_, hi_;
            std::array<int, 3> dims_{};
            std::vector<FineCell> cells_;
            std::vector<char> surface_, state_;
            std::vector<int> slot_;       ///< fine cell index -> cells_ index or -1
            std::vector<int> ringStart_;  ///< Chebyshev distance (cells) to the nearest surface cell
        };
    }  // namespace

    /// shrink the block size until the bound meets the tolerance or the sphere budget runs out
    SphereCover coverTriangles(const std::vector<Eigen::Vector3d> &vertices,
                               const std::vector<Eigen::Vector3i> &triangles, const SpherizerOptions &options,
                               double slack)
    {
        const SurfaceCover surface(vertices, triangles, options.tolerance, slack);
        const Eigen::Vector3d extent = surface.extent();
        SphereCover best;
        bool haveBest = false;
        Eigen::Vector3i previous(0, 0, 0);
        int mergesLeft = 2;  // merging is the expensive step: try it on the first two over-budget partitions
        // blocks of about s x s x s, s shrinking from the longest extent down to the fine cell
        for (double s = extent.maxCoeff(); s >= 0.5 * surface.fineCell(); s *= 0.8)
        {
            Eigen::Vector3i n;
            for (int a = 0; a < 3; ++a)
            {
                n[a] = std::max(1, static_cast<int>(std::lround(extent[a] / s)));
            }
            if (n == previous)
            {
                continue;
            }
            previous = n;
            std::vector<std::vector<Eigen::Vector3d>> pieces;
            std::vector<double> bounds;
            SphereCover c = surface.cover(n, &pieces, &bounds);
            const int count = static_cast<int>(c.spheres.size());
            if (count > options.maxSpheresPerGeometry && count <= 2 * options.maxSpheresPerGeometry &&
                (!haveBest || c.protrusion < best.protrusion) && mergesLeft-- > 0)
            {
                // too many spheres but a better bound: merge down to the budget
                c = surface.merge(std::move(pieces), c, std::move(bounds), options.maxSpheresPerGeometry);
            }
            const bool fits = static_cast<int>(c.spheres.size()) <= options.maxSpheresPerGeometry;
            if (fits && c.protrusion <= options.tolerance)
            {
                c.toleranceMet = true;
                return c;
            }
            if (fits && (!haveBest || c.protrusion < best.protrusion))
            {
                best = c;
                haveBest = true;
            }
            if (!fits && count > 2 * options.maxSpheresPerGeometry)
            {
                break;
            }
        }
        if (!haveBest)
        {
            best = surface.cover(Eigen::Vector3i(1, 1, 1));  // one sphere always fits
        }
        best.toleranceMet = false;
        return best;
    }
}  // namespace ropras::ompl_ext
