#include "ropras/pomdp/PathCache.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <string>

#include "ropras/core/Error.h"
#include "ropras/ompl_ext/motion/JointSteps.h"

namespace ropras::pomdp
{
    void PathCache::Settings::validate() const
    {
        if (!(radius >= 0.0) || !std::isfinite(radius))
            throw Error("PathCache: reuse radius (path_reuse) " + std::to_string(radius) + " must be finite and >= 0");
        if (pathsPerTarget == 0 || maxTargets == 0)
            throw Error("PathCache: paths per target (path_reuse_paths) and targets kept must be >= 1");
        if (prefixSteps > 0 && !(prefixStep > 0.0 && std::isfinite(prefixStep)))
            throw Error("PathCache: the prefix step " + std::to_string(prefixStep) +
                        " must be finite and > 0 when a prefix of " + std::to_string(prefixSteps) + " steps is set");
    }

    PathCache::PathCache(std::size_t dof, const Settings &settings) : dof_(dof), settings_(settings)
    {
        if (dof_ == 0)
            throw Error("PathCache: dof must be >= 1");
        settings_.validate();
        near_.reserve(settings_.pathsPerTarget);
    }

    PathCache::Entry *PathCache::entryOf(const double *target) noexcept
    {
        for (auto &e : entries_)
        {
            if (std::equal(e.target.begin(), e.target.end(), target))
                return &e;
        }
        return nullptr;
    }

    double PathCache::nearest(const std::vector<double> &path, const double *start, std::size_t &segment,
                              double &t) const noexcept
    {
        double bestD2 = std::numeric_limits<double>::infinity();
        const std::size_t n = path.size() / dof_;
        for (std::size_t i = 0; i + 1 < n; ++i)
        {
            const double *a = &path[i * dof_], *b = &path[(i + 1) * dof_];
            double ab2 = 0.0, apab = 0.0;
            for (std::size_t j = 0; j < dof_; ++j)
            {
                ab2 += (b[j] - a[j]) * (b[j] - a[j]);
                apab += (start[j] - a[j]) * (b[j] - a[j]);
            }
            const double u = ab2 > 0.0 ? std::clamp(apab / ab2, 0.0, 1.0) : 0.0;
            double d2 = 0.0;
            for (std::size_t j = 0; j < dof_; ++j)
            {
                const double p = a[j] + u * (b[j] - a[j]);
                d2 += (start[j] - p) * (start[j] - p);
            }
            if (d2 < bestD2)
            {
                bestD2 = d2;
                segment = i;
                t = u;
            }
        }
        return bestD2;
    }

    std::size_t PathCache::prefixWaypoints(const double *path, std::size_t count) const noexcept
    {
        if (settings_.prefixSteps == 0)
            return count;
        std::size_t pieces = 0;
        for (std::size_t s = 0; s + 1 < count; ++s)
        {
            double length2 = 0.0;
            for (std::size_t j = 0; j < dof_; ++j)
            {
                const double d = path[(s + 1) * dof_ + j] - path[s * dof_ + j];
                length2 += d * d;
            }
            if (length2 == 0.0)
                continue;
            pieces += ompl_ext::segmentPieces(std::sqrt(length2), settings_.prefixStep);
            if (pieces >= settings_.prefixSteps)
                return s + 2;
        }
        return count;
    }

    bool PathCache::find(const ompl_ext::CollisionChecker &checker, const ompl_ext::Environment &environment,
                         double resolution, const double *start, const double *target, Rng &rng,
                         std::vector<double> &out) noexcept
    {
        if (!enabled())
            return false;
        ++statistics_.queries;
        Entry *entry = entryOf(target);
        if (entry == nullptr || entry->paths.size() < settings_.pathsPerTarget)
        {
            ++statistics_.warming;
            return false;
        }
        near_.clear();
        for (const auto &path : entry->paths)
        {
            Near candidate{&path, 0, 0.0};
            if (nearest(path, start, candidate.segment, candidate.t) <= settings_.radius * settings_.radius)
                near_.push_back(candidate);
        }
        if (near_.empty())
            return false;
        const Near chosen = near_[rng.uniformIndex(near_.size())];
        const std::vector<double> *best = chosen.path;
        const std::size_t bestSegment = chosen.segment;
        const double bestT = chosen.t;
        try
        {
            std::vector<double> joined(start, start + dof_);
            const double *a = &(*best)[bestSegment * dof_], *b = &(*best)[(bestSegment + 1) * dof_];
            if (bestT < 1.0)
            {
                for (std::size_t j = 0; j < dof_; ++j)
                    joined.push_back(a[j] + bestT * (b[j] - a[j]));
            }
            joined.insert(joined.end(), best->begin() + static_cast<std::ptrdiff_t>((bestSegment + 1) * dof_),
                          best->end());
            const std::size_t whole = joined.size() / dof_;
            const std::size_t n = prefixWaypoints(joined.data(), whole);
            joined.resize(n * dof_);
            for (std::size_t i = 0; i + 1 < n; ++i)
            {
                if (!checker.isMotionValid(environment, &joined[i * dof_], &joined[(i + 1) * dof_], resolution))
                {
                    ++statistics_.rejected;
                    return false;
                }
            }
            out.swap(joined);
            ++statistics_.hits;
            if (n < whole)
                ++statistics_.truncated;
            return true;
        }
        catch (...)
        {
            return false;
        }
    }

    void PathCache::store(const double *target, const double *waypoints, std::size_t count) noexcept
    {
        if (!enabled() || count < 2)
            return;
        try
        {
            Entry *entry = entryOf(target);
            if (entry == nullptr)
            {
                if (entries_.size() < settings_.maxTargets)
                {
                    entries_.push_back(Entry{});
                    entry = &entries_.back();
                }
                else
                {
                    entry = &entries_[nextEntry_];
                    nextEntry_ = (nextEntry_ + 1) % settings_.maxTargets;
                    *entry = Entry{};
                }
                entry->target.assign(target, target + dof_);
            }
            std::vector<double> path(waypoints, waypoints + count * dof_);
            if (entry->paths.size() < settings_.pathsPerTarget)
            {
                entry->paths.push_back(std::move(path));
            }
            else
            {
                entry->paths[entry->next] = std::move(path);
                entry->next = (entry->next + 1) % settings_.pathsPerTarget;
            }
            ++statistics_.stored;
        }
        catch (...)
        {
        }
    }
}  // namespace ropras::pomdp
