// `ropras bench-collision`: speed of the SIMD kinematics and collision kernels on MoveIt scenes (FK, batch,
// single configuration, motions), next to FCL with the same spheres and FCL with the URDF meshes.
#include <algorithm>
#include <chrono>
#include <filesystem>
#include <fstream>
#include <iomanip>
#include <iostream>
#ifdef __GLIBC__
#include <malloc.h>
#endif
#include <nlohmann/json.hpp>
#include <optional>
#include <random>

#include "ArgumentChecks.h"
#include "BenchClock.h"
#include "CommandRegistry.h"
#include "Median.h"
#include "OutputChecks.h"
#include "RobotSelection.h"
#include "ropras/core/Error.h"
#include "ropras/core/InputFile.h"
#include "ropras/core/MemoryLimit.h"
#include "ropras/ompl_ext/collision/CollisionChecker.h"
#include "ropras/ompl_ext/collision/FclReferenceChecker.h"
#include "ropras/ompl_ext/scene/SceneYaml.h"

namespace
{
    using namespace ropras;
    using namespace ropras::ompl_ext;

    struct BenchArgs
    {
        std::string urdf, srdf, meshUrdf, scenes, json, backend{"best"}, clock{"wall"}, attached;
        int repeat{5};
        std::size_t configs{1000};    ///< random configurations per scene
        std::size_t edges{40};        ///< valid and invalid 1 rad edges per scene (each)
        std::size_t fclConfigs{100};  ///< configurations per scene for FCL with spheres
        std::size_t meshConfigs{20};  ///< configurations per scene for FCL with meshes
        std::size_t farBoxes{0};      ///< boxes out of reach added to every scene (a shared base)
        double farRadius{2.0};        ///< ... at this distance from the world origin or more
        double edgeLength{1.0};
        double resolution{1.0 / 32.0};
        unsigned seed{1};
        ropras::bin::RobotSelection selection;
    };

    using ropras::bin::median;

    /// the clock run() chose (--clock)
    std::optional<ropras::bin::BenchClock> benchClock;

    double nowNs()
    {
        return benchClock->nowNs();
    }

    /// nanoseconds per item of \a body(), which processes \a items items
    template <class F>
    double nsPer(std::size_t items, F &&body)
    {
        if (items == 0)
            return std::numeric_limits<double>::quiet_NaN();
        const double t0 = nowNs();
        body();
        const double t1 = nowNs();
        return (t1 - t0) / static_cast<double>(items);
    }

    struct Scene
    {
        std::string path;
        Environment env;
        std::vector<double> configs;                 ///< row-major, configs x dof
        std::vector<double> valid, invalid;          ///< single configurations by verdict
        std::vector<double> edgeValid, edgeInvalid;  ///< pairs of rows (q0, q1)
        Environment held;                            ///< --attached: the scene (as base) with the held bodies
        std::vector<double> validHeld;               ///< configurations valid while holding them
    };

    /// --attached: cost of holding bodies (same configurations with and without them) and of particle scenes
    struct HeldRows
    {
        std::vector<double> without, with, batchWithout, batchWith, particle, particleFirst;
    };

