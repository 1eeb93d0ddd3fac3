// `ropras <command> [options]`: thin front end over the library; every command lives in commands/.
#include <algorithm>
#include <cstdint>
#include <iostream>

#include "CommandRegistry.h"
#include "ropras/core/Error.h"
#include "ropras/core/InputFile.h"
#include "ropras/core/MemoryLimit.h"

int main(int argc, char **argv)
{
    CLI::App app{"ropras: long-horizon online POMDP planning for robots on OMPL"};
    app.require_subcommand(1);
    // limits of every command (given before or after the command name): input files and count-driven memory
    std::uint64_t maxInputSize = ropras::inputSizeLimit(), maxMemory = ropras::memoryLimit();
    app.add_option("--max-input-size", maxInputSize,
                   "largest input file read (URDF, SRDF, scene, request, config, JSON lines, recording, mesh), "
                   "e.g. 512MiB")
        ->transform(CLI::AsSizeValue(false))
        ->default_str("256MiB");
    app.add_option("--max-memory", maxMemory,
                   "memory a count option may ask for (samples, configurations, particles); default: physical memory")
        ->transform(CLI::AsSizeValue(false));
    app.fallthrough();
    auto &registry = ropras::bin::commandRegistry();
    std::sort(registry.begin(), registry.end(), [](const auto &a, const auto &b) { return a.name < b.name; });
    std::function<int()> run;
    for (auto &command : registry)
    {
        CLI::App *sub = app.add_subcommand(command.name, command.description);
        auto body = command.setup(*sub);
        sub->callback([&run, body] { run = body; });
    }
    // CLI11 reports an unknown command only as "A subcommand is required": name it and list the commands
    if (argc > 1 && argv[1][0] != '-' &&
        std::none_of(registry.begin(), registry.end(), [&](const auto &c) { return c.name == argv[1]; }))
    {
        std::cerr << "ropras: error: unknown command '" << argv[1] << "'; commands:";
        for (const auto &command : registry)
            std::cerr << ' ' << command.name;
        std::cerr << '\n';
        return 2;
    }
    try
    {
        app.parse(argc, argv);
    }
    catch (const CLI::ParseError &e)
    {
        // --help exits 0; every command-line error (unknown option, missing file, bad number) exits 2
        return app.exit(e) == 0 ? 0 : 2;
    }
    try
    {
        ropras::setInputSizeLimit(maxInputSize);
        ropras::setMemoryLimit(maxMemory);
        return run();
    }
    catch (const ropras::Error &e)
    {
        std::cerr << "ropras: error: " << e.what() << '\n';
        return 2;
    }
    catch (const std::exception &e)
    {
        // a library error type that escaped the ropras::Error translation: still a clear message, never an abort
        std::cerr << "ropras: error: " << e.what() << '\n';
        return 2;
    }
}
