// Issue 17: every input file goes through one reader that refuses special files (/dev/zero, a FIFO, a folder)
// and files above the size limit, naming the file.
#include "ropras/core/InputFile.h"

#include <gtest/gtest.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cstdint>
#include <filesystem>
#include <fstream>
#include <string>

#include "ExpectError.h"

namespace fs = std::filesystem;
using ropras::test::expectErrorMentions;

namespace
{
    fs::path scratchDir()
    {
        const fs::path dir = fs::temp_directory_path() / ("ropras-input-file-test-" + std::to_string(::getpid()));
        fs::create_directories(dir);
        return dir;
    }
}  // namespace

TEST(InputFile, ReadsARegularFileWhole)
{
    const fs::path dir = scratchDir();
    const std::string text = std::string("line one\n") + std::string(100000, 'x') + "\nend";
    std::ofstream((dir / "a.txt").string(), std::ios::binary) << text;
    EXPECT_EQ(ropras::readInputFile((dir / "a.txt").string(), "test"), text);
    EXPECT_EQ(ropras::checkInputFile((dir / "a.txt").string(), "test"), text.size());
    fs::remove_all(dir);
}

TEST(InputFile, RefusesSpecialFilesAndMissingOnes)
{
    const fs::path dir = scratchDir();
    expectErrorMentions([] { ropras::readInputFile("/dev/zero", "URDF"); },
                        {"URDF '/dev/zero': is a character device, not a regular file"});
    expectErrorMentions([&] { ropras::readInputFile(dir.string(), "scene"); }, {"is a folder"});
    const fs::path fifo = dir / "fifo";
    ASSERT_EQ(::mkfifo(fifo.c_str(), 0600), 0);
    // before the reader, opening a FIFO blocked forever (no writer); now it is refused before it is opened
    expectErrorMentions([&] { ropras::readInputFile(fifo.string(), "results file"); }, {"fifo': is a FIFO"});
    expectErrorMentions([&] { ropras::readInputFile((dir / "none.yaml").string(), "request"); },
                        {"none.yaml': file not found"});
    // a symbolic link to a regular file is read, one to a device refused
    std::ofstream((dir / "b.txt").string()) << "b";
    fs::create_symlink(dir / "b.txt", dir / "link.txt");
    fs::create_symlink("/dev/zero", dir / "zero.txt");
    EXPECT_EQ(ropras::readInputFile((dir / "link.txt").string(), "test"), "b");
    expectErrorMentions([&] { ropras::readInputFile((dir / "zero.txt").string(), "test"); }, {"character device"});
    fs::remove_all(dir);
}

TEST(InputFile, RefusesFilesAboveTheSizeLimit)
{
    const fs::path dir = scratchDir();
    std::ofstream((dir / "big.txt").string()) << std::string(2048, 'y');
    const std::uint64_t saved = ropras::inputSizeLimit();
    EXPECT_EQ(saved, ropras::DEFAULT_INPUT_SIZE_LIMIT);
    ropras::setInputSizeLimit(2047);
    expectErrorMentions([&] { ropras::readInputFile((dir / "big.txt").string(), "scene"); },
                        {"big.txt': the file is 2048 bytes, more than the input size limit 2047 bytes"});
    ropras::setInputSizeLimit(2048);
    EXPECT_EQ(ropras::readInputFile((dir / "big.txt").string(), "scene").size(), 2048u);
    expectErrorMentions([] { ropras::setInputSizeLimit(0); }, {"at least 1 byte"});
    ropras::setInputSizeLimit(saved);
    fs::remove_all(dir);
}

TEST(InputFile, FormatsByteCounts)
{
    EXPECT_EQ(ropras::formatBytes(1), "1 byte");
    EXPECT_EQ(ropras::formatBytes(1023), "1023 bytes");
    EXPECT_EQ(ropras::formatBytes(10239), "10239 bytes");
    EXPECT_EQ(ropras::formatBytes(15360), "15 KiB");
    EXPECT_EQ(ropras::formatBytes(1536 * 1024), "1.5 MiB");
    EXPECT_EQ(ropras::formatBytes(std::uint64_t(256) << 20), "256 MiB");
    EXPECT_EQ(ropras::formatBytes(std::uint64_t(3) << 40), "3.0 TiB");
}