    /** \brief ns to make one particle's scene: a copy of an overlay of \a base with four movable objects (two
        cylinders, a box, a sphere) and a pose set for each. Made for a belief of 2000 particles in three passes,
        as a filter makes the next belief while the previous one lives and then drops the previous one. Returns
        {first pass, third pass}: the first starts after the allocator returned its free memory to the system
        (malloc_trim) and pays for the first touch of every page (page faults); the third reuses the memory the first
        pass's belief left to the allocator. */
    std::pair<double, double> particleSceneNs(const std::shared_ptr<const Environment> &base, std::size_t &sink)
    {
        Environment movable(base);
        movable.addCylinder("can0", Eigen::Isometry3d::Identity(), 0.03, 0.12);
        movable.addCylinder("can1", Eigen::Isometry3d::Identity(), 0.03, 0.12);
        movable.addBox("box", Eigen::Isometry3d::Identity(), Eigen::Vector3d(0.05, 0.05, 0.1));
        movable.addSphere("ball", Eigen::Vector3d::Zero(), 0.04);
        constexpr std::size_t n = 2000;
        double ns[3] = {0.0, 0.0, 0.0};
        std::vector<Environment> previous;
#ifdef __GLIBC__
        malloc_trim(0);
#endif
        for (double &passNs : ns)
        {
            std::vector<Environment> particles;
            particles.reserve(n);
            passNs = nsPer(n,
                           [&]
                           {
                               for (std::size_t k = 0; k < n; ++k)
                               {
                                   particles.push_back(movable);
                                   Environment &e = particles.back();
                                   Eigen::Isometry3d pose = Eigen::Isometry3d::Identity();
                                   for (int id = 0; id < 4; ++id)
                                   {
                                       pose.translation() = Eigen::Vector3d(0.4 + 0.001 * double(k), 0.1 * id, 0.3);
                                       e.setObjectPose(id, pose);
                                   }
                               }
                           });
            sink += particles.back().objectCount();
            previous = std::move(particles);
        }
        return {ns[0], ns[2]};
    }

    /** \brief --far-boxes: \a count boxes (0.05 to 0.3 m, any orientation) with centres uniform over the shell from
        \a radius to \a radius + 3 m around the world origin, out of the robot's reach when \a radius exceeds it. */
    std::shared_ptr<const Environment> farBoxes(std::size_t count, double radius, unsigned seed)
    {
        auto env = std::make_shared<Environment>();
        std::mt19937_64 rng(seed ^ 0x9e3779b97f4a7c15ULL);
        std::normal_distribution<double> normal;
        std::uniform_real_distribution<double> unit(0.0, 1.0);
        for (std::size_t k = 0; k < count; ++k)
        {
            Eigen::Vector3d dir(normal(rng), normal(rng), normal(rng));
            dir /= std::max(dir.norm(), 1e-9);
            // uniform in volume: r^3 uniform between the shell's radii
            const double r0 = radius * radius * radius, r1 = std::pow(radius + 3.0, 3.0);
            const double r = std::cbrt(r0 + unit(rng) * (r1 - r0));
            const Eigen::Vector3d extents(0.05 + 0.25 * unit(rng), 0.05 + 0.25 * unit(rng), 0.05 + 0.25 * unit(rng));
            Eigen::Isometry3d pose = Eigen::Isometry3d::Identity();
            pose.linear() =
                Eigen::Quaterniond(normal(rng), normal(rng), normal(rng), normal(rng)).normalized().toRotationMatrix();
            // the box's farthest point is inside the shell's outer side, its nearest outside the inner radius
            pose.translation() = dir * std::max(r, radius + 0.5 * extents.norm());
            env->addBox("far" + std::to_string(k), pose, extents);
        }
        return env;
    }

    /// \a scene's objects in an overlay over \a base
    Environment overBase(const Environment &scene, std::shared_ptr<const Environment> base)
    {
        Environment over(std::move(base));
        for (std::size_t id = 0; id < scene.objectCount(); ++id)
        {
            const int i = static_cast<int>(id);
            over.addObject(scene.objectName(i), scene.objectShapes(i), scene.objectPose(i));
        }
        return over;
    }

    SimdBackend parseBackend(const std::string &name)
    {
        if (name == "best")
            return SimdBackend::Best;
        if (name == "scalar")
            return SimdBackend::Scalar;
        if (name == "avx2")
            return SimdBackend::Avx2;
        throw Error("bench-collision: unknown --backend '" + name + "' (best, scalar, avx2)");
    }

