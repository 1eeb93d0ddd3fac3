#ifndef ROPRAS_BIN_OUTPUT_CHECKS_H
#define ROPRAS_BIN_OUTPUT_CHECKS_H

#include <sys/stat.h>

#include <string>
#include <vector>

#include "ropras/core/Error.h"

namespace ropras::bin
{
    /** \brief Throws ropras::Error when the output file \a out (of option \a option) is one of the \a inputs:
        compared by device and inode, so a symbolic link, a hard link or another spelling of the same path
        ("./r.jsonl", "dir/../r.jsonl") is caught as well. An output that does not exist yet is no input.
        Called before a command does any work, so that an input is never overwritten. */
    inline void refuseOverwritingInputs(const std::string &option, const std::string &out,
                                        const std::vector<std::string> &inputs)
    {
        struct stat target;
        if (out.empty() || ::stat(out.c_str(), &target) != 0)
            return;
        for (const std::string &input : inputs)
        {
            struct stat source;
            if (!input.empty() && ::stat(input.c_str(), &source) == 0 && source.st_dev == target.st_dev &&
                source.st_ino == target.st_ino)
            {
                throw Error(option + " '" + out + "' is the input '" + input +
                            "' (the same file): refusing to overwrite an input; choose another output file");
            }
        }
    }
}  // namespace ropras::bin

#endif
