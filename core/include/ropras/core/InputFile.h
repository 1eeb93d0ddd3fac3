#ifndef ROPRAS_CORE_INPUT_FILE_H
#define ROPRAS_CORE_INPUT_FILE_H

#include <cstdint>
#include <string>

namespace ropras
{
    /** \brief The one way the project reads an input file (URDF, SRDF, scene, request, configuration, JSON
        lines, recording, mesh): the path must name a regular file (after symbolic links; a FIFO, a device such
        as /dev/zero, a socket or a folder is refused) no larger than inputSizeLimit(). Every refusal throws
        ropras::Error "<what> '<path>': <reason>". */

    /// default inputSizeLimit(): 256 MiB
    constexpr std::uint64_t DEFAULT_INPUT_SIZE_LIMIT = std::uint64_t(256) << 20;

    /// the largest input file accepted (bytes); process-wide, DEFAULT_INPUT_SIZE_LIMIT unless set
    std::uint64_t inputSizeLimit() noexcept;

    /// sets inputSizeLimit() (`ropras --max-input-size`); throws ropras::Error for 0
    void setInputSizeLimit(std::uint64_t bytes);

    /// checks \a path as described above and returns its size in bytes
    std::uint64_t checkInputFile(const std::string &path, const std::string &what);

    /// checkInputFile(), then the whole file (never more than inputSizeLimit() bytes, even if it grows)
    std::string readInputFile(const std::string &path, const std::string &what);

    /// "1.5 GiB", "512 KiB", "4322 bytes" (exact below 10 KiB): a byte count for messages
    std::string formatBytes(std::uint64_t bytes);
}  // namespace ropras

#endif
