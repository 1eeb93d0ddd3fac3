// `ropras bench-queries`: nanoseconds per object of the Environment queries (firstHit, objectDistances,
// objectsWithin) on random scenes of each shape type with 10, 100 and 1000 objects.
#include <algorithm>
#include <chrono>
#include <fstream>
#include <iomanip>
#include <iostream>
#include <nlohmann/json.hpp>
#include <random>
#include <sstream>

#include "ArgumentChecks.h"
#include "BenchClock.h"
#include "CommandRegistry.h"
#include "ropras/core/Error.h"
#include "ropras/ompl_ext/scene/EnvironmentQueries.h"

namespace
{
    using namespace ropras;
    using namespace ropras::ompl_ext;

    struct QueryArgs
    {
        std::vector<std::size_t> objects{10, 100, 1000};
        std::size_t queries{2000};
        int repeat{7};
        double segmentLength{0.5};
        std::string clock{"wall"}, json;
        unsigned seed{1};
    };

    using ropras::bin::median;

    /// \a count objects of \a type in [-1, 1]^3, sized so that they fill about the same share of the cube
    /// whatever the count (about 10 %); clouds: 64 points of radius size / 4 in a cube of side size
    Environment scene(ShapeType type, std::size_t count, std::mt19937_64 &rng)
    {
        std::uniform_real_distribution<double> u(-1.0, 1.0);
        std::normal_distribution<double> n(0.0, 1.0);
        const double size = 0.9 / std::cbrt(static_cast<double>(count));
        Environment env;
        for (std::size_t i = 0; i < count; ++i)
        {
            Eigen::Isometry3d pose = Eigen::Isometry3d::Identity();
            pose.linear() = Eigen::Quaterniond(n(rng), n(rng), n(rng), n(rng)).normalized().toRotationMatrix();
            pose.translation() = Eigen::Vector3d(u(rng), u(rng), u(rng));
            const double s = size * (0.5 + 0.25 * (1.0 + u(rng)));
            const std::string name = "o" + std::to_string(i);
            switch (type)
            {
                case ShapeType::Sphere:
                    env.addSphere(name, pose.translation(), 0.5 * s);
                    break;
                case ShapeType::Box:
                    env.addBox(name, pose, Eigen::Vector3d(s, 0.8 * s, 0.6 * s));
                    break;
                case ShapeType::Cylinder:
                    env.addCylinder(name, pose, 0.4 * s, s);
                    break;
                case ShapeType::Capsule:
                    env.addCapsule(name, pose, 0.3 * s, 0.7 * s);
                    break;
                case ShapeType::PointCloud:
                {
                    std::vector<Eigen::Vector3f> points;
                    for (int k = 0; k < 64; ++k)
                        points.push_back((0.5 * s * Eigen::Vector3d(u(rng), u(rng), u(rng))).cast<float>());
                    env.addPointCloud(name, PointCloud::build(points, static_cast<float>(0.25 * s)), pose);
                    break;
                }
            }
        }
        return env;
    }

    struct Case
    {
        ShapeType type;
        std::size_t count;
        Environment env;
        std::vector<Eigen::Vector3d> a, b;  ///< segments (and a: distance query points)
        std::vector<double> segmentNs, distanceNs, withinNs;
        std::size_t hits{0};
    };

