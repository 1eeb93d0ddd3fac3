#include "ropras/scenarios/SvgRenderer.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <sstream>

#include "RecordingReader.h"
#include "SvgArm.h"
#include "SvgFootprints.h"
#include "SvgObjects.h"
#include "SvgPicture.h"
#include "ropras/core/Error.h"
#include "ropras/core/InputFile.h"

namespace ropras::scenarios
{
    namespace
    {
        using detail::num;
        using detail::Reader;
        using detail::RecordedBelief;
        using detail::Recording;
        using detail::Shape;
        using detail::SvgFrame;
        using detail::Vec;
        using detail::xmlEscape;

        /// the scene's shape layers drawn under everything else, with their fill opacity
        constexpr std::pair<const char *, double> SCENE_LAYERS[] = {
            {"observation_zones", 0.25}, {"landmarks", 0.25}, {"light", 0.25},
            {"danger_zones", 0.45},      {"walls", 0.85},     {"obstacles", 0.5}};

        void drawShape(std::ostringstream &svg, const SvgFrame &f, const Shape &s, const std::string &colour,
                       double opacity, bool shadeByDepth, double markerRadius)
        {
            const int u = f.u, v = f.v;
            switch (s.kind)
            {
                case Shape::Kind::BOX:
                {
                    double alpha = opacity;
                    const int depth = 3 - u - v;  // the axis the view looks along
                    if (shadeByDepth && f.hi[depth] > f.lo[depth])
                    {
                        // nearer the viewer (higher in the top view) darker: opacity 0.5x to 1.5x by the box's mean
                        const double t = std::clamp(
                            (0.5 * (s.lo[depth] + s.hi[depth]) - f.lo[depth]) / (f.hi[depth] - f.lo[depth]), 0.0, 1.0);
                        alpha = std::min(1.0, opacity * (0.5 + t));
                    }
                    const double w = std::max(0.5, (s.hi[u] - s.lo[u]) * f.scale);
                    const double h = std::max(0.5, (s.hi[v] - s.lo[v]) * f.scale);
                    svg << "<rect x=\"" << num(f.x(s.lo[u])) << "\" y=\"" << num(f.y(s.hi[v])) << "\" width=\""
                        << num(w) << "\" height=\"" << num(h) << "\" fill=\"" << colour << "\" fill-opacity=\""
                        << num(alpha) << "\" stroke=\"" << colour << "\" stroke-width=\"0.8\"/>\n";
                    break;
                }
                case Shape::Kind::DISC:
                    svg << "<circle cx=\"" << num(f.x(s.lo[u])) << "\" cy=\"" << num(f.y(s.lo[v])) << "\" r=\""
                        << num(std::max(0.5, s.radius * f.scale)) << "\" fill=\"" << colour << "\" fill-opacity=\""
                        << num(opacity) << "\" stroke=\"" << colour << "\" stroke-width=\"0.8\"/>\n";
                    break;
                case Shape::Kind::POINT:
                    svg << "<circle cx=\"" << num(f.x(s.lo[u])) << "\" cy=\"" << num(f.y(s.lo[v])) << "\" r=\""
                        << num(markerRadius) << "\" fill=\"" << colour
                        << "\" stroke=\"#000000\" stroke-width=\"0.6\"/>\n";
                    break;
            }
        }

        /** \brief The recorded beliefs at the chosen steps (all when none are chosen); throws naming a chosen step
            that was not recorded. */
        std::vector<const RecordedBelief *> chosenBeliefs(const Recording &rec, const SvgOptions &options,
                                                          const Reader &r)
        {
            std::vector<const RecordedBelief *> out;
            for (const auto &b : rec.beliefs)
            {
                if (options.beliefSteps.empty() || std::find(options.beliefSteps.begin(), options.beliefSteps.end(),
                                                             b.step) != options.beliefSteps.end())
                {
                    out.push_back(&b);
                }
            }
            for (const std::size_t step : options.beliefSteps)
            {
                if (std::none_of(rec.beliefs.begin(), rec.beliefs.end(),
                                 [step](const RecordedBelief &b) { return b.step == step; }))
                {
                    std::string known;
                    for (const auto &b : rec.beliefs)
                    {
                        known += (known.empty() ? "" : ", ") + std::to_string(b.step);
                    }
                    r.fail("belief step " + std::to_string(step),
                           "was not recorded (recorded steps: " + (known.empty() ? std::string("none") : known) +
                               "; record more with --belief-every K)");
                }
            }
            return out;
        }

