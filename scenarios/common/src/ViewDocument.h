#ifndef ROPRAS_SCENARIOS_VIEW_DOCUMENT_H
#define ROPRAS_SCENARIOS_VIEW_DOCUMENT_H
// Private to ropras_scenarios: builds the JSON document that the viewer page draws (`ropras view`; its keys are
// listed in doc/viewer.md). Numbers are rounded to a fixed unit so the page stays small.

#include <array>
#include <cstddef>
#include <map>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

namespace ropras::ompl_ext
{
    class RobotModel;
    class Environment;
}  // namespace ropras::ompl_ext

namespace ropras::scenarios::detail
{
    using Vec3 = std::array<double, 3>;
    using Quat = std::array<double, 4>;  ///< x, y, z, w

    /** \brief The viewer's document: layers of static shapes, bodies of spheres moving per frame, paths, belief
        snapshots and rays. */
    class ViewDocument
    {
    public:
        /** \brief \a unit: coordinates are rounded to multiples of it (m). */
        explicit ViewDocument(double unit);

        /** \brief The index of layer \a name, added with \a colour and \a opacity when new. */
        int layer(const std::string &name, const std::string &colour, double opacity);
        void box(int layer, const Vec3 &centre, const Vec3 &size, const Quat &rotation = {0.0, 0.0, 0.0, 1.0});
        void sphere(int layer, const Vec3 &centre, double radius);
        /// axis along the local z axis
        void cylinder(int layer, const Vec3 &centre, const Quat &rotation, double radius, double length);
        void marker(int layer, const Vec3 &centre, double radius) { sphere(layer, centre, radius); }

        /** \brief Spheres moving per frame: \a centres holds frames x radii.size() x 3 numbers. */
        void body(const std::string &name, const std::string &colour, const std::vector<double> &radii,
                  const std::vector<double> &centres);
        /** \brief A path of one point per frame. */
        void path(const std::string &label, const std::string &colour, const std::vector<Vec3> &points);
        /** \brief Belief particles of one label: snapshot i holds \a points[i] from frame \a steps[i] on. */
        void beliefs(const std::string &label, const std::string &colour, const std::vector<std::size_t> &steps,
                     const std::vector<std::vector<Vec3>> &points);
        /** \brief Ray segments (origin, end): snapshot i, \a segments[i], is shown from frame \a steps[i] on. */
        void rays(const std::vector<std::size_t> &steps, const std::vector<std::vector<std::array<Vec3, 2>>> &segments);

        nlohmann::json &json() { return json_; }
        const nlohmann::json &json() const { return json_; }

        /** \brief \a xyz (x, y, z triples) packed for the page: per axis the smallest value and a step, and
            every value as the nearest of 65536 levels between the smallest and the largest, little-endian
            uint16, base64: {"q16": "...", "origin": [x, y, z], "step": [sx, sy, sz]} (the error is at most half
            a step: 1/131070 of the extent per axis). */
        static nlohmann::json packed(const std::vector<double> &xyz);

    private:
        double round(double v) const;
        void push(nlohmann::json &list, const Vec3 &p) const;

        double unit_;
        nlohmann::json json_;
        std::map<std::string, int> layers_;
    };

    /** \brief Per configuration (dof() values each) the world centres of \a robot's collision spheres by its
        forward kinematics, followed by the spheres of \a environment's attached bodies (null: none), flat (3
        numbers per sphere); \a radii receives the radii in the same order. */
    std::vector<double> robotSphereFrames(const ompl_ext::RobotModel &robot, const ompl_ext::Environment *environment,
                                          const std::vector<std::vector<double>> &configurations,
                                          std::vector<double> &radii, std::size_t &attachedCount);

    /** \brief Every object of \a environment (and of its bases) as layer \a layerName shapes of \a view: boxes,
        spheres, cylinders, capsules (a cylinder and two spheres), point clouds (their points as spheres).
        Returns the number of shapes added. */
    std::size_t addEnvironment(ViewDocument &view, const ompl_ext::Environment &environment);
}  // namespace ropras::scenarios::detail

#endif
