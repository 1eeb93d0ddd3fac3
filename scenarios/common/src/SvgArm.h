#ifndef ROPRAS_SCENARIOS_COMMON_SVG_ARM_H
#define ROPRAS_SCENARIOS_COMMON_SVG_ARM_H
// Private to ropras_scenarios: the robot posed by forward kinematics at chosen steps, and the recorded rays, in the
// views of `ropras render` (SvgRenderer).

#include <cstddef>
#include <nlohmann/json.hpp>
#include <sstream>
#include <string>
#include <vector>

#include "RecordingReader.h"
#include "SvgPicture.h"

namespace ropras::scenarios::detail
{
    /** \brief The robot's collision spheres at chosen steps: for each step, one centre per sphere. */
    struct ArmPoses
    {
        std::vector<std::size_t> steps;
        std::vector<double> radii;              ///< per sphere
        std::vector<std::vector<Vec>> centres;  ///< per chosen step, per sphere
        std::size_t lastStep{0};                ///< the trajectory's last step (for the time colours)
    };

    /** \brief Poses the recording's robot (its key "robot": URDF + configurations, read relative to \a folder) by
        forward kinematics at \a chosen steps; empty \a chosen = up to 6 steps spread evenly from the first to the
        last. Empty poses when the recording has no robot. Throws ropras::Error naming \a r's source for a
        malformed robot entry or a chosen step past the trajectory's end. */
    ArmPoses armPoses(const nlohmann::json &recording, std::size_t frames, const std::vector<std::size_t> &chosen,
                      const Reader &r, const std::string &folder);

    /** \brief The spheres of every pose projected onto \a f's plane, one group per step coloured by its time
        (\a main: the top view, whose group has the id "arm"; the side view's has the class). */
    void drawArm(std::ostringstream &svg, const SvgFrame &f, const ArmPoses &poses, bool main);

    /** \brief Every segment of \a rays as a line in \a f's plane (group id / class "rays"). */
    void drawRays(std::ostringstream &svg, const SvgFrame &f, const std::vector<RecordedRays> &rays, bool main);
}  // namespace ropras::scenarios::detail

#endif
