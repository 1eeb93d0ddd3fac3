// `ropras bench-ik`: our inverse kinematics next to Orocos KDL's on reachable random targets of one chain.
// Targets are the reference FK of random in-limit configurations (seeded); both solvers get the same first
// configuration, the same random restarts (drawn from the same per-target seed in the same order), the same
// iteration budget per attempt and the same time limit; a solve counts when the result is within the same
// tolerances (checked with the reference FK) and within the joint limits. Solvers alternate order per target.
#include <kdl/chain.hpp>
#include <kdl/chainfksolverpos_recursive.hpp>
#include <kdl/chainiksolverpos_lma.hpp>
#include <kdl/chainiksolverpos_nr_jl.hpp>
#include <kdl/chainiksolvervel_pinv.hpp>
#include <kdl/tree.hpp>
#include <kdl_parser/kdl_parser.hpp>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <fstream>
#include <iomanip>
#include <iostream>
#include <memory>
#include <nlohmann/json.hpp>
#include <sstream>

#include "ArgumentChecks.h"
#include "CommandRegistry.h"
#include "Median.h"
#include "ropras/core/Error.h"
#include "ropras/core/Rng.h"
#include "ropras/ompl_ext/kinematics/InverseKinematics.h"

namespace
{
    using namespace ropras;
    using namespace ropras::ompl_ext;
    using Clock = std::chrono::steady_clock;
    using ropras::bin::median;

    constexpr std::size_t MAX_POSES = 1000000;
    constexpr std::size_t MAX_COUNT = 1000000;  ///< restarts, iterations
    constexpr double MAX_TIME = 3600.0;         ///< s per target

    struct BenchIkArgs
    {
        std::string urdf, tip, json, target{"pose"};
        std::size_t poses{1000};
        std::size_t restarts{100};
        std::size_t iterations{100};
        double time{0.005};
        double positionTolerance{1e-5};
        double orientationTolerance{1e-5};
        std::uint64_t seed{1};
    };

    /// KDL's solvers for the same chain, built by kdl_parser from the same URDF
    class KdlIk
    {
    public:
        KdlIk(const std::string &urdf, const KinematicChain &chain, bool pose, const BenchIkArgs &a)
            : chain_(chain), pose_(pose), iterations_(a.iterations)
        {
            KDL::Tree tree;
            if (!kdl_parser::treeFromFile(urdf, tree))
                throw Error("bench-ik: kdl_parser cannot build a KDL tree from '" + urdf + "'");
            const std::string root = chain.robot().links().front().name;
            if (!tree.getChain(root, chain.tipName(), kdl_))
                throw Error("bench-ik: KDL has no chain '" + root + "' -> '" + chain.tipName() + "'");
            std::vector<std::string> names;
            for (const KDL::Segment &s : kdl_.segments)
                if (s.getJoint().getType() != KDL::Joint::None)
                    names.push_back(s.getJoint().getName());
            if (names.size() != chain.size())
                throw Error("bench-ik: KDL's chain to '" + chain.tipName() + "' has " + std::to_string(names.size()) +
                            " joints, ours " + std::to_string(chain.size()) +
                            " (held or mimic joints on the chain are not supported by the comparison)");
            const unsigned n = kdl_.getNrOfJoints();
            lower_.resize(n);
            upper_.resize(n);
            for (unsigned i = 0; i < n; ++i)
            {
                if (names[i] != chain.joints()[i].name)
                    throw Error("bench-ik: KDL's joint " + std::to_string(i) + " is '" + names[i] + "', ours '" +
                                chain.joints()[i].name + "'");
                lower_(i) = chain.joints()[i].lower;
                upper_(i) = chain.joints()[i].upper;
            }
            fk_ = std::make_unique<KDL::ChainFkSolverPos_recursive>(kdl_);
            // NR_JL's eps bounds each twist component: 1/sqrt(3) of the tolerance keeps the norms within it
            const double eps = std::min(a.positionTolerance, a.orientationTolerance) / std::sqrt(3.0);
            vel_ = std::make_unique<KDL::ChainIkSolverVel_pinv>(kdl_);
            nrjl_ = std::make_unique<KDL::ChainIkSolverPos_NR_JL>(kdl_, lower_, upper_, *fk_, *vel_,
                                                                  static_cast<unsigned>(iterations_), eps);
            // position only: NR_JL has no task weights; LMA does (it ignores the limits: checked afterwards)
            Eigen::Matrix<double, 6, 1> weights;
            weights << 1, 1, 1, 0, 0, 0;
            lma_ = std::make_unique<KDL::ChainIkSolverPos_LMA>(kdl_, weights, a.positionTolerance,
                                                               static_cast<int>(iterations_));
        }

