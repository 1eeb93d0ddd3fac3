// The PLY format (Greg Turk's, as in http://paulbourke.net/dataformats/ply/): a text header of elements and their
// properties, then every element's instances as text or as binary records of either byte order.
#include <algorithm>
#include <array>
#include <cctype>

#include "ropras/core/Error.h"
#include "ropras/core/MemoryLimit.h"
#include "scene/PointCloudFormats.h"

namespace ropras::ompl_ext::point_cloud_formats
{
    namespace
    {
        struct PlyProperty
        {
            std::string name;
            ScalarType type;
            bool list{false};
            ScalarType countType;  ///< the type of a list's length
        };

        struct PlyElement
        {
            std::string name;
            std::uint64_t count{0};
            std::vector<PlyProperty> properties;
            int line{0};
        };

        bool scalarType(std::string_view word, ScalarType &type)
        {
            static const std::array<std::pair<const char *, ScalarType>, 16> TYPES{{
                {"char", {'I', 1}},
                {"int8", {'I', 1}},
                {"uchar", {'U', 1}},
                {"uint8", {'U', 1}},
                {"short", {'I', 2}},
                {"int16", {'I', 2}},
                {"ushort", {'U', 2}},
                {"uint16", {'U', 2}},
                {"int", {'I', 4}},
                {"int32", {'I', 4}},
                {"uint", {'U', 4}},
                {"uint32", {'U', 4}},
                {"float", {'F', 4}},
                {"float32", {'F', 4}},
                {"double", {'F', 8}},
                {"float64", {'F', 8}},
            }};
            for (const auto &[name, t] : TYPES)
                if (word == name)
                {
                    type = t;
                    return true;
                }
            return false;
        }

        class PlyParser
        {
        public:
            PlyParser(const std::string &text, const std::string &source) : text_(text), source_(source) {}

            [[noreturn]] void fail(int line, const std::string &what) const
            {
                throw Error("point cloud '" + source_ + "'" + (line > 0 ? ":" + std::to_string(line) : "") + ": " +
                            what);
            }

            /// the elements; \a format "ascii", "binary_little_endian" or "binary_big_endian"
            std::vector<PlyElement> header(std::string &format, std::size_t &dataStart, int &dataLine) const
            {
                std::size_t pos = 0;
                std::string_view line;
                if (!nextLine(text_, pos, line) || line != "ply")
                    fail(1, "not a PLY file (the first line must be 'ply')");
                std::vector<PlyElement> elements;
                for (int number = 2; nextLine(text_, pos, line); ++number)
                {
                    const std::vector<std::string_view> w = words(line);
                    if (w.empty() || w[0] == "comment" || w[0] == "obj_info")
                        continue;
                    if (w[0] == "end_header")
                    {
                        if (format.empty())
                            fail(number, "no format line before end_header");
                        dataStart = pos;
                        dataLine = number + 1;
                        return elements;
                    }
                    if (w[0] == "format")
                    {
                        if (w.size() != 3 ||
                            (w[1] != "ascii" && w[1] != "binary_little_endian" && w[1] != "binary_big_endian"))
                            fail(number, "expected 'format ascii|binary_little_endian|binary_big_endian 1.0'");
                        format = std::string(w[1]);
                    }
                    else if (w[0] == "element")
                    {
                        std::uint64_t count = 0;
                        if (w.size() != 3 || !parseCount(w[2], count))
                            fail(number, "expected 'element <name> <count>'");
                        elements.push_back({std::string(w[1]), count, {}, number});
                    }
                    else if (w[0] == "property")
                    {
                        if (elements.empty())
                            fail(number, "a property before any element");
                        PlyProperty p;
                        const bool list = w.size() == 5 && w[1] == "list";
                        if (list
                                ? !scalarType(w[2], p.countType) || p.countType.kind == 'F' || !scalarType(w[3], p.type)
                                : w.size() != 3 || !scalarType(w[1], p.type))
                            fail(number,
                                 "expected 'property <type> <name>' or 'property list <integer type> <type> "
                                 "<name>' (types: char, uchar, short, ushort, int, uint, float, double)");
                        p.list = list;
                        p.name = std::string(w.back());
                        elements.back().properties.push_back(p);
                    }
                    else
                        fail(number, "unknown header line '" + std::string(w[0]) + "'");
                }
                fail(0, "no end_header line: the header is cut short");
            }

        private:
            const std::string &text_;
            const std::string &source_;
        };

        /// reads the values of one element's instances, as text or binary, checking every bound
        class PlyData
        {
        public:
            PlyData(const PlyParser &parser, const std::string &text, std::size_t start, int line,
                    const std::string &format)
                : parser_(parser),
                  text_(text),
                  pos_(start),
                  line_(line),
                  ascii_(format == "ascii"),
                  swap_(format == "binary_big_endian")
            {
            }

