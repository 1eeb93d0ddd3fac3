#ifndef ROPRAS_BIN_COMMAND_REGISTRY_H
#define ROPRAS_BIN_COMMAND_REGISTRY_H

#include <CLI/CLI.hpp>
#include <functional>
#include <string>
#include <vector>

namespace ropras::bin
{
    /** \brief A subcommand of `ropras`: \a setup declares its options on the CLI11 subcommand and returns
        the function that runs it (returning the process exit code). */
    struct Command
    {
        std::string name;
        std::string description;
        std::function<std::function<int()>(CLI::App &)> setup;
    };

    std::vector<Command> &commandRegistry();

    /** \brief Static registration: `static const CommandRegistrar reg{{"name", "what it does", setup}};` */
    struct CommandRegistrar
    {
        explicit CommandRegistrar(Command command) { commandRegistry().push_back(std::move(command)); }
    };
}  // namespace ropras::bin

#endif
