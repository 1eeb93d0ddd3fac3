#ifndef ROPRAS_OMPL_EXT_COLLISION_CHECKER_H
#define ROPRAS_OMPL_EXT_COLLISION_CHECKER_H

#include <cstdint>
#include <memory>

#include "ropras/ompl_ext/model/RobotModel.h"
#include "ropras/ompl_ext/scene/Environment.h"

namespace ropras::ompl_ext
{
    /** \brief Which SIMD kernels to run. Scalar is always compiled; Avx2 only when the build targets AVX2
        (ROPRAS_NATIVE_SIMD on an AVX2 machine). Best picks the widest compiled backend. */
    enum class SimdBackend
    {
        Best,
        Scalar,
        Avx2
    };

    /// true when \a backend is compiled into this build (Best and Scalar always are)
    bool simdBackendAvailable(SimdBackend backend) noexcept;
    const char *simdBackendName(SimdBackend backend) noexcept;

    /** \brief Vectorized forward kinematics and sphere collision checking for one RobotModel.

        The constructor compiles the model into a compact float "kinematic program"; the checks are const,
        noexcept, allocation-free and thread-safe (scratch lives in per-thread storage), so several threads
        may share one checker. A configuration is valid when it is finite, within the joint limits, its
        spheres touch no obstacle and no self-collision pair touches. */
    class CollisionChecker
    {
    public:
        explicit CollisionChecker(std::shared_ptr<const RobotModel> robot, SimdBackend backend = SimdBackend::Best);
        ~CollisionChecker();
        CollisionChecker(const CollisionChecker &) = delete;
        CollisionChecker &operator=(const CollisionChecker &) = delete;

        const RobotModel &robot() const { return *robot_; }
        const std::shared_ptr<const RobotModel> &robotPtr() const { return robot_; }
        SimdBackend backend() const { return backend_; }
        /// configurations per SIMD batch (8 with AVX2)
        int width() const noexcept;
        /** \brief Sphere pairs the self-collision test examines: those of the robot's self-collision pairs that can
            touch within the joint limits (reachableSpherePairs); the others never collide and are never tested. */
        std::size_t selfSpherePairs() const noexcept;

        /// one configuration (dof() values)
        bool isValid(const Environment &env, const double *q) const noexcept;
        /// \a count configurations, row-major (count x dof()); writes one verdict each; returns the number valid
        std::size_t isValidBatch(const Environment &env, const double *qs, std::size_t count,
                                 bool *valid) const noexcept;
        /** \brief The part of isValidBatch without the robot's self-collision pairs: \a hit[i] is true when
            configuration i is outside its joint limits (or not finite), or touches an obstacle, or an attached body
            collides. A configuration that hits is invalid; one that does not may still self-collide (isValidBatch
            decides). A cheaper filter where invalid configurations are the common case (VectorizedRRTConnect's
            batched extension ends). Returns the number that hit. */
        std::size_t obstacleHitsBatch(const Environment &env, const double *qs, std::size_t count,
                                      bool *hit) const noexcept;
        /** \brief True when all \a count configurations (row-major, count x dof()) are valid. Faster than
            isValidBatch when the answer may be false: it stops at the first block of width() rows in which any
            configuration collides (the query VAMP's block check answers). Empty input: true. */
        bool allValid(const Environment &env, const double *qs, std::size_t count) const noexcept;
        /** \brief The straight joint-space motion q0 -> q1, interpolated at \a resolution (max joint step,
            rad or m) and raked over the SIMD lanes. q1 is checked; q0 is assumed valid (checked too when
            \a checkStart). When \a lastValidFraction is non-null it receives 1 if the motion is valid, else the
            largest t in [0,1) such that every checked configuration up to t is valid (within one step), so that
            q0 + t (q1 - q0) is where a blocked motion stops in either case. */
        bool isMotionValid(const Environment &env, const double *q0, const double *q1, double resolution,
                           double *lastValidFraction = nullptr, bool checkStart = false) const noexcept;

        /// FK only: world centres (x, y, z) and radius of every sphere, 4 floats each, indexed like spheres()
        void sphereCenters(const double *q, float *out) const noexcept;
        /// FK only, width() configurations at once (row-major), out: spheres x 4 x width(), lane-minor
        void sphereCentersBatch(const double *qs, float *out) const noexcept;

    private:
        struct Program;
        std::shared_ptr<const RobotModel> robot_;
        SimdBackend backend_;
        std::unique_ptr<Program> program_;
    };
}  // namespace ropras::ompl_ext

#endif
