// `ropras spherize`: writes a copy of a URDF whose collision geometry (boxes, cylinders, meshes) is replaced by the
// conservative sphere cover that RobotModel computes for it, so that the robot ships without its meshes.
#include <tinyxml2.h>

#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <map>
#include <sstream>
#include <stdexcept>

#include "ArgumentChecks.h"
#include "CommandRegistry.h"
#include "ropras/core/Error.h"
#include "ropras/ompl_ext/model/RobotModel.h"

namespace
{
    namespace fs = std::filesystem;
    using namespace ropras::ompl_ext;

    struct Args
    {
        std::string urdf, output;
        double tolerance{SpherizerOptions{}.tolerance};
        int maxSpheres{SpherizerOptions{}.maxSpheresPerGeometry};
        std::vector<std::string> links;  ///< "LINK=TOLERANCE/MAX" overrides
    };

    /// the settings of one link: "TOLERANCE/MAX" or "TOLERANCE"; anything else throws Error naming the option
    SpherizerOptions parseLinkSettings(const std::string &link, const std::string &value, SpherizerOptions o)
    {
        const std::string what = "--link " + link + "=" + value + ": expected TOLERANCE or TOLERANCE/MAX_SPHERES, ";
        const auto slash = value.find('/');
        std::size_t used = 0;
        try
        {
            o.tolerance = std::stod(value.substr(0, slash), &used);
            if (used != value.substr(0, slash).size())
                throw std::invalid_argument(value);
            if (slash != std::string::npos)
            {
                const double max = std::stod(value.substr(slash + 1), &used);
                if (used != value.size() - slash - 1 || !(max >= 1 && max <= 100000) || max != std::floor(max))
                    throw ropras::Error(what + "the sphere count must be a whole number in [1, 100000]");
                o.maxSpheresPerGeometry = static_cast<int>(max);
            }
        }
        catch (const std::logic_error &)
        {
            throw ropras::Error(what + "got something else");
        }
        if (!(std::isfinite(o.tolerance) && o.tolerance > 0))
            throw ropras::Error(what + "the tolerance must be a finite number > 0");
        return o;
    }

    /// 7 decimals (0.1 micrometre): enough for any robot, short enough to read
    std::string fixed7(double v)
    {
        char text[40];
        std::snprintf(text, sizeof(text), "%.7f", v == 0.0 ? 0.0 : v);
        return text;
    }

    /** The radius written for a sphere whose centre is written rounded to 7 decimals: rounded up, plus the
        centre's rounding (at most sqrt(3) * 0.5e-7 m), so the written sphere contains the computed one. */
    double writtenRadius(double radius)
    {
        return std::ceil((radius + 1e-7) * 1e7) / 1e7;
    }

    std::string describe(const CollisionGeometry &g)
    {
        std::ostringstream out;
        switch (g.type)
        {
            case CollisionGeometry::Type::Sphere:
                out << "sphere r " << g.radius;
                break;
            case CollisionGeometry::Type::Box:
                out << "box " << g.extents.x() << " x " << g.extents.y() << " x " << g.extents.z();
                break;
            case CollisionGeometry::Type::Cylinder:
                out << "cylinder r " << g.radius << " l " << g.length;
                break;
            case CollisionGeometry::Type::Mesh:
                out << "mesh " << fs::path(g.meshPath).filename().string();
                break;
        }
        char bound[64];
        std::snprintf(bound, sizeof(bound), " (protrusion bound %.4f m)", g.coverProtrusion);
        return out.str() + bound;
    }

