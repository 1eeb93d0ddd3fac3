// PCL's PCD format (https://pointclouds.org/documentation/tutorials/pcd_file_format.html): a text header, then the
// points as text lines or as packed binary records.
#include <array>
#include <map>

#include "ropras/core/Error.h"
#include "ropras/core/MemoryLimit.h"
#include "scene/PointCloudFormats.h"

namespace ropras::ompl_ext::point_cloud_formats
{
    namespace
    {
        /// the most values one field of a point may have
        constexpr std::uint64_t MAX_COUNT = 1 << 16;

        /// the header: one entry per field, the point count and where the data starts
        struct PcdHeader
        {
            std::vector<std::string> fields;
            std::vector<ScalarType> types;
            std::vector<std::uint64_t> counts;
            std::uint64_t width{0}, height{1}, points{0};
            bool pointsGiven{false};
            std::string data;
            std::size_t dataStart{0};
            int dataLine{0};
        };

        class PcdParser
        {
        public:
            PcdParser(const std::string &text, const std::string &source) : text_(text), source_(source) {}

            [[noreturn]] void fail(int line, const std::string &what) const
            {
                throw Error("point cloud '" + source_ + "'" + (line > 0 ? ":" + std::to_string(line) : "") + ": " +
                            what);
            }

            PcdHeader header()
            {
                PcdHeader h;
                std::size_t pos = 0;
                std::string_view line;
                std::map<std::string, int> seen;
                std::vector<std::string_view> sizes, types;
                for (int number = 1; nextLine(text_, pos, line); ++number)
                {
                    const std::vector<std::string_view> w = words(line);
                    if (w.empty() || w[0].front() == '#')
                        continue;
                    const std::string key(w[0]);
                    if (!seen.emplace(key, number).second)
                        fail(number, key + " given twice (first on line " + std::to_string(seen[key]) + ")");
                    const std::vector<std::string_view> values(w.begin() + 1, w.end());
                    if (key == "VERSION" || key == "VIEWPOINT")
                        continue;  // the viewpoint is the sensor pose; PCL does not apply it to the points
                    if (key == "FIELDS")
                        for (std::string_view v : values)
                            h.fields.emplace_back(v);
                    else if (key == "SIZE")
                        sizes = values;
                    else if (key == "TYPE")
                        types = values;
                    else if (key == "COUNT")
                        for (std::string_view v : values)
                            h.counts.push_back(count(number, "COUNT", v));
                    else if (key == "WIDTH" || key == "HEIGHT" || key == "POINTS")
                    {
                        if (values.size() != 1)
                            fail(number, key + " takes one count");
                        (key == "WIDTH"    ? h.width
                         : key == "HEIGHT" ? h.height
                                           : h.points) = count(number, key, values[0]);
                        h.pointsGiven = h.pointsGiven || key == "POINTS";
                    }
                    else if (key == "DATA")
                    {
                        if (values.size() != 1)
                            fail(number, "DATA takes one word (ascii or binary)");
                        h.data = std::string(values[0]);
                        h.dataStart = pos;
                        h.dataLine = number + 1;
                        finish(h, sizes, types, seen);
                        return h;
                    }
                    else
                        fail(number, "unknown header line '" + key +
                                         "' (not a PCD file? expected VERSION, FIELDS, SIZE, TYPE, COUNT, WIDTH, "
                                         "HEIGHT, VIEWPOINT, POINTS, DATA)");
                }
                fail(0, "no DATA line: not a PCD file, or its header is cut short");
            }

        private:
            std::uint64_t count(int line, const std::string &key, std::string_view word) const
            {
                std::uint64_t value = 0;
                if (!parseCount(word, value))
                    fail(line, key + ": '" + std::string(word) + "' is not a whole number");
                return value;
            }

            void finish(PcdHeader &h, const std::vector<std::string_view> &sizes,
                        const std::vector<std::string_view> &types, const std::map<std::string, int> &seen) const
            {
                const auto lineOf = [&](const char *key) { return seen.count(key) ? seen.at(key) : 0; };
                if (h.fields.empty())
                    fail(lineOf("DATA"), "no FIELDS line");
                if (h.counts.empty())
                    h.counts.assign(h.fields.size(), 1);
                if (sizes.size() != h.fields.size() || types.size() != h.fields.size() ||
                    h.counts.size() != h.fields.size())
                    fail(lineOf("FIELDS"), std::to_string(h.fields.size()) + " FIELDS but " +
                                               std::to_string(sizes.size()) + " SIZE, " + std::to_string(types.size()) +
                                               " TYPE and " + std::to_string(h.counts.size()) + " COUNT entries");
                for (std::size_t i = 0; i < h.fields.size(); ++i)
                {
                    if (h.counts[i] > MAX_COUNT)
                        fail(lineOf("COUNT"), "field '" + h.fields[i] + "' has COUNT " + std::to_string(h.counts[i]) +
                                                  " (at most " + std::to_string(MAX_COUNT) + ")");
                    const std::string type(types[i]);
                    const std::string size(sizes[i]);
                    ScalarType t{type.size() == 1 ? type[0] : '?', size.size() == 1 ? size[0] - '0' : 0};
                    const bool sizeOk = t.size == 1 || t.size == 2 || t.size == 4 || t.size == 8;
                    if ((t.kind != 'I' && t.kind != 'U' && t.kind != 'F') || !sizeOk ||
                        (t.kind == 'F' && t.size != 4 && t.size != 8))
                        fail(lineOf("TYPE"), "field '" + h.fields[i] + "' has TYPE " + type + " SIZE " + size +
                                                 " (expected I or U of 1, 2, 4 or 8 bytes, or F of 4 or 8)");
                    h.types.push_back(t);
                }
                if (!h.pointsGiven)
                    h.points = h.width * h.height;
                if (h.width > (std::uint64_t(1) << 40) || h.height > (std::uint64_t(1) << 20) ||
                    h.width * h.height != h.points)
                    fail(lineOf("POINTS"), "WIDTH " + std::to_string(h.width) + " x HEIGHT " +
                                               std::to_string(h.height) + " is not POINTS " + std::to_string(h.points));
            }

