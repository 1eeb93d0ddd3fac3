// ShelfMoveModel's placement rules: where a can may stand, the grasp and the release, the held can following the
// hand.
#include <algorithm>
#include <cmath>

#include "ropras/scenarios/manipulation/ShelfMoveModel.h"

namespace ropras::scenarios
{
    namespace
    {
        constexpr double PI = 3.14159265358979323846;
    }  // namespace

    Eigen::Isometry3d ShelfMoveModel::graspTransform() const
    {
        Eigen::Isometry3d t = Eigen::Isometry3d::Identity();
        t.translation() = Eigen::Vector3d(0.0, 0.0, config_.graspOffset);
        t.linear() = Eigen::AngleAxisd(PI / 2.0, Eigen::Vector3d::UnitY()).toRotationMatrix();
        return t;
    }

    int ShelfMoveModel::supportingBox(const double *c) const noexcept
    {
        const double bottom = c[2] - 0.5 * config_.canLength;
        const double r = config_.canRadius;
        for (std::size_t i = 0; i < config_.shelf.size(); ++i)
        {
            const auto &b = config_.shelf[i];
            if (std::abs(b[2] + 0.5 * b[5] - bottom) <= 1e-3 && std::abs(c[0] - b[0]) <= 0.5 * b[3] - r &&
                std::abs(c[1] - b[1]) <= 0.5 * b[4] - r)
            {
                return static_cast<int>(i);
            }
        }
        return -1;
    }

    bool ShelfMoveModel::canPlacementValid(const State &s, std::size_t k) const noexcept
    {
        const double *c = s.can[k];
        if (!(std::isfinite(c[0]) && std::isfinite(c[1]) && std::isfinite(c[2])))
        {
            return false;
        }
        const int support = supportingBox(c);
        if (support < 0)
        {
            return false;
        }
        const double r = config_.canRadius;
        const double half = 0.5 * config_.canLength;
        for (std::size_t i = 0; i < config_.shelf.size(); ++i)
        {
            if (static_cast<int>(i) == support)
            {
                continue;
            }
            const auto &b = config_.shelf[i];
            if (c[2] + half <= b[2] - 0.5 * b[5] || c[2] - half + 1e-4 >= b[2] + 0.5 * b[5])
            {
                continue;  // no overlap in z
            }
            const double dx = std::max(0.0, std::abs(c[0] - b[0]) - 0.5 * b[3]);
            const double dy = std::max(0.0, std::abs(c[1] - b[1]) - 0.5 * b[4]);
            if (dx * dx + dy * dy < r * r)
            {
                return false;
            }
        }
        for (std::size_t j = 0; j < SHELF_CANS; ++j)
        {
            if (j == k || static_cast<int>(j) == s.held)
            {
                continue;
            }
            const double *o = s.can[j];
            if (std::abs(o[2] - c[2]) < 2.0 * half && std::hypot(o[0] - c[0], o[1] - c[1]) < 2.0 * r)
            {
                return false;
            }
        }
        return true;
    }

    bool ShelfMoveModel::validState(const State &s) const noexcept
    {
        for (std::size_t k = 0; k < SHELF_CANS; ++k)
        {
            if (static_cast<int>(k) != s.held && !canPlacementValid(s, k))
            {
                return false;
            }
        }
        return arm_->checker()->isValid(scene(s), s.q);
    }

    void ShelfMoveModel::followHand(State &s) const noexcept
    {
        if (s.held < 0 || s.held >= static_cast<int>(SHELF_CANS))
        {
            return;
        }
        const Eigen::Vector3d p = graspPoint(s);
        for (int a = 0; a < 3; ++a)
        {
            s.can[s.held][a] = p[a];
        }
    }

    int ShelfMoveModel::graspableCan(const State &s) const noexcept
    {
        if (s.held >= 0)
        {
            return -1;
        }
        const Eigen::Isometry3d ee = arm_->endEffectorPose(s.q);
        if (std::abs(ee.linear().col(0).z()) < std::cos(config_.graspAxisTolerance))
        {
            return -1;
        }
        const Eigen::Vector3d p = ee * Eigen::Vector3d(0.0, 0.0, config_.graspOffset);
        const double half = 0.5 * config_.canLength;
        int best = -1;
        double bestDistance = config_.graspTolerance;
        for (std::size_t k = 0; k < SHELF_CANS; ++k)
        {
            const double *c = s.can[k];
            const double dz = std::max(0.0, std::abs(p.z() - c[2]) - half);
            const double d = std::sqrt((p.x() - c[0]) * (p.x() - c[0]) + (p.y() - c[1]) * (p.y() - c[1]) + dz * dz);
            if (d <= bestDistance)
            {
                bestDistance = d;
                best = static_cast<int>(k);
            }
        }
        return best;
    }

    ShelfMoveModel::State ShelfMoveModel::placedOnSlot(const State &s, std::size_t k, std::size_t slot) const noexcept
    {
        State placed = s;
        for (std::size_t a = 0; a < 3; ++a)
        {
            placed.can[k][a] = config_.slots[slot][a];
        }
        if (placed.held == static_cast<int>(k))
        {
            placed.held = -1;
        }
        return placed;
    }

    int ShelfMoveModel::releaseSlot(const State &s) const noexcept
    {
        if (s.held < 0 || s.held >= static_cast<int>(SHELF_CANS))
        {
            return -1;
        }
        const Eigen::Vector3d p = graspPoint(s);
        int best = -1;
        double bestDistance = 1e300;
        for (std::size_t i = 0; i < config_.slots.size(); ++i)
        {
            const auto &slot = config_.slots[i];
            const double d = (p - Eigen::Vector3d(slot[0], slot[1], slot[2])).norm();
            if (d > config_.placeTolerance || d >= bestDistance)
            {
                continue;
            }
            const State placed = placedOnSlot(s, static_cast<std::size_t>(s.held), i);
            if (canPlacementValid(placed, static_cast<std::size_t>(s.held)) &&
                arm_->checker()->isValid(scene(placed), placed.q))
            {
                best = static_cast<int>(i);
                bestDistance = d;
            }
        }
        return best;
    }
}  // namespace ropras::scenarios
