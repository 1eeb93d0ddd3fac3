#ifndef ROPRAS_SCENARIOS_RECORDING_READER_H
#define ROPRAS_SCENARIOS_RECORDING_READER_H
// Private to ropras_scenarios: the parts of a recording of `ropras run --record` (doc/scenarios.md) as read and
// checked once for `ropras render` (SvgRenderer) and `ropras view` (EpisodeView).

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "ropras/core/Error.h"
#include "ropras/ompl_ext/model/RobotModel.h"

namespace ropras::scenarios::detail
{
    using Vec = std::array<double, 3>;

    /** \brief A scene element: a box, a disc or a point (x, y, z; z = 0 in 2-D). */
    struct Shape
    {
        enum class Kind
        {
            BOX,
            DISC,
            POINT
        } kind{Kind::POINT};
        Vec lo{}, hi{};
        double radius{0.0};
    };

    /** \brief Reads and checks the parts of a recording, naming \a source and the key in every error. */
    class Reader
    {
    public:
        explicit Reader(std::string source) : source_(std::move(source)) {}

        /// the file (or name) that errors name
        const std::string &source() const { return source_; }

        [[noreturn]] void fail(const std::string &key, const std::string &problem) const
        {
            throw Error(source_ + ": " + key + " " + problem);
        }

        /** \brief A coordinate list of 2 or 3 finite numbers (at least \a minDims). */
        Vec point(const nlohmann::json &j, const std::string &key, std::size_t minDims = 2) const
        {
            if (!j.is_array() || j.size() < minDims || j.size() > 3)
            {
                fail(key, "must be a point [x, y] or [x, y, z], not " + clip(j));
            }
            Vec out{0.0, 0.0, 0.0};
            for (std::size_t k = 0; k < j.size(); ++k)
            {
                if (!j[k].is_number() || !std::isfinite(j[k].get<double>()))
                {
                    fail(key, "has a coordinate that is not a finite number: " + clip(j));
                }
                out[k] = j[k].get<double>();
            }
            return out;
        }

        static bool isPoint(const nlohmann::json &j)
        {
            return j.is_array() && (j.size() == 2 || j.size() == 3) &&
                   std::all_of(j.begin(), j.end(), [](const nlohmann::json &v) { return v.is_number(); });
        }

        Shape box(const Vec &lo, const Vec &hi, const std::string &key) const
        {
            for (int k = 0; k < 3; ++k)
            {
                if (lo[k] > hi[k])
                {
                    fail(key, "is a box whose lower corner exceeds its upper corner on axis " + std::to_string(k));
                }
            }
            Shape s;
            s.kind = Shape::Kind::BOX;
            s.lo = lo;
            s.hi = hi;
            return s;
        }

        Shape shape(const nlohmann::json &j, const std::string &key) const
        {
            if (isPoint(j))
            {
                Shape s;
                s.lo = s.hi = point(j, key);
                return s;
            }
            if (j.is_array() && j.size() == 2 && isPoint(j[0]) && isPoint(j[1]))
            {
                return box(point(j[0], key), point(j[1], key), key);
            }
            if (j.is_object())
            {
                for (const auto &names : {std::pair<const char *, const char *>{"lo", "hi"}, {"min", "max"}})
                {
                    if (j.contains(names.first) && j.contains(names.second))
                    {
                        return box(point(j[names.first], key + "." + names.first),
                                   point(j[names.second], key + "." + names.second), key);
                    }
                }
                const char *centerKey = j.contains("center") ? "center" : j.contains("centre") ? "centre" : nullptr;
                if (centerKey && j.contains("radius"))
                {
                    Shape s;
                    s.kind = Shape::Kind::DISC;
                    s.lo = s.hi = point(j[centerKey], key + "." + centerKey);
                    s.radius = number(j["radius"], key + ".radius");
                    if (s.radius < 0.0)
                    {
                        fail(key + ".radius", "is negative");
                    }
                    return s;
                }
                if (centerKey && j.contains("half_extents"))
                {
                    const Vec c = point(j[centerKey], key + "." + centerKey);
                    const Vec h = point(j["half_extents"], key + ".half_extents");
                    return box(Vec{c[0] - h[0], c[1] - h[1], c[2] - h[2]}, Vec{c[0] + h[0], c[1] + h[1], c[2] + h[2]},
                               key);
                }
            }
            fail(key, "is not a box [lo, hi], {\"center\", \"radius\"} or a point [x, y(, z)]: " + clip(j));
        }

