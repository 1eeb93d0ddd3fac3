#include "SvgPicture.h"

#include <algorithm>
#include <cmath>
#include <cstdio>

namespace ropras::scenarios::detail
{
    std::string num(double v)
    {
        char buffer[32];
        std::snprintf(buffer, sizeof(buffer), "%.2f", v);
        return buffer;
    }

    std::string xmlEscape(const std::string &text)
    {
        std::string out;
        for (const char c : text)
        {
            switch (c)
            {
                case '&':
                    out += "&amp;";
                    break;
                case '<':
                    out += "&lt;";
                    break;
                case '>':
                    out += "&gt;";
                    break;
                case '"':
                    out += "&quot;";
                    break;
                default:
                    out += (static_cast<unsigned char>(c) < 0x20 && c != '\t' && c != '\n') ? ' ' : c;
            }
        }
        return out;
    }

    double niceStep(double span)
    {
        const double raw = std::max(span, 1e-9) / 8.0;
        const double p = std::pow(10.0, std::floor(std::log10(raw)));
        const double m = raw / p;
        return (m < 1.5 ? 1.0 : m < 3.5 ? 2.0 : m < 7.5 ? 5.0 : 10.0) * p;
    }

    std::string timeColour(double t)
    {
        static const double stops[][3] = {{68, 1, 84}, {59, 82, 139}, {33, 145, 140}, {94, 201, 98}, {253, 231, 37}};
        t = std::clamp(std::isfinite(t) ? t : 0.0, 0.0, 1.0) * 4.0;
        const int i = std::min(3, static_cast<int>(t));
        const double w = t - i;
        char buffer[8];
        std::snprintf(buffer, sizeof(buffer), "#%02x%02x%02x",
                      static_cast<int>(std::lround(stops[i][0] + w * (stops[i + 1][0] - stops[i][0]))),
                      static_cast<int>(std::lround(stops[i][1] + w * (stops[i + 1][1] - stops[i][1]))),
                      static_cast<int>(std::lround(stops[i][2] + w * (stops[i + 1][2] - stops[i][2]))));
        return buffer;
    }

    void drawAxes(std::ostringstream &svg, const SvgFrame &f)
    {
        const char *names = "xyz";
        svg << "<g class=\"axes\" font-size=\"10\" fill=\"#333333\" stroke=\"#333333\" stroke-width=\"0.8\">\n";
        for (const int axis : {f.u, f.v})
        {
            const double step = niceStep(f.hi[axis] - f.lo[axis]);
            const double first = std::ceil(f.lo[axis] / step - 1e-9) * step;
            for (double w = first; w <= f.hi[axis] + 1e-9 * step; w += step)
            {
                const double value = std::abs(w) < 1e-9 * step ? 0.0 : w;
                char label[32];
                std::snprintf(label, sizeof(label), "%g", value);
                if (axis == f.u)
                {
                    const double x = f.x(value), y = f.top + f.height();
                    svg << "<line class=\"tick\" x1=\"" << num(x) << "\" y1=\"" << num(y) << "\" x2=\"" << num(x)
                        << "\" y2=\"" << num(y + 5) << "\"/>\n<text stroke=\"none\" text-anchor=\"middle\" x=\""
                        << num(x) << "\" y=\"" << num(y + 16) << "\">" << label << "</text>\n";
                }
                else
                {
                    const double x = f.left, y = f.y(value);
                    svg << "<line class=\"tick\" x1=\"" << num(x - 5) << "\" y1=\"" << num(y) << "\" x2=\"" << num(x)
                        << "\" y2=\"" << num(y) << "\"/>\n<text stroke=\"none\" text-anchor=\"end\" x=\"" << num(x - 7)
                        << "\" y=\"" << num(y + 3.5) << "\">" << label << "</text>\n";
                }
            }
        }
        svg << "<text class=\"axis-name\" stroke=\"none\" text-anchor=\"middle\" x=\"" << num(f.left + 0.5 * f.width())
            << "\" y=\"" << num(f.top + f.height() + 29) << "\">" << names[f.u] << " (m)</text>\n";
        svg << "<text class=\"axis-name\" stroke=\"none\" text-anchor=\"middle\" transform=\"translate("
            << num(f.left - 44) << " " << num(f.top + 0.5 * f.height()) << ") rotate(-90)\">" << names[f.v]
            << " (m)</text>\n";
        svg << "<text class=\"view-name\" stroke=\"none\" text-anchor=\"end\" x=\"" << num(f.left + f.width() - 4)
            << "\" y=\"" << num(f.top + 12) << "\">" << f.name << "</text>\n";
        svg << "</g>\n";
    }