            /// fails unless \a element's instances can fit in the data left (before anything is allocated)
            void checkFits(const PlyElement &element) const
            {
                std::uint64_t least = 0;  // bytes of one instance, at least (text: a character and a space each)
                for (const PlyProperty &p : element.properties)
                    least += ascii_ ? 2 : p.list ? p.countType.size : p.type.size;
                const std::uint64_t left = text_.size() - std::min(text_.size(), pos_);
                if (least > 0 && element.count > left / least)
                    parser_.fail(element.line, "element " + element.name + " " + std::to_string(element.count) +
                                                   ": that many instances cannot fit in the " + std::to_string(left) +
                                                   " bytes of data left");
            }

            double value(ScalarType type, const std::string &what)
            {
                if (!ascii_)
                {
                    if (text_.size() - std::min(text_.size(), pos_) < std::size_t(type.size))
                        parser_.fail(0, "the binary data ends inside " + what);
                    const double v =
                        readScalar(reinterpret_cast<const unsigned char *>(text_.data()) + pos_, type, swap_);
                    pos_ += type.size;
                    return v;
                }
                const std::string_view word = nextWord(what);
                double v = 0.0;
                if (!parseNumber(word, v))
                    parser_.fail(line_, what + ": '" + std::string(word) + "' is not a number");
                return v;
            }

            /// one instance's values of the scalar properties (lists are read and dropped)
            void instance(const PlyElement &element, std::uint64_t index, std::vector<double> &out)
            {
                out.clear();
                const std::string what = element.name + " " + std::to_string(index);
                for (const PlyProperty &p : element.properties)
                {
                    if (!p.list)
                    {
                        out.push_back(value(p.type, what + " property " + p.name));
                        continue;
                    }
                    const double n = value(p.countType, what + " list " + p.name);
                    if (n < 0 || n > 1e6)
                        parser_.fail(line_, what + " list " + p.name + " has length " + std::to_string(n));
                    for (int k = 0; k < int(n); ++k)
                        value(p.type, what + " list " + p.name);
                    out.push_back(0.0);
                }
                if (ascii_)
                    endLine(what);
            }

            void end() const
            {
                const std::string_view rest = std::string_view(text_).substr(std::min(text_.size(), pos_));
                if (ascii_ ? !words(rest).empty() : !rest.empty())
                    parser_.fail(ascii_ ? line_ : 0,
                                 "data after the last element (" + std::to_string(rest.size()) + " bytes)");
            }

        private:
            std::string_view nextWord(const std::string &what)
            {
                while (pos_ < text_.size() && (text_[pos_] == ' ' || text_[pos_] == '\t' || text_[pos_] == '\r'))
                    ++pos_;
                const std::size_t start = pos_;
                while (pos_ < text_.size() && !std::isspace(static_cast<unsigned char>(text_[pos_])))
                    ++pos_;
                if (pos_ == start)
                    parser_.fail(line_, pos_ >= text_.size() ? "the data ends inside " + what
                                                             : what + ": the line ends before its values do");
                return std::string_view(text_).substr(start, pos_ - start);
            }

            /// an instance is one line of text
            void endLine(const std::string &what)
            {
                while (pos_ < text_.size() && (text_[pos_] == ' ' || text_[pos_] == '\t' || text_[pos_] == '\r'))
                    ++pos_;
                if (pos_ < text_.size() && text_[pos_] != '\n')
                    parser_.fail(line_, what + ": more values on the line than its properties");
                ++pos_;
                ++line_;
            }

            const PlyParser &parser_;
            const std::string &text_;
            std::size_t pos_;
            int line_;
            bool ascii_, swap_;
        };
    }  // namespace

    std::vector<Eigen::Vector3f> readPly(const std::string &text, const std::string &source,
                                         const PointCloudFileOptions &options)
    {
        const PlyParser parser(text, source);
        std::string format;
        std::size_t start = 0;
        int line = 0;
        const std::vector<PlyElement> elements = parser.header(format, start, line);
        const auto vertex =
            std::find_if(elements.begin(), elements.end(), [](const PlyElement &e) { return e.name == "vertex"; });
        if (vertex == elements.end())
            parser.fail(0, "no 'vertex' element");
        std::array<int, 3> xyz{-1, -1, -1};
        for (std::size_t i = 0; i < vertex->properties.size(); ++i)
            for (int k = 0; k < 3; ++k)
                if (vertex->properties[i].name == std::string(1, char('x' + k)) && !vertex->properties[i].list)
                    xyz[k] = static_cast<int>(i);
        for (int k = 0; k < 3; ++k)
            if (xyz[k] < 0)
                parser.fail(vertex->line, "the vertex element has no scalar property " + std::string(1, char('x' + k)));

        PlyData data(parser, text, start, line, format);
        std::vector<Eigen::Vector3f> points;
        std::vector<double> values;
        for (const PlyElement &element : elements)
        {
            data.checkFits(element);
            if (&element == &*vertex)
            {
                checkedBytes(element.count, sizeof(Eigen::Vector3f), "point cloud '" + source + "'");
                points.reserve(element.count);
            }
            for (std::uint64_t i = 0; i < element.count; ++i)
            {
                data.instance(element, i, values);
                if (&element == &*vertex)
                    addPoint(values[xyz[0]], values[xyz[1]], values[xyz[2]], i, source, options, points);
            }
        }
        data.end();
        return points;
    }
}  // namespace ropras::ompl_ext::point_cloud_formats
