#ifndef ROPRAS_BIN_PROGRESS_BAR_H
#define ROPRAS_BIN_PROGRESS_BAR_H

#include <algorithm>
#include <cstdio>
#include <iostream>
#include <string>

namespace ropras::bin
{
    /// "42s", "3m07s", "2h05m09s"
    inline std::string formatDuration(double seconds)
    {
        const auto s = static_cast<long long>(seconds + 0.5);
        char buffer[32];
        if (s >= 3600)
            std::snprintf(buffer, sizeof(buffer), "%lldh%02lldm%02llds", s / 3600, (s / 60) % 60, s % 60);
        else if (s >= 60)
            std::snprintf(buffer, sizeof(buffer), "%lldm%02llds", s / 60, s % 60);
        else
            std::snprintf(buffer, sizeof(buffer), "%llds", s);
        return buffer;
    }

    /// the ETA of \a done of \a total items after \a elapsed seconds, at the mean rate so far (0 before the first)
    inline double remainingSeconds(double elapsed, std::size_t done, std::size_t total)
    {
        return done > 0 && total > done ? elapsed / static_cast<double>(done) * static_cast<double>(total - done) : 0.0;
    }

    /// "[#####.........................]" with \a done of \a total filled
    inline std::string progressBar(std::size_t done, std::size_t total, int width = 30)
    {
        const int filled = total == 0 ? width : static_cast<int>(width * std::min(done, total) / total);
        return "[" + std::string(filled, '#') + std::string(width - filled, '.') + "]";
    }
}  // namespace ropras::bin

#endif