        const char *name() const { return pose_ ? "kdl (ChainIkSolverPos_NR_JL)" : "kdl (ChainIkSolverPos_LMA)"; }

        /// one attempt from \a start (chain joint values) into \a out; true when KDL reports convergence
        bool attempt(const KDL::Frame &target, const KDL::JntArray &start, KDL::JntArray &out)
        {
            const int rc = pose_ ? nrjl_->CartToJnt(start, target, out) : lma_->CartToJnt(start, target, out);
            return rc >= 0;
        }

        std::size_t size() const { return chain_.size(); }

    private:
        const KinematicChain &chain_;
        bool pose_;
        std::size_t iterations_;
        KDL::Chain kdl_;
        KDL::JntArray lower_, upper_;
        std::unique_ptr<KDL::ChainFkSolverPos_recursive> fk_;
        std::unique_ptr<KDL::ChainIkSolverVel_pinv> vel_;
        std::unique_ptr<KDL::ChainIkSolverPos_NR_JL> nrjl_;
        std::unique_ptr<KDL::ChainIkSolverPos_LMA> lma_;
    };

    /// ns per configuration of the chain's single-configuration FK and of its batch FK (blocks of 4), over the
    /// same configurations, alternating 5 times; medians
    std::pair<double, double> timeLinkPoses(const KinematicChain &chain, const std::vector<double> &qs)
    {
        const std::size_t dof = chain.robot().dof(), count = qs.size() / dof;
        std::vector<double> out(12 * count);
        std::vector<double> single, batch;
        double sink = 0.0;
        for (int rep = 0; rep < 5; ++rep)
        {
            auto t0 = Clock::now();
            for (std::size_t k = 0; k < count; ++k)
                sink += chain.tipPose(qs.data() + k * dof).translation().x();
            single.push_back(std::chrono::duration<double, std::nano>(Clock::now() - t0).count() /
                             static_cast<double>(count));
            t0 = Clock::now();
            chain.tipPosesBatch(qs.data(), count, out.data());
            sink += out[9];
            batch.push_back(std::chrono::duration<double, std::nano>(Clock::now() - t0).count() /
                            static_cast<double>(count));
        }
        if (sink == 1e300)
            std::cout << ' ';  // keeps the work observable
        return {median(single), median(batch)};
    }

    struct Tally
    {
        std::vector<double> us;
        std::size_t solved{0}, attempts{0}, iterations{0};
        std::size_t timedOut{0};  ///< ours: solves the time limit ended
    };

    /// within the tolerances by the reference FK, and within the joint limits
    bool verified(const RobotModel &robot, int tip, const IkTarget &target, const std::vector<double> &q,
                  const BenchIkArgs &a)
    {
        if (!robot.withinBounds(q.data()))
            return false;
        const Eigen::Isometry3d t = robot.linkTransformsReference(q.data())[static_cast<std::size_t>(tip)];
        if ((t.translation() - target.position()).norm() > a.positionTolerance)
            return false;
        if (target.kind() != IkTargetKind::Pose)
            return true;
        return Eigen::AngleAxisd(target.orientation() * Eigen::Quaterniond(t.linear()).conjugate()).angle() <=
               a.orientationTolerance;
    }

