#ifndef ROPRAS_SCENARIOS_SVG_OBJECTS_H
#define ROPRAS_SCENARIOS_SVG_OBJECTS_H
// Private to ropras_scenarios: the movable upright objects of a recording (cans) for `ropras render`, read from the
// scene's "objects", "slots" and "reserved_slot" keys: cylinders at the chosen steps (held ones outlined at the
// holder), their belief particles in one colour per object, and the slots with the reserved one marked.

#include <cstddef>
#include <nlohmann/json.hpp>
#include <sstream>
#include <string>
#include <vector>

#include "RecordingReader.h"
#include "SvgPicture.h"

namespace ropras::scenarios::detail
{
    /** \brief The scene's upright cylinders that follow recorded labels, and the slots they may be set down on.

        Scene keys (all optional): "objects": {"labels": [label, ...], "radius": r, "height": h, "holder": label,
        "grasp_event": prefix, "release_event": prefix} (an object is held from the step of the event
        prefix + label, e.g. "grasp-can0", until the step of release prefix + label; event names may join several
        with '+' and go on after a '-'); "slots": [{"center": c, "radius": r}, ...]; "reserved_slot": index. */
    struct SceneObjects
    {
        std::vector<std::size_t> labels;  ///< indices into the recording's labels
        long holder{-1};                  ///< index of the label that carries held objects, -1 = none
        double radius{0.0}, height{0.0};
        std::vector<std::vector<bool>> held;  ///< per object, per step
        std::vector<Shape> slots;
        long reserved{-1};               ///< index into slots, -1 = none
        std::vector<std::size_t> steps;  ///< the steps at which the objects are drawn
        bool empty() const { return labels.empty() && slots.empty(); }
    };

    /** \brief Reads the objects of \a rec drawn at \a chosen steps (empty = up to 6 spread evenly over the
        episode); throws ropras::Error naming \a r's source for a malformed key, an unknown label or a chosen step
        past the trajectory's end. */
    SceneObjects readSceneObjects(const Recording &rec, const std::vector<std::size_t> &chosen, const Reader &r);

    /// the colour of the \a k-th object (its belief particles and outline)
    std::string objectColour(std::size_t k);

    /** \brief Whether recorded label \a label is one of the objects (its particles are drawn by drawObjectBeliefs). */
    bool isObjectLabel(const SceneObjects &objects, std::size_t label);

    /** \brief The slots (class "slot", the reserved one "slot reserved", drawn last) and the objects at the chosen
        steps (class "can"; held ones "can held", at the holder's position when the scene names one) in \a f's
        plane: circles of the radius in the top view, 2 radius x height rectangles in a side view (\a main: the top
        view, whose groups carry ids). */
    void drawObjects(std::ostringstream &svg, const SvgFrame &f, const SceneObjects &objects, const Recording &rec,
                     bool main);

    /** \brief The particles of every object in \a beliefs (class "particle object-particle", data-label), one colour
        per object. */
    void drawObjectBeliefs(std::ostringstream &svg, const SvgFrame &f, const SceneObjects &objects,
                           const Recording &rec, const std::vector<const RecordedBelief *> &beliefs, bool main);

    /// the legend entries of the objects, their particles, the slots and the reserved slot
    std::vector<LegendEntry> objectLegend(const SceneObjects &objects, const Recording &rec, bool beliefs);
}  // namespace ropras::scenarios::detail

#endif
