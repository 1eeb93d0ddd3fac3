#ifndef ROPRAS_TEST_ALLOCATION_COUNTER_H
#define ROPRAS_TEST_ALLOCATION_COUNTER_H

// Replaces the global operator new / delete of a test executable with counting versions. Include it in exactly
// ONE source file per test executable (the definitions are not inline: replacement functions must not be); other
// files of the same executable define ROPRAS_ALLOCATION_COUNTER_ONLY first and get the counters alone.

#include <malloc.h>

#include <atomic>
#include <cstdlib>
#include <new>

namespace ropras::test
{
    /// heap allocations (operator new calls) so far in this process
    inline std::atomic<std::size_t> allocationCount{0};
    /// bytes held by operator new's blocks now (malloc_usable_size of each), and the most since resetPeakBytes()
    inline std::atomic<std::size_t> liveBytes{0};
    inline std::atomic<std::size_t> peakBytes{0};

    /// starts a new peak: peakBytes = liveBytes
    inline void resetPeakBytes()
    {
        peakBytes.store(liveBytes.load());
    }

    inline void countAllocation(void *p)
    {
        allocationCount.fetch_add(1, std::memory_order_relaxed);
        const std::size_t live =
            liveBytes.fetch_add(malloc_usable_size(p), std::memory_order_relaxed) + malloc_usable_size(p);
        std::size_t peak = peakBytes.load(std::memory_order_relaxed);
        while (live > peak && !peakBytes.compare_exchange_weak(peak, live, std::memory_order_relaxed))
        {
        }
    }

    inline void countRelease(void *p)
    {
        if (p != nullptr)
            liveBytes.fetch_sub(malloc_usable_size(p), std::memory_order_relaxed);
    }
}  // namespace ropras::test

// None of the replacements is inlined: GCC 12 would otherwise pair malloc with operator delete and warn
// (-Wmismatched-new-delete).
#ifndef ROPRAS_ALLOCATION_COUNTER_ONLY
[[gnu::noinline]] void *operator new(std::size_t size)
{
    if (void *p = std::malloc(size == 0 ? 1 : size))
    {
        ropras::test::countAllocation(p);
        return p;
    }
    throw std::bad_alloc();
}

[[gnu::noinline]] void operator delete(void *p) noexcept
{
    ropras::test::countRelease(p);
    std::free(p);
}

[[gnu::noinline]] void operator delete(void *p, std::size_t) noexcept
{
    ropras::test::countRelease(p);
    std::free(p);
}
#endif

#endif
