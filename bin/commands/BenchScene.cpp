// `ropras bench-scene`: seconds and peak memory of loading a MoveIt PlanningScene file of N boxes (issue 17, item 12:
// setup linear in the input, memory proportional to it). Each size is written to a temporary file, then loaded with
// loadPlanningScene as `plan` and `check-collision` load theirs; the peak resident set of each load is measured
// from the kernel's high-water mark, reset before the load (/proc/self/clear_refs), as growth over the resident set
// before it (after malloc_trim, so that memory freed by earlier loads is not counted as already there).
#include <malloc.h>
#include <unistd.h>

#include <cstdio>
#include <filesystem>
#include <fstream>
#include <iomanip>
#include <iostream>
#include <nlohmann/json.hpp>
#include <sstream>
#include <string>
#include <vector>

#include "ArgumentChecks.h"
#include "BenchClock.h"
#include "CommandRegistry.h"
#include "ropras/core/Error.h"
#include "ropras/core/InputFile.h"
#include "ropras/ompl_ext/scene/SceneYaml.h"

namespace
{
    using namespace ropras;
    using namespace ropras::ompl_ext;

    struct SceneArgs
    {
        std::vector<std::size_t> boxes{10000, 100000};
        int repeat{3};
        std::string clock{"wall"}, dir, json;
    };

    /// the largest scene: 1 000 000 boxes are a 220 MB file, below the default input size limit
    constexpr std::size_t MAX_BOXES = 1000000;

    /// \a boxes collision objects of one box each on a 100 x 100 grid of layers, 0.1 m apart (a MoveIt scene file as
    /// MoveIt writes one: every object with its header, pose and one primitive with its own pose)
    void writeBoxesScene(const std::string &path, std::size_t boxes)
    {
        std::ofstream out(path);
        out << "name: boxes\nworld:\n  collision_objects:\n";
        for (std::size_t i = 0; i < boxes; ++i)
        {
            out << "    - header:\n        frame_id: world\n      id: box" << i
                << "\n      pose:\n        position: {x: " << static_cast<double>(i % 100) * 0.1
                << ", y: " << static_cast<double>(i / 100 % 100) * 0.1
                << ", z: " << 1.0 + static_cast<double>(i / 10000) * 0.1
                << "}\n        orientation: {x: 0, y: 0, z: 0, w: 1}\n"
                   "      primitives:\n        - type: box\n          dimensions: [0.05, 0.05, 0.05]\n"
                   "      primitive_poses:\n        - position: [0, 0, 0]\n          orientation: [0, 0, 0, 1]\n"
                   "      operation: 0\n";
        }
        if (!out.flush())
            throw Error("bench-scene: cannot write '" + path + "'");
    }

    /// VmRSS or VmHWM of this process in bytes (0 when /proc is not there)
    std::uint64_t statusBytes(const std::string &key)
    {
        std::ifstream status("/proc/self/status");
        std::string line;
        while (std::getline(status, line))
            if (line.compare(0, key.size() + 1, key + ":") == 0)
                return std::stoull(line.substr(key.size() + 1)) * 1024;
        return 0;
    }

    /// resets VmHWM to the current resident set; false where the kernel does not allow it
    bool resetPeak()
    {
        std::ofstream clear("/proc/self/clear_refs");
        clear << "5";
        return static_cast<bool>(clear.flush());
    }

    struct Row
    {
        std::size_t boxes{0};
        std::uint64_t fileBytes{0}, peakBytes{0};
        std::vector<double> seconds;
    };

    void printRows(const std::vector<Row> &rows, const SceneArgs &args)
    {
        std::cout << "median of " << args.repeat << " interleaved loads, " << args.clock
                  << " clock; peak = the largest growth of the resident set over a load\n";
        std::cout << std::setw(9) << "boxes" << std::setw(11) << "file MiB" << std::setw(10) << "load s"
                  << std::setw(12) << "us per box" << std::setw(11) << "peak MiB" << std::setw(13) << "peak / file"
                  << '\n';
        for (const Row &r : rows)
        {
            const double seconds = ropras::bin::median(r.seconds);
            std::cout << std::setw(9) << r.boxes << std::fixed << std::setprecision(1) << std::setw(11)
                      << static_cast<double>(r.fileBytes) / 1048576.0 << std::setprecision(3) << std::setw(10)
                      << seconds << std::setprecision(1) << std::setw(12)
                      << 1e6 * seconds / static_cast<double>(r.boxes) << std::setw(11)
                      << static_cast<double>(r.peakBytes) / 1048576.0 << std::setprecision(2) << std::setw(13)
                      << static_cast<double>(r.peakBytes) / static_cast<double>(r.fileBytes) << '\n';
        }
    }

