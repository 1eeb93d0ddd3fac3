#ifndef ROPRAS_OMPL_EXT_CROSS_CHECK_H
#define ROPRAS_OMPL_EXT_CROSS_CHECK_H

#include <cstdint>
#include <memory>
#include <random>
#include <string>
#include <vector>

#include "ropras/ompl_ext/collision/CollisionChecker.h"
#include "ropras/ompl_ext/model/RobotModel.h"
#include "ropras/ompl_ext/scene/Environment.h"

namespace ropras::ompl_ext
{
    /** \brief A named environment to cross-check in. */
    struct CrossCheckScene
    {
        std::string name;
        Environment env;
    };

    /** \brief Settings of crossCheckSpheres() and compareWithMeshes(). */
    struct CrossCheckOptions
    {
        /// random configurations in total (uniform within the joint limits), spread evenly over the scenes
        std::size_t samples{10000};
        std::uint64_t seed{1};
        /// a disagreement with the FCL reference is tolerated when FCL's signed distance is within this (m)
        double contactTolerance{1e-4};
        /// SIMD sphere centres must match RobotModel::sphereCentersReference within this (m)
        double centerTolerance{1e-5};
        /// every how many configurations the sphere centres are compared (1: all)
        std::size_t centerStride{4};
        std::vector<SimdBackend> backends{SimdBackend::Best, SimdBackend::Scalar};
        /// disagreements described in the report (at most)
        std::size_t maxExamples{5};
    };

    /** \brief Agreement of one CollisionChecker backend with FclSphereChecker. */
    struct BackendAgreement
    {
        SimdBackend backend{SimdBackend::Best};
        std::size_t agree{0};
        std::size_t nearContact{0};      ///< disagreements within the contact tolerance
        std::size_t disagreements{0};    ///< disagreements outside it (must be 0)
        double maxCenterError{0.0};      ///< m, sphereCenters and sphereCentersBatch vs the reference
        std::size_t centerChecks{0};     ///< configurations whose centres were compared
        std::size_t batchMismatches{0};  ///< isValidBatch verdicts differing from isValid (must be 0)
    };

    struct CrossCheckReport
    {
        std::size_t configurations{0};
        std::size_t referenceValid{0};  ///< FCL says collision-free
        std::vector<BackendAgreement> backends;
        std::vector<std::string> examples;  ///< first disagreements outside the tolerance
        /// true when every backend agrees outside the tolerance, its batch verdicts match and its centres are
        /// within the tolerance
        bool passed(double centerTolerance) const;
    };

    /** \brief Random configurations in every scene, checked by CollisionChecker (each backend; isValid and
        isValidBatch) and by FclSphereChecker; disagreements are classified with FclSphereChecker::distance.
        Deterministic for a seed. Throws ropras::Error when there is no scene or a backend is not compiled. */
    CrossCheckReport crossCheckSpheres(const std::shared_ptr<const RobotModel> &robot,
                                       const std::vector<CrossCheckScene> &scenes, const CrossCheckOptions &options);

    /** \brief How a sphere model compares with the robot's mesh geometry (FclMeshChecker). */
    struct MeshComparison
    {
        std::size_t configurations{0};
        std::size_t agree{0};
        std::size_t meshValid{0};
        std::size_t unsafe{0};                ///< sphere model says valid, the meshes collide
        std::size_t unsafeSelf{0};            ///< ... of which the meshes collide with themselves
        std::size_t overConservative{0};      ///< sphere model says invalid, the meshes are free
        std::size_t overConservativeSelf{0};  ///< ... of which the spheres collide with themselves
        std::size_t outOfLimits{0};           ///< invalid in both for being out of either model's limits
        std::vector<std::string> unsafeExamples;
    };

    /** \brief Random configurations checked by CollisionChecker(\a sphereRobot, Best) and
        FclMeshChecker(\a meshRobot). Both models must have the same planning joints (else ropras::Error). */
    MeshComparison compareWithMeshes(const std::shared_ptr<const RobotModel> &sphereRobot,
                                     const std::shared_ptr<const RobotModel> &meshRobot,
                                     const std::vector<CrossCheckScene> &scenes, const CrossCheckOptions &options);

    /// uniform random configuration within the joint limits (dof() values into \a q)
    void sampleConfiguration(const RobotModel &robot, std::mt19937_64 &rng, double *q);
}  // namespace ropras::ompl_ext

#endif
