#ifndef ROPRAS_CORE_ERROR_H
#define ROPRAS_CORE_ERROR_H

#include <stdexcept>
#include <string>

namespace ropras
{
    /** \brief The one exception type of the project.

        Thrown at API boundaries (loading files, validating arguments, looking up names) with a message
        that names the offending file, name or value. Planning outcomes are status values, never
        exceptions; hot paths (FK, collision, tree search, rollouts) never throw. */
    class Error : public std::runtime_error
    {
    public:
        explicit Error(const std::string &message) : std::runtime_error(message) {}
    };
}  // namespace ropras

#endif
