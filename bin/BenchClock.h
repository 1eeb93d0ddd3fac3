#ifndef ROPRAS_BIN_BENCH_CLOCK_H
#define ROPRAS_BIN_BENCH_CLOCK_H

#include <time.h>

#include <algorithm>
#include <chrono>
#include <limits>
#include <string>
#include <vector>

#include "Median.h"

#include "ropras/core/Error.h"

namespace ropras::bin
{
    /** \brief The benchmarks' clock: wall (steady_clock) or this thread's CPU time (excludes the time the thread
        waits for a core: use it on a loaded machine). */
    class BenchClock
    {
    public:
        /// "wall" or "cpu"; anything else throws Error naming \a command and the value
        BenchClock(const std::string &name, const std::string &command) : cpu_(name == "cpu")
        {
            if (name != "wall" && name != "cpu")
                throw Error(command + ": unknown --clock '" + name + "' (wall, cpu)");
        }

        double nowNs() const
        {
            if (cpu_)
            {
                timespec t{};
                clock_gettime(CLOCK_THREAD_CPUTIME_ID, &t);
                return 1e9 * static_cast<double>(t.tv_sec) + static_cast<double>(t.tv_nsec);
            }
            return std::chrono::duration<double, std::nano>(std::chrono::steady_clock::now().time_since_epoch())
                .count();
        }

    private:
        bool cpu_;
    };

}  // namespace ropras::bin

#endif
