#include "ropras/ompl_ext/collision/CrossCheck.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>
#include <sstream>

#include "ropras/core/Error.h"
#include "ropras/ompl_ext/collision/FclReferenceChecker.h"

namespace ropras::ompl_ext
{
    namespace
    {
        std::string formatConfiguration(const RobotModel &robot, const double *q)
        {
            std::ostringstream s;
            s.precision(17);
            s << '[';
            for (std::size_t i = 0; i < robot.dof(); ++i)
                s << (i ? ", " : "") << q[i];
            s << ']';
            return s.str();
        }

        /// configurations for scene \a index when \a total are spread over \a scenes
        std::size_t shareOf(std::size_t total, std::size_t scenes, std::size_t index)
        {
            return total / scenes + (index < total % scenes ? 1 : 0);
        }

        /// largest deviation of 4-float sphere records (x, y, z, r) from the reference centres and radii
        double centerError(const RobotModel &robot, const std::vector<Eigen::Vector3d> &reference, const float *out,
                           std::size_t stride)
        {
            double worst = 0.0;
            const auto &spheres = robot.spheres();
            for (std::size_t s = 0; s < spheres.size(); ++s)
            {
                const Eigen::Vector3d c(out[(4 * s + 0) * stride], out[(4 * s + 1) * stride],
                                        out[(4 * s + 2) * stride]);
                const double r = out[(4 * s + 3) * stride];
                double e = (c - reference[s]).norm();
                e = std::max(e, std::abs(r - spheres[s].radius));
                if (!std::isfinite(e))
                    return std::numeric_limits<double>::infinity();
                worst = std::max(worst, e);
            }
            return worst;
        }
    }  // namespace

    void sampleConfiguration(const RobotModel &robot, std::mt19937_64 &rng, double *q)
    {
        for (std::size_t i = 0; i < robot.dof(); ++i)
        {
            const PlanningJoint &joint = robot.joints()[i];
            q[i] = std::uniform_real_distribution<double>(joint.lower, joint.upper)(rng);
        }
    }

    bool CrossCheckReport::passed(double centerTolerance) const
    {
        for (const BackendAgreement &b : backends)
            if (b.disagreements != 0 || b.batchMismatches != 0 || !(b.maxCenterError <= centerTolerance))
                return false;
        return configurations > 0;
    }

    namespace
    {
        /// configurations sampled and checked at a time (a multiple of every SIMD width)
        constexpr std::size_t CHUNK = 4096;

        /// what crossCheckSpheres() compares one configuration with
        struct CrossCheckContext
        {
            const RobotModel &robot;
            const std::vector<std::unique_ptr<CollisionChecker>> &checkers;
            const FclSphereChecker &reference;
            const CrossCheckOptions &options;
            CrossCheckReport &report;
            std::vector<float> &centers;
            std::size_t stride;
        };

        std::string disagreement(const CrossCheckContext &c, const CrossCheckScene &scene, SimdBackend backend,
                                 bool verdict, bool expected, double distance, const double *q)
        {
            std::ostringstream s;
            s << "scene '" << scene.name << "', " << simdBackendName(backend) << " says "
              << (verdict ? "valid" : "invalid") << ", FCL says " << (expected ? "valid" : "invalid")
              << " (signed distance " << distance << " m), q = " << formatConfiguration(c.robot, q);
            const std::string what = c.reference.describeCollision(scene.env, q);
            if (!what.empty())
                s << "; FCL: " << what;
            return s.str();
        }

