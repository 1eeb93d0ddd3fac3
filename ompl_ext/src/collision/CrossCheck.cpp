#include "ropras/ompl_ext/collision/CrossCheck.h"

#include <algorithm>
#include <cmath>
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
        const std::size_t sphereCount = robot->spheres().size();
        const std::size_t stride = std::max<std::size_t>(options.centerStride, 1);
        std::mt19937_64 rng(options.seed);

        std::vector<double> qs;
        std::vector<float> centers(sphereCount * 4);
        std::unique_ptr<bool[]> batch;
        for (std::size_t sceneIndex = 0; sceneIndex < scenes.size(); ++sceneIndex)
        {
            const CrossCheckScene &scene = scenes[sceneIndex];
            const std::size_t count = shareOf(options.samples, scenes.size(), sceneIndex);
            if (count == 0)
                continue;
            qs.resize(count * dof);
            for (std::size_t k = 0; k < count; ++k)
                sampleConfiguration(*robot, rng, qs.data() + k * dof);
            batch.reset(new bool[count * checkers.size()]);
            for (std::size_t b = 0; b < checkers.size(); ++b)
                checkers[b]->isValidBatch(scene.env, qs.data(), count, batch.get() + b * count);

            for (std::size_t k = 0; k < count; ++k)
            {
                const double *q = qs.data() + k * dof;
                const bool expected = reference.isValid(scene.env, q);
                report.referenceValid += expected;
                ++report.configurations;
                double distance = std::numeric_limits<double>::quiet_NaN();
                const bool compareCenters = k % stride == 0;
                std::vector<Eigen::Vector3d> referenceCenters;
                if (compareCenters)
                    referenceCenters = robot->sphereCentersReference(q);
                for (std::size_t b = 0; b < checkers.size(); ++b)
                {
                    BackendAgreement &agreement = report.backends[b];
                    const bool verdict = checkers[b]->isValid(scene.env, q);
                    if (verdict != batch[b * count + k])
                        ++agreement.batchMismatches;
                    if (verdict == expected)
                        ++agreement.agree;
                    else
                    {
                        if (std::isnan(distance))
                            distance = reference.distance(scene.env, q);
                        if (std::abs(distance) <= options.contactTolerance)
                            ++agreement.nearContact;
                        else
                        {
                            ++agreement.disagreements;
                            if (report.examples.size() < options.maxExamples)
                            {
                                std::ostringstream s;
                                s << "scene '" << scene.name << "', " << simdBackendName(agreement.backend) << " says "
                                  << (verdict ? "valid" : "invalid") << ", FCL says "
                                  << (expected ? "valid" : "invalid") << " (signed distance " << distance
                                  << " m), q = " << formatConfiguration(*robot, q);
                                const std::string what = reference.describeCollision(scene.env, q);
                                if (!what.empty())
                                    s << "; FCL: " << what;
                                report.examples.push_back(s.str());
                            }
                        }
                    }
                    if (compareCenters)
                    {
                        checkers[b]->sphereCenters(q, centers.data());
                        agreement.maxCenterError = std::max(agreement.maxCenterError,
                                                            centerError(*robot, referenceCenters, centers.data(), 1));
                        ++agreement.centerChecks;
                    }
                }
            }

            // the batched kinematics: whole SIMD batches of this scene's configurations
            for (std::size_t b = 0; b < checkers.size(); ++b)
            {
                const std::size_t width = std::size_t(checkers[b]->width());
                std::vector<float> out(sphereCount * 4 * width);
                for (std::size_t first = 0; first + width <= count; first += width * stride)
                {
                    checkers[b]->sphereCentersBatch(qs.data() + first * dof, out.data());
                    for (std::size_t lane = 0; lane < width; ++lane)
                    {
                        const auto referenceCenters = robot->sphereCentersReference(qs.data() + (first + lane) * dof);
                        report.backends[b].maxCenterError =
                            std::max(report.backends[b].maxCenterError,
                                     centerError(*robot, referenceCenters, out.data() + lane, width));
                        ++report.backends[b].centerChecks;
                    }
                }
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