        /** \brief Everything one view (top or side) draws; \a main: the top view, which carries the element ids,
            the ranges and the time labels. */
        struct ViewParts
        {
            const Recording &rec;
            const std::vector<const RecordedBelief *> &beliefs;
            const Reader &r;
            double robotRadius;
            std::size_t lastStep;
            const detail::ArmPoses &arm;
            const std::vector<detail::RecordedRays> &rays;
            const detail::SceneObjects &objects;
        };

        /// the element that opens a view's group: with an id in the top view (\a main), a class in the side view
        std::string openGroup(const std::string &id, bool main)
        {
            return main ? "<g id=\"" + id + "\">\n" : "<g class=\"" + id + "\">\n";
        }

        /// the colour of label \a k's path: an object's own colour, else the label's
        std::string pathColour(const ViewParts &p, std::size_t k)
        {
            const auto &labels = p.objects.labels;
            const auto it = std::find(labels.begin(), labels.end(), k);
            return it != labels.end() ? detail::objectColour(std::size_t(it - labels.begin()))
                                      : detail::labelColour(p.rec.labels[k], k);
        }

        /// the scene's zones, walls and obstacles, the goal and the starts
        void drawSceneLayers(std::ostringstream &svg, const SvgFrame &f, const ViewParts &p, bool main)
        {
            const nlohmann::json &scene = *p.rec.scene;
            const Reader &r = p.r;
            const double markerRadius = 5.0;
            for (const auto &layer : SCENE_LAYERS)
            {
                if (!scene.contains(layer.first))
                    continue;
                const auto shapes = r.shapes(scene[layer.first], std::string("scene.") + layer.first);
                if (shapes.empty())
                    continue;
                svg << openGroup(layer.first, main);
                for (const auto &s : shapes)
                {
                    drawShape(svg, f, s, detail::layerColour(layer.first, 0), layer.second, p.rec.dims == 3 && main,
                              markerRadius);
                }
                svg << "</g>\n";
            }
            const auto goals = detail::sceneGoals(scene, r);
            if (!goals.empty())
            {
                svg << openGroup("goal", main);
                for (const auto &s : goals)
                    drawShape(svg, f, s, detail::layerColour("goal", 0), 0.45, false, markerRadius + 2.0);
                svg << "</g>\n";
            }
            if (scene.contains("starts"))
            {
                svg << openGroup("starts", main);
                for (const auto &s : r.shapes(scene["starts"], "scene.starts"))
                    drawShape(svg, f, s, detail::layerColour("starts", 0), 0.6, false, markerRadius);
                svg << "</g>\n";
            }
        }

        /** \brief Belief particles coloured by the time of their snapshot, the true positions circled (the scene
            objects' particles and positions are drawn by SvgObjects instead). */
        void drawBeliefs(std::ostringstream &svg, const SvgFrame &f, const ViewParts &p, bool main,
                         detail::LabelPlacer &labels)
        {
            if (p.beliefs.empty())
                return;
            svg << openGroup("beliefs", main);
            for (const auto *belief : p.beliefs)
            {
                const std::string colour =
                    detail::timeColour(p.lastStep ? double(belief->step) / double(p.lastStep) : 0.0);
                svg << "<g class=\"belief\" data-step=\"" << belief->step << "\" fill=\"" << colour << "\">\n";
                for (const auto &particle : belief->particles)
                {
                    for (std::size_t k = 0; k < particle.size(); ++k)
                    {
                        if (detail::isObjectLabel(p.objects, k))
                            continue;
                        svg << "<circle class=\"particle\" cx=\"" << num(f.x(particle[k][f.u])) << "\" cy=\""
                            << num(f.y(particle[k][f.v])) << "\" r=\"2.2\" fill-opacity=\"0.45\"/>\n";
                    }
                }
                for (std::size_t k = 0; k < p.rec.paths.size() && belief->step < p.rec.paths[k].size(); ++k)
                {
                    if (detail::isObjectLabel(p.objects, k))
                        continue;
                    const Vec &q = p.rec.paths[k][belief->step];
                    svg << "<circle cx=\"" << num(f.x(q[f.u])) << "\" cy=\"" << num(f.y(q[f.v]))
                        << "\" r=\"4\" fill=\"none\" stroke=\"#000000\" stroke-width=\"1\"/>\n";
                    if (main)
                        labels.place(svg, f.x(q[f.u]), f.y(q[f.v]), "t=" + std::to_string(belief->step));
                }
                svg << "</g>\n";
            }
            svg << "</g>\n";
        }

