#include "ropras/core/MemoryLimit.h"

#include <unistd.h>

#include <atomic>
#include <limits>

#include "ropras/core/Error.h"
#include "ropras/core/InputFile.h"

namespace ropras
{
    namespace
    {
        std::uint64_t physicalMemory() noexcept
        {
            const long pages = ::sysconf(_SC_PHYS_PAGES);
            const long pageSize = ::sysconf(_SC_PAGESIZE);
            if (pages <= 0 || pageSize <= 0)
                return std::uint64_t(8) << 30;  // unknown: assume 8 GiB
            return static_cast<std::uint64_t>(pages) * static_cast<std::uint64_t>(pageSize);
        }

        std::atomic<std::uint64_t> &limitSetting()
        {
            static std::atomic<std::uint64_t> limit{physicalMemory()};
            return limit;
        }
    }  // namespace

    std::uint64_t memoryLimit() noexcept
    {
        return limitSetting().load();
    }

    void setMemoryLimit(std::uint64_t bytes)
    {
        if (bytes == 0)
            throw Error("the memory limit must be at least 1 byte");
        limitSetting().store(bytes);
    }

    std::uint64_t checkedBytes(std::uint64_t count, std::uint64_t bytesEach, const std::string &what)
    {
        const std::uint64_t limit = memoryLimit();
        const bool overflows = bytesEach != 0 && count > std::numeric_limits<std::uint64_t>::max() / bytesEach;
        const std::uint64_t total = overflows ? 0 : count * bytesEach;
        if (overflows || total > limit)
        {
            throw Error(what + " asks for " + std::to_string(count) + " x " + std::to_string(bytesEach) +
                        " bytes = " + (overflows ? std::string("more than 2^64 bytes") : formatBytes(total)) +
                        ", more than the memory limit " + formatBytes(limit) + " (ropras --max-memory)");
        }
        return total;
    }
}  // namespace ropras
