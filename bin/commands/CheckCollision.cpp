// `ropras check-collision`: cross-checks the SIMD collision kernels against the independent FCL reference on a
// user's robot and scenes (verdict 1, agreement), and optionally whether the sphere model covers the robot's meshes
// (verdict 2, safety).
#include <algorithm>
#include <chrono>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <regex>
#include <sstream>

#include "ArgumentChecks.h"
#include "CommandRegistry.h"
#include "RobotSelection.h"
#include "ropras/core/Error.h"
#include "ropras/core/InputFile.h"
#include "ropras/ompl_ext/collision/CrossCheck.h"
#include "ropras/ompl_ext/collision/FclReferenceChecker.h"
#include "ropras/ompl_ext/scene/SceneYaml.h"

namespace
{
    namespace fs = std::filesystem;
    using namespace ropras::ompl_ext;

    /// the largest --samples / --mesh-samples
    constexpr std::uint64_t MAX_SAMPLES = 1000000000;

    struct Args
    {
        std::string urdf, srdf, scenes, meshUrdf;
        ropras::bin::RobotSelection selection;
        std::size_t samples{10000};
        std::size_t meshSamples{0};
        std::uint64_t seed{1};
        double tolerance{1e-4};
    };

    /// true when the file has a top-level `world:` key (a PlanningScene rather than a request)
    bool looksLikeScene(const fs::path &path)
    {
        ropras::checkInputFile(path.string(), "--scenes file");
        std::ifstream in(path);
        static const std::regex world(R"(^world\s*:)");
        for (std::string line; std::getline(in, line);)
            if (std::regex_search(line, world))
                return true;
        return false;
    }

    std::vector<CrossCheckScene> loadScenes(const std::string &where, std::size_t &skipped)
    {
        std::vector<CrossCheckScene> scenes;
        const fs::path root(where);
        std::error_code ec;
        if (!fs::exists(root, ec))
            throw ropras::Error("--scenes '" + where + "': no such file or folder");
        if (!fs::is_directory(root, ec))
        {
            // a file (loadPlanningScene refuses a special file such as /dev/zero, or one above the size limit)
            scenes.push_back({root.filename().string(), loadPlanningScene(root.string())});
            return scenes;
        }
        std::vector<fs::path> files;
        for (const auto &entry : fs::recursive_directory_iterator(root))
        {
            const std::string ext = entry.path().extension().string();
            if (entry.is_regular_file() && (ext == ".yaml" || ext == ".yml"))
                files.push_back(entry.path());
        }
        std::sort(files.begin(), files.end());
        for (const fs::path &file : files)
        {
            if (!looksLikeScene(file))
            {
                ++skipped;
                continue;
            }
            scenes.push_back({fs::relative(file, root).string(), loadPlanningScene(file.string())});
        }
        if (scenes.empty())
            throw ropras::Error("--scenes '" + where + "': no MoveIt PlanningScene (YAML with a 'world' key) found");
        return scenes;
    }

    std::string backendLabel(SimdBackend backend)
    {
        if (backend != SimdBackend::Best)
            return simdBackendName(backend);
        return simdBackendAvailable(SimdBackend::Avx2) ? "best (avx2)" : "best (scalar)";
    }

    std::string percent(std::size_t part, std::size_t whole)
    {
        char text[32];
        std::snprintf(text, sizeof(text), "%.2f%%", whole ? 100.0 * double(part) / double(whole) : 0.0);
        return text;
    }

    std::string number(double value)
    {
        std::ostringstream s;
        s << value;
        return s.str();
    }

    /// why the agreement verdict fails: every failed check with its figure (never an empty list)
    std::string agreementFailures(const CrossCheckReport &report, double centerTolerance)
    {
        std::vector<std::string> reasons;
        if (report.configurations == 0)
            reasons.push_back("no configuration was checked");
        for (const BackendAgreement &b : report.backends)
        {
            const std::string name = backendLabel(b.backend);
            if (b.disagreements != 0)
                reasons.push_back(name + ": " + std::to_string(b.disagreements) +
                                  " verdicts disagree with FCL outside the contact tolerance (DISAGREEMENT lines)");
            if (b.batchMismatches != 0)
                reasons.push_back(name + ": " + std::to_string(b.batchMismatches) +
                                  " batch verdicts differ from the single-configuration ones");
            if (!(b.maxCenterError <= centerTolerance))
                reasons.push_back(name + ": sphere centres off by " + number(b.maxCenterError) + " m (tolerance " +
                                  number(centerTolerance) +
                                  " m; float kinematics lose precision with huge joint values or link offsets)");
        }
        std::string out;
        for (const std::string &r : reasons)
            out += (out.empty() ? "" : "; ") + r;
        return out;
    }

