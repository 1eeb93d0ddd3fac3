// GCC 12 reports a false -Wmaybe-uninitialized inside Eigen's AVX-512 4x4 products (-march=native builds).
#if defined(__GNUC__) && !defined(__clang__)
#pragma GCC diagnostic ignored "-Wmaybe-uninitialized"
#endif

#include <urdf_model/model.h>

#include <algorithm>
#include <cmath>
#include <sstream>

#include "model/EnclosingSphere.h"
#include "model/ModelText.h"
#include "model/RobotModelBuilder.h"
#include "model/UrdfPose.h"
#include "model/UrdfSanity.h"
#include "ropras/ompl_ext/model/MeshLoader.h"

namespace ropras::ompl_ext
{
    namespace
    {
        using model_text::fmt;
        using urdf_pose::finitePose;
        using urdf_pose::toIsometry;
    }  // namespace

    void RobotModelBuilder::checkPositive(double v, const std::string &what, const std::string &link, int element) const
    {
        if (!std::isfinite(v) || v <= 0.0)
        {
            fail("link '" + link + "' <collision> #" + std::to_string(element) + ": " + what + " " + fmt(v) +
                 " must be positive and finite");
        }
        failIf(urdf_sanity::sizeProblem("link '" + link + "' <collision> #" + std::to_string(element) + ": " + what, v,
                                        what == "mesh scale"));
    }

    void RobotModelBuilder::buildCollisionGeometry(const urdf::ModelInterface &urdf)
    {
        std::map<std::string, SphereCover> meshCovers;  // "path|scale" -> cover in the mesh frame
        for (std::size_t li = 0; li < model_->links_.size(); ++li)
        {
            const Link &link = model_->links_[li];
            const urdf::Link &ul = *urdf.links_.at(link.name);
            if (static_cast<int>(ul.collision_array.size()) != collisionCount_[link.name])
            {
                fail("link '" + link.name + "': urdfdom accepted " + std::to_string(ul.collision_array.size()) +
                     " of its " + std::to_string(collisionCount_[link.name]) + " <collision> elements");
            }
            std::vector<Sphere> linkSpheres;
            int element = 0;
            for (const urdf::CollisionSharedPtr &c : ul.collision_array)
            {
                ++element;
                if (!c || !c->geometry)
                {
                    continue;
                }
                CollisionGeometry g;
                g.link = static_cast<int>(li);
                g.origin = toIsometry(c->origin);
                if (!finitePose(g.origin))
                {
                    fail("link '" + link.name + "' <collision> #" + std::to_string(element) + ": non-finite <origin>");
                }
                failIf(urdf_sanity::originProblem(
                    "link '" + link.name + "' <collision> #" + std::to_string(element) + " <origin>", g.origin));
                SphereCover cover;
                try
                {
                    cover = coverElement(*c, link.name, element, g, meshCovers);
                }
                catch (const Error &e)
                {
                    const std::string msg = e.what();
                    if (msg.find(urdfName_) != std::string::npos)
                    {
                        throw;
                    }
                    fail("link '" + link.name + "' <collision> #" + std::to_string(element) + ": " + msg);
                }
                for (Sphere &s : cover.spheres)
                {
                    s.center = g.origin * s.center;
                    linkSpheres.push_back(s);
                }
                g.coverProtrusion = cover.protrusion;
                model_->geometries_.push_back(g);
            }
            if (linkSpheres.empty())
            {
                continue;
            }
            addCollisionLink(li, linkSpheres);
        }
    }

