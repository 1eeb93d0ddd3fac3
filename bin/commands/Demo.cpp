// `ropras demo`: loads a robot and a scene (by default the shipped ropras_arm and scenes/tabletop.yaml), prints
// what was loaded, how fast the SIMD checker is, how its verdicts compare with FCL, and a few named poses.
#include <algorithm>
#include <chrono>
#include <cstdio>
#include <filesystem>
#include <iostream>
#include <map>
#include <random>

#include "ArgumentChecks.h"
#include "CommandRegistry.h"
#include "ropras/core/Error.h"
#include "ropras/core/MemoryLimit.h"
#include "ropras/ompl_ext/collision/CollisionChecker.h"
#include "ropras/ompl_ext/collision/CrossCheck.h"
#include "ropras/ompl_ext/collision/FclReferenceChecker.h"
#include "ropras/ompl_ext/scene/SceneYaml.h"

namespace
{
    namespace fs = std::filesystem;
    using namespace ropras::ompl_ext;
    using Clock = std::chrono::steady_clock;

    struct Args
    {
        std::string urdf, srdf, scene;
        std::size_t samples{10000};
        std::uint64_t seed{1};
    };

    /** \brief Where the shipped data lives: next to an installed executable (<prefix>/bin/ropras ->
        <prefix>/share/ropras/<what>), else the source tree the executable was built from (compile definition),
        else relative to a build tree (<build>/bin/ropras -> <source>/<what>). */
    fs::path shippedDir(const std::string &compiled, const std::string &what)
    {
        std::vector<fs::path> candidates;
        std::error_code ec;
        const fs::path exe = fs::read_symlink("/proc/self/exe", ec);
        if (!ec)
            candidates.push_back(exe.parent_path() / ".." / "share" / "ropras" / what);
        candidates.push_back(compiled);
        if (!ec)
            candidates.push_back(exe.parent_path() / ".." / ".." / what);
        for (const fs::path &candidate : candidates)
            if (fs::is_directory(candidate))
                return fs::weakly_canonical(candidate);
        std::string tried;
        for (const fs::path &candidate : candidates)
            tried += "\n  " + candidate.string();
        throw ropras::Error("demo: the shipped " + what + " folder was not found; tried:" + tried +
                            "\npass the files explicitly (--urdf, --srdf, --scene)");
    }

    double median(std::vector<double> values)
    {
        if (values.empty())
            return 0.0;
        std::nth_element(values.begin(), values.begin() + long(values.size() / 2), values.end());
        return values[values.size() / 2];
    }

    std::string backendLabel()
    {
        return simdBackendAvailable(SimdBackend::Avx2) ? "AVX2 (8 configurations per SIMD batch)" : "scalar";
    }

    /// named poses: for the shipped arm hand-picked ones, for any robot the zero, middle and limit poses
    std::vector<std::pair<std::string, std::vector<double>>> namedPoses(const RobotModel &robot)
    {
        std::vector<std::pair<std::string, std::vector<double>>> poses;
        const std::size_t n = robot.dof();
        if (robot.name() == "ropras_arm" && n == 6)
        {
            poses.push_back({"home (upright)", {0, 0, 0, 0, 0, 0}});
            poses.push_back({"reach over the table", {0.0, 0.55, 0.95, 0.0, 0.0, 0.0}});
            poses.push_back({"wrist down onto the table", {0.0, 0.75, 1.35, 0.0, 0.0, 0.0}});
            poses.push_back({"upper arm across the table edge", {0.0, 1.15, 1.15, 0.0, 0.0, 0.0}});
            poses.push_back({"gripper into the shelf", {1.35, 0.9, 0.9, 0.0, 0.0, 0.0}});
            poses.push_back({"forearm into the wall", {2.9, 0.9, 0.6, 0.0, 0.0, 0.0}});
            poses.push_back({"folded: wrist against the base", {-1.57, 1.6, 2.4, 0.0, 0.0, 0.0}});
        }
        std::vector<double> zero(n), middle(n), lower(n), upper(n);
        for (std::size_t i = 0; i < n; ++i)
        {
            const PlanningJoint &j = robot.joints()[i];
            zero[i] = std::clamp(0.0, j.lower, j.upper);
            middle[i] = 0.5 * (j.lower + j.upper);
            lower[i] = j.lower;
            upper[i] = j.upper;
        }
        if (poses.empty())
            poses.push_back({"zero (clamped into the limits)", zero});
        poses.push_back({"middle of the limits", middle});
        poses.push_back({"all lower limits", lower});
        poses.push_back({"all upper limits", upper});
        return poses;
    }

