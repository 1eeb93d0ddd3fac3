// Issue 17: JSON lines are appended whole (one write per record and newline), a record an interrupted run cut off
// is ended on the next append, and the table skips it with a warning naming file and line.
#include <gtest/gtest.h>
#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>

#include "ExpectError.h"
#include "ropras/scenarios/JsonLinesAppender.h"
#include "ropras/scenarios/ResultTable.h"

namespace ropras::scenarios::test
{
    using ropras::test::expectErrorMentions;

    namespace
    {
        std::string readAll(const std::filesystem::path &path)
        {
            std::ifstream in(path, std::ios::binary);
            std::ostringstream s;
            s << in.rdbuf();
            return s.str();
        }

        const char *const RECORD =
            R"({"scenario": "light-dark", "solver": "pomcp", "heuristic": "dynamic", "seed": 1, "episode": 0, )"
            R"("success": true, "discounted_return": 1, "undiscounted_return": 2, "steps": 3, "sims_per_call": 4, )"
            R"("plan_time_s": 0.1, "ref_failures": 0})";
    }  // namespace

    TEST(JsonLines, AppenderEndsACutOffLineAndWritesWholeLines)
    {
        const auto dir = std::filesystem::temp_directory_path() / ("ropras-append-" + std::to_string(::getpid()));
        std::filesystem::create_directories(dir);
        const auto path = dir / "runs.jsonl";
        const std::string cut = std::string(RECORD).substr(0, 50);
        std::ofstream(path, std::ios::binary) << RECORD << '\n' << cut;
        {
            JsonLinesAppender out(path.string(), "--out");
            EXPECT_EQ(out.repairedLine(), 2u);
            out.append(std::string(RECORD).replace(std::string(RECORD).find("\"episode\": 0"), 12, "\"episode\": 1"));
            expectErrorMentions([&] { out.append("{\n}"); }, {"contains a newline"});
        }
        const std::string text = readAll(path);
        EXPECT_EQ(text,
                  std::string(RECORD) + "\n" + cut + "\n" +
                      std::string(RECORD).replace(std::string(RECORD).find("\"episode\": 0"), 12, "\"episode\": 1") +
                      "\n");
        {
            JsonLinesAppender again(path.string(), "--out");  // now every line is ended
            EXPECT_EQ(again.repairedLine(), 0u);
        }
        ResultTable table;
        EXPECT_EQ(table.addFile(path.string()), 2u);
        ASSERT_EQ(table.warnings().size(), 1u);
        EXPECT_NE(table.warnings()[0].find("runs.jsonl:2: truncated record"), std::string::npos) << table.warnings()[0];
        expectErrorMentions([&] { JsonLinesAppender((dir / "no" / "x.jsonl").string(), "--out"); },
                            {"--out: cannot open", "x.jsonl"});
        std::filesystem::remove_all(dir);
    }

    TEST(JsonLines, TableSkipsATruncatedLastLineButNotOtherMalformedLines)
    {
        ResultTable table;
        std::istringstream cutLast(std::string(RECORD) + "\n" + std::string(RECORD).substr(0, 70));
        EXPECT_EQ(table.addJsonLines(cutLast, "r.jsonl"), 1u);
        ASSERT_EQ(table.warnings().size(), 1u);
        EXPECT_NE(table.warnings()[0].find("r.jsonl:2: truncated record"), std::string::npos);
        // a line that is wrong before its end is malformed, not truncated
        std::istringstream broken(std::string(RECORD) + "\n{\"scenario\": x}\n");
        ResultTable other;
        expectErrorMentions([&] { other.addJsonLines(broken, "s.jsonl"); }, {"s.jsonl:2: malformed JSON"});
        std::istringstream cutInAString(std::string(RECORD).substr(0, 50) + "\n" + RECORD + "\n");
        ResultTable third;
        EXPECT_EQ(third.addJsonLines(cutInAString, "u.jsonl"), 1u);  // cut inside "heuristic": still a truncation
        ASSERT_EQ(third.warnings().size(), 1u);
        EXPECT_NE(third.warnings()[0].find("u.jsonl:1: truncated record"), std::string::npos);
        std::istringstream notObject("\"abc\n");
        expectErrorMentions([&] { other.addJsonLines(notObject, "t.jsonl"); }, {"t.jsonl:1: malformed JSON"});
    }
}  // namespace ropras::scenarios::test
