#ifndef ROPRAS_CORE_MEMORY_LIMIT_H
#define ROPRAS_CORE_MEMORY_LIMIT_H

#include <cstdint>
#include <string>

namespace ropras
{
    /** \brief The memory one request may ask for: count options (samples, configurations, particles) are
        turned into bytes with checkedBytes() before anything is allocated, so an absurd count is an error that
        names the option and the amount instead of std::bad_alloc. */

    /// the limit in bytes; process-wide, the machine's physical memory unless set (`ropras --max-memory`)
    std::uint64_t memoryLimit() noexcept;

    /// sets memoryLimit(); throws ropras::Error for 0
    void setMemoryLimit(std::uint64_t bytes);

    /** \brief \a count x \a bytesEach without overflow; throws ropras::Error "<what> asks for <count> x
        <bytesEach> bytes = <total>, more than the memory limit <limit> (ropras --max-memory)" when the product
        overflows or exceeds memoryLimit(). \a what names the option and its value, e.g. "--samples 1000000000". */
    std::uint64_t checkedBytes(std::uint64_t count, std::uint64_t bytesEach, const std::string &what);
}  // namespace ropras

#endif
