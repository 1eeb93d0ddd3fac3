#include "CommandRegistry.h"

namespace ropras::bin
{
    std::vector<Command> &commandRegistry()
    {
        static std::vector<Command> registry;
        return registry;
    }
}  // namespace ropras::bin
