#ifndef ROPRAS_OMPL_EXT_SRC_POINT_CLOUD_FORMATS_H
#define ROPRAS_OMPL_EXT_SRC_POINT_CLOUD_FORMATS_H

#include <Eigen/Core>
#include <cstddef>
#include <cstdint>
#include <cstring>
#include <string>
#include <string_view>
#include <vector>

#include "ropras/ompl_ext/scene/PointCloudFile.h"

namespace ropras::ompl_ext::point_cloud_formats
{
    /// a scalar type of a binary record: integer (signed or not) or floating, of 1, 2, 4 or 8 bytes
    struct ScalarType
    {
        char kind{'F'};  ///< 'I' signed, 'U' unsigned, 'F' floating
        int size{4};
    };

    /// the \a T stored at \a b (any alignment)
    template <typename T>
    double loadScalar(const unsigned char *b)
    {
        T v;
        std::memcpy(&v, b, sizeof(T));
        return static_cast<double>(v);
    }

    /// the value at \a p (\a swap: the file's byte order is not the machine's)
    inline double readScalar(const unsigned char *p, ScalarType type, bool swap)
    {
        unsigned char b[8];
        for (int i = 0; i < type.size; ++i)
            b[i] = p[swap ? type.size - 1 - i : i];
        if (type.kind == 'F')
            return type.size == 4 ? loadScalar<float>(b) : loadScalar<double>(b);
        const bool s = type.kind == 'I';
        switch (type.size)
        {
            case 1:
                return s ? loadScalar<std::int8_t>(b) : loadScalar<std::uint8_t>(b);
            case 2:
                return s ? loadScalar<std::int16_t>(b) : loadScalar<std::uint16_t>(b);
            case 4:
                return s ? loadScalar<std::int32_t>(b) : loadScalar<std::uint32_t>(b);
            default:
                return s ? loadScalar<std::int64_t>(b) : loadScalar<std::uint64_t>(b);
        }
    }

    /// the next line of \a text from \a pos (without "\n" or "\r\n"); false at the end
    bool nextLine(std::string_view text, std::size_t &pos, std::string_view &line);
    /// the whitespace-separated words of \a line
    std::vector<std::string_view> words(std::string_view line);
    /// \a word as a number (decimal, nan, inf); false when it is not one
    bool parseNumber(std::string_view word, double &value);
    /// \a word as a count in [0, 2^63); false when it is not one
    bool parseCount(std::string_view word, std::uint64_t &value);

    /** \brief Appends the point to \a out, or drops it (options.dropNonFinite) or throws naming \a source and
        point \a index when a coordinate is NaN or infinite. */
    void addPoint(double x, double y, double z, std::uint64_t index, const std::string &source,
                  const PointCloudFileOptions &options, std::vector<Eigen::Vector3f> &out);

    std::vector<Eigen::Vector3f> readPcd(const std::string &data, const std::string &source,
                                         const PointCloudFileOptions &options);
    std::vector<Eigen::Vector3f> readPly(const std::string &data, const std::string &source,
                                         const PointCloudFileOptions &options);
}  // namespace ropras::ompl_ext::point_cloud_formats

#endif