    int run(const QueryArgs &args)
    {
        const ropras::bin::BenchClock clock(args.clock, "bench-queries");
        for (std::size_t n : args.objects)
            if (n == 0 || n > 100000)
                throw Error("bench-queries: --objects " + std::to_string(n) + " is outside [1, 100000]");
        if (args.queries > 1000000)
            throw Error("bench-queries: --queries " + std::to_string(args.queries) + " is more than 1000000");
        std::mt19937_64 rng(args.seed);
        std::uniform_real_distribution<double> u(-1.0, 1.0);
        std::vector<Case> cases;
        for (ShapeType type :
             {ShapeType::Sphere, ShapeType::Box, ShapeType::Cylinder, ShapeType::Capsule, ShapeType::PointCloud})
            for (std::size_t count : args.objects)
            {
                Case c{type, count, scene(type, count, rng), {}, {}, {}, {}, {}, 0};
                for (std::size_t q = 0; q < args.queries; ++q)
                {
                    const Eigen::Vector3d a(u(rng), u(rng), u(rng));
                    const Eigen::Vector3d dir = Eigen::Vector3d(u(rng), u(rng), u(rng)).normalized();
                    c.a.push_back(a);
                    c.b.push_back(a + args.segmentLength * dir);
                }
                cases.push_back(std::move(c));
            }

        // interleaved: every repetition runs every case once; medians per case
        double sink = 0.0;
        std::vector<ObjectDistance> distances;
        std::vector<int> within;
        for (int rep = 0; rep < args.repeat; ++rep)
            for (Case &c : cases)
            {
                const double items = static_cast<double>(c.a.size() * c.count);
                std::size_t hits = 0;
                double t0 = clock.nowNs();
                for (std::size_t q = 0; q < c.a.size(); ++q)
                {
                    const SegmentHit hit = firstHit(c.env, c.a[q], c.b[q]);
                    hits += hit.hit ? 1u : 0u;
                    sink += hit.fraction;
                }
                double t1 = clock.nowNs();
                c.segmentNs.push_back((t1 - t0) / items);
                c.hits = hits;
                t0 = clock.nowNs();
                for (std::size_t q = 0; q < c.a.size(); ++q)
                {
                    objectDistances(c.env, c.a[q], 0.05, distances);
                    sink += distances.front().distance;
                }
                t1 = clock.nowNs();
                c.distanceNs.push_back((t1 - t0) / items);
                t0 = clock.nowNs();
                for (std::size_t q = 0; q < c.a.size(); ++q)
                {
                    objectsWithin(c.env, c.a[q], 0.05, 0.1, within);
                    sink += static_cast<double>(within.size());
                }
                t1 = clock.nowNs();
                c.withinNs.push_back((t1 - t0) / items);
            }

        std::cout << args.queries << " queries per case (segments of " << args.segmentLength
                  << " m from random points in [-1, 1]^3; distances from a 0.05 m sphere; objects within 0.1 m), "
                  << "median of " << args.repeat << " interleaved repetitions, " << args.clock << " clock\n";
        std::cout << std::left << std::setw(10) << "type" << std::right << std::setw(8) << "objects" << std::setw(8)
                  << "hit %" << std::setw(16) << "segment ns/obj" << std::setw(17) << "distance ns/obj" << std::setw(15)
                  << "within ns/obj" << '\n';
        nlohmann::json rows = nlohmann::json::array();
        for (const Case &c : cases)
        {
            const double hitShare = 100.0 * static_cast<double>(c.hits) / static_cast<double>(c.a.size());
            std::cout << std::left << std::setw(10) << shapeTypeName(c.type) << std::right << std::setw(8) << c.count
                      << std::fixed << std::setprecision(1) << std::setw(8) << hitShare << std::setw(16)
                      << median(c.segmentNs) << std::setw(17) << median(c.distanceNs) << std::setw(15)
                      << median(c.withinNs) << '\n';
            rows.push_back({{"type", shapeTypeName(c.type)},
                            {"objects", c.count},
                            {"hit_percent", hitShare},
                            {"segment_ns_per_object", median(c.segmentNs)},
                            {"distance_ns_per_object", median(c.distanceNs)},
                            {"within_ns_per_object", median(c.withinNs)}});
        }
        if (!args.json.empty())
        {
            std::ofstream out(args.json);
            out << nlohmann::json{{"queries", args.queries},
                                  {"repeat", args.repeat},
                                  {"clock", args.clock},
                                  {"cases", rows}}
                       .dump(2)
                << '\n';
            if (!out)
                throw Error("bench-queries: cannot write '" + args.json + "'");
        }
        return std::isnan(sink) ? 1 : 0;  // keeps the work observable
    }

    std::function<int()> setup(CLI::App &app)
    {
        auto args = std::make_shared<QueryArgs>();
        app.add_option("--objects", args->objects, "object counts per scene (each shape type)")
            ->capture_default_str()
            ->check(ropras::bin::POSITIVE_COUNT);
        app.add_option("--queries", args->queries, "queries per scene and repetition")
            ->capture_default_str()
            ->check(ropras::bin::POSITIVE_COUNT);
        app.add_option("--repeat", args->repeat, "interleaved repetitions (medians are reported)")
            ->capture_default_str()
            ->check(ropras::bin::POSITIVE_COUNT);
        app.add_option("--segment-length", args->segmentLength, "segment length (m)")
            ->capture_default_str()
            ->check(ropras::bin::POSITIVE_NUMBER);
        app.add_option("--clock", args->clock, "wall (steady clock) or cpu (thread CPU time: use on a loaded machine)")
            ->capture_default_str();
        app.add_option("--json", args->json, "write the medians as JSON");
        app.add_option("--seed", args->seed, "random seed")->capture_default_str();
        return [args] { return run(*args); };
    }

    const ropras::bin::CommandRegistrar reg{
        {"bench-queries", "time the Environment queries (segment hit, distances, objects within) per object", setup}};
}  // namespace