    int run(const BenchArgs &a)
    {
        ropras::bin::refuseOverwritingInputs("--json", a.json, {a.urdf, a.srdf, a.meshUrdf});
        benchClock.emplace(a.clock, "bench-collision");
        const RobotModel::Options robotOptions = a.selection.options();
        const auto robot = RobotModel::fromUrdfFile(a.urdf, a.srdf, robotOptions);
        ropras::bin::Warnings warnings("bench-collision");
        warnings.add(robot->warnings());
        warnings.print();
        const CollisionChecker checker(robot, parseBackend(a.backend));
        const std::size_t dof = robot->dof();
        const auto w = static_cast<std::size_t>(checker.width());

        std::vector<std::string> paths;
        for (const auto &entry : std::filesystem::recursive_directory_iterator(a.scenes))
        {
            const std::string name = entry.path().filename().string();
            if (entry.is_regular_file() && name.rfind("scene", 0) == 0 && entry.path().extension() == ".yaml")
                paths.push_back(entry.path().string());
        }
        std::sort(paths.begin(), paths.end());
        if (paths.empty())
            throw Error("bench-collision: no scene*.yaml under '" + a.scenes + "'");

        // problem sets (fixed seed): uniform configurations, split by verdict; 1 rad edges from valid starts
        std::mt19937_64 rng(a.seed);
        const auto uniform = [&](double *q)
        {
            for (std::size_t j = 0; j < dof; ++j)
                q[j] = std::uniform_real_distribution<double>(robot->joints()[j].lower, robot->joints()[j].upper)(rng);
        };
        // --attached: bodies held by the robot (robot_state.attached_collision_objects of a PlanningScene file)
        std::optional<Environment> heldBodies;
        if (!a.attached.empty())
        {
            heldBodies = loadPlanningScene(a.attached, robot);
            if (heldBodies->attachedCount() == 0)
                throw Error("bench-collision: " + a.attached +
                            " attaches no object (robot_state.attached_collision_objects)");
        }
        // every scene keeps its configurations twice (all, and split by verdict) and its edges (two ends)
        const std::string joints =
            " per scene x " + std::to_string(paths.size()) + " scenes, " + std::to_string(dof) + " joints";
        const std::uint64_t configBytes = ropras::checkedBytes(a.configs, paths.size() * 2 * dof * sizeof(double),
                                                               "--configs " + std::to_string(a.configs) + joints);
        const std::uint64_t edgeBytes = ropras::checkedBytes(a.edges, paths.size() * 4 * dof * sizeof(double),
                                                             "--edges " + std::to_string(a.edges) + joints);
        if (configBytes + edgeBytes > ropras::memoryLimit())
            throw Error("--configs " + std::to_string(a.configs) + " and --edges " + std::to_string(a.edges) +
                        " together ask for " + ropras::formatBytes(configBytes + edgeBytes) +
                        ", more than the memory limit " + ropras::formatBytes(ropras::memoryLimit()) +
                        " (ropras --max-memory)");
        // --far-boxes: one shared base of boxes out of reach under every scene
        const std::shared_ptr<const Environment> far =
            a.farBoxes > 0 ? farBoxes(a.farBoxes, a.farRadius, a.seed) : nullptr;
        std::vector<Scene> scenes;
        for (const std::string &path : paths)
        {
            Scene s{path, loadPlanningScene(path), {}, {}, {}, {}, {}, {}, {}};
            if (far)
                s.env = overBase(s.env, far);
            s.configs.resize(a.configs * dof);
            for (std::size_t k = 0; k < a.configs; ++k)
            {
                double *q = s.configs.data() + k * dof;
                uniform(q);
                auto &bucket = checker.isValid(s.env, q) ? s.valid : s.invalid;
                bucket.insert(bucket.end(), q, q + dof);
            }
            if (heldBodies)
            {
                s.held = Environment(std::make_shared<const Environment>(s.env));
                for (std::size_t i = 0; i < heldBodies->attachedCount(); ++i)
                    s.held.attach(robot, heldBodies->attachedBody(i));
                for (std::size_t k = 0; k < s.valid.size(); k += dof)
                    if (checker.isValid(s.held, s.valid.data() + k))
                        s.validHeld.insert(s.validHeld.end(), s.valid.data() + k, s.valid.data() + k + dof);
            }
            std::vector<double> q0(dof), q1(dof), dir(dof);
            for (std::size_t attempt = 0; attempt < 200 * a.edges && (s.edgeValid.size() < 2 * a.edges * dof ||
                                                                      s.edgeInvalid.size() < 2 * a.edges * dof);
                 ++attempt)
            {
                uniform(q0.data());
                if (!checker.isValid(s.env, q0.data()))
                    continue;
                double big = 0.0;
                for (std::size_t j = 0; j < dof; ++j)
                {
                    dir[j] = std::uniform_real_distribution<double>(-1.0, 1.0)(rng);
                    big = std::max(big, std::abs(dir[j]));
                }
                bool inside = true;
                for (std::size_t j = 0; j < dof; ++j)
                {
                    q1[j] = q0[j] + a.edgeLength * dir[j] / big;  // max-norm length exactly edgeLength
                    inside = inside && q1[j] >= robot->joints()[j].lower && q1[j] <= robot->joints()[j].upper;
                }
                if (!inside)
                    continue;
                auto &bucket =
                    checker.isMotionValid(s.env, q0.data(), q1.data(), a.resolution) ? s.edgeValid : s.edgeInvalid;
                if (bucket.size() >= 2 * a.edges * dof)
                    continue;
                bucket.insert(bucket.end(), q0.begin(), q0.end());
                bucket.insert(bucket.end(), q1.begin(), q1.end());
            }
            scenes.push_back(std::move(s));
        }

        std::optional<FclSphereChecker> fclSpheres;
        fclSpheres.emplace(robot);
        std::shared_ptr<const RobotModel> meshRobot;
        std::optional<FclMeshChecker> fclMeshes;
        if (!a.meshUrdf.empty())
        {
            meshRobot = RobotModel::fromUrdfFile(a.meshUrdf, a.srdf, robotOptions);
            if (meshRobot->dof() != dof)
                throw Error("bench-collision: --mesh-urdf '" + a.meshUrdf + "' has " +
                            std::to_string(meshRobot->dof()) + " joints, --urdf has " + std::to_string(dof));
            fclMeshes.emplace(meshRobot);
        }

        std::size_t sink = 0;
        std::vector<double> fk, batch, batchAll, singleValid, singleInvalid, edgeValid, edgeInvalid, fclSphere, fclMesh;
        std::vector<float> centres(4 * robot->spheres().size() * w);
        std::unique_ptr<bool[]> verdicts(new bool[a.configs]);
        std::size_t totalConfigs = 0, nValid = 0, nInvalid = 0, nEdgeValid = 0, nEdgeInvalid = 0;
        for (const Scene &s : scenes)
        {
            totalConfigs += a.configs / w * w;
            nValid += s.valid.size() / dof;
            nInvalid += s.invalid.size() / dof;
            nEdgeValid += s.edgeValid.size() / (2 * dof);
            nEdgeInvalid += s.edgeInvalid.size() / (2 * dof);
        }
        HeldRows held;
        for (int rep = 0; rep < a.repeat; ++rep)
        {
            fk.push_back(nsPer(totalConfigs,
                               [&]
                               {
                                   for (const Scene &s : scenes)
                                       for (std::size_t k = 0; k + w <= a.configs; k += w)
                                       {
                                           checker.sphereCentersBatch(s.configs.data() + k * dof, centres.data());
                                           sink += centres[0] > 0.0f ? 1 : 0;
                                       }
                               }));
            batch.push_back(nsPer(totalConfigs,
                                  [&]
                                  {
                                      for (const Scene &s : scenes)
                                          sink += checker.isValidBatch(s.env, s.configs.data(), a.configs / w * w,
                                                                       verdicts.get());
                                  }));
            // the same blocks of 8, asked whether all 8 are valid (stops at a block's first collision)
            batchAll.push_back(nsPer(totalConfigs,
                                     [&]
                                     {
                                         for (const Scene &s : scenes)
                                             for (std::size_t k = 0; k + w <= a.configs; k += w)
                                                 sink += checker.allValid(s.env, s.configs.data() + k * dof, w) ? 1 : 0;
                                     }));
            singleValid.push_back(nsPer(nValid,
                                        [&]
                                        {
                                            for (const Scene &s : scenes)
                                                for (std::size_t k = 0; k < s.valid.size(); k += dof)
                                                    sink += checker.isValid(s.env, s.valid.data() + k) ? 1 : 0;
                                        }));
            singleInvalid.push_back(nsPer(nInvalid,
                                          [&]
                                          {
                                              for (const Scene &s : scenes)
                                                  for (std::size_t k = 0; k < s.invalid.size(); k += dof)
                                                      sink += checker.isValid(s.env, s.invalid.data() + k) ? 1 : 0;
                                          }));
            edgeValid.push_back(nsPer(nEdgeValid,
                                      [&]
                                      {
                                          for (const Scene &s : scenes)
                                              for (std::size_t k = 0; k < s.edgeValid.size(); k += 2 * dof)
                                                  sink +=
                                                      checker.isMotionValid(s.env, s.edgeValid.data() + k,
                                                                            s.edgeValid.data() + k + dof, a.resolution)
                                                          ? 1
                                                          : 0;
                                      }));
            edgeInvalid.push_back(nsPer(nEdgeInvalid,
                                        [&]
                                        {
                                            for (const Scene &s : scenes)
                                                for (std::size_t k = 0; k < s.edgeInvalid.size(); k += 2 * dof)
                                                    sink += checker.isMotionValid(s.env, s.edgeInvalid.data() + k,
                                                                                  s.edgeInvalid.data() + k + dof,
                                                                                  a.resolution)
                                                                ? 1
                                                                : 0;
                                        }));
            if (heldBodies)
            {
                std::size_t nHeld = 0;
                for (const Scene &s : scenes)
                    nHeld += s.validHeld.size() / dof;
                // interleaved: the same configurations without and with the held bodies
                const auto singles = [&](bool holding)
                {
                    return nsPer(
                        nHeld,
                        [&]
                        {
                            for (const Scene &s : scenes)
                                for (std::size_t k = 0; k < s.validHeld.size(); k += dof)
                                    sink += checker.isValid(holding ? s.held : s.env, s.validHeld.data() + k) ? 1 : 0;
                        });
                };
                const auto batches = [&](bool holding)
                {
                    return nsPer(totalConfigs,
                                 [&]
                                 {
                                     for (const Scene &s : scenes)
                                         sink += checker.isValidBatch(holding ? s.held : s.env, s.configs.data(),
                                                                      a.configs / w * w, verdicts.get());
                                 });
                };
                held.without.push_back(singles(false));
                held.with.push_back(singles(true));
                held.batchWithout.push_back(batches(false));
                held.batchWith.push_back(batches(true));
                const auto [first, warm] =
                    particleSceneNs(std::make_shared<const Environment>(scenes.front().env), sink);
                held.particleFirst.push_back(first);
                held.particle.push_back(warm);
            }
            // FCL: its object cache is rebuilt per scene, outside the timed loops
            double fclNs = 0.0, meshNs = 0.0;
            std::size_t fclCount = 0, meshCount = 0;
            for (const Scene &s : scenes)
            {
                const std::size_t n = std::min(a.fclConfigs, a.configs), m = std::min(a.meshConfigs, a.configs);
                sink += fclSpheres->isValid(s.env, s.configs.data()) ? 1 : 0;  // warm the cache
                fclNs += nsPer(1,
                               [&]
                               {
                                   for (std::size_t k = 0; k < n; ++k)
                                       sink += fclSpheres->isValid(s.env, s.configs.data() + k * dof) ? 1 : 0;
                               });
                fclCount += n;
                if (fclMeshes)
                {
                    sink += fclMeshes->isValid(s.env, s.configs.data()) ? 1 : 0;
                    meshNs += nsPer(1,
                                    [&]
                                    {
                                        for (std::size_t k = 0; k < m; ++k)
                                            sink += fclMeshes->isValid(s.env, s.configs.data() + k * dof) ? 1 : 0;
                                    });
                    meshCount += m;
                }
            }
            fclSphere.push_back(fclCount > 0 ? fclNs / static_cast<double>(fclCount)
                                             : std::numeric_limits<double>::quiet_NaN());
            if (fclMeshes)
                fclMesh.push_back(meshCount > 0 ? meshNs / static_cast<double>(meshCount)
                                                : std::numeric_limits<double>::quiet_NaN());
        }

        struct Row
        {
            const char *key, *what;
            double ns;
            std::size_t count;
        };
        const std::vector<Row> rows{
            {"fk_ns", "FK only, batch of 8 (per config)", median(fk), totalConfigs},
            {"batch_ns", "batch of 8 distinct (per config)", median(batch), totalConfigs},
            {"batch_all_ns", "batch of 8, all valid? (per config)", median(batchAll), totalConfigs},
            {"single_valid_ns", "single config, valid", median(singleValid), nValid},
            {"single_invalid_ns", "single config, invalid", median(singleInvalid), nInvalid},
            {"edge_valid_ns", "1 rad edge at 1/32 rad, valid", median(edgeValid), nEdgeValid},
            {"edge_invalid_ns", "1 rad edge at 1/32 rad, invalid", median(edgeInvalid), nEdgeInvalid},
            {"fcl_sphere_ns", "FCL, same spheres (per config)", median(fclSphere), fclSphere.empty() ? 0u : 1u},
            {"fcl_mesh_ns", "FCL, URDF meshes (per config)", median(fclMesh), fclMesh.empty() ? 0u : 1u},
        };
        std::vector<Row> heldRows;
        if (heldBodies)
        {
            std::size_t nHeld = 0;
            for (const Scene &s : scenes)
                nHeld += s.validHeld.size() / dof;
            heldRows = {
                {"held_single_without_ns", "single valid, not holding", median(held.without), nHeld},
                {"held_single_with_ns", "single valid, holding --attached", median(held.with), nHeld},
                {"held_batch_without_ns", "batch of 8, not holding", median(held.batchWithout), totalConfigs},
                {"held_batch_with_ns", "batch of 8, holding --attached", median(held.batchWith), totalConfigs},
                {"particle_scene_ns", "particle scene, 4 movable objects", median(held.particle), 2000},
                {"particle_scene_first_ns", "particle scene, first pass (fresh memory)", median(held.particleFirst),
                 2000},
            };
        }
        std::cout << "robot " << robot->name() << " (" << dof << " dof, " << robot->spheres().size()
                  << " spheres), backend " << simdBackendName(checker.backend()) << ", " << scenes.size() << " scenes, "
                  << a.configs << " configs/scene, median of " << a.repeat << " repetitions\n";
        std::size_t allSelfPairs = 0;
        for (const auto &pair : robot->selfCollisionPairs())
            allSelfPairs +=
                static_cast<std::size_t>(robot->collisionLinks()[static_cast<std::size_t>(pair.first)].sphereCount) *
                static_cast<std::size_t>(robot->collisionLinks()[static_cast<std::size_t>(pair.second)].sphereCount);
        std::cout << "self-collision sphere pairs tested: " << checker.selfSpherePairs() << " of " << allSelfPairs
                  << " (the others cannot touch within the joint limits)\n";
        std::cout << std::left << std::setw(36) << "measurement" << std::right << std::setw(14) << "ns" << std::setw(12)
                  << "samples" << '\n';
        std::vector<Row> allRows = rows;
        allRows.insert(allRows.end(), heldRows.begin(), heldRows.end());
        for (const Row &r : allRows)
        {
            std::cout << std::left << std::setw(36) << r.what << std::right << std::setw(14) << std::fixed
                      << std::setprecision(1) << r.ns << std::setw(12)
                      << (std::string(r.key).rfind("fcl", 0) == 0 ? std::string("") : std::to_string(r.count)) << '\n';
        }
        if (!a.json.empty())
        {
            nlohmann::json j;
            j["robot"] = robot->name();
            j["backend"] = simdBackendName(checker.backend());
            j["scenes"] = scenes.size();
            j["configs_per_scene"] = a.configs;
            j["repeat"] = a.repeat;
            j["resolution"] = a.resolution;
            j["clock"] = a.clock;
            for (const Row &r : allRows)
                j[r.key] = std::isnan(r.ns) ? nlohmann::json(nullptr) : nlohmann::json(r.ns);
            std::ofstream out(a.json);
            if (!out)
                throw Error("bench-collision: cannot write '" + a.json + "'");
            out << j.dump(2) << '\n';
        }
        return sink == static_cast<std::size_t>(-1) ? 1 : 0;  // keeps the work observable
    }