    /// the mesh comparison and its report lines
    MeshComparison compareMeshes(const Args &args, const RobotModel::Options &options,
                                 const std::shared_ptr<const RobotModel> &robot,
                                 const std::vector<CrossCheckScene> &scenes, const CrossCheckOptions &check)
    {
        // the same self pairs as the sphere model: its "Always" pairs, not ones found on the mesh covers
        RobotModel::Options meshModelOptions = options;
        meshModelOptions.disableAlwaysColliding = false;
        meshModelOptions.disabledPairs = robot->alwaysCollidingPairs();
        const auto meshRobot = RobotModel::fromUrdfFile(args.meshUrdf, args.srdf, meshModelOptions);
        CrossCheckOptions meshOptions = check;
        meshOptions.samples = args.meshSamples ? args.meshSamples : std::min<std::size_t>(args.samples, 5000);
        const MeshComparison m = compareWithMeshes(robot, meshRobot, scenes, meshOptions);
        std::cout << "\nmeshes     " << args.meshUrdf << " (FCL, " << meshRobot->collisionGeometries().size()
                  << " collision elements), " << m.configurations << " configurations:\n";
        std::cout << "  agree              " << m.agree << " (" << percent(m.agree, m.configurations) << ")\n";
        std::cout << "  unsafe             " << m.unsafe << " (" << percent(m.unsafe, m.configurations)
                  << "): spheres free, meshes collide (" << m.unsafeSelf << " of them self-collisions)\n";
        std::cout << "  over-conservative  " << m.overConservative << " ("
                  << percent(m.overConservative, m.configurations) << "): spheres collide, meshes free ("
                  << m.overConservativeSelf << " of them self-collisions)\n";
        for (const std::string &example : m.unsafeExamples)
            std::cout << "  unsafe example: " << example << '\n';
        return m;
    }