        /// one configuration: each backend's single and batch verdicts against FCL's, and (when \a centres) its
        /// sphere centres against the double-precision reference
        template <class BatchVerdict>
        void compareConfiguration(const CrossCheckContext &c, const CrossCheckScene &scene, const double *q,
                                  bool compareCenters, BatchVerdict &&batchVerdict)
        {
            const bool expected = c.reference.isValid(scene.env, q);
            c.report.referenceValid += expected;
            ++c.report.configurations;
            double distance = std::numeric_limits<double>::quiet_NaN();
            std::vector<Eigen::Vector3d> referenceCenters;
            if (compareCenters)
                referenceCenters = c.robot.sphereCentersReference(q);
            for (std::size_t b = 0; b < c.checkers.size(); ++b)
            {
                BackendAgreement &agreement = c.report.backends[b];
                const bool verdict = c.checkers[b]->isValid(scene.env, q);
                if (verdict != batchVerdict(b))
                    ++agreement.batchMismatches;
                if (verdict == expected)
                    ++agreement.agree;
                else
                {
                    if (std::isnan(distance))
                        distance = c.reference.distance(scene.env, q);
                    if (std::abs(distance) <= c.options.contactTolerance)
                        ++agreement.nearContact;
                    else
                    {
                        ++agreement.disagreements;
                        if (c.report.examples.size() < c.options.maxExamples)
                            c.report.examples.push_back(
                                disagreement(c, scene, agreement.backend, verdict, expected, distance, q));
                    }
                }
                if (compareCenters)
                {
                    c.checkers[b]->sphereCenters(q, c.centers.data());
                    agreement.maxCenterError =
                        std::max(agreement.maxCenterError, centerError(c.robot, referenceCenters, c.centers.data(), 1));
                    ++agreement.centerChecks;
                }
            }
        }

        /// the batched kinematics on whole SIMD batches of the \a chunk configurations \a qs, which are the
        /// scene's configurations from index \a chunkStart on (batches start at multiples of width x stride)
        void batchedCenters(const CrossCheckContext &c, const double *qs, std::size_t chunkStart, std::size_t chunk)
        {
            const std::size_t dof = c.robot.dof();
            for (std::size_t b = 0; b < c.checkers.size(); ++b)
            {
                const std::size_t width = std::size_t(c.checkers[b]->width());
                const std::size_t step = c.stride > SIZE_MAX / width ? SIZE_MAX : width * c.stride;
                std::vector<float> out(c.robot.spheres().size() * 4 * width);
                const std::size_t rem = chunkStart % step;
                for (std::size_t start = rem == 0 ? 0 : step - rem; start < chunk && width <= chunk - start;
                     start += step)
                {
                    c.checkers[b]->sphereCentersBatch(qs + start * dof, out.data());
                    for (std::size_t lane = 0; lane < width; ++lane)
                    {
                        const auto referenceCenters = c.robot.sphereCentersReference(qs + (start + lane) * dof);
                        c.report.backends[b].maxCenterError =
                            std::max(c.report.backends[b].maxCenterError,
                                     centerError(c.robot, referenceCenters, out.data() + lane, width));
                        ++c.report.backends[b].centerChecks;
                    }
                    if (chunk - start <= step)
                        break;
                }
            }
        }
    }  // namespace

    CrossCheckReport crossCheckSpheres(const std::shared_ptr<const RobotModel> &robot,
                                       const std::vector<CrossCheckScene> &scenes, const CrossCheckOptions &options)
    {
        if (!robot)
            throw Error("crossCheckSpheres: null robot model");
        if (scenes.empty())
            throw Error("crossCheckSpheres: no scenes to check robot '" + robot->name() + "' in");
        if (options.backends.empty())
            throw Error("crossCheckSpheres: no SIMD backend selected");
        std::vector<std::unique_ptr<CollisionChecker>> checkers;
        CrossCheckReport report;
        for (SimdBackend backend : options.backends)
        {
            if (!simdBackendAvailable(backend))
                throw Error(std::string("crossCheckSpheres: SIMD backend '") + simdBackendName(backend) +
                            "' is not compiled into this build");
            checkers.push_back(std::make_unique<CollisionChecker>(robot, backend));
            report.backends.push_back(BackendAgreement{});
            report.backends.back().backend = backend;
        }
        const FclSphereChecker reference(robot);
        const std::size_t dof = robot->dof();
        std::vector<float> centers(robot->spheres().size() * 4);
        const CrossCheckContext context{
            *robot, checkers, reference, options, report, centers, std::max<std::size_t>(options.centerStride, 1)};
        std::mt19937_64 rng(options.seed);

        // a scene's configurations are sampled and checked CHUNK at a time: memory does not grow with the sample
        // count (and no count x dof product can overflow); the draws and verdicts are those of one big batch
        std::vector<double> qs(CHUNK * dof);
        std::unique_ptr<bool[]> batch(new bool[CHUNK * checkers.size()]);
        for (std::size_t sceneIndex = 0; sceneIndex < scenes.size(); ++sceneIndex)
        {
            const CrossCheckScene &scene = scenes[sceneIndex];
            const std::size_t count = shareOf(options.samples, scenes.size(), sceneIndex);
            for (std::size_t chunkStart = 0; chunkStart < count; chunkStart += CHUNK)
            {
                const std::size_t chunk = std::min(CHUNK, count - chunkStart);
                for (std::size_t k = 0; k < chunk; ++k)
                    sampleConfiguration(*robot, rng, qs.data() + k * dof);
                for (std::size_t b = 0; b < checkers.size(); ++b)
                    checkers[b]->isValidBatch(scene.env, qs.data(), chunk, batch.get() + b * CHUNK);
                for (std::size_t k = 0; k < chunk; ++k)
                    compareConfiguration(context, scene, qs.data() + k * dof, (chunkStart + k) % context.stride == 0,
                                         [&](std::size_t b) { return batch[b * CHUNK + k]; });
                batchedCenters(context, qs.data(), chunkStart, chunk);
                if (count - chunkStart <= CHUNK)
                    break;  // chunkStart + CHUNK could overflow for a count near 2^64
            }
        }
        return report;
    }