    int run(const BenchIkArgs &a)
    {
        if (a.target != "pose" && a.target != "position")
            throw Error("bench-ik: unknown --target '" + a.target + "' (pose, position)");
        if (a.poses > MAX_POSES)
            throw Error("bench-ik: --poses " + std::to_string(a.poses) + " is more than " + std::to_string(MAX_POSES));
        for (const auto &[name, value] : {std::pair("--restarts", a.restarts), std::pair("--iterations", a.iterations)})
            if (value > MAX_COUNT)
                throw Error("bench-ik: " + std::string(name) + " " + std::to_string(value) + " is more than " +
                            std::to_string(MAX_COUNT));
        if (a.time > MAX_TIME)
        {
            std::ostringstream message;
            message << "bench-ik: --time " << a.time << " s is more than " << MAX_TIME << " s per target";
            throw Error(message.str());
        }
        const bool pose = a.target == "pose";
        const auto robot = RobotModel::fromUrdfFile(a.urdf);
        const InverseKinematics ik(robot, a.tip);
        const KinematicChain &chain = ik.chain();
        if (chain.size() == 0)
            throw Error("bench-ik: link '" + a.tip + "' does not move (no planning joint between it and the root)");
        KdlIk kdl(a.urdf, chain, pose, a);
        IkOptions options;
        options.positionTolerance = a.positionTolerance;
        options.orientationTolerance = a.orientationTolerance;
        options.maxIterations = a.iterations;
        options.restarts = a.restarts;
        options.timeLimit = a.time;
        options.validate();

        const std::size_t dof = robot->dof(), n = chain.size();
        const int tip = robot->linkIndex(a.tip);
        IkWorkspace ws = ik.makeWorkspace();
        std::vector<double> q(dof), seed = robot->defaultConfiguration(), kdlQ = seed;
        KDL::JntArray start(static_cast<unsigned>(n)), out(static_cast<unsigned>(n));
        core::Rng targets(a.seed);
        Tally ours, theirs;
        for (std::size_t k = 0; k < a.poses; ++k)
        {
            std::vector<double> goal = seed;
            for (const ChainJoint &j : chain.joints())
                goal[static_cast<std::size_t>(j.variable)] = targets.uniform(j.lower, j.upper);
            const Eigen::Isometry3d t = robot->linkTransformsReference(goal.data())[static_cast<std::size_t>(tip)];
            const IkTarget target = pose ? IkTarget::pose(t) : IkTarget::position(t.translation());
            const std::uint64_t startSeed = targets.split();

            auto runOurs = [&]
            {
                core::Rng rng(startSeed);
                std::vector<double> first = seed;
                for (const ChainJoint &j : chain.joints())
                    first[static_cast<std::size_t>(j.variable)] = rng.uniform(j.lower, j.upper);
                const auto t0 = Clock::now();
                const IkResult r = ik.solve(target, first.data(), rng, ws, q.data(), options);
                ours.us.push_back(std::chrono::duration<double, std::micro>(Clock::now() - t0).count());
                ours.attempts += r.attempts;
                ours.iterations += r.iterations;
                ours.timedOut += r.status == IkStatus::TimedOut ? 1 : 0;
                ours.solved += r.status == IkStatus::Solved && verified(*robot, tip, target, q, a) ? 1 : 0;
            };
            auto runKdl = [&]
            {
                core::Rng rng(startSeed);  // the same first configuration and restarts, in the same order
                KDL::Frame frame;
                for (int r = 0; r < 3; ++r)
                {
                    frame.p(r) = t.translation()[r];
                    for (int c = 0; c < 3; ++c)
                        frame.M(r, c) = t.linear()(r, c);
                }
                const auto t0 = Clock::now();
                const double deadline = a.time;
                bool solved = false;
                for (std::size_t attempt = 0; attempt <= a.restarts && !solved; ++attempt)
                {
                    if (attempt > 0 && std::chrono::duration<double>(Clock::now() - t0).count() > deadline)
                        break;
                    for (std::size_t i = 0; i < n; ++i)
                        start(static_cast<unsigned>(i)) = rng.uniform(chain.joints()[i].lower, chain.joints()[i].upper);
                    ++theirs.attempts;
                    if (!kdl.attempt(frame, start, out))
                        continue;
                    for (std::size_t i = 0; i < n; ++i)
                        kdlQ[static_cast<std::size_t>(chain.joints()[i].variable)] = out(static_cast<unsigned>(i));
                    solved = verified(*robot, tip, target, kdlQ, a);
                }
                theirs.us.push_back(std::chrono::duration<double, std::micro>(Clock::now() - t0).count());
                theirs.solved += solved ? 1 : 0;
            };
            if (k % 2 == 0)
            {
                runOurs();
                runKdl();
            }
            else
            {
                runKdl();
                runOurs();
            }
        }

        std::vector<double> fkConfigurations;
        for (std::size_t k = 0; k < 4096; ++k)
            for (std::size_t i = 0; i < dof; ++i)
                fkConfigurations.push_back(targets.uniform(robot->joints()[i].lower, robot->joints()[i].upper));
        const auto [fkSingle, fkBatch] = timeLinkPoses(chain, fkConfigurations);

        const double total = static_cast<double>(a.poses);
        std::cout << "robot " << robot->name() << ", chain " << robot->links().front().name << " -> " << a.tip << " ("
                  << n << " joints), target " << a.target << ", " << a.poses << " reachable random targets (seed "
                  << a.seed << "), up to " << a.restarts << " restarts x " << a.iterations << " iterations, time limit "
                  << a.time * 1e3 << " ms, tolerances " << a.positionTolerance << " m / " << a.orientationTolerance
                  << " rad\n";
        std::cout << std::left << std::setw(32) << "solver" << std::right << std::setw(10) << "solved" << std::setw(14)
                  << "median us" << std::setw(16) << "attempts/solve" << std::setw(18) << "iterations/solve" << '\n';
        auto row = [&](const char *name, const Tally &tally, bool ours)
        {
            std::cout << std::left << std::setw(32) << name << std::right << std::setw(9) << std::fixed
                      << std::setprecision(1) << 100.0 * static_cast<double>(tally.solved) / total << '%'
                      << std::setw(14) << std::setprecision(1) << median(tally.us) << std::setw(16)
                      << std::setprecision(2) << static_cast<double>(tally.attempts) / total << std::setw(18)
                      << (ours ? std::to_string(static_cast<double>(tally.iterations) / total).substr(0, 6) : "-")
                      << '\n';
        };
        row("ropras", ours, true);
        row(kdl.name(), theirs, false);  // KDL does not report its iterations
        std::cout << "ropras: " << a.poses - ours.solved << " unsolved, " << ours.timedOut << " of them timed out\n";
        std::cout << "tip pose (FK), ns per configuration: single " << std::setprecision(1) << fkSingle
                  << ", batch of 4 " << fkBatch << '\n';
        if (!a.json.empty())
        {
            nlohmann::json j;
            j["robot"] = robot->name();
            j["tip"] = a.tip;
            j["target"] = a.target;
            j["poses"] = a.poses;
            j["seed"] = a.seed;
            j["restarts"] = a.restarts;
            j["iterations"] = a.iterations;
            j["time_limit_s"] = a.time;
            j["position_tolerance_m"] = a.positionTolerance;
            j["orientation_tolerance_rad"] = a.orientationTolerance;
            j["kdl_solver"] = kdl.name();
            j["ropras_solved"] = static_cast<double>(ours.solved) / total;
            j["kdl_solved"] = static_cast<double>(theirs.solved) / total;
            j["ropras_median_us"] = median(ours.us);
            j["kdl_median_us"] = median(theirs.us);
            j["ropras_attempts_per_solve"] = static_cast<double>(ours.attempts) / total;
            j["kdl_attempts_per_solve"] = static_cast<double>(theirs.attempts) / total;
            j["ropras_iterations_per_solve"] = static_cast<double>(ours.iterations) / total;
            j["ropras_timed_out"] = static_cast<double>(ours.timedOut) / total;
            j["fk_single_ns"] = fkSingle;
            j["fk_batch_ns"] = fkBatch;
            std::ofstream file(a.json);
            if (!file)
                throw Error("bench-ik: cannot write '" + a.json + "'");
            file << j.dump(2) << '\n';
        }
        return 0;
    }

