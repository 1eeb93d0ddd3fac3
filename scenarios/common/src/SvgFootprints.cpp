#include "SvgFootprints.h"

#include <cmath>
#include <cstdio>

#include "ropras/core/Error.h"

namespace ropras::scenarios::detail
{
    namespace
    {
        std::string num(double v)
        {
            char buffer[32];
            std::snprintf(buffer, sizeof(buffer), "%.2f", v);
            return buffer;
        }

        double finiteNumber(const nlohmann::json &v, const std::string &key, const std::string &source)
        {
            if (!v.is_number() || !std::isfinite(v.get<double>()))
            {
                throw Error(source + ": " + key + " must be a finite number, not " + v.dump());
            }
            return v.get<double>();
        }

        std::size_t labelIndex(const std::vector<std::string> &labels, const std::string &label)
        {
            for (std::size_t k = 0; k < labels.size(); ++k)
            {
                if (labels[k] == label)
                {
                    return k;
                }
            }
            return labels.size();
        }
    }  // namespace

    void drawBodies(std::ostream &svg, const nlohmann::json &scene, const std::vector<std::string> &labels,
                    const std::vector<std::vector<std::array<double, 3>>> &paths, const SvgMap &map,
                    const std::string &source)
    {
        if (scene.contains("discs"))
        {
            const auto &discs = scene["discs"];
            if (!discs.is_object())
            {
                throw Error(source + ": scene.discs must be an object {label: radius}, not " + discs.dump());
            }
            svg << "<g id=\"discs\">\n";
            for (const auto &item : discs.items())
            {
                const double r = finiteNumber(item.value(), "scene.discs." + item.key(), source);
                const std::size_t k = labelIndex(labels, item.key());
                if (k == labels.size() || !(r > 0.0))
                {
                    continue;
                }
                for (const auto &p : paths[k])
                {
                    svg << "<circle cx=\"" << num(map.x(p[0])) << "\" cy=\"" << num(map.y(p[1])) << "\" r=\""
                        << num(r * map.scale) << "\" fill=\"#c2185b\" fill-opacity=\"0.06\" stroke=\"#c2185b\""
                        << " stroke-opacity=\"0.35\" stroke-width=\"0.6\"/>\n";
                }
            }
            svg << "</g>\n";
        }
        if (scene.contains("footprint"))
        {
            const auto &fp = scene["footprint"];
            if (!fp.is_object() || !fp.contains("label") || !fp["label"].is_string() || !fp.contains("polygon") ||
                !fp["polygon"].is_array() || fp["polygon"].size() < 3)
            {
                throw Error(source +
                            ": scene.footprint must be {\"label\": name, \"polygon\": [[x, y], ...] (>= 3)}, not " +
                            fp.dump());
            }
            std::vector<std::array<double, 2>> polygon;
            for (const auto &v : fp["polygon"])
            {
                if (!v.is_array() || v.size() != 2)
                {
                    throw Error(source + ": scene.footprint.polygon has a vertex that is not [x, y]: " + v.dump());
                }
                polygon.push_back({finiteNumber(v[0], "scene.footprint.polygon", source),
                                   finiteNumber(v[1], "scene.footprint.polygon", source)});
            }
            const std::size_t k = labelIndex(labels, fp["label"].get<std::string>());
            if (k == labels.size())
            {
                return;
            }
            svg << "<g id=\"footprint\">\n";
            for (const auto &p : paths[k])
            {
                const double c = std::cos(p[2]), s = std::sin(p[2]);
                svg << "<polygon fill=\"#1a4fa0\" fill-opacity=\"0.05\" stroke=\"#1a4fa0\" stroke-opacity=\"0.4\""
                    << " stroke-width=\"0.6\" points=\"";
                for (std::size_t i = 0; i < polygon.size(); ++i)
                {
                    const double x = p[0] + c * polygon[i][0] - s * polygon[i][1];
                    const double y = p[1] + s * polygon[i][0] + c * polygon[i][1];
                    svg << (i > 0 ? " " : "") << num(map.x(x)) << "," << num(map.y(y));
                }
                svg << "\"/>\n";
                // the heading: a short line from the centre forward
                const double hx = p[0] + 0.15 * c, hy = p[1] + 0.15 * s;
                svg << "<line x1=\"" << num(map.x(p[0])) << "\" y1=\"" << num(map.y(p[1])) << "\" x2=\""
                    << num(map.x(hx)) << "\" y2=\"" << num(map.y(hy)) << "\" stroke=\"#1a4fa0\" stroke-opacity=\"0.6\""
                    << " stroke-width=\"0.8\"/>\n";
            }
            svg << "</g>\n";
        }
    }
}  // namespace ropras::scenarios::detail
