#ifndef ROPRAS_SCENARIOS_SVG_RENDERER_H
#define ROPRAS_SCENARIOS_SVG_RENDERER_H

#include <cstddef>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

namespace ropras::scenarios
{
    /** \brief What `ropras render` draws besides the scene and the trajectory. */
    struct SvgOptions
    {
        /// steps whose recorded belief particles are drawn; empty = every recorded belief
        std::vector<std::size_t> beliefSteps;
        /// steps at which the recorded robot (key "robot") is drawn posed by forward kinematics and the scene's
        /// "objects" (cans) are drawn; empty = up to 6 steps spread evenly over the episode
        std::vector<std::size_t> armSteps;
        /// width of the map in pixels (the height follows the bounds' aspect ratio)
        double width{800.0};
    };

    /** \brief Reads a recording written by `ropras run --record` (format: doc/scenarios.md); throws
        ropras::Error naming \a path when it cannot be read or is not JSON. */
    nlohmann::json loadRecording(const std::string &path);

    /** \brief The recording of one episode as a standalone SVG document, top-down (x right, y up; z ignored
        but for shading 3-D boxes, higher ones darker): the bounds, walls (gray), obstacles (cyan), danger
        zones (red), observation zones / landmarks / light (purple), the goal (green), the starts (orange),
        the executed trajectory of every label (drones in distinct colours, the target green), belief
        particles (coloured by their step) with the true position at the chosen steps, the robot's collision
        spheres posed by forward kinematics at the chosen arm steps when the recording has "robot" (URDF +
        configurations; coloured by time), the recorded "rays" (red segments), the scene's "objects" (cans, one
        colour each, held ones dashed at the holder; their belief particles in their colour) at the chosen arm
        steps and its "slots" (the "reserved_slot" bold), the detection range and capture radius when the scene
        has them, a legend, and a title with scenario, solver, outcome and steps. Scene keys it does not know are
        ignored.

        Scene shapes may be boxes `[lo, hi]` or `{"lo": .., "hi": ..}` / `{"min": .., "max": ..}` /
        `{"center": .., "half_extents": ..}`, discs `{"center": .., "radius": r}` or points `[x, y(, z)]`.
        Throws ropras::Error naming \a source and the offending key for a malformed recording (no scene or
        bounds, a trajectory step with the wrong number of points, a non-numeric coordinate, a requested belief
        step that was not recorded, a malformed "objects", "slots" or "reserved_slot" key). */
    std::string renderSvg(const nlohmann::json &recording, const SvgOptions &options = SvgOptions(),
                          const std::string &source = "recording");
}  // namespace ropras::scenarios

#endif
