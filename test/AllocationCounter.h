#ifndef ROPRAS_TEST_ALLOCATION_COUNTER_H
#define ROPRAS_TEST_ALLOCATION_COUNTER_H

// Replaces the global operator new / delete of a test executable with counting versions. Include it in exactly
// ONE source file per test executable (the definitions are not inline: replacement functions must not be); other
// files of the same executable define ROPRAS_ALLOCATION_COUNTER_ONLY first and get the counter alone.

#include <atomic>
#include <cstdlib>
#include <new>

namespace ropras::test
{
    /// heap allocations (operator new calls) so far in this process
    inline std::atomic<std::size_t> allocationCount{0};
}  // namespace ropras::test

// None of the replacements is inlined: GCC 12 would otherwise pair malloc with operator delete and warn
// (-Wmismatched-new-delete).
#ifndef ROPRAS_ALLOCATION_COUNTER_ONLY
[[gnu::noinline]] void *operator new(std::size_t size)
{
    ropras::test::allocationCount.fetch_add(1, std::memory_order_relaxed);
    if (void *p = std::malloc(size == 0 ? 1 : size))
    {
        return p;
    }
    throw std::bad_alloc();
}

[[gnu::noinline]] void operator delete(void *p) noexcept
{
    std::free(p);
}

[[gnu::noinline]] void operator delete(void *p, std::size_t) noexcept
{
    std::free(p);
}
#endif

#endif
