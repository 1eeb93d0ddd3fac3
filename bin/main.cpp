// `ropras <command> [options]`: thin front end over the library; every command lives in commands/.
#include <algorithm>
#include <iostream>

#include "CommandRegistry.h"
#include "ropras/core/Error.h"

int main(int argc, char **argv)
{
    CLI::App app{"ropras: long-horizon online POMDP planning for robots on OMPL"};
    app.require_subcommand(1);
    auto &registry = ropras::bin::commandRegistry();
    std::sort(registry.begin(), registry.end(), [](const auto &a, const auto &b) { return a.name < b.name; });
    std::function<int()> run;
    for (auto &command : registry)
    {
        CLI::App *sub = app.add_subcommand(command.name, command.description);
        auto body = command.setup(*sub);
        sub->callback([&run, body] { run = body; });
    }
    try
    {
        app.parse(argc, argv);
    }
    catch (const CLI::ParseError &e)
    {
        return app.exit(e);
    }
    try
    {
        return run();
    }
    catch (const ropras::Error &e)
    {
        std::cerr << "ropras: error: " << e.what() << '\n';
        return 2;
    }
}