            const std::string &text_;
            const std::string &source_;
        };

        /// index of field \a name among the header's fields (which must have COUNT 1), -1 when absent
        int fieldIndex(const PcdHeader &h, const std::string &name)
        {
            for (std::size_t i = 0; i < h.fields.size(); ++i)
                if (h.fields[i] == name)
                    return h.counts[i] == 1 ? static_cast<int>(i) : -2;
            return -1;
        }
    }  // namespace

    std::vector<Eigen::Vector3f> readPcd(const std::string &text, const std::string &source,
                                         const PointCloudFileOptions &options)
    {
        PcdParser parser(text, source);
        const PcdHeader h = parser.header();
        std::array<int, 3> xyz{};
        for (int k = 0; k < 3; ++k)
        {
            const std::string name(1, char('x' + k));
            xyz[k] = fieldIndex(h, name);
            if (xyz[k] < 0)
                parser.fail(0, xyz[k] == -1 ? "no field '" + name + "' (FIELDS must include x y z)"
                                            : "field '" + name + "' has a COUNT other than 1");
        }
        std::vector<Eigen::Vector3f> points;
        const std::size_t available = text.size() - std::min(text.size(), h.dataStart);
        if (h.data == "ascii")
        {
            // every point is a line of at least one character per value and a separator
            std::uint64_t values = 0;
            for (std::uint64_t c : h.counts)
                values += c;
            if (h.points > available / std::max<std::uint64_t>(1, 2 * values - 1))
                parser.fail(h.dataLine, "POINTS " + std::to_string(h.points) + " ascii points of " +
                                            std::to_string(values) + " values cannot fit in the " +
                                            std::to_string(available) + " bytes of data");
            checkedBytes(h.points, sizeof(Eigen::Vector3f), "point cloud '" + source + "'");
            points.reserve(h.points);
            std::size_t pos = h.dataStart;
            std::string_view line;
            int number = h.dataLine;
            for (std::uint64_t i = 0; i < h.points; ++number)
            {
                if (!nextLine(text, pos, line))
                    parser.fail(number, "the data ends after " + std::to_string(i) + " of POINTS " +
                                            std::to_string(h.points) + " points");
                const std::vector<std::string_view> w = words(line);
                if (w.empty())
                    continue;
                if (w.size() != values)
                    parser.fail(number, "point " + std::to_string(i) + " has " + std::to_string(w.size()) +
                                            " values, the header gives " + std::to_string(values));
                double v[3];
                for (int k = 0; k < 3; ++k)
                {
                    std::size_t column = 0;
                    for (int f = 0; f < xyz[k]; ++f)
                        column += h.counts[f];
                    if (!parseNumber(w[column], v[k]))
                        parser.fail(number, "point " + std::to_string(i) + ": '" + std::string(w[column]) +
                                                "' is not a number");
                }
                addPoint(v[0], v[1], v[2], i, source, options, points);
                ++i;
            }
            while (nextLine(text, pos, line))
                if (!words(line).empty())
                    parser.fail(number, "data after the POINTS " + std::to_string(h.points) + " points");
                else
                    ++number;
            return points;
        }
        if (h.data != "binary")
            parser.fail(h.dataLine - 1,
                        "DATA " + h.data +
                            " is not supported (ascii or binary; convert binary_compressed files with PCL's "
                            "pcl_convert_pcd_ascii_binary)");
        std::vector<std::size_t> offset(h.fields.size() + 1, 0);
        for (std::size_t f = 0; f < h.fields.size(); ++f)
            offset[f + 1] = offset[f] + std::size_t(h.types[f].size) * h.counts[f];
        const std::uint64_t record = offset.back();
        if (h.points > available / record)
            parser.fail(h.dataLine, "POINTS " + std::to_string(h.points) + " binary points of " +
                                        std::to_string(record) + " bytes do not fit in the " +
                                        std::to_string(available) + " bytes of data");
        if (h.points * record != available)
            parser.fail(h.dataLine, "POINTS " + std::to_string(h.points) + " binary points of " +
                                        std::to_string(record) + " bytes are " + std::to_string(h.points * record) +
                                        " bytes of data, the file holds " + std::to_string(available) +
                                        " (trailing data)");
        checkedBytes(h.points, sizeof(Eigen::Vector3f), "point cloud '" + source + "'");
        points.reserve(h.points);
        const auto *data = reinterpret_cast<const unsigned char *>(text.data()) + h.dataStart;
        for (std::uint64_t i = 0; i < h.points; ++i)
        {
            const unsigned char *p = data + i * record;
            addPoint(readScalar(p + offset[xyz[0]], h.types[xyz[0]], false),
                     readScalar(p + offset[xyz[1]], h.types[xyz[1]], false),
                     readScalar(p + offset[xyz[2]], h.types[xyz[2]], false), i, source, options, points);
        }
        return points;
    }
}  // namespace ropras::ompl_ext::point_cloud_formats
