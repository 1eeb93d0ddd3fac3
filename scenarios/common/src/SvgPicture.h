#ifndef ROPRAS_SCENARIOS_SVG_PICTURE_H
#define ROPRAS_SCENARIOS_SVG_PICTURE_H
// Private to ropras_scenarios: the drawing parts of SvgRenderer (`ropras render`): a view's world-to-pixel frame,
// metric axes, paths with arrows, a time colour ramp, labels that avoid each other, a legend that wraps.

#include <array>
#include <cstddef>
#include <sstream>
#include <string>
#include <vector>

namespace ropras::scenarios::detail
{
    using Point = std::array<double, 3>;

    /// room left of a view for the tick numbers and the axis name, and below it for the x ticks
    constexpr double AXIS_MARGIN = 58.0;
    constexpr double AXIS_BELOW = 34.0;

    /** \brief A view of the world's axes u (right) and v (up) in pixels: the top view (x, y) or a side view (x, z). */
    struct SvgFrame
    {
        Point lo{}, hi{};
        int u{0}, v{1};
        double scale{1.0};
        double left{0.0}, top{0.0};
        std::string clipId, name;
        double x(double wu) const { return left + (wu - lo[u]) * scale; }
        double y(double wv) const { return top + (hi[v] - wv) * scale; }
        double width() const { return (hi[u] - lo[u]) * scale; }
        double height() const { return (hi[v] - lo[v]) * scale; }
    };

    /// "%.2f"
    std::string num(double v);
    /// & < > " escaped, control characters blanked (XML 1.0)
    std::string xmlEscape(const std::string &text);
    /// 1, 2 or 5 times a power of ten near span / 8
    double niceStep(double span);
    /// a colour of the viridis-like ramp, t in [0, 1] (dark blue early, yellow late)
    std::string timeColour(double t);

    /** \brief Ticks every niceStep(extent of the axis) metres along both axes of \a f with their numbers, the axis
       names with
        "(m)", and the view's name. */
    void drawAxes(std::ostringstream &svg, const SvgFrame &f);

    /** \brief \a path as polylines (a jump longer than \a jump starts a new one), a hollow circle at its start and
        up to 8 arrowheads spaced evenly along its length pointing the way it goes. */
    void drawPath(std::ostringstream &svg, const SvgFrame &f, const std::vector<Point> &path, const std::string &colour,
                  const std::string &label, double jump);

    /** \brief Places small text labels next to points without overprinting each other or leaving a rectangle:
        tries four spots around the point and skips the label when none is free. */
    class LabelPlacer
    {
    public:
        LabelPlacer(double left, double top, double right, double bottom);
        /// returns whether the label was drawn
        bool place(std::ostringstream &svg, double x, double y, const std::string &text);

    private:
        double left_, top_, right_, bottom_;
        std::vector<std::array<double, 4>> taken_;
    };

    struct LegendEntry
    {
        std::string name, colour;
    };

    /** \brief Where each legend entry goes: rows wrapped before \a right. */
    struct Legend
    {
        std::vector<std::array<double, 2>> at;
        double bottom{0.0};
    };
    Legend layoutLegend(const std::vector<LegendEntry> &entries, double left, double top, double right);
    void drawLegend(std::ostringstream &svg, const std::vector<LegendEntry> &entries, const Legend &layout);

    /** \brief The time ramp of the belief colours as a bar from step \a first to \a last, labelled. */
    void drawTimeGradient(std::ostringstream &svg, double x, double y, double width, std::size_t first,
                          std::size_t last);
}  // namespace ropras::scenarios::detail

#endif
