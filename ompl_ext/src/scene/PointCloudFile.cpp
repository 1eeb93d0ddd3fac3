#include "ropras/ompl_ext/scene/PointCloudFile.h"

#include <algorithm>
#include <cctype>
#include <charconv>
#include <cmath>
#include <filesystem>
#include <sstream>

#include "ropras/core/Error.h"
#include "ropras/core/InputFile.h"
#include "scene/PointCloudFormats.h"

namespace ropras::ompl_ext
{
    namespace point_cloud_formats
    {
        bool nextLine(std::string_view text, std::size_t &pos, std::string_view &line)
        {
            if (pos >= text.size())
                return false;
            const std::size_t end = std::min(text.find('\n', pos), text.size());
            line = text.substr(pos, end - pos);
            if (!line.empty() && line.back() == '\r')
                line.remove_suffix(1);
            pos = end + 1;
            return true;
        }

        std::vector<std::string_view> words(std::string_view line)
        {
            std::vector<std::string_view> out;
            std::size_t i = 0;
            while (i < line.size())
            {
                while (i < line.size() && std::isspace(static_cast<unsigned char>(line[i])))
                    ++i;
                const std::size_t start = i;
                while (i < line.size() && !std::isspace(static_cast<unsigned char>(line[i])))
                    ++i;
                if (i > start)
                    out.push_back(line.substr(start, i - start));
            }
            return out;
        }

        bool parseNumber(std::string_view word, double &value)
        {
            if (!word.empty() && word.front() == '+')
                word.remove_prefix(1);
            const auto [end, ec] = std::from_chars(word.data(), word.data() + word.size(), value);
            return !word.empty() && ec == std::errc() && end == word.data() + word.size();
        }

        bool parseCount(std::string_view word, std::uint64_t &value)
        {
            const auto [end, ec] = std::from_chars(word.data(), word.data() + word.size(), value);
            return !word.empty() && ec == std::errc() && end == word.data() + word.size() &&
                   value < (std::uint64_t(1) << 63);
        }

        void addPoint(double x, double y, double z, std::uint64_t index, const std::string &source,
                      const PointCloudFileOptions &options, std::vector<Eigen::Vector3f> &out)
        {
            const Eigen::Vector3f p(static_cast<float>(x), static_cast<float>(y), static_cast<float>(z));
            if (p.allFinite())
            {
                out.push_back(p);
                return;
            }
            if (options.dropNonFinite)
                return;
            std::ostringstream msg;
            msg << "point cloud '" << source << "': point " << index << " is (" << x << ", " << y << ", " << z
                << "), not finite" << (std::isfinite(x) && std::isfinite(y) && std::isfinite(z) ? " as a float" : "")
                << " (an organized cloud's missing return? set drop_non_finite to drop such points)";
            throw Error(msg.str());
        }
    }  // namespace point_cloud_formats

    std::vector<Eigen::Vector3f> loadPointCloudFile(const std::string &path, const PointCloudFileOptions &options)
    {
        std::string extension = std::filesystem::path(path).extension().string();
        std::transform(extension.begin(), extension.end(), extension.begin(),
                       [](unsigned char c) { return char(std::tolower(c)); });
        if (extension != ".pcd" && extension != ".ply")
            throw Error("point cloud '" + path + "': unknown format '" + extension +
                        "' (expected a .pcd or .ply file)");
        const std::string data = readInputFile(path, "point cloud");
        return extension == ".pcd" ? point_cloud_formats::readPcd(data, path, options)
                                   : point_cloud_formats::readPly(data, path, options);
    }
}  // namespace ropras::ompl_ext