    int run(const SceneArgs &args)
    {
        const ropras::bin::BenchClock clock(args.clock, "bench-scene");
        for (std::size_t n : args.boxes)
            if (n > MAX_BOXES)
                throw Error("bench-scene: --boxes " + std::to_string(n) + " is more than " + std::to_string(MAX_BOXES));
        const std::filesystem::path dir =
            args.dir.empty() ? std::filesystem::temp_directory_path() : std::filesystem::path(args.dir);
        std::vector<Row> rows;
        std::vector<std::string> paths;
        for (std::size_t n : args.boxes)
        {
            const std::string path =
                (dir / ("ropras-bench-scene-" + std::to_string(getpid()) + "-" + std::to_string(n) + ".yaml")).string();
            writeBoxesScene(path, n);
            paths.push_back(path);
            rows.push_back({n, checkInputFile(path, "scene"), 0, {}});
        }
        bool peakMeasured = true;
        try
        {
            for (int rep = 0; rep < args.repeat; ++rep)
                for (std::size_t k = 0; k < rows.size(); ++k)
                {
                    malloc_trim(0);  // the heap earlier loads freed goes back to the system: it would hide growth
                    peakMeasured = resetPeak() && peakMeasured;
                    const std::uint64_t before = statusBytes("VmRSS");
                    const double t0 = clock.nowNs();
                    const Environment env = loadPlanningScene(paths[k]);
                    const double t1 = clock.nowNs();
                    const std::uint64_t peak = statusBytes("VmHWM");
                    if (env.objectCount() != rows[k].boxes)
                        throw Error("bench-scene: " + paths[k] + " gave " + std::to_string(env.objectCount()) +
                                    " objects, expected " + std::to_string(rows[k].boxes));
                    rows[k].seconds.push_back((t1 - t0) * 1e-9);
                    rows[k].peakBytes = std::max(rows[k].peakBytes, peak > before ? peak - before : 0);
                }
        }
        catch (...)
        {
            for (const std::string &path : paths)
                std::remove(path.c_str());
            throw;
        }
        for (const std::string &path : paths)
            std::remove(path.c_str());
        if (!peakMeasured)
            std::cout << "(the kernel refused to reset the peak resident set: peaks include earlier loads)\n";
        printRows(rows, args);
        if (!args.json.empty())
        {
            nlohmann::json out = nlohmann::json::array();
            for (const Row &r : rows)
                out.push_back({{"boxes", r.boxes},
                               {"file_bytes", r.fileBytes},
                               {"load_seconds", ropras::bin::median(r.seconds)},
                               {"peak_bytes", r.peakBytes}});
            std::ofstream file(args.json);
            file << out.dump(2) << '\n';
            if (!file)
                throw Error("bench-scene: cannot write '" + args.json + "'");
        }
        return 0;
    }

    std::function<int()> setup(CLI::App &app)
    {
        auto args = std::make_shared<SceneArgs>();
        app.add_option("--boxes", args->boxes, "scene sizes (boxes, one collision object each; at most 1000000)")
            ->capture_default_str()
            ->check(ropras::bin::POSITIVE_COUNT);
        app.add_option("--repeat", args->repeat, "interleaved loads of every size (medians are reported)")
            ->capture_default_str()
            ->check(ropras::bin::countCheck(1, 100, "1 <= COUNT <= 100"));
        app.add_option("--clock", args->clock, "wall (steady clock) or cpu (thread CPU time: use on a loaded machine)")
            ->capture_default_str();
        app.add_option("--dir", args->dir, "folder for the generated scene files (default: the system's temporary one)")
            ->check(CLI::ExistingDirectory);
        app.add_option("--json", args->json, "write the figures as JSON");
        return [args] { return run(*args); };
    }

    const ropras::bin::CommandRegistrar reg{
        {"bench-scene", "time and peak memory of loading MoveIt scene files of N boxes", setup}};
}  // namespace