    int run(const Args &a)
    {
        RobotModel::Options options;
        options.spherizer.tolerance = a.tolerance;
        options.spherizer.maxSpheresPerGeometry = a.maxSpheres;
        options.disableAlwaysColliding = false;  // only the spheres are needed
        const auto robot = RobotModel::fromUrdfFile(a.urdf, "", options);
        // per-link settings: the model is loaded once more for each, and those links take their spheres from it
        std::map<std::string, std::shared_ptr<const RobotModel>> modelOf;
        std::map<std::string, SpherizerOptions> settingsOf;
        for (const auto &[link, value] : ropras::bin::keyValueOptions(a.links, "--link"))
        {
            robot->linkIndex(link);  // throws for an unknown link
            const SpherizerOptions s = parseLinkSettings(link, value, options.spherizer);
            settingsOf[link] = s;
            RobotModel::Options linkOptions = options;
            linkOptions.spherizer = s;
            modelOf[link] = RobotModel::fromUrdfFile(a.urdf, "", linkOptions);
        }
        const auto modelFor = [&](const std::string &link) -> const RobotModel &
        {
            const auto it = modelOf.find(link);
            return it == modelOf.end() ? *robot : *it->second;
        };

        tinyxml2::XMLDocument doc;
        if (doc.LoadFile(a.urdf.c_str()) != tinyxml2::XML_SUCCESS)
            throw ropras::Error(a.urdf + ": malformed XML: " + (doc.ErrorStr() ? doc.ErrorStr() : ""));
        tinyxml2::XMLElement *root = doc.FirstChildElement("robot");
        if (root == nullptr)
            throw ropras::Error(a.urdf + ": no <robot> element");

        std::map<std::string, int> collisionLinkOf;
        for (std::size_t i = 0; i < robot->collisionLinks().size(); ++i)
            collisionLinkOf[robot->collisionLinks()[i].name] = static_cast<int>(i);

        std::size_t written = 0;
        for (tinyxml2::XMLElement *link = root->FirstChildElement("link"); link != nullptr;
             link = link->NextSiblingElement("link"))
        {
            while (tinyxml2::XMLElement *c = link->FirstChildElement("collision"))
                link->DeleteChild(c);
            const char *name = link->Attribute("name");
            const auto it = collisionLinkOf.find(name ? name : "");
            if (it == collisionLinkOf.end())
                continue;
            const RobotModel &model = modelFor(it->first);
            const CollisionLink &cl = model.collisionLinks()[it->second];
            std::string covers;
            for (const CollisionGeometry &g : model.collisionGeometries())
                if (g.link == cl.link)
                    covers += (covers.empty() ? "" : ", ") + describe(g);
            link->InsertEndChild(
                doc.NewComment((" " + std::to_string(cl.sphereCount) + " spheres covering " + covers + " ").c_str()));
            for (int s = cl.firstSphere; s < cl.firstSphere + cl.sphereCount; ++s)
            {
                const CollisionSphere &sphere = model.spheres()[s];
                tinyxml2::XMLElement *collision = doc.NewElement("collision");
                tinyxml2::XMLElement *origin = collision->InsertNewChildElement("origin");
                const Eigen::Vector3d &c = sphere.centerInLink;
                origin->SetAttribute("xyz", (fixed7(c.x()) + " " + fixed7(c.y()) + " " + fixed7(c.z())).c_str());
                origin->SetAttribute("rpy", "0 0 0");
                collision->InsertNewChildElement("geometry")
                    ->InsertNewChildElement("sphere")
                    ->SetAttribute("radius", fixed7(writtenRadius(sphere.radius)).c_str());
                link->InsertEndChild(collision);
                ++written;
            }
        }

        std::string linkNote;
        for (const std::string &l : a.links)
            linkNote += " --link " + l;
        std::ostringstream note;
        note << " Collision spheres written by `ropras spherize --tolerance " << a.tolerance << " --max-spheres "
             << a.maxSpheres << linkNote << "` from the collision geometry of " << fs::path(a.urdf).filename().string()
             << ": " << written << " spheres on " << robot->collisionLinks().size()
             << " links. Every surface point of each element lies inside a sphere of its link (radii rounded up). ";
        root->InsertFirstChild(doc.NewComment(note.str().c_str()));
        if (doc.SaveFile(a.output.c_str()) != tinyxml2::XML_SUCCESS)
            throw ropras::Error("--output: cannot write '" + a.output + "'");

        std::cout << "wrote " << a.output << ": " << written << " spheres on " << robot->collisionLinks().size()
                  << " links (tolerance " << a.tolerance << " m, at most " << a.maxSpheres << " per element)\n";
        for (const CollisionLink &link : robot->collisionLinks())
        {
            const RobotModel &model = modelFor(link.name);
            const CollisionLink &cl = model.collisionLinks()[collisionLinkOf.at(link.name)];
            const auto s = settingsOf.find(cl.name);
            std::cout << "  " << cl.name << ": " << cl.sphereCount << " spheres";
            if (s != settingsOf.end())
                std::cout << " (tolerance " << s->second.tolerance << ", at most " << s->second.maxSpheresPerGeometry
                          << ")";
            for (const CollisionGeometry &g : model.collisionGeometries())
                if (g.link == cl.link)
                    std::cout << "; " << describe(g);
            std::cout << '\n';
        }
        return 0;
    }

    std::function<int()> setup(CLI::App &app)
    {
        auto a = std::make_shared<Args>();
        app.add_option("--urdf", a->urdf, "robot URDF with box / cylinder / mesh collision geometry")
            ->required()
            ->check(CLI::ExistingFile);
        app.add_option("--output", a->output, "URDF to write: the same robot with sphere collision elements")
            ->required();
        app.add_option("--tolerance", a->tolerance, "how far (m) spheres may reach beyond the geometry")
            ->capture_default_str()
            ->check(ropras::bin::POSITIVE_NUMBER);
        app.add_option("--max-spheres", a->maxSpheres, "at most this many spheres per collision element")
            ->capture_default_str()
            ->check(ropras::bin::POSITIVE_COUNT & CLI::Range(1, 100000));
        app.add_option("--link", a->links,
                       "LINK=TOLERANCE/MAX: other settings for one link (repeatable), e.g. panda_link5=0.015/40");
        return [a] { return run(*a); };
    }

    const ropras::bin::CommandRegistrar reg{
        {"spherize", "write a URDF whose collision geometry is a conservative sphere cover (no meshes needed)", setup}};
}  // namespace