        /// the executed paths, with arrows along them and a filled end
        void drawTrajectories(std::ostringstream &svg, const SvgFrame &f, const ViewParts &p, bool main)
        {
            svg << openGroup("trajectory", main);
            const double jump = 0.2 * std::max(f.hi[f.u] - f.lo[f.u], f.hi[f.v] - f.lo[f.v]);
            for (std::size_t k = 0; k < p.rec.labels.size(); ++k)
            {
                const auto &path = p.rec.paths[k];
                const std::string colour = pathColour(p, k);
                detail::drawPath(svg, f, path, colour, xmlEscape(p.rec.labels[k]), jump);
                if (!path.empty() && !detail::isObjectLabel(p.objects, k))
                {
                    const Vec &end = path.back();
                    svg << "<circle cx=\"" << num(f.x(end[f.u])) << "\" cy=\"" << num(f.y(end[f.v])) << "\" r=\""
                        << num(std::max(3.0, p.robotRadius * f.scale)) << "\" fill=\"" << colour << "\"/>\n";
                }
            }
            svg << "</g>\n";
        }

        /// multi-drone: the detection range around the agents and the capture radius around the target (top view)
        void drawRanges(std::ostringstream &svg, const SvgFrame &f, const ViewParts &p)
        {
            const nlohmann::json &scene = *p.rec.scene;
            const auto rangeCircles = [&](const char *key, bool aroundTarget, const char *dash)
            {
                if (!scene.contains(key))
                    return;
                const double radius = p.r.number(scene[key], std::string("scene.") + key);
                if (radius <= 0.0)
                    return;
                svg << "<g id=\"" << key << "\">\n";
                for (std::size_t k = 0; k < p.rec.labels.size(); ++k)
                {
                    if ((p.rec.labels[k] == "target") != aroundTarget || p.rec.paths[k].empty())
                        continue;
                    const Vec &end = p.rec.paths[k].back();
                    svg << "<circle cx=\"" << num(f.x(end[f.u])) << "\" cy=\"" << num(f.y(end[f.v])) << "\" r=\""
                        << num(radius * f.scale) << "\" fill=\"none\" stroke=\""
                        << detail::labelColour(p.rec.labels[k], k) << "\" stroke-dasharray=\"" << dash
                        << "\" stroke-width=\"1\"/>\n";
                }
                svg << "</g>\n";
            };
            rangeCircles("detection_range", false, "4 3");
            rangeCircles("capture_radius", true, "2 2");
        }

        void drawView(std::ostringstream &svg, const SvgFrame &f, const ViewParts &p, bool main,
                      detail::LabelPlacer &labels)
        {
            svg << "<rect " << (main ? "id=\"bounds\" " : "class=\"bounds\" ") << "x=\"" << num(f.left) << "\" y=\""
                << num(f.top) << "\" width=\"" << num(f.width()) << "\" height=\"" << num(f.height())
                << "\" fill=\"#fafafa\" stroke=\"#000000\" stroke-width=\"1.5\"/>\n";
            svg << "<g clip-path=\"url(#" << f.clipId << ")\">\n";
            drawSceneLayers(svg, f, p, main);
            drawBeliefs(svg, f, p, main, labels);
            // the arm posed at the chosen steps and the recorded rays, under the objects and the path lines
            detail::drawArm(svg, f, p.arm, main);
            detail::drawRays(svg, f, p.rays, main);
            // bodies along the paths (a mobile base's footprint, a pedestrian's disc), under the path lines; top view
            if (main)
            {
                detail::drawBodies(
                    svg, *p.rec.scene, p.rec.labels, p.rec.paths,
                    detail::SvgMap{[&f](double x) { return f.x(x); }, [&f](double y) { return f.y(y); }, f.scale},
                    p.r.source());
            }
            // the slots and the objects (cans) at the chosen steps with their belief particles
            detail::drawObjects(svg, f, p.objects, p.rec, main);
            detail::drawObjectBeliefs(svg, f, p.objects, p.rec, p.beliefs, main);
            drawTrajectories(svg, f, p, main);
            if (main)
                drawRanges(svg, f, p);
            svg << "</g>\n";
            detail::drawAxes(svg, f);
        }