    std::function<int()> setup(CLI::App &app)
    {
        auto args = std::make_shared<BenchArgs>();
        app.add_option("--urdf", args->urdf, "spherized robot URDF")->required()->check(CLI::ExistingFile);
        app.add_option("--srdf", args->srdf, "SRDF (disabled self-collision pairs)")->check(CLI::ExistingFile);
        app.add_option("--mesh-urdf", args->meshUrdf, "URDF with mesh collision geometry (FCL mesh baseline)")
            ->check(CLI::ExistingFile);
        app.add_option("--scenes", args->scenes, "folder searched recursively for scene*.yaml (MoveIt PlanningScene)")
            ->required()
            ->check(CLI::ExistingDirectory);
        app.add_option("--json", args->json, "write the medians as JSON");
        app.add_option("--repeat", args->repeat, "repetitions (medians are reported)")
            ->capture_default_str()
            ->check(ropras::bin::REPEATS);
        app.add_option("--configs", args->configs, "random configurations per scene")
            ->capture_default_str()
            ->check(ropras::bin::POSITIVE_COUNT);
        app.add_option("--edges", args->edges, "valid and invalid edges per scene (each)")
            ->capture_default_str()
            ->check(ropras::bin::NON_NEGATIVE_COUNT);
        app.add_option("--fcl-configs", args->fclConfigs, "configurations per scene for FCL with spheres")
            ->capture_default_str()
            ->check(ropras::bin::NON_NEGATIVE_COUNT);
        app.add_option("--mesh-configs", args->meshConfigs, "configurations per scene for FCL with meshes")
            ->capture_default_str()
            ->check(ropras::bin::NON_NEGATIVE_COUNT);
        app.add_option("--resolution", args->resolution, "motion-check joint step (rad)")
            ->capture_default_str()
            ->check(ropras::bin::POSITIVE_NUMBER);
        app.add_option("--backend", args->backend, "best, scalar or avx2")->capture_default_str();
        app.add_option("--clock", args->clock, "wall (steady clock) or cpu (thread CPU time: use on a loaded machine)")
            ->capture_default_str();
        app.add_option("--attached", args->attached,
                       "PlanningScene YAML whose robot_state.attached_collision_objects the robot holds: adds rows for "
                       "the same valid configurations with and without them, and the cost of a particle scene")
            ->check(CLI::ExistingFile);
        app.add_option("--far-boxes", args->farBoxes,
                       "add this many boxes out of reach (a shared base under every scene; see --far-radius)")
            ->capture_default_str()
            ->check(CLI::Range(std::size_t{0}, std::size_t{1000000}));
        app.add_option("--far-radius", args->farRadius,
                       "--far-boxes lie from this distance (m) to 3 m beyond it from the world origin")
            ->capture_default_str()
            ->check(CLI::Range(0.0, 1e3));
        app.add_option("--seed", args->seed, "random seed")->capture_default_str()->check(ropras::bin::SEED32);
        args->selection.addOptions(app, false);
        return [args] { return run(*args); };
    }

    const ropras::bin::CommandRegistrar reg{
        {"bench-collision", "time the SIMD kinematics and collision kernels (and FCL) on MoveIt scenes", setup}};
}  // namespace
