#ifndef ROPRAS_SCENARIOS_COMMON_SVG_FOOTPRINTS_H
#define ROPRAS_SCENARIOS_COMMON_SVG_FOOTPRINTS_H

#include <array>
#include <functional>
#include <nlohmann/json.hpp>
#include <ostream>
#include <string>
#include <vector>

namespace ropras::scenarios::detail
{
    /** \brief The map transform of the SVG renderer: world x, y -> pixels, and pixels per metre. */
    struct SvgMap
    {
        std::function<double(double)> x, y;
        double scale{1.0};
    };

    /** \brief Draws the bodies along the recorded paths that the scene describes (SvgRenderer):
        - "footprint": {"label": L, "polygon": [[x, y], ...]}: the polygon (in the body frame) at every step of
          label L's path, turned by the heading that the path's points carry in z (mobile bases);
        - "discs": {L: r, ...}: a disc of radius r at every step of label L's path (a pedestrian's sphere).
        Labels the recording does not have are ignored. Throws ropras::Error naming \a source and the key for a
        malformed entry. Writes nothing when the scene has neither key. */
    void drawBodies(std::ostream &svg, const nlohmann::json &scene, const std::vector<std::string> &labels,
                    const std::vector<std::vector<std::array<double, 3>>> &paths, const SvgMap &map,
                    const std::string &source);
}  // namespace ropras::scenarios::detail

#endif