    int run(const Args &args)
    {
        const auto start = std::chrono::steady_clock::now();
        const RobotModel::Options options = args.selection.options();
        const auto robot = RobotModel::fromUrdfFile(args.urdf, args.srdf, options);
        ropras::bin::Warnings warnings("check-collision");
        warnings.add(robot->warnings());
        warnings.print();
        std::size_t skipped = 0;
        std::vector<CrossCheckScene> scenes = loadScenes(args.scenes, skipped);
        const std::size_t sceneFiles = scenes.size();
        scenes.push_back({"(no obstacles)", Environment()});

        std::cout << "robot      " << robot->name() << " (" << args.urdf << "): " << robot->dof() << " joints [";
        for (std::size_t i = 0; i < robot->dof(); ++i)
            std::cout << (i ? ", " : "") << robot->joints()[i].name;
        std::cout << "], " << robot->spheres().size() << " spheres on " << robot->collisionLinks().size() << " links, "
                  << robot->selfCollisionPairs().size() << " self-collision pairs\n";
        std::cout << "scenes     " << sceneFiles << " from " << args.scenes;
        if (skipped)
            std::cout << " (" << skipped << " other YAML files skipped)";
        std::cout << " + 1 without obstacles (self-collision only)\n";
        std::cout << "samples    " << args.samples << " configurations uniform in the joint limits, seed " << args.seed
                  << ", about " << args.samples / scenes.size() << " per scene\n";

        CrossCheckOptions check;
        check.samples = args.samples;
        check.seed = args.seed;
        check.contactTolerance = args.tolerance;
        // Best is the widest compiled backend; when that is the scalar one, checking it twice adds nothing
        check.backends = {SimdBackend::Best};
        if (simdBackendAvailable(SimdBackend::Avx2))
            check.backends.push_back(SimdBackend::Scalar);
        const CrossCheckReport report = crossCheckSpheres(robot, scenes, check);

        std::cout << "reference  FCL 0.7 (double) on the same spheres: " << report.referenceValid << " of "
                  << report.configurations << " collision-free ("
                  << percent(report.referenceValid, report.configurations) << ")\n\n";
        std::printf("%-12s %10s %13s %14s %14s %20s\n", "backend", "agree", "near-contact", "disagreements",
                    "batch!=single", "max centre error");
        for (const BackendAgreement &b : report.backends)
            std::printf("%-12s %10zu %13zu %14zu %14zu %18.2e m\n", backendLabel(b.backend).c_str(), b.agree,
                        b.nearContact, b.disagreements, b.batchMismatches, b.maxCenterError);
        std::cout << "(near-contact: verdicts that differ where FCL's signed distance is within " << args.tolerance
                  << " m of contact; centres compared on "
                  << (report.backends.empty() ? 0 : report.backends[0].centerChecks) << " configurations)\n";
        for (const std::string &example : report.examples)
            std::cout << "DISAGREEMENT " << example << '\n';

        // pairs in contact by design: disabled when in contact everywhere, reported when in contact at the default
        if (!robot->alwaysCollidingPairs().empty())
        {
            std::cout << "\nnote: self-collision pairs in contact in every sampled configuration, disabled "
                         "(MoveIt's \"Always\" rule; RobotModel::Options::disableAlwaysColliding):\n";
            for (const auto &[a, b] : robot->alwaysCollidingPairs())
                std::cout << "  " << a << " / " << b << '\n';
        }
        if (!robot->defaultCollidingPairs().empty())
        {
            std::cout << "\nwarning: self-collision pairs in contact at the default configuration (joints at 0 "
                         "clamped; kept enabled, add them to the SRDF's disable_collisions if in contact by design):\n";
            for (const auto &[a, b] : robot->defaultCollidingPairs())
                std::cout << "  " << a << " / " << b << '\n';
        }

        // verdict 2 (with --mesh-urdf): is the sphere model safe, i.e. does it cover the meshes?
        std::string safety = "not checked (no --mesh-urdf)";
        bool safe = true;
        if (!args.meshUrdf.empty())
        {
            const MeshComparison m = compareMeshes(args, options, robot, scenes, check);
            safe = m.unsafe == 0;
            safety = safe ? "SAFE: the spheres cover the meshes in all " + std::to_string(m.configurations) +
                                " configurations (" + std::to_string(m.overConservative) + " over-conservative)"
                          : "UNSAFE: " + std::to_string(m.unsafe) + " of " + std::to_string(m.configurations) +
                                " configurations (" + percent(m.unsafe, m.configurations) +
                                ") are collision-free for the spheres while the meshes collide";
            if (!safe)
                std::cout << "\nwarning: the sphere model is not conservative: a planner using it can return paths "
                             "on which the real robot collides. Cover the meshes (spherize the collision meshes, see "
                             "doc/spherizer.md) or enlarge the spheres of the links named above.\n";
        }

        // verdict 1: do the SIMD kernels compute what the same-sphere FCL reference computes?
        const bool agrees = report.passed(check.centerTolerance);
        std::string agreement;
        if (agrees)
            agreement = "PASS: every verdict more than " + number(args.tolerance) +
                        " m from contact agrees with FCL on the same spheres, sphere centres within " +
                        number(check.centerTolerance) + " m";
        else
            agreement = "FAIL: " + agreementFailures(report, check.centerTolerance);
        const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
        std::cout << "\nagreement  " << agreement << '\n' << "safety     " << safety << '\n';
        const bool passed = agrees && safe;
        std::printf("result     %s (%.1f s)\n", passed ? "PASS" : "FAIL", seconds);
        return passed ? 0 : 1;
    }

    std::function<int()> setup(CLI::App &app)
    {
        auto a = std::make_shared<Args>();
        app.add_option("--urdf", a->urdf, "robot URDF (its sphere model is checked)")
            ->required()
            ->check(CLI::ExistingFile);
        app.add_option("--srdf", a->srdf, "SRDF (disabled self-collision pairs)")->check(CLI::ExistingFile);
        a->selection.addOptions(app, false);
        app.add_option("--scenes", a->scenes, "a MoveIt PlanningScene YAML, or a folder searched recursively")
            ->required();
        // checked a chunk at a time (memory does not grow with the count); time does, about 10 us per sample
        app.add_option("--samples", a->samples, "random configurations in total (at most 10^9)")
            ->capture_default_str()
            ->check(ropras::bin::countCheck(1, MAX_SAMPLES, "COUNT"));
        app.add_option("--mesh-urdf", a->meshUrdf, "the same robot with mesh collision geometry (FCL mesh comparison)")
            ->check(CLI::ExistingFile);
        app.add_option("--mesh-samples", a->meshSamples,
                       "configurations for the mesh comparison (default min(samples, 5000), at most 10^9)")
            ->check(ropras::bin::countCheck(0, MAX_SAMPLES, "COUNT"));
        app.add_option("--seed", a->seed, "random seed")->capture_default_str()->check(ropras::bin::SEED);
        app.add_option("--tolerance", a->tolerance, "contact tolerance (m) within which disagreements are accepted")
            ->capture_default_str()
            ->check(ropras::bin::NON_NEGATIVE_NUMBER);
        return [a] { return run(*a); };
    }

    const ropras::bin::CommandRegistrar reg{
        {"check-collision", "cross-check the SIMD collision checker against FCL on your robot and scenes", setup}};
}  // namespace