    void drawPath(std::ostringstream &svg, const SvgFrame &f, const std::vector<Point> &path, const std::string &colour,
                  const std::string &label, double jump)
    {
        if (path.empty())
            return;
        const auto gap = [&](std::size_t t)
        { return std::hypot(path[t][f.u] - path[t - 1][f.u], path[t][f.v] - path[t - 1][f.v]); };
        std::size_t begin = 0;
        double length = 0.0;
        while (begin < path.size())
        {
            std::size_t stop = begin + 1;
            while (stop < path.size() && gap(stop) <= jump)
            {
                length += gap(stop);
                ++stop;
            }
            svg << "<polyline class=\"path\" data-label=\"" << label << "\" fill=\"none\" stroke=\"" << colour
                << "\" stroke-width=\"2\" stroke-linejoin=\"round\" points=\"";
            for (std::size_t t = begin; t < stop; ++t)
            {
                svg << (t > begin ? " " : "") << num(f.x(path[t][f.u])) << "," << num(f.y(path[t][f.v]));
            }
            svg << "\"/>\n";
            begin = stop;
        }
        svg << "<circle class=\"path-start\" cx=\"" << num(f.x(path[0][f.u])) << "\" cy=\"" << num(f.y(path[0][f.v]))
            << "\" r=\"4\" fill=\"#ffffff\" stroke=\"" << colour << "\" stroke-width=\"1.5\"/>\n";
        // arrowheads at 1/9 ... 8/9 of the length, pointing along the segment they sit on
        if (length <= 0.0)
            return;
        double walked = 0.0;
        int next = 1;
        for (std::size_t t = 1; t < path.size() && next <= 8; ++t)
        {
            const double d = gap(t);
            if (d > jump || d <= 0.0)
                continue;
            while (next <= 8 && walked + d >= length * next / 9.0)
            {
                const double s = (length * next / 9.0 - walked) / d;
                const double px = f.x(path[t - 1][f.u] + s * (path[t][f.u] - path[t - 1][f.u]));
                const double py = f.y(path[t - 1][f.v] + s * (path[t][f.v] - path[t - 1][f.v]));
                const double ax = f.x(path[t][f.u]) - f.x(path[t - 1][f.u]);
                const double ay = f.y(path[t][f.v]) - f.y(path[t - 1][f.v]);
                const double n = std::hypot(ax, ay);
                if (n > 0.0)
                {
                    const double ux = ax / n, uy = ay / n;
                    svg << "<polygon class=\"arrow\" fill=\"" << colour << "\" points=\"" << num(px + 6 * ux) << ","
                        << num(py + 6 * uy) << " " << num(px - 4 * ux - 4 * uy) << "," << num(py - 4 * uy + 4 * ux)
                        << " " << num(px - 4 * ux + 4 * uy) << "," << num(py - 4 * uy - 4 * ux) << "\"/>\n";
                }
                ++next;
            }
            walked += d;
        }
    }

    LabelPlacer::LabelPlacer(double left, double top, double right, double bottom)
        : left_(left), top_(top), right_(right), bottom_(bottom)
    {
    }

    bool LabelPlacer::place(std::ostringstream &svg, double x, double y, const std::string &text)
    {
        const double w = 6.0 * static_cast<double>(text.size()) + 2.0, h = 11.0;
        const double spots[][2] = {{x + 5, y - 5}, {x - 5 - w, y - 5}, {x + 5, y + 5 + h}, {x - 5 - w, y + 5 + h}};
        for (const auto &spot : spots)
        {
            const std::array<double, 4> box{spot[0], spot[1] - h, spot[0] + w, spot[1]};
            if (box[0] < left_ || box[1] < top_ || box[2] > right_ || box[3] > bottom_)
                continue;
            const bool free = std::none_of(taken_.begin(), taken_.end(),
                                           [&](const std::array<double, 4> &o) {
                                               return box[0] < o[2] && o[0] < box[2] && box[1] < o[3] && o[1] < box[3];
                                           });
            if (!free)
                continue;
            taken_.push_back(box);
            svg << "<text class=\"time-label\" x=\"" << num(box[0]) << "\" y=\"" << num(box[3] - 2)
                << "\" font-size=\"10\" fill=\"#000000\">" << xmlEscape(text) << "</text>\n";
            return true;
        }
        return false;
    }

    Legend layoutLegend(const std::vector<LegendEntry> &entries, double left, double top, double right)
    {
        Legend out;
        double x = left, y = top + 12.0;
        for (const auto &e : entries)
        {
            const double w = 24.0 + 7.0 * static_cast<double>(e.name.size());
            if (x > left && x + w > right)
            {
                x = left;
                y += 18.0;
            }
            out.at.push_back({x, y});
            x += w;
        }
        out.bottom = y + 6.0;
        return out;
    }

    void drawLegend(std::ostringstream &svg, const std::vector<LegendEntry> &entries, const Legend &layout)
    {
        svg << "<g id=\"legend\" font-size=\"12\">\n";
        for (std::size_t i = 0; i < entries.size(); ++i)
        {
            const double x = layout.at[i][0], y = layout.at[i][1];
            svg << "<rect x=\"" << num(x) << "\" y=\"" << num(y - 10) << "\" width=\"12\" height=\"12\" fill=\""
                << entries[i].colour << "\"/>\n<text x=\"" << num(x + 16) << "\" y=\"" << num(y) << "\">"
                << xmlEscape(entries[i].name) << "</text>\n";
        }
        svg << "</g>\n";
    }

    void drawTimeGradient(std::ostringstream &svg, double x, double y, double width, std::size_t first,
                          std::size_t last)
    {
        svg << "<g id=\"time_legend\" font-size=\"11\">\n<defs><linearGradient id=\"time-ramp\">";
        for (int i = 0; i <= 4; ++i)
        {
            svg << "<stop offset=\"" << i * 25 << "%\" stop-color=\"" << timeColour(i / 4.0) << "\"/>";
        }
        svg << "</linearGradient></defs>\n<text x=\"" << num(x) << "\" y=\"" << num(y + 10)
            << "\">belief at step</text>\n<rect x=\"" << num(x + 90) << "\" y=\"" << num(y + 1) << "\" width=\""
            << num(width) << "\" height=\"10\" fill=\"url(#time-ramp)\"/>\n<text class=\"time-first\" x=\""
            << num(x + 90) << "\" y=\"" << num(y + 23) << "\">" << first << "</text>\n<text class=\"time-last\" x=\""
            << num(x + 90 + width) << "\" y=\"" << num(y + 23) << "\" text-anchor=\"end\">" << last
            << "</text>\n</g>\n";
    }
}  // namespace ropras::scenarios::detail
