// `ropras collision-matrix`: MoveIt Setup Assistant's default collision matrix for a sphere model: which link
// pairs are adjacent, never or always in contact over random configurations. Prints SRDF disable_collisions lines.
#include <cstdio>
#include <fstream>
#include <iostream>
#include <random>
#include <sstream>

#include "ArgumentChecks.h"
#include "CommandRegistry.h"
#include "ropras/core/Error.h"
#include "ropras/ompl_ext/model/RobotModel.h"

namespace
{
    using namespace ropras::ompl_ext;

    struct Args
    {
        std::string urdf, srdf, output;
        std::size_t samples{10000};
        std::uint64_t seed{1};
    };

    /// true when some sphere of collision link a touches (or overlaps) some sphere of collision link b
    bool inContact(const RobotModel &robot, const std::vector<Eigen::Vector3d> &centers, int a, int b)
    {
        const CollisionLink &la = robot.collisionLinks()[a];
        const CollisionLink &lb = robot.collisionLinks()[b];
        for (int i = la.firstSphere; i < la.firstSphere + la.sphereCount; ++i)
            for (int j = lb.firstSphere; j < lb.firstSphere + lb.sphereCount; ++j)
            {
                const double r = robot.spheres()[i].radius + robot.spheres()[j].radius;
                if ((centers[i] - centers[j]).squaredNorm() <= r * r)
                    return true;
            }
        return false;
    }

    int run(const Args &a)
    {
        RobotModel::Options options;
        options.disableAlwaysColliding = false;  // this command classifies those pairs itself
        const auto robot = RobotModel::fromUrdfFile(a.urdf, a.srdf, options);
        const auto &links = robot->collisionLinks();
        const std::size_t n = links.size();

        // pairs the model checks: on different frames, not adjacent, not disabled by the given SRDF
        std::vector<std::vector<int>> checked(n, std::vector<int>(n, 0));
        for (const auto &[i, j] : robot->selfCollisionPairs())
            checked[i][j] = 1;
        std::vector<std::pair<int, int>> candidates(robot->selfCollisionPairs().begin(),
                                                    robot->selfCollisionPairs().end());
        std::vector<std::size_t> contacts(candidates.size(), 0);
        std::mt19937_64 rng(a.seed);
        std::vector<double> q(robot->dof());
        for (std::size_t s = 0; s < a.samples; ++s)
        {
            for (std::size_t k = 0; k < q.size(); ++k)
            {
                const double u = static_cast<double>(rng() >> 11) * 0x1.0p-53;
                q[k] = robot->joints()[k].lower + u * (robot->joints()[k].upper - robot->joints()[k].lower);
            }
            const std::vector<Eigen::Vector3d> centers = robot->sphereCentersReference(q.data());
            for (std::size_t p = 0; p < candidates.size(); ++p)
                contacts[p] += inContact(*robot, centers, candidates[p].first, candidates[p].second);
        }
        const std::vector<double> q0 = robot->defaultConfiguration();
        const std::vector<Eigen::Vector3d> centers0 = robot->sphereCentersReference(q0.data());

        // one block per reason, each under a comment that says why its pairs are disabled
        std::ostringstream out, rigid, joint, never, always, keptNote;
        const auto line = [&](std::ostringstream &block, int i, int j, const char *reason)
        {
            block << "  <disable_collisions link1=\"" << links[i].name << "\" link2=\"" << links[j].name
                  << "\" reason=\"" << reason << "\"/>\n";
        };
        for (std::size_t i = 0; i < n; ++i)
            for (std::size_t j = i + 1; j < n; ++j)
                if (!checked[i][j])
                    line(links[i].frame == links[j].frame ? rigid : joint, static_cast<int>(i), static_cast<int>(j),
                         "Adjacent");
        std::size_t kept = 0;
        for (std::size_t p = 0; p < candidates.size(); ++p)
        {
            const auto [i, j] = candidates[p];
            if (contacts[p] == 0)
                line(never, i, j, "Never");
            else if (contacts[p] == a.samples)
                line(always, i, j, "Always");
            else
            {
                ++kept;
                keptNote << "       " << links[i].name << " / " << links[j].name << ": " << contacts[p]
                         << (inContact(*robot, centers0, i, j) ? ", and at the default configuration" : "") << '\n';
            }
        }
        const std::string samples = std::to_string(a.samples) +
                                    " random configurations (uniform in the joint limits, seed " +
                                    std::to_string(a.seed) + ")";
        out << "  <!-- ropras collision-matrix --samples " << a.samples << " --seed " << a.seed << " on the "
            << robot->spheres().size() << " spheres of " << n << " links -->\n";
        out << "  <!-- Adjacent: one joint apart -->\n" << joint.str();
        out << "  <!-- Adjacent: rigidly connected (only fixed joints between them) -->\n" << rigid.str();
        out << "  <!-- Never: the spheres touch in none of " << samples << " -->\n" << never.str();
        out << "  <!-- Always: the spheres touch in all of " << samples << " -->\n" << always.str();
        out << "  <!-- checked (" << kept << " pairs), in contact in this many of the " << a.samples
            << " configurations:\n"
            << keptNote.str() << "  -->\n";
        if (a.output.empty())
            std::cout << out.str();
        else
        {
            std::ofstream file(a.output);
            file << out.str();
            if (!file)
                throw ropras::Error("--output: cannot write '" + a.output + "'");
            std::cout << "wrote " << a.output << ": " << candidates.size() - kept << " of " << candidates.size()
                      << " sampled pairs disabled, " << kept << " checked\n";
        }
        return 0;
    }

    std::function<int()> setup(CLI::App &app)
    {
        auto a = std::make_shared<Args>();
        app.add_option("--urdf", a->urdf, "robot URDF (its sphere model is sampled)")
            ->required()
            ->check(CLI::ExistingFile);
        app.add_option("--srdf", a->srdf, "SRDF whose disable_collisions pairs are left out")->check(CLI::ExistingFile);
        app.add_option("--samples", a->samples, "random configurations, uniform in the joint limits")
            ->capture_default_str()
            ->check(ropras::bin::POSITIVE_COUNT & CLI::Range(1.0, 1e8));
        app.add_option("--seed", a->seed, "random seed")->capture_default_str();
        app.add_option("--output", a->output, "write the SRDF lines to this file instead of standard output");
        return [a] { return run(*a); };
    }

    const ropras::bin::CommandRegistrar reg{
        {"collision-matrix",
         "SRDF disable_collisions pairs by MoveIt Setup Assistant's rules (adjacent, never / always in contact)",
         setup}};
}  // namespace
