#ifndef ROPRAS_BIN_RESULT_FILES_H
#define ROPRAS_BIN_RESULT_FILES_H

#include <iostream>
#include <string>
#include <vector>

#include "ropras/core/Error.h"
#include "ropras/scenarios/ResultTable.h"

namespace ropras::bin
{
    /** \brief The episode records of the JSON-lines \a files (`ropras table`, `ropras plot`): warnings (an empty
        file, a duplicate or truncated record) go to standard error as "<command>: warning: ..."; throws
        ropras::Error when a file is malformed or no file holds a record. */
    inline void readResultFiles(scenarios::ResultTable &table, const std::vector<std::string> &files,
                                const std::string &command)
    {
        for (const auto &file : files)
        {
            if (table.addFile(file) == 0)
            {
                std::cerr << command << ": warning: " << file << " holds no episode record\n";
            }
        }
        for (const auto &warning : table.warnings())
        {
            std::cerr << command << ": warning: " << warning << '\n';
        }
        if (table.size() == 0)
        {
            throw Error("no episode records in " + std::to_string(files.size()) + " file(s)");
        }
    }
}  // namespace ropras::bin

#endif