        std::vector<detail::LegendEntry> legendEntries(const Recording &rec, bool beliefs, bool arm, bool rays,
                                                       const detail::SceneObjects &objects, const Reader &r)
        {
            std::vector<detail::LegendEntry> legend;
            for (const auto &layer : SCENE_LAYERS)
            {
                const char *key = layer.first;
                if (rec.scene->contains(key) && !r.shapes((*rec.scene)[key], std::string("scene.") + key).empty())
                {
                    std::string name = key;
                    std::replace(name.begin(), name.end(), '_', ' ');
                    legend.push_back({name, detail::layerColour(key, 0)});
                }
            }
            if (rec.scene->contains("goal"))
                legend.push_back({"goal", detail::layerColour("goal", 0)});
            if (rec.scene->contains("starts"))
                legend.push_back({"starts", detail::layerColour("starts", 0)});
            if (beliefs && rec.labels.size() > objects.labels.size())
                legend.push_back({"belief particles (colour: time)", detail::timeColour(0.5)});
            if (arm)
                legend.push_back({"robot spheres at chosen steps (colour: time)", detail::timeColour(0.25)});
            if (rays)
                legend.push_back({"rays", "#d32f2f"});
            const auto objectEntries = detail::objectLegend(objects, rec, beliefs);
            legend.insert(legend.end(), objectEntries.begin(), objectEntries.end());
            for (std::size_t k = 0; k < rec.labels.size(); ++k)
            {
                if (!detail::isObjectLabel(objects, k))
                    legend.push_back({rec.labels[k], detail::labelColour(rec.labels[k], k)});
            }
            return legend;
        }
        /// the top view (x right, y up) of \a rec's bounds, \a width px wide, and the side view (x right, z up) below
        std::array<SvgFrame, 2> viewFrames(const Recording &rec, double width)
        {
            SvgFrame top;
            top.lo = rec.bounds.lo;
            top.hi = rec.bounds.hi;
            top.scale = width / (top.hi[0] - top.lo[0]);
            top.left = detail::AXIS_MARGIN;
            top.top = 72.0;
            top.clipId = "clip-top";
            top.name = "top view";
            SvgFrame side = top;
            side.v = 2;
            side.clipId = "clip-side";
            side.name = "side view";
            side.top = top.top + top.height() + detail::AXIS_BELOW + 18.0;
            return {top, side};
        }

        /// the lines above the views (font sizes 16 bold, 13, 11): the title, the outcome, what the views show
        std::array<std::string, 3> headerLines(const Recording &rec, bool sideView)
        {
            const std::string views = rec.dims == 3 ? "top view (x, y; higher boxes darker)" +
                                                          std::string(sideView ? ", side view (x, z) below" : "")
                                                    : std::string("top view (x, y)");
            return {rec.title, rec.subtitle, views + "; arrows show the direction of travel, a filled disc the end"};
        }

        /// about the width in pixels of the longest header line (sans-serif: ~0.54 em a character, bold ~0.62)
        double headerWidth(const std::array<std::string, 3> &lines)
        {
            return std::max({0.62 * 16.0 * double(lines[0].size()), 0.54 * 13.0 * double(lines[1].size()),
                             0.54 * 11.0 * double(lines[2].size())});
        }

        /// the svg element, the views' clip paths, the white background and the header lines
        void openDocument(std::ostringstream &svg, const std::array<std::string, 3> &header,
                          const std::array<SvgFrame, 2> &frames, double width, double height)
        {
            svg << "<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n"
                << "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"" << num(width) << "\" height=\"" << num(height)
                << "\" viewBox=\"0 0 " << num(width) << " " << num(height) << "\" font-family=\"sans-serif\">\n";
            svg << "<title>" << xmlEscape(header[0]) << "</title>\n";
            svg << "<defs>\n";
            for (const SvgFrame &f : frames)
            {
                svg << "<clipPath id=\"" << f.clipId << "\"><rect x=\"" << num(f.left) << "\" y=\"" << num(f.top)
                    << "\" width=\"" << num(f.width()) << "\" height=\"" << num(f.height()) << "\"/></clipPath>\n";
            }
            svg << "</defs>\n<rect x=\"0\" y=\"0\" width=\"" << num(width) << "\" height=\"" << num(height)
                << "\" fill=\"#ffffff\"/>\n";
            const double left = frames[0].left;
            svg << "<text x=\"" << num(left) << "\" y=\"22\" font-size=\"16\" font-weight=\"bold\">"
                << xmlEscape(header[0]) << "</text>\n";
            svg << "<text x=\"" << num(left) << "\" y=\"44\" font-size=\"13\">" << xmlEscape(header[1]) << "</text>\n";
            svg << "<text x=\"" << num(left) << "\" y=\"62\" font-size=\"11\" fill=\"#555555\">" << xmlEscape(header[2])
                << "</text>\n";
        }
    }  // namespace

