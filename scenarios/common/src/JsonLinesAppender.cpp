#include "ropras/scenarios/JsonLinesAppender.h"

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>

#include "ropras/core/Error.h"

namespace ropras::scenarios
{
    namespace
    {
        /// the number of newlines in the file open as \a fd (read in blocks; called only to name a cut-off line)
        std::size_t countLines(int fd)
        {
            std::size_t lines = 0;
            char buffer[1 << 16];
            off_t offset = 0;
            for (;;)
            {
                const ssize_t n = ::pread(fd, buffer, sizeof(buffer), offset);
                if (n <= 0)
                    return lines;
                for (ssize_t i = 0; i < n; ++i)
                    lines += buffer[i] == '\n';
                offset += n;
            }
        }
    }  // namespace

    JsonLinesAppender::JsonLinesAppender(const std::string &path, const std::string &option)
        : path_(path), option_(option)
    {
        fd_ = ::open(path.c_str(), O_RDWR | O_APPEND | O_CREAT | O_CLOEXEC, 0644);
        if (fd_ < 0)
        {
            throw Error(option + ": cannot open \"" + path + "\" for appending: " + std::strerror(errno));
        }
        struct stat info;
        if (::fstat(fd_, &info) != 0 || !S_ISREG(info.st_mode))
        {
            ::close(fd_);
            throw Error(option + ": \"" + path + "\" is not a regular file");
        }
        char last = '\n';
        if (info.st_size > 0 && ::pread(fd_, &last, 1, info.st_size - 1) == 1 && last != '\n')
        {
            repairedLine_ = countLines(fd_) + 1;
            writeAll("\n");
        }
    }

    JsonLinesAppender::~JsonLinesAppender()
    {
        if (fd_ >= 0)
            ::close(fd_);
    }

    void JsonLinesAppender::append(const std::string &record)
    {
        if (record.find('\n') != std::string::npos)
        {
            throw Error(option_ + ": a JSON-lines record for \"" + path_ + "\" contains a newline");
        }
        writeAll(record + '\n');
    }

    void JsonLinesAppender::writeAll(const std::string &bytes)
    {
        // one write(2) for the whole line; a short write (only possible on a full disk or a fatal signal) is
        // continued, an interrupted one retried
        std::size_t done = 0;
        while (done < bytes.size())
        {
            const ssize_t n = ::write(fd_, bytes.data() + done, bytes.size() - done);
            if (n < 0 && errno == EINTR)
                continue;
            if (n <= 0)
            {
                throw Error(option_ + ": writing to \"" + path_ + "\" failed: " + std::strerror(errno));
            }
            done += static_cast<std::size_t>(n);
        }
    }
}  // namespace ropras::scenarios
