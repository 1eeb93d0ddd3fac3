#include "ropras/core/InputFile.h"

#include <sys/stat.h>

#include <atomic>
#include <cerrno>
#include <cstdio>
#include <cstring>
#include <fstream>

#include "ropras/core/Error.h"

namespace ropras
{
    namespace
    {
        std::atomic<std::uint64_t> &limitSetting()
        {
            static std::atomic<std::uint64_t> limit{DEFAULT_INPUT_SIZE_LIMIT};
            return limit;
        }

        std::string kindOf(mode_t mode)
        {
            if (S_ISDIR(mode))
                return "a folder";
            if (S_ISCHR(mode))
                return "a character device";
            if (S_ISBLK(mode))
                return "a block device";
            if (S_ISFIFO(mode))
                return "a FIFO (named pipe)";
            if (S_ISSOCK(mode))
                return "a socket";
            return "not a regular file";
        }

        [[noreturn]] void fail(const std::string &what, const std::string &path, const std::string &reason)
        {
            throw Error(what + " '" + path + "': " + reason);
        }

        std::string tooLarge(std::uint64_t size)
        {
            return "the file is " + formatBytes(size) + ", more than the input size limit " +
                   formatBytes(inputSizeLimit()) + " (ropras --max-input-size)";
        }
    }  // namespace

    std::uint64_t inputSizeLimit() noexcept
    {
        return limitSetting().load();
    }

    void setInputSizeLimit(std::uint64_t bytes)
    {
        if (bytes == 0)
            throw Error("the input size limit must be at least 1 byte");
        limitSetting().store(bytes);
    }

    std::uint64_t checkInputFile(const std::string &path, const std::string &what)
    {
        struct stat info;
        if (::stat(path.c_str(), &info) != 0)
        {
            const int error = errno;
            fail(what, path, error == ENOENT ? std::string("file not found") : std::strerror(error));
        }
        if (!S_ISREG(info.st_mode))
            fail(what, path, "is " + kindOf(info.st_mode) + ", not a regular file");
        const auto size = static_cast<std::uint64_t>(info.st_size);
        if (size > inputSizeLimit())
            fail(what, path, tooLarge(size));
        return size;
    }

    std::string readInputFile(const std::string &path, const std::string &what)
    {
        const std::uint64_t size = checkInputFile(path, what);
        std::ifstream in(path, std::ios::binary);
        if (!in)
            fail(what, path, "cannot open the file");
        std::string text(static_cast<std::size_t>(size), '\0');
        in.read(text.data(), static_cast<std::streamsize>(size));
        text.resize(static_cast<std::size_t>(in.gcount()));
        if (in.bad())
            fail(what, path, "cannot read the file");
        // a file that grew after stat() is read up to the limit, never further
        char extra[4096];
        while (in && text.size() <= inputSizeLimit())
        {
            in.read(extra, sizeof(extra));
            text.append(extra, static_cast<std::size_t>(in.gcount()));
        }
        if (text.size() > inputSizeLimit())
            fail(what, path, tooLarge(text.size()));
        return text;
    }

    std::string formatBytes(std::uint64_t bytes)
    {
        static const char *const UNITS[] = {"KiB", "MiB", "GiB", "TiB", "PiB", "EiB"};
        if (bytes < 10 * 1024)  // exact below 10 KiB (a limit of 4096 bytes and a file of 4322)
            return std::to_string(bytes) + (bytes == 1 ? " byte" : " bytes");
        double value = static_cast<double>(bytes) / 1024.0;
        std::size_t unit = 0;
        while (value >= 1024.0 && unit + 1 < sizeof(UNITS) / sizeof(UNITS[0]))
        {
            value /= 1024.0;
            ++unit;
        }
        char text[32];
        std::snprintf(text, sizeof(text), value < 10.0 ? "%.1f %s" : "%.0f %s", value, UNITS[unit]);
        return text;
    }
}  // namespace ropras
