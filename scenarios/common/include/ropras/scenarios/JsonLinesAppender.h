#ifndef ROPRAS_SCENARIOS_JSON_LINES_APPENDER_H
#define ROPRAS_SCENARIOS_JSON_LINES_APPENDER_H

#include <cstddef>
#include <string>

namespace ropras::scenarios
{
    /** \brief Appends lines to a JSON-lines file, each line (record and newline) with one write(2) on a file
        opened with O_APPEND: a signal can no longer fall between a record and its newline, and lines of
        processes appending to the same file do not interleave. A file whose last line has no newline (left by
        an interrupted writer of an older version) is first ended with one, so that the new records start on
        their own lines; repairedLine() then says which line was cut off (ResultTable skips it with a warning). */
    class JsonLinesAppender
    {
    public:
        /** \brief Opens (creates) \a path for appending; throws ropras::Error "<option>: cannot open ..." */
        JsonLinesAppender(const std::string &path, const std::string &option);
        ~JsonLinesAppender();
        JsonLinesAppender(const JsonLinesAppender &) = delete;
        JsonLinesAppender &operator=(const JsonLinesAppender &) = delete;

        /** \brief Writes \a record (one line of JSON, without newline) and a newline; throws ropras::Error when
            the write fails (disk full, I/O error) or \a record contains a newline. */
        void append(const std::string &record);

        /// the 1-based number of the cut-off line that was ended with a newline on opening, 0 when none was
        std::size_t repairedLine() const noexcept { return repairedLine_; }

    private:
        void writeAll(const std::string &bytes);

        std::string path_, option_;
        int fd_{-1};
        std::size_t repairedLine_{0};
    };
}  // namespace ropras::scenarios

#endif
