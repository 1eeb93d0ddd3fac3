#ifndef ROPRAS_SCENARIOS_VIEWER_PAGE_H
#define ROPRAS_SCENARIOS_VIEWER_PAGE_H

#include <nlohmann/json.hpp>
#include <string>

namespace ropras::scenarios
{
    /// where Debian's libjs-three puts three.js
    constexpr const char *DEFAULT_THREE_DIR = "/usr/share/javascript/three";

    /** \brief The parts of three.js the viewer page embeds. */
    struct ThreeJs
    {
        std::string library;        ///< three.min.js (the global THREE)
        std::string orbitControls;  ///< examples/js/controls/OrbitControls.js (THREE.OrbitControls)
    };

    /** \brief Reads three.min.js and examples/js/controls/OrbitControls.js from \a dir (Debian's libjs-three);
        throws ropras::Error naming the missing or unreadable file and the package to install. */
    ThreeJs loadThreeJs(const std::string &dir = DEFAULT_THREE_DIR);

    /** \brief One self-contained HTML page (no network, no server) that draws \a view (a document of
        episodeView() or motionView(), doc/viewer.md) in 3-D with an orbit camera, a time slider, play/pause and
        speed. three.js, the viewer script (scenarios/common/viewer/) and \a view as JSON are inline. */
    std::string viewerPage(const nlohmann::json &view, const ThreeJs &three);

    /** \brief \a text with every "</" written "<\\/" (JSON and JS strings read it the same), so that no
        "</script>" inside it ends the script element of a page. */
    std::string scriptSafe(const std::string &text);
}  // namespace ropras::scenarios

#endif
