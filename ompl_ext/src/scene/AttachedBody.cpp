#include "ropras/ompl_ext/scene/AttachedBody.h"

#include <algorithm>
#include <cmath>
#include <string>
#include <utility>

#include "model/EnclosingSphere.h"
#include "ropras/core/Error.h"
#include "ropras/ompl_ext/model/RobotModel.h"
#include "scene/ShapeValidation.h"

namespace ropras::ompl_ext
{
    namespace
    {
        /// the sphere cover of one shape, in the body frame
        void coverShape(const Shape &shape, const SpherizerOptions &options, std::vector<Sphere> &out)
        {
            std::vector<Sphere> local;
            switch (shape.type)
            {
                case ShapeType::Sphere:
                    local.push_back({Eigen::Vector3d::Zero(), shape.radius});
                    break;
                case ShapeType::Box:
                    local = spherizer::coverBox(shape.extents, options);
                    break;
                case ShapeType::Cylinder:
                    local = spherizer::coverCylinder(shape.radius, shape.length, options);
                    break;
                case ShapeType::Capsule:
                    // the cylinder between the cap centres and the two caps (each a sphere of the capsule's radius)
                    if (shape.length > 0.0)
                        local = spherizer::coverCylinder(shape.radius, shape.length, options);
                    local.push_back({Eigen::Vector3d(0.0, 0.0, 0.5 * shape.length), shape.radius});
                    local.push_back({Eigen::Vector3d(0.0, 0.0, -0.5 * shape.length), shape.radius});
                    break;
                case ShapeType::PointCloud:
                    break;  // refused before
            }
            for (Sphere &s : local)
                out.push_back({shape.pose * s.center, s.radius});
        }

        void coverMesh(const std::string &where, const AttachedMesh &mesh, const SpherizerOptions &options,
                       std::vector<Sphere> &out)
        {
            if (mesh.vertices.empty() || mesh.triangles.empty())
                throw Error(where + ": the mesh has no triangles");
            for (const Eigen::Vector3d &v : mesh.vertices)
                if (!v.allFinite())
                    throw Error(where + ": the mesh has a non-finite vertex");
            const auto n = static_cast<int>(mesh.vertices.size());
            for (const Eigen::Vector3i &t : mesh.triangles)
                if ((t.array() < 0).any() || (t.array() >= n).any())
                    throw Error(where + ": a triangle names vertex " + std::to_string(t.maxCoeff()) + " or " +
                                std::to_string(t.minCoeff()) + " of " + std::to_string(n));
            const std::string poseError = detail::poseProblem(mesh.pose);
            if (!poseError.empty())
                throw Error(where + ": " + poseError);
            for (const Sphere &s : spherizer::coverMesh(mesh.vertices, mesh.triangles, options))
                out.push_back({mesh.pose * s.center, s.radius});
        }

        int linkOf(const RobotModel &robot, const std::string &where, const std::string &name)
        {
            try
            {
                return robot.linkIndex(name);
            }
            catch (const Error &)
            {
                throw Error(where + ": robot '" + robot.name() + "' has no link '" + name + "'");
            }
        }
    }  // namespace

    AttachedSpheres compileAttachedBody(std::shared_ptr<const RobotModel> robot, const AttachedBody &body,
                                        const SpherizerOptions &spherizer)
    {
        const std::string where = "attached body '" + body.name + "'";
        if (!robot)
            throw Error(where + ": no robot model given (null pointer)");
        const int link = linkOf(*robot, where, body.link);
        const std::string poseError = detail::poseProblem(body.pose);
        if (!poseError.empty())
            throw Error(where + ": " + poseError);
        if (body.shapes.empty() && body.meshes.empty())
            throw Error(where + ": it has no shapes");

        std::vector<Sphere> inBody;
        for (std::size_t k = 0; k < body.shapes.size(); ++k)
        {
            detail::validateShape(where, k, body.shapes[k]);
            if (body.shapes[k].type == ShapeType::PointCloud)
                throw Error(where + " shape " + std::to_string(k) + ": point clouds cannot be attached");
            coverShape(body.shapes[k], spherizer, inBody);
        }
        for (std::size_t k = 0; k < body.meshes.size(); ++k)
            coverMesh(where + " mesh " + std::to_string(k), body.meshes[k], spherizer, inBody);

        AttachedSpheres out;
        out.link = link;
        const Link &l = robot->links()[static_cast<std::size_t>(link)];
        out.frame = l.frame;
        out.count = static_cast<int>(inBody.size());
        std::vector<Sphere> inFrame;
        for (const Sphere &s : inBody)
        {
            out.spheresInLink.push_back({body.pose * s.center, s.radius});
            inFrame.push_back({l.inFrame * out.spheresInLink.back().center, s.radius});
        }
        const auto padded = static_cast<std::size_t>((out.count + ATTACHED_SPHERE_PADDING - 1) /
                                                     ATTACHED_SPHERE_PADDING * ATTACHED_SPHERE_PADDING);
        for (std::size_t i = 0; i < padded; ++i)
        {
            const Sphere &s = inFrame[i % inFrame.size()];  // padding repeats the body's own spheres
            out.x.push_back(static_cast<float>(s.center.x()));
            out.y.push_back(static_cast<float>(s.center.y()));
            out.z.push_back(static_cast<float>(s.center.z()));
            out.r.push_back(static_cast<float>(s.radius));
        }
        const Sphere bound = enclosingSphere(inFrame);
        out.bx = static_cast<float>(bound.center.x());
        out.by = static_cast<float>(bound.center.y());
        out.bz = static_cast<float>(bound.center.z());
        // enlarged for float rounding: culling with it never drops a touching sphere
        out.br = static_cast<float>(bound.radius * (1.0 + 1e-5) + 1e-6);

        std::vector<int> touch{link};
        for (const std::string &name : body.touchLinks)
            touch.push_back(linkOf(*robot, where + " touch link", name));
        out.mayTouch.assign(robot->collisionLinks().size(), 0);
        for (std::size_t c = 0; c < robot->collisionLinks().size(); ++c)
            if (std::find(touch.begin(), touch.end(), robot->collisionLinks()[c].link) != touch.end())
                out.mayTouch[c] = 1;
        // links of the body's own frame never move relative to it: decide their contact once, in double
        out.skipLink = out.mayTouch;
        for (std::size_t c = 0; c < robot->collisionLinks().size(); ++c)
            if (out.mayTouch[c] != 0 && robot->collisionLinks()[c].frame != out.frame)
                out.touchesOtherFrames = true;
        for (std::size_t c = 0; c < robot->collisionLinks().size(); ++c)
        {
            const CollisionLink &cl = robot->collisionLinks()[c];
            if (cl.frame != out.frame)
                continue;
            out.skipLink[c] = 1;
            if (out.mayTouch[c] != 0)
                continue;
            for (int k = cl.firstSphere; k < cl.firstSphere + cl.sphereCount; ++k)
            {
                const CollisionSphere &s = robot->spheres()[static_cast<std::size_t>(k)];
                for (const Sphere &b : inFrame)
                    if ((s.centerInFrame - b.center).norm() <= s.radius + b.radius)
                        out.alwaysCollides = true;
            }
        }
        out.robot = std::move(robot);
        return out;
    }
}  // namespace ropras::ompl_ext
