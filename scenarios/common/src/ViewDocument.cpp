#include "ViewDocument.h"

#include <Eigen/Geometry>
#include <algorithm>
#include <cmath>

#include "ropras/core/Error.h"
#include "ropras/ompl_ext/model/RobotModel.h"
#include "ropras/ompl_ext/scene/Environment.h"

namespace ropras::scenarios::detail
{
    ViewDocument::ViewDocument(double unit) : unit_(unit)
    {
        if (!(unit > 0.0 && std::isfinite(unit)))
        {
            throw Error("view: the rounding unit must be a finite number > 0");
        }
        for (const char *key : {"layers", "boxes", "spheres", "cylinders", "bodies", "paths", "beliefs"})
        {
            json_[key] = nlohmann::json::array();
        }
    }

    namespace
    {
        std::string base64(const std::vector<unsigned char> &bytes)
        {
            static const char *alphabet = "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789+/";
            std::string out;
            out.reserve((bytes.size() + 2) / 3 * 4);
            for (std::size_t i = 0; i < bytes.size(); i += 3)
            {
                const unsigned v = (unsigned(bytes[i]) << 16) |
                                   (i + 1 < bytes.size() ? unsigned(bytes[i + 1]) << 8 : 0u) |
                                   (i + 2 < bytes.size() ? unsigned(bytes[i + 2]) : 0u);
                out += alphabet[(v >> 18) & 63];
                out += alphabet[(v >> 12) & 63];
                out += i + 1 < bytes.size() ? alphabet[(v >> 6) & 63] : '=';
                out += i + 2 < bytes.size() ? alphabet[v & 63] : '=';
            }
            return out;
        }

    }  // namespace

    nlohmann::json ViewDocument::packed(const std::vector<double> &xyz)
    {
        Vec3 lo{0.0, 0.0, 0.0}, hi{0.0, 0.0, 0.0};
        for (std::size_t i = 0; i < xyz.size(); ++i)
        {
            const std::size_t k = i % 3;
            if (!std::isfinite(xyz[i]))
            {
                throw Error("view: coordinate " + std::to_string(i) + " is not a finite number");
            }
            lo[k] = i < 3 ? xyz[i] : std::min(lo[k], xyz[i]);
            hi[k] = i < 3 ? xyz[i] : std::max(hi[k], xyz[i]);
        }
        Vec3 step{};
        for (std::size_t k = 0; k < 3; ++k)
        {
            step[k] = hi[k] > lo[k] ? (hi[k] - lo[k]) / 65535.0 : 1.0;
        }
        std::vector<unsigned char> bytes;
        bytes.reserve(xyz.size() * 2);
        for (std::size_t i = 0; i < xyz.size(); ++i)
        {
            const std::size_t k = i % 3;
            const auto level = static_cast<unsigned>(std::clamp(std::lround((xyz[i] - lo[k]) / step[k]), 0L, 65535L));
            bytes.push_back(static_cast<unsigned char>(level & 0xff));
            bytes.push_back(static_cast<unsigned char>(level >> 8));
        }
        return {{"q16", base64(bytes)}, {"origin", lo}, {"step", step}, {"count", xyz.size() / 3}};
    }

    double ViewDocument::round(double v) const
    {
        return std::round(v / unit_) * unit_;
    }

    void ViewDocument::push(nlohmann::json &list, const Vec3 &p) const
    {
        for (const double v : p)
        {
            list.push_back(round(v));
        }
    }

    int ViewDocument::layer(const std::string &name, const std::string &colour, double opacity)
    {
        const auto it = layers_.find(name);
        if (it != layers_.end())
        {
            return it->second;
        }
        const int index = static_cast<int>(layers_.size());
        layers_[name] = index;
        json_["layers"].push_back({{"name", name}, {"colour", colour}, {"opacity", opacity}});
        return index;
    }

    void ViewDocument::box(int layer, const Vec3 &centre, const Vec3 &size, const Quat &rotation)
    {
        nlohmann::json b = nlohmann::json::array({layer});
        push(b, centre);
        push(b, size);
        for (const double q : rotation)
        {
            b.push_back(std::round(q * 1e6) / 1e6);
        }
        json_["boxes"].push_back(std::move(b));
    }

    void ViewDocument::sphere(int layer, const Vec3 &centre, double radius)
    {
        nlohmann::json s = nlohmann::json::array({layer});
        push(s, centre);
        s.push_back(round(radius));
        json_["spheres"].push_back(std::move(s));
    }

    void ViewDocument::cylinder(int layer, const Vec3 &centre, const Quat &rotation, double radius, double length)
    {
        nlohmann::json c = nlohmann::json::array({layer});
        push(c, centre);
        c.push_back(round(radius));
        c.push_back(round(length));
        for (const double q : rotation)
        {
            c.push_back(std::round(q * 1e6) / 1e6);
        }
        json_["cylinders"].push_back(std::move(c));
    }

    void ViewDocument::body(const std::string &name, const std::string &colour, const std::vector<double> &radii,
                            const std::vector<double> &centres)
    {
        nlohmann::json r = nlohmann::json::array();
        for (const double v : radii)
        {
            r.push_back(round(v));
        }
        json_["bodies"].push_back(
            {{"name", name}, {"colour", colour}, {"radii", std::move(r)}, {"centres", packed(centres)}});
    }

    void ViewDocument::path(const std::string &label, const std::string &colour, const std::vector<Vec3> &points)
    {
        std::vector<double> flat;
        flat.reserve(points.size() * 3);
        for (const auto &v : points)
        {
            flat.insert(flat.end(), v.begin(), v.end());
        }
        json_["paths"].push_back({{"label", label}, {"colour", colour}, {"points", packed(flat)}});
    }

