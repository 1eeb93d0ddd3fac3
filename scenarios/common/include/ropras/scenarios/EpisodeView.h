#ifndef ROPRAS_SCENARIOS_EPISODE_VIEW_H
#define ROPRAS_SCENARIOS_EPISODE_VIEW_H

#include <nlohmann/json.hpp>
#include <string>

namespace ropras::scenarios
{
    /** \brief The viewer document (doc/viewer.md) of an episode recorded by `ropras run --record` (format:
        doc/scenarios.md), for viewerPage().

        Draws every scene key that holds shapes (walls, obstacles, danger zones, observation zones, landmarks,
        light, the goal, and keys it does not know; boxes in 2-D scenes get a height), the starts as markers,
        one marker sphere per label and frame with its path, the belief particles of every snapshot per label,
        and rays (key "rays": [{"step", "segments": [[origin, end], ...]}]). When the recording has "robot"
        ({"urdf": FILE or "embedded:KEY", "configurations": one joint vector per trajectory step}), the robot's
        collision spheres are posed per frame by the project's forward kinematics (RobotModel); a relative FILE
        resolves against \a folder. Throws ropras::Error naming \a source and the key for a malformed recording
        (including a configuration with the wrong joint count, a non-finite value, or a URDF that cannot be read). */
    nlohmann::json episodeView(const nlohmann::json &recording, const std::string &source,
                               const std::string &folder = ".");
}  // namespace ropras::scenarios

#endif