    SphereCover RobotModelBuilder::coverElement(const urdf::Collision &c, const std::string &link, int element,
                                                CollisionGeometry &g,
                                                std::map<std::string, SphereCover> &meshCovers) const
    {
        SphereCover cover;
        switch (c.geometry->type)
        {
            case urdf::Geometry::SPHERE:
            {
                g.type = CollisionGeometry::Type::Sphere;
                g.radius = static_cast<const urdf::Sphere &>(*c.geometry).radius;
                checkPositive(g.radius, "sphere radius", link, element);
                cover.spheres.push_back(Sphere{Eigen::Vector3d::Zero(), g.radius});
                break;
            }
            case urdf::Geometry::BOX:
            {
                const urdf::Vector3 &d = static_cast<const urdf::Box &>(*c.geometry).dim;
                g.type = CollisionGeometry::Type::Box;
                g.extents = Eigen::Vector3d(d.x, d.y, d.z);
                for (int k = 0; k < 3; ++k)
                {
                    checkPositive(g.extents[k], "box size", link, element);
                }
                cover = spherizer::coverBoxDetailed(g.extents, options_.spherizer);
                break;
            }
            case urdf::Geometry::CYLINDER:
            {
                const auto &cyl = static_cast<const urdf::Cylinder &>(*c.geometry);
                g.type = CollisionGeometry::Type::Cylinder;
                g.radius = cyl.radius;
                g.length = cyl.length;
                checkPositive(g.radius, "cylinder radius", link, element);
                checkPositive(g.length, "cylinder length", link, element);
                cover = spherizer::coverCylinderDetailed(g.radius, g.length, options_.spherizer);
                break;
            }
            case urdf::Geometry::MESH:
            {
                cover = meshCover(static_cast<const urdf::Mesh &>(*c.geometry), link, element, g, meshCovers);
                break;
            }
            default:
                fail("link '" + link + "' <collision> #" + std::to_string(element) + ": unsupported geometry");
        }
        return cover;
    }

    SphereCover RobotModelBuilder::meshCover(const urdf::Mesh &mesh, const std::string &link, int element,
                                             CollisionGeometry &g, std::map<std::string, SphereCover> &meshCovers) const
    {
        g.type = CollisionGeometry::Type::Mesh;
        g.scale = Eigen::Vector3d(mesh.scale.x, mesh.scale.y, mesh.scale.z);
        for (int k = 0; k < 3; ++k)
        {
            checkPositive(std::abs(g.scale[k]), "mesh scale", link, element);
        }
        g.meshPath = resolveMeshPath(mesh.filename, model_->baseDir_, urdfName_);
        std::ostringstream key;
        key.precision(17);
        key << g.meshPath << '|' << g.scale.x() << ',' << g.scale.y() << ',' << g.scale.z();
        auto it = meshCovers.find(key.str());
        if (it == meshCovers.end())
        {
            const TriangleMesh tm = loadMesh(g.meshPath, g.scale);
            it = meshCovers
                     .emplace(key.str(), spherizer::coverMeshDetailed(tm.vertices, tm.triangles, options_.spherizer))
                     .first;
        }
        return it->second;
    }

    void RobotModelBuilder::addCollisionLink(std::size_t li, const std::vector<Sphere> &linkSpheres)
    {
        const Link &link = model_->links_[li];
        CollisionLink cl;
        cl.name = link.name;
        cl.link = static_cast<int>(li);
        cl.frame = link.frame;
        cl.firstSphere = static_cast<int>(model_->spheres_.size());
        cl.sphereCount = static_cast<int>(linkSpheres.size());
        std::vector<Sphere> inFrame;
        for (const Sphere &s : linkSpheres)
        {
            CollisionSphere cs;
            cs.centerInLink = s.center;
            cs.centerInFrame = link.inFrame * s.center;
            cs.radius = s.radius;
            cs.collisionLink = static_cast<int>(model_->collisionLinks_.size());
            model_->spheres_.push_back(cs);
            inFrame.push_back(Sphere{cs.centerInFrame, cs.radius});
        }
        // the refinement costs 2 x iterations x spheres: a link of 100 000 spheres gets 200 iterations
        // instead of 2000 (the bound still encloses every sphere exactly; it is only a little less tight)
        const int iterations =
            inFrame.size() > 10000 ? std::max(200, static_cast<int>(2e7 / double(inFrame.size()))) : 2000;
        const Sphere bound = enclosingSphere(inFrame, iterations);
        cl.boundCenterInFrame = bound.center;
        cl.boundRadius = bound.radius;
        model_->collisionLinks_.push_back(cl);
    }
}  // namespace ropras::ompl_ext