    void ViewDocument::beliefs(const std::string &label, const std::string &colour,
                               const std::vector<std::size_t> &steps, const std::vector<std::vector<Vec3>> &points)
    {
        nlohmann::json offsets = nlohmann::json::array();
        std::vector<double> flat;
        std::size_t offset = 0;
        for (const auto &snapshot : points)
        {
            offsets.push_back(offset);
            offset += snapshot.size();
            for (const auto &p : snapshot)
            {
                flat.insert(flat.end(), p.begin(), p.end());
            }
        }
        offsets.push_back(offset);
        json_["beliefs"].push_back(
            {{"label", label}, {"colour", colour}, {"steps", steps}, {"offsets", offsets}, {"points", packed(flat)}});
    }

    void ViewDocument::rays(const std::vector<std::size_t> &steps,
                            const std::vector<std::vector<std::array<Vec3, 2>>> &segments)
    {
        nlohmann::json offsets = nlohmann::json::array({0});
        std::vector<double> flat;
        for (const auto &snapshot : segments)
        {
            for (const auto &segment : snapshot)
            {
                flat.insert(flat.end(), segment[0].begin(), segment[0].end());
                flat.insert(flat.end(), segment[1].begin(), segment[1].end());
            }
            offsets.push_back(flat.size() / 6);
        }
        json_["rays"] = {{"steps", steps}, {"offsets", offsets}, {"segments", packed(flat)}};
    }

    std::vector<double> robotSphereFrames(const ompl_ext::RobotModel &robot, const ompl_ext::Environment *environment,
                                          const std::vector<std::vector<double>> &configurations,
                                          std::vector<double> &radii, std::size_t &attachedCount)
    {
        radii.clear();
        for (const auto &s : robot.spheres())
        {
            radii.push_back(s.radius);
        }
        attachedCount = 0;
        std::vector<const ompl_ext::AttachedSpheres *> attached;
        for (const ompl_ext::Environment *e = environment; e; e = e->base())
        {
            for (std::size_t i = 0; i < e->attachedCount(); ++i)
            {
                attached.push_back(&e->attachedSpheres(i));
                for (const auto &s : e->attachedSpheres(i).spheresInLink)
                {
                    radii.push_back(s.radius);
                    ++attachedCount;
                }
            }
        }
        std::vector<double> out;
        out.reserve(configurations.size() * radii.size() * 3);
        for (const auto &q : configurations)
        {
            for (const auto &c : robot.sphereCentersReference(q.data()))
            {
                out.insert(out.end(), {c.x(), c.y(), c.z()});
            }
            if (attached.empty())
            {
                continue;
            }
            const auto links = robot.linkTransformsReference(q.data());
            for (const auto *a : attached)
            {
                const Eigen::Isometry3d &pose = links[static_cast<std::size_t>(a->link)];
                for (const auto &s : a->spheresInLink)
                {
                    const Eigen::Vector3d c = pose * s.center;
                    out.insert(out.end(), {c.x(), c.y(), c.z()});
                }
            }
        }
        return out;
    }

    std::size_t addEnvironment(ViewDocument &view, const ompl_ext::Environment &environment)
    {
        std::size_t added = 0;
        if (environment.base())
        {
            added += addEnvironment(view, *environment.base());
        }
        static const char *palette[] = {"#4f9fbf", "#8d6e63", "#7cb342", "#ffb300", "#26a69a", "#ab47bc", "#78909c"};
        for (std::size_t id = 0; id < environment.objectCount(); ++id)
        {
            const std::string &name = environment.objectName(static_cast<int>(id));
            const int solid = view.layer(name, palette[id % (sizeof(palette) / sizeof(palette[0]))], 0.8);
            const auto &shapes = environment.objectShapes(static_cast<int>(id));
            for (std::size_t k = 0; k < shapes.size(); ++k)
            {
                const auto &shape = shapes[k];
                const Eigen::Isometry3d pose = environment.shapeWorldPose(static_cast<int>(id), k);
                const Eigen::Vector3d t = pose.translation();
                const Eigen::Quaterniond q(pose.rotation());
                const Vec3 centre{t.x(), t.y(), t.z()};
                const Quat rotation{q.x(), q.y(), q.z(), q.w()};
                switch (shape.type)
                {
                    case ompl_ext::ShapeType::Box:
                        view.box(solid, centre, {shape.extents.x(), shape.extents.y(), shape.extents.z()}, rotation);
                        break;
                    case ompl_ext::ShapeType::Sphere:
                        view.sphere(solid, centre, shape.radius);
                        break;
                    case ompl_ext::ShapeType::Cylinder:
                        view.cylinder(solid, centre, rotation, shape.radius, shape.length);
                        break;
                    case ompl_ext::ShapeType::Capsule:
                    {
                        view.cylinder(solid, centre, rotation, shape.radius, shape.length);
                        for (const double end : {-0.5, 0.5})
                        {
                            const Eigen::Vector3d c = pose * Eigen::Vector3d(0.0, 0.0, end * shape.length);
                            view.sphere(solid, {c.x(), c.y(), c.z()}, shape.radius);
                        }
                        break;
                    }
                    case ompl_ext::ShapeType::PointCloud:
                        for (const auto &p : shape.cloud->points())
                        {
                            const Eigen::Vector3d c = pose * p.cast<double>();
                            view.sphere(solid, {c.x(), c.y(), c.z()}, shape.cloud->pointRadius());
                        }
                        break;
                }
                ++added;
            }
        }
        return added;
    }
}  // namespace ropras::scenarios::detail
