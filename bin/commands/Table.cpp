// `ropras table FILES...`: merges the JSON lines of `ropras run` (shards, solvers, scenarios) into one table.
#include <fstream>
#include <iostream>
#include <memory>
#include <string>
#include <vector>

#include "CommandRegistry.h"
#include "OutputChecks.h"
#include "ResultFiles.h"
#include "ropras/core/Error.h"
#include "ropras/scenarios/ResultTable.h"

namespace
{
    struct TableOptions
    {
        std::vector<std::string> files;
        std::string out;
        std::string csv;
    };

    void writeFile(const std::string &option, const std::string &path, const std::string &text)
    {
        std::ofstream file(path);
        file << text;
        if (!file)
        {
            throw ropras::Error(option + ": cannot write \"" + path + "\"");
        }
    }

    int run(const TableOptions &o)
    {
        ropras::bin::refuseOverwritingInputs("--out", o.out, o.files);
        ropras::bin::refuseOverwritingInputs("--csv", o.csv, o.files);
        ropras::scenarios::ResultTable table;
        ropras::bin::readResultFiles(table, o.files, "ropras table");
        const std::string markdown = table.markdown();
        std::cout << markdown;
        if (!o.out.empty())
        {
            writeFile("--out", o.out, markdown);
        }
        if (!o.csv.empty())
        {
            writeFile("--csv", o.csv, table.csv());
        }
        return 0;
    }

    std::function<int()> setup(CLI::App &app)
    {
        auto o = std::make_shared<TableOptions>();
        app.add_option("files", o->files, "JSON-lines files written by `ropras run --out`")
            ->required()
            ->check(CLI::ExistingFile);
        app.add_option("--out", o->out, "Also write the Markdown table to this file");
        app.add_option("--csv", o->csv, "Also write the rows as CSV (full precision, standard errors) to this file");
        return [o] { return run(*o); };
    }

    const ropras::bin::CommandRegistrar reg{
        {"table", "Merge the JSON lines of `ropras run` (shards, solvers, scenarios) into one Markdown table", setup}};
}  // namespace