    MeshComparison compareWithMeshes(const std::shared_ptr<const RobotModel> &sphereRobot,
                                     const std::shared_ptr<const RobotModel> &meshRobot,
                                     const std::vector<CrossCheckScene> &scenes, const CrossCheckOptions &options)
    {
        if (!sphereRobot || !meshRobot)
            throw Error("compareWithMeshes: null robot model");
        if (scenes.empty())
            throw Error("compareWithMeshes: no scenes");
        const auto &a = sphereRobot->joints();
        const auto &b = meshRobot->joints();
        bool same = a.size() == b.size();
        for (std::size_t i = 0; same && i < a.size(); ++i)
            same = a[i].name == b[i].name;
        if (!same)
        {
            std::ostringstream msg;
            msg << "compareWithMeshes: the planning joints of '" << sphereRobot->source() << "' (";
            for (std::size_t i = 0; i < a.size(); ++i)
                msg << (i ? ", " : "") << a[i].name;
            msg << ") and '" << meshRobot->source() << "' (";
            for (std::size_t i = 0; i < b.size(); ++i)
                msg << (i ? ", " : "") << b[i].name;
            msg << ") differ";
            throw Error(msg.str());
        }
        const CollisionChecker spheres(sphereRobot, SimdBackend::Best);
        const FclMeshChecker meshes(meshRobot);
        const FclSphereChecker sphereReference(sphereRobot);  // tells why the spheres collide
        MeshComparison result;
        std::mt19937_64 rng(options.seed ^ 0x9e3779b97f4a7c15ull);
        std::vector<double> q(sphereRobot->dof());
        for (std::size_t sceneIndex = 0; sceneIndex < scenes.size(); ++sceneIndex)
        {
            const CrossCheckScene &scene = scenes[sceneIndex];
            const std::size_t count = shareOf(options.samples, scenes.size(), sceneIndex);
            for (std::size_t k = 0; k < count; ++k)
            {
                sampleConfiguration(*sphereRobot, rng, q.data());
                const bool sphereValid = spheres.isValid(scene.env, q.data());
                const bool meshValid = meshes.isValid(scene.env, q.data());
                ++result.configurations;
                result.meshValid += meshValid;
                if (sphereValid == meshValid)
                {
                    ++result.agree;
                    result.outOfLimits += !meshRobot->withinBounds(q.data()) || !sphereRobot->withinBounds(q.data());
                }
                else if (sphereValid)
                {
                    ++result.unsafe;
                    const std::string what = meshes.describeCollision(scene.env, q.data());
                    result.unsafeSelf += what.rfind("self-collision", 0) == 0;
                    if (result.unsafeExamples.size() < options.maxExamples)
                        result.unsafeExamples.push_back("scene '" + scene.name + "', q = " +
                                                        formatConfiguration(*sphereRobot, q.data()) + ": " + what);
                }
                else
                {
                    ++result.overConservative;
                    const std::string what = sphereReference.describeCollision(scene.env, q.data());
                    result.overConservativeSelf += what.rfind("self-collision", 0) == 0;
                }
            }
        }
        return result;
    }
}  // namespace ropras::ompl_ext