    std::function<int()> setup(CLI::App &app)
    {
        auto args = std::make_shared<BenchIkArgs>();
        app.add_option("--urdf", args->urdf, "robot URDF")->required()->check(CLI::ExistingFile);
        app.add_option("--tip", args->tip, "tip link of the chain (root link -> tip)")->required();
        app.add_option("--json", args->json, "write the figures as JSON");
        app.add_option("--target", args->target, "pose (full pose) or position (position only)")->capture_default_str();
        app.add_option("--poses", args->poses, "reachable random targets (at most 1e6)")
            ->capture_default_str()
            ->check(ropras::bin::POSITIVE_COUNT);
        app.add_option("--restarts", args->restarts, "random restarts after the first attempt (both solvers)")
            ->capture_default_str()
            ->check(ropras::bin::NON_NEGATIVE_COUNT);
        app.add_option("--iterations", args->iterations, "iterations per attempt (both solvers)")
            ->capture_default_str()
            ->check(ropras::bin::POSITIVE_COUNT);
        app.add_option("--time", args->time, "time limit per target (s, both solvers)")
            ->capture_default_str()
            ->check(ropras::bin::POSITIVE_NUMBER);
        app.add_option("--position-tolerance", args->positionTolerance, "m")
            ->capture_default_str()
            ->check(ropras::bin::POSITIVE_NUMBER);
        app.add_option("--orientation-tolerance", args->orientationTolerance, "rad")
            ->capture_default_str()
            ->check(ropras::bin::POSITIVE_NUMBER);
        app.add_option("--seed", args->seed, "random seed (targets and starts)")->capture_default_str();
        return [args] { return run(*args); };
    }

    const ropras::bin::CommandRegistrar reg{
        {"bench-ik", "time our inverse kinematics next to Orocos KDL's on reachable random targets", setup}};
}  // namespace