        std::vector<Shape> shapes(const nlohmann::json &j, const std::string &key) const
        {
            std::vector<Shape> out;
            if (j.is_null())
            {
                return out;
            }
            if (!j.is_array())
            {
                fail(key, "must be an array of shapes, not " + clip(j));
            }
            for (std::size_t i = 0; i < j.size(); ++i)
            {
                out.push_back(shape(j[i], key + "[" + std::to_string(i) + "]"));
            }
            return out;
        }

        double number(const nlohmann::json &j, const std::string &key) const
        {
            if (!j.is_number() || !std::isfinite(j.get<double>()))
            {
                fail(key, "must be a finite number, not " + clip(j));
            }
            return j.get<double>();
        }

        static std::string clip(const nlohmann::json &j)
        {
            std::string s = j.dump();
            return s.size() > 80 ? s.substr(0, 77) + "..." : s;
        }

    private:
        std::string source_;
    };

    /** \brief The belief particles recorded at one step: per particle, one point per label. */
    struct RecordedBelief
    {
        std::size_t step{0};
        std::vector<std::vector<Vec>> particles;
    };

    /** \brief A checked recording: the scene (as JSON, with its bounds and dimension), the labels, the trajectory
        of every label, every recorded belief, and a title and subtitle (scenario, solver, outcome, steps, seed). */
    struct Recording
    {
        const nlohmann::json *json{nullptr};
        const nlohmann::json *scene{nullptr};
        Shape bounds;
        int dims{2};
        std::vector<std::string> labels;
        std::vector<std::vector<Vec>> paths;  ///< per label, per step
        std::vector<RecordedBelief> beliefs;
        std::string title, subtitle;
    };

    /** \brief Reads \a recording (kept referenced: it must outlive the result); throws ropras::Error naming \a r's
        source and the key for a malformed recording. */
    Recording parseRecording(const nlohmann::json &recording, const Reader &r);

    /** \brief The colour of a scene layer (walls gray, obstacles cyan, danger zones red, observation zones /
        landmarks / light purple, goal green, starts orange); keys it does not know get the \a index-th colour of a
        palette. */
    std::string layerColour(const std::string &key, std::size_t index);

    /** \brief The colour of a recorded label: "robot" blue, "target" green, others (drones) from a palette. */
    std::string labelColour(const std::string &label, std::size_t index);

    /** \brief The scene's goal: one shape or a list of shapes (empty when the scene has none). */
    std::vector<Shape> sceneGoals(const nlohmann::json &scene, const Reader &r);

    /** \brief A recording's key "robot" read: the robot of its URDF ("embedded:KEY" or a file relative to
        \a folder) and its planning-joint values per step. */
    struct RecordedRobot
    {
        std::shared_ptr<const ompl_ext::RobotModel> model;
        std::vector<std::vector<double>> configurations;  ///< per step, model->dof() values
    };

    /** \brief Reads \a robot (`{"urdf", "configurations"}`), one configuration per step of the \a frames of the
        trajectory; throws ropras::Error naming \a r's source and the key for a malformed entry. */
    RecordedRobot readRecordedRobot(const nlohmann::json &robot, std::size_t frames, const Reader &r,
                                    const std::string &folder);

    /** \brief The segments of a recording's key "rays" at one step. */
    struct RecordedRays
    {
        std::size_t step{0};
        std::vector<std::array<Vec, 2>> segments;  ///< origin, end
    };

    /** \brief Reads \a rays (`[{"step": n, "segments": [[origin, end], ...]}, ...]`); throws ropras::Error naming
        \a r's source and the entry for a malformed one. */
    std::vector<RecordedRays> readRecordedRays(const nlohmann::json &rays, const Reader &r);
}  // namespace ropras::scenarios::detail

#endif