    int run(Args args)
    {
        if (args.urdf.empty())
        {
            const fs::path robots = shippedDir(ROPRAS_DEFAULT_ROBOTS_DIR, "robots");
            args.urdf = (robots / "ropras_arm" / "ropras_arm.urdf").string();
            if (args.srdf.empty() && fs::exists(robots / "ropras_arm" / "ropras_arm.srdf"))
                args.srdf = (robots / "ropras_arm" / "ropras_arm.srdf").string();
        }
        if (args.scene.empty())
            args.scene = (shippedDir(ROPRAS_DEFAULT_SCENES_DIR, "scenes") / "tabletop.yaml").string();

        const auto t0 = Clock::now();
        const auto robot = RobotModel::fromUrdfFile(args.urdf, args.srdf);
        const double loadMs = std::chrono::duration<double, std::milli>(Clock::now() - t0).count();
        const Environment env = loadPlanningScene(args.scene);

        // --- what was loaded
        std::cout << "ropras demo: SIMD collision checking of a URDF robot in a MoveIt scene\n\n";
        std::cout << "robot   " << robot->name() << "  (" << args.urdf << (args.srdf.empty() ? "" : " + SRDF")
                  << ", loaded in " << std::lround(loadMs) << " ms)\n";
        std::cout << "        " << robot->dof() << " planning joints:\n";
        for (const PlanningJoint &j : robot->joints())
            std::printf("          %-22s [%7.3f, %7.3f]\n", j.name.c_str(), j.lower, j.upper);
        std::map<CollisionGeometry::Type, int> kinds;
        for (const CollisionGeometry &g : robot->collisionGeometries())
            ++kinds[g.type];
        std::cout << "        collision geometry: " << kinds[CollisionGeometry::Type::Sphere] << " spheres, "
                  << kinds[CollisionGeometry::Type::Box] << " boxes, " << kinds[CollisionGeometry::Type::Cylinder]
                  << " cylinders, " << kinds[CollisionGeometry::Type::Mesh] << " meshes\n";
        std::cout << "        sphere model: " << robot->spheres().size() << " spheres on "
                  << robot->collisionLinks().size() << " links, " << robot->selfCollisionPairs().size()
                  << " self-collision link pairs\n";
        for (const auto &[a, b] : robot->alwaysCollidingPairs())
            std::cout << "        disabled, in contact in every sampled configuration (\"Always\"): " << a << " / " << b
                      << '\n';
        for (const auto &[a, b] : robot->defaultCollidingPairs())
            std::cout << "        warning: in contact at the default configuration (\"Default\", kept): " << a << " / "
                      << b << '\n';
        std::cout << '\n';

        std::map<ShapeType, int> shapes;
        std::size_t primitives = 0;
        for (std::size_t id = 0; id < env.objectCount(); ++id)
            for (const Shape &s : env.objectShapes(int(id)))
            {
                ++shapes[s.type];
                ++primitives;
            }
        std::cout << "scene   " << args.scene << "\n        " << env.objectCount() << " objects, " << primitives
                  << " primitives (" << shapes[ShapeType::Box] << " boxes, " << shapes[ShapeType::Cylinder]
                  << " cylinders, " << shapes[ShapeType::Sphere] << " spheres):";
        for (std::size_t id = 0; id < env.objectCount(); ++id)
            std::cout << (id ? ", " : " ") << env.objectName(int(id));
        std::cout << "\n\n";

        // --- random configurations: verdicts and agreement with FCL
        const CollisionChecker checker(robot);
        const FclSphereChecker fcl(robot);
        const std::size_t n = args.samples, dof = robot->dof();
        std::mt19937_64 rng(args.seed);
        ropras::checkedBytes(n, dof * sizeof(double) + sizeof(bool) + sizeof(double *),
                             "--samples " + std::to_string(n) + " (" + std::to_string(dof) + " joints)");
        std::vector<double> qs(n * dof);
        for (std::size_t k = 0; k < n; ++k)
            sampleConfiguration(*robot, rng, qs.data() + k * dof);
        std::unique_ptr<bool[]> valid(new bool[n]);
        const std::size_t validCount = checker.isValidBatch(env, qs.data(), n, valid.get());
        std::cout << "checker " << backendLabel() << "\n";
        std::printf("verdicts over %zu random configurations (uniform in the limits, seed %llu):\n", n,
                    static_cast<unsigned long long>(args.seed));
        std::printf("        collision-free %zu (%.1f%%), in collision %zu (%.1f%%)\n", validCount,
                    100.0 * double(validCount) / double(n), n - validCount, 100.0 * double(n - validCount) / double(n));
        const std::size_t fclCount = std::min<std::size_t>(n, 2000);
        std::size_t agree = 0;
        const auto f0 = Clock::now();
        for (std::size_t k = 0; k < fclCount; ++k)
            agree += fcl.isValid(env, qs.data() + k * dof) == valid[k];
        const double fclNs = std::chrono::duration<double, std::nano>(Clock::now() - f0).count() / double(fclCount);
        std::printf("        FCL reference (same spheres, double precision) agrees on %zu of %zu\n\n", agree, fclCount);

        // --- timings
        volatile bool sink = false;
        std::vector<double> single;
        const std::size_t timed = std::min<std::size_t>(n, 5000);
        constexpr int REPEAT = 16;
        for (std::size_t k = 0; k < timed; ++k)
        {
            const double *q = qs.data() + k * dof;
            const auto a = Clock::now();
            for (int r = 0; r < REPEAT; ++r)
                sink = checker.isValid(env, q);
            single.push_back(std::chrono::duration<double, std::nano>(Clock::now() - a).count() / REPEAT);
        }
        std::vector<double> batch;
        for (int r = 0; r < 5; ++r)
        {
            const auto a = Clock::now();
            checker.isValidBatch(env, qs.data(), n, valid.get());
            batch.push_back(std::chrono::duration<double, std::nano>(Clock::now() - a).count() / double(n));
        }
        // motions between consecutive collision-free samples
        std::vector<const double *> free;
        for (std::size_t k = 0; k < n; ++k)
            if (valid[k])
                free.push_back(qs.data() + k * dof);
        std::vector<double> motion;
        std::size_t motionsValid = 0;
        constexpr double RESOLUTION = 0.05;
        for (std::size_t k = 0; k + 1 < free.size() && motion.size() < 2000; ++k)
        {
            const auto a = Clock::now();
            const bool ok = checker.isMotionValid(env, free[k], free[k + 1], RESOLUTION);
            motion.push_back(std::chrono::duration<double, std::nano>(Clock::now() - a).count());
            motionsValid += ok;
        }
        sink = !sink;
        std::cout << "timings (this machine, one thread)\n";
        std::printf("        single configuration   %8.0f ns median   (isValid; FCL on the same spheres: %.0f ns)\n",
                    median(single), fclNs);
        std::printf("        batch                  %8.0f ns per configuration   (isValidBatch over %zu)\n",
                    median(batch), n);
        if (!motion.empty())
            std::printf(
                "        motion                 %8.0f ns median   (isMotionValid at %.2f rad, %zu motions "
                "between free samples, %zu free)\n",
                median(motion), RESOLUTION, motion.size(), motionsValid);
        std::cout << '\n';

        // --- named poses
        std::cout << "named configurations\n";
        for (const auto &[name, q] : namedPoses(*robot))
        {
            const bool ok = checker.isValid(env, q.data());
            std::printf("        %-32s %s", name.c_str(), ok ? "collision-free" : "IN COLLISION");
            if (!robot->withinBounds(q.data()))
                std::printf("  (outside the joint limits)");
            else if (!ok)
            {
                // what touches, per FCL: the scene first, then the robot itself
                const std::string scene = fcl.describeCollision(env, q.data());
                const std::string self = fcl.describeCollision(Environment(), q.data());
                if (!scene.empty() && scene != self)
                    std::printf("\n%43s%s", "", scene.c_str());
                if (!self.empty())
                    std::printf("\n%43s%s", "", self.c_str());
            }
            std::printf("\n");
        }
        return 0;
    }

    std::function<int()> setup(CLI::App &app)
    {
        auto a = std::make_shared<Args>();
        app.add_option("--urdf", a->urdf, "robot URDF (default: the shipped robots/ropras_arm/ropras_arm.urdf)")
            ->check(CLI::ExistingFile);
        app.add_option("--srdf", a->srdf, "SRDF (default: the shipped arm's, with the default URDF)")
            ->check(CLI::ExistingFile);
        app.add_option("--scene", a->scene, "MoveIt PlanningScene YAML (default: the shipped scenes/tabletop.yaml)")
            ->check(CLI::ExistingFile);
        app.add_option("--samples", a->samples, "random configurations")
            ->capture_default_str()
            ->check(ropras::bin::POSITIVE_COUNT);
        app.add_option("--seed", a->seed, "random seed")->capture_default_str()->check(ropras::bin::SEED);
        return [a] { return run(*a); };
    }

    const ropras::bin::CommandRegistrar reg{
        {"demo", "load a robot and a scene, time the SIMD collision checker, compare it with FCL", setup}};
}  // namespace
