#ifndef ROPRAS_BIN_MEDIAN_H
#define ROPRAS_BIN_MEDIAN_H

#include <algorithm>
#include <cstddef>
#include <limits>
#include <vector>

namespace ropras::bin
{
    /// the median of the benchmark commands' timings (mean of the two middle values for an even count; NaN if empty)
    inline double median(std::vector<double> v)
    {
        if (v.empty())
            return std::numeric_limits<double>::quiet_NaN();
        std::sort(v.begin(), v.end());
        const std::size_t n = v.size();
        return n % 2 == 1 ? v[n / 2] : 0.5 * (v[n / 2 - 1] + v[n / 2]);
    }
}  // namespace ropras::bin

#endif
