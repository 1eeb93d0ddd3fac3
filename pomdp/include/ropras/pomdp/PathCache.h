#ifndef ROPRAS_POMDP_PATH_CACHE_H
#define ROPRAS_POMDP_PATH_CACHE_H

#include <cstddef>
#include <vector>

#include "ropras/ompl_ext/collision/CollisionChecker.h"
#include "ropras/ompl_ext/scene/Environment.h"
#include "ropras/pomdp/Rng.h"

namespace ropras::pomdp
{
    /** \brief Experience reuse for the OMPL reference policy ("plan once, cut many macro-actions"): the joint
        paths it planned, kept per target configuration, so that a later query toward the same target from a
        start near one of them continues along it instead of planning anew.

        A query from \a start to \a target looks at the kept paths whose target equals \a target (exactly: the
        arm scenarios draw their targets from a finite pool of IK solutions). While fewer than \a pathsPerTarget
        paths are kept for it, the query misses (the caller plans anew and stores the result: every target gets
        that many independently planned paths, which keeps the reference policy diverse). Then it finds, for
        each kept path, the point of its segments nearest to \a start (joint-space L2), draws one of the paths
        whose point is within the reuse radius uniformly, and returns start -> that point -> the rest of it, after
       checking every segment of the result with the CollisionChecker in the query's environment (so a path kept from
       another particle's world is never returned when it collides in this one; with Settings::prefixSteps only the part
       of it its caller reads is checked and returned). Like any SBMP's answer the result is a
       collision-free path from start to target; only the paths come from memory (cf. OMPL's experience-based Lightning
       / Thunder planners).

        Capacity: at most \a pathsPerTarget paths per target (the oldest is replaced) and \a maxTargets targets
        (the oldest target is dropped). Not thread-safe (one per reference policy). */
    class PathCache
    {
    public:
        struct Settings
        {
            double radius{0.0};             ///< reuse radius (joint-space L2, rad); 0 disables the cache
            std::size_t pathsPerTarget{4};  ///< paths kept per target configuration
            std::size_t maxTargets{64};     ///< target configurations kept
            /** \brief The part of a continued path its caller reads: when \a prefixSteps > 0, the caller cuts at
                most \a prefixSteps points of at most \a prefixStep (joint-space L2) from the path's start, each
                segment split into equal pieces (discretizeJointPath, as the arm scenarios' PathToMacroAction
                "motion path up to a predefined length" does). Then find() checks and returns only the whole
                segments that cut reaches (the macro-action cut from it is the same as from the whole path, and a
                collision beyond it does not reject the path). 0 = the whole path (the default). */
            double prefixStep{0.0};
            std::size_t prefixSteps{0};
            void validate() const;
        };

        struct Statistics
        {
            std::size_t queries{0};    ///< find() calls
            std::size_t hits{0};       ///< paths returned
            std::size_t warming{0};    ///< misses because the target had fewer than pathsPerTarget paths
            std::size_t rejected{0};   ///< a near path was found but collided in the query's environment
            std::size_t truncated{0};  ///< hits returned as a prefix (Settings::prefixSteps), not up to the target
            std::size_t stored{0};     ///< store() calls
        };

        /** \brief Throws ropras::Error for dof == 0, a negative or non-finite radius or zero capacities. */
        PathCache(std::size_t dof, const Settings &settings);

        bool enabled() const { return settings_.radius > 0.0; }
        const Settings &settings() const { return settings_; }
        const Statistics &statistics() const { return statistics_; }

        /** \brief Writes a kept path from \a start to \a target (row-major, first = start, last = target) to
            \a out and returns true, or returns false (out unchanged) when no kept path toward \a target passes
            within the radius of \a start, the target has fewer than pathsPerTarget paths, or the joined path
            collides in \a environment (checked at \a resolution). With Settings::prefixSteps the path written ends
            where the caller's cut ends (its last waypoint is then not \a target). noexcept: allocation failures
            count as a miss. */
        bool find(const ompl_ext::CollisionChecker &checker, const ompl_ext::Environment &environment,
                  double resolution, const double *start, const double *target, Rng &rng,
                  std::vector<double> &out) noexcept;

        /** \brief Keeps the path \a waypoints (\a count x dof, last = \a target) for later queries. */
        void store(const double *target, const double *waypoints, std::size_t count) noexcept;

        void clear() { entries_.clear(); }

    private:
        struct Entry
        {
            std::vector<double> target;
            std::vector<std::vector<double>> paths;
            std::size_t next{0};  ///< the path replaced when full
        };

        struct Near
        {
            const std::vector<double> *path;
            std::size_t segment;
            double t;
        };

        Entry *entryOf(const double *target) noexcept;
        /// the point of \a path nearest to \a start; returns its squared distance
        double nearest(const std::vector<double> &path, const double *start, std::size_t &segment,
                       double &t) const noexcept;
        /// the waypoints of \a path (\a count of them) that the caller's cut reads (Settings::prefixSteps)
        std::size_t prefixWaypoints(const double *path, std::size_t count) const noexcept;

        std::size_t dof_;
        Settings settings_;
        std::vector<Entry> entries_;
        std::size_t nextEntry_{0};
        std::vector<Near> near_;
        Statistics statistics_;
    };
}  // namespace ropras::pomdp

#endif