    nlohmann::json loadRecording(const std::string &path)
    {
        const std::string text = readInputFile(path, "recording");
        try
        {
            return nlohmann::json::parse(text);
        }
        catch (const nlohmann::json::exception &e)  // parse_error, and out_of_range for 1e400
        {
            throw Error("recording \"" + path + "\": malformed JSON: " + e.what());
        }
    }

    std::string renderSvg(const nlohmann::json &recording, const SvgOptions &options, const std::string &source)
    {
        const Reader r(source);
        const Recording rec = detail::parseRecording(recording, r);
        if (!(std::isfinite(options.width) && options.width >= 50.0))
        {
            r.fail("the picture width", "must be >= 50 px");
        }
        const auto beliefs = chosenBeliefs(rec, options, r);
        double robotRadius = 0.0;
        if (rec.scene->contains("robot_radius"))
        {
            robotRadius = std::max(0.0, r.number((*rec.scene)["robot_radius"], "scene.robot_radius"));
        }
        std::size_t lastStep = 0;
        for (const auto *b : beliefs)
            lastStep = std::max(lastStep, b->step);
        const auto slash = source.rfind('/');
        const std::string folder = slash == std::string::npos ? "." : source.substr(0, slash);
        const detail::ArmPoses arm = detail::armPoses(recording, rec.paths.front().size(), options.armSteps, r, folder);
        const std::vector<detail::RecordedRays> rays = recording.contains("rays")
                                                           ? detail::readRecordedRays(recording["rays"], r)
                                                           : std::vector<detail::RecordedRays>();
        const detail::SceneObjects objects = detail::readSceneObjects(rec, options.armSteps, r);

        // layout: the header, the top view and, for 3-D problems, the side view below it, both with metric axes;
        // then the legend rows (as wide as the header's longest line at least)
        const auto frames = viewFrames(rec, options.width);
        const SvgFrame &top = frames[0], &side = frames[1];
        const bool sideView = rec.dims == 3 && rec.bounds.hi[2] > rec.bounds.lo[2];
        const auto header = headerLines(rec, sideView);
        const double viewsBottom = (sideView ? side.top + side.height() : top.top + top.height()) + detail::AXIS_BELOW;
        const double totalWidth = std::max(top.left + top.width() + 24.0, top.left + headerWidth(header) + 12.0);
        const auto legend = legendEntries(rec, !beliefs.empty(), !arm.steps.empty(), !rays.empty(), objects, r);
        detail::Legend placed = detail::layoutLegend(legend, top.left, viewsBottom + 14.0, totalWidth - 12.0);
        const double gradientHeight = beliefs.empty() ? 0.0 : 30.0;
        const double totalHeight = placed.bottom + gradientHeight + 12.0;

        std::ostringstream svg;
        openDocument(svg, header, frames, totalWidth, totalHeight);
        const ViewParts parts{rec, beliefs, r, robotRadius, lastStep, arm, rays, objects};
        detail::LabelPlacer labels(top.left, top.top, top.left + top.width(), top.top + top.height());
        drawView(svg, top, parts, true, labels);
        if (sideView)
        {
            detail::LabelPlacer none(0, 0, 0, 0);
            svg << "<g id=\"side_view\">\n";
            drawView(svg, side, parts, false, none);
            svg << "</g>\n";
        }
        detail::drawLegend(svg, legend, placed);
        if (!beliefs.empty())
        {
            detail::drawTimeGradient(svg, top.left, placed.bottom + 6.0, std::min(240.0, top.width()), 0, lastStep);
        }
        svg << "</svg>\n";
        return svg.str();
    }
}  // namespace ropras::scenarios
