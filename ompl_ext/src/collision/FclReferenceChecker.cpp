#include "ropras/ompl_ext/collision/FclReferenceChecker.h"

// Only the FCL headers we use: <fcl/fcl.h> alone takes seconds to compile.
#include <fcl/broadphase/broadphase_dynamic_AABB_tree.h>
#include <fcl/geometry/bvh/BVH_model.h>
#include <fcl/geometry/shape/box.h>
#include <fcl/geometry/shape/cylinder.h>
#include <fcl/geometry/shape/sphere.h>
#include <fcl/math/bv/OBBRSS.h>
#include <fcl/narrowphase/collision.h>
#include <fcl/narrowphase/collision_object.h>
#include <fcl/narrowphase/distance.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <limits>
#include <map>
#include <mutex>
#include <sstream>

#include "collision/FclScene.h"
#include "ropras/core/Error.h"
#include "ropras/ompl_ext/model/MeshLoader.h"

namespace ropras::ompl_ext
{
    namespace
    {
        using fcl_reference::GeometryPtr;
        using fcl_reference::ObstacleScene;
        using fcl_reference::SceneCache;
        using fcl_reference::tagLabel;

        /// signed distance of one pair: minus the deepest penetration FCL reports, else FCL's distance
        double signedPairDistance(const fcl::CollisionObjectd *a, const fcl::CollisionObjectd *b)
        {
            fcl::CollisionRequestd request(1000, true);
            fcl::CollisionResultd result;
            if (fcl::collide(a, b, request, result) > 0)
            {
                double depth = 0.0;
                for (std::size_t i = 0; i < result.numContacts(); ++i)
                    depth = std::max(depth, result.getContact(i).penetration_depth);
                return -depth;
            }
            fcl::DistanceRequestd distanceRequest;
            fcl::DistanceResultd distanceResult;
            fcl::distance(a, b, distanceRequest, distanceResult);
            return distanceResult.min_distance;
        }

        struct CollideData
        {
            fcl::CollisionRequestd request;
            bool hit{false};
            const fcl::CollisionObjectd *obstacle{nullptr};
        };

        bool collideCallback(fcl::CollisionObjectd *o1, fcl::CollisionObjectd *o2, void *data)
        {
            auto *d = static_cast<CollideData *>(data);
            if (d->hit)
                return true;
            fcl::CollisionResultd result;
            if (fcl::collide(o1, o2, d->request, result) > 0)
            {
                d->hit = true;
                d->obstacle = o1->getUserData() != nullptr ? o1 : o2;
            }
            return d->hit;
        }

        /** \brief The robot as FCL objects grouped by collision link. Elements are posed by the caller,
            then checked against a scene and against themselves over the self-collision pairs. */
        class Body
        {
        public:
            struct Element
            {
                std::unique_ptr<fcl::CollisionObjectd> object;
                int group{-1};
                std::string label;
            };

            void addElement(GeometryPtr geometry, int group, std::string label)
            {
                if (group < 0)  // not part of any self pair
                    group = int(std::max(groups_.size(), reservedGroups_));
                Element element;
                element.object = std::make_unique<fcl::CollisionObjectd>(std::move(geometry));
                element.group = group;
                element.label = std::move(label);
                if (group >= int(groups_.size()))
                    groups_.resize(std::size_t(group) + 1);
                groups_[std::size_t(group)].push_back(int(elements_.size()));
                elements_.push_back(std::move(element));
            }
            /// groups 0..count-1 are the collision links (the self pairs index them)
            void setGroupCount(std::size_t count)
            {
                reservedGroups_ = std::max(reservedGroups_, count);
                if (count > groups_.size())
                    groups_.resize(count);
            }
            void setSelfPairs(std::vector<std::pair<int, int>> pairs) { selfPairs_ = std::move(pairs); }
            std::size_t size() const { return elements_.size(); }

            void pose(std::size_t element, const Eigen::Isometry3d &transform)
            {
                fcl::CollisionObjectd &object = *elements_[element].object;
                object.setTransform(transform);
                object.computeAABB();
            }

            /// first contact found; "" when none
            std::string firstCollision(const ObstacleScene &scene) const
            {
                if (!scene.objects.empty())
                {
                    for (const Element &element : elements_)
                    {
                        CollideData data;
                        scene.manager->collide(element.object.get(), &data, collideCallback);
                        if (data.hit)
                            return element.label + " touches " + scene.labels[tagLabel(data.obstacle)];
                    }
                }
                std::vector<fcl::AABBd> boxes = groupBoxes();
                for (const auto &[a, b] : selfPairs_)
                {
                    if (!boxes[std::size_t(a)].overlap(boxes[std::size_t(b)]))
                        continue;
                    for (int i : groups_[std::size_t(a)])
                    {
                        for (int j : groups_[std::size_t(b)])
                        {
                            const auto *oi = elements_[std::size_t(i)].object.get();
                            const auto *oj = elements_[std::size_t(j)].object.get();
                            if (!oi->getAABB().overlap(oj->getAABB()))
                                continue;
                            fcl::CollisionRequestd request;
                            fcl::CollisionResultd result;
                            if (fcl::collide(oi, oj, request, result) > 0)
                                return "self-collision: " + elements_[std::size_t(i)].label + " touches " +
                                       elements_[std::size_t(j)].label;
                        }
                    }
                }
                return "";
            }

            double signedDistance(const ObstacleScene &scene) const
            {
                double best = std::numeric_limits<double>::infinity();
                // A pair whose bounding boxes are disjoint is at least as far apart as the boxes are.
                auto visit = [&best](const fcl::CollisionObjectd *a, const fcl::CollisionObjectd *b)
                {
                    const double lower = a->getAABB().distance(b->getAABB());
                    if (lower > 0.0 && lower >= best)
                        return;
                    best = std::min(best, signedPairDistance(a, b));
                };
                for (const Element &element : elements_)
                    for (const auto &obstacle : scene.objects)
                        visit(element.object.get(), obstacle.get());
                for (const auto &[a, b] : selfPairs_)
                    for (int i : groups_[std::size_t(a)])
                        for (int j : groups_[std::size_t(b)])
                            visit(elements_[std::size_t(i)].object.get(), elements_[std::size_t(j)].object.get());
                return best;
            }

            /// label of the first element outside the groups in \a skip that touches \a object; "" when none
            std::string touching(const fcl::CollisionObjectd &object, const std::vector<std::uint8_t> &skip) const
            {
                for (const Element &element : elements_)
                {
                    if (element.group >= 0 && std::size_t(element.group) < skip.size() &&
                        skip[std::size_t(element.group)])
                        continue;
                    if (!element.object->getAABB().overlap(object.getAABB()))
                        continue;
                    fcl::CollisionRequestd request;
                    fcl::CollisionResultd result;
                    if (fcl::collide(element.object.get(), &object, request, result) > 0)
                        return element.label;
                }
                return "";
            }

            /// smallest signed distance from \a object to an element outside the groups in \a skip
            double distanceTo(const fcl::CollisionObjectd &object, const std::vector<std::uint8_t> &skip) const
            {
                double best = std::numeric_limits<double>::infinity();
                for (const Element &element : elements_)
                    if (element.group < 0 || std::size_t(element.group) >= skip.size() ||
                        !skip[std::size_t(element.group)])
                        best = std::min(best, signedPairDistance(element.object.get(), &object));
                return best;
            }

        private:
            std::vector<fcl::AABBd> groupBoxes() const
            {
                std::vector<fcl::AABBd> boxes(groups_.size());
                for (std::size_t g = 0; g < groups_.size(); ++g)
                {
                    bool first = true;
                    for (int e : groups_[g])
                    {
                        const fcl::AABBd &box = elements_[std::size_t(e)].object->getAABB();
                        if (first)
                            boxes[g] = box;
                        else
                            boxes[g] += box;
                        first = false;
                    }
                }
                return boxes;
            }

            std::vector<Element> elements_;
            std::vector<std::vector<int>> groups_;  ///< element indices per collision link
            std::vector<std::pair<int, int>> selfPairs_;
            std::size_t reservedGroups_{0};
        };

        /// an attached body's spheres posed by the reference FK, as FCL spheres
        struct PosedAttachment
        {
            std::string label;
            int frame{-1};
            const std::vector<std::uint8_t> *mayTouch{nullptr};
            std::vector<std::unique_ptr<fcl::CollisionObjectd>> spheres;
        };

        std::vector<PosedAttachment> poseAttachments(const RobotModel &robot, const Environment &env, const double *q)
        {
            std::vector<PosedAttachment> out;
            if (!env.hasAttachedBodies())
                return out;
            const std::vector<Eigen::Isometry3d> transforms = robot.linkTransformsReference(q);
            for (const Environment *e = &env; e != nullptr; e = e->base())
                for (std::size_t i = 0; i < e->attachedCount(); ++i)
                {
                    const AttachedSpheres &a = e->attachedSpheres(i);
                    const std::string &name = e->attachedBody(i).name;
                    if (a.robot.get() != &robot)
                        throw Error("FCL reference: attached body '" + name + "' was attached to another robot model " +
                                    "than '" + robot.name() + "'");
                    PosedAttachment posed;
                    posed.label = "attached body '" + name + "'";
                    posed.frame = a.frame;
                    posed.mayTouch = &a.mayTouch;
                    for (const Sphere &s : a.spheresInLink)
                    {
                        Eigen::Isometry3d at = Eigen::Isometry3d::Identity();
                        at.translation() = transforms[std::size_t(a.link)] * s.center;
                        auto object =
                            std::make_unique<fcl::CollisionObjectd>(std::make_shared<fcl::Sphered>(s.radius), at);
                        object->computeAABB();
                        posed.spheres.push_back(std::move(object));
                    }
                    out.push_back(std::move(posed));
                }
            return out;
        }

        bool objectsCollide(const fcl::CollisionObjectd &a, const fcl::CollisionObjectd &b)
        {
            fcl::CollisionRequestd request;
            fcl::CollisionResultd result;
            return a.getAABB().overlap(b.getAABB()) && fcl::collide(&a, &b, request, result) > 0;
        }

        /// first contact of an attached body (obstacles, robot links it may not touch, bodies on other frames)
        std::string attachedCollision(const Body &body, const ObstacleScene &scene,
                                      const std::vector<PosedAttachment> &attached)
        {
            for (std::size_t k = 0; k < attached.size(); ++k)
                for (const auto &sphere : attached[k].spheres)
                {
                    if (!scene.objects.empty())
                    {
                        CollideData data;
                        scene.manager->collide(sphere.get(), &data, collideCallback);
                        if (data.hit)
                            return attached[k].label + " touches " + scene.labels[tagLabel(data.obstacle)];
                    }
                    const std::string link = body.touching(*sphere, *attached[k].mayTouch);
                    if (!link.empty())
                        return attached[k].label + " touches " + link;
                    for (std::size_t m = k + 1; m < attached.size(); ++m)
                        if (attached[m].frame != attached[k].frame)
                            for (const auto &other : attached[m].spheres)
                                if (objectsCollide(*sphere, *other))
                                    return attached[k].label + " touches " + attached[m].label;
                }
            return "";
        }

        double attachedDistance(const Body &body, const ObstacleScene &scene,
                                const std::vector<PosedAttachment> &attached)
        {
            double best = std::numeric_limits<double>::infinity();
            for (std::size_t k = 0; k < attached.size(); ++k)
                for (const auto &sphere : attached[k].spheres)
                {
                    for (const auto &obstacle : scene.objects)
                        best = std::min(best, signedPairDistance(sphere.get(), obstacle.get()));
                    best = std::min(best, body.distanceTo(*sphere, *attached[k].mayTouch));
                    for (std::size_t m = k + 1; m < attached.size(); ++m)
                        if (attached[m].frame != attached[k].frame)
                            for (const auto &other : attached[m].spheres)
                                best = std::min(best, signedPairDistance(sphere.get(), other.get()));
                }
            return best;
        }

        /// the first contact of the robot, else of its attached bodies; "" when none (both checkers' query)
        std::string firstContact(const Body &body, const ObstacleScene &scene,
                                 const std::vector<PosedAttachment> &attached)
        {
            const std::string robot = body.firstCollision(scene);
            return robot.empty() ? attachedCollision(body, scene, attached) : robot;
        }

        double smallestDistance(const Body &body, const ObstacleScene &scene,
                                const std::vector<PosedAttachment> &attached)
        {
            return std::min(body.signedDistance(scene), attachedDistance(body, scene, attached));
        }

        void requireFinite(const RobotModel &robot, const double *q, const char *who)
        {
            for (std::size_t i = 0; i < robot.dof(); ++i)
            {
                if (!std::isfinite(q[i]))
                {
                    std::ostringstream msg;
                    msg << who << ": joint '" << robot.joints()[i].name << "' of robot '" << robot.name()
                        << "' is not finite (" << q[i] << ")";
                    throw Error(msg.str());
                }
            }
        }
        /** \brief Poses the robot body of \a impl (FclSphereChecker::Impl or FclMeshChecker::Impl) at \a q in the
            cached obstacle scene of \a env and returns \a query(body, scene), under the impl's mutex. */
        template <class Impl, class Query>
        auto posedQuery(const RobotModel &robot, Impl &impl, const Environment &env, const double *q,
                        const Query &query)
        {
            std::lock_guard<std::mutex> lock(impl.mutex);
            const ObstacleScene &scene = impl.cache.get(env);
            impl.pose(robot, q);
            return query(impl.body, scene, poseAttachments(robot, env, q));
        }
    }  // namespace

    // ---------------------------------------------------------------------------------------------------------
    // FclSphereChecker

    struct FclSphereChecker::Impl
    {
        std::mutex mutex;
        Body body;
        SceneCache cache;

        void pose(const RobotModel &robot, const double *q)
        {
            const std::vector<Eigen::Vector3d> centers = robot.sphereCentersReference(q);
            for (std::size_t i = 0; i < centers.size(); ++i)
            {
                Eigen::Isometry3d at = Eigen::Isometry3d::Identity();
                at.translation() = centers[i];
                body.pose(i, at);
            }
        }
    };

    FclSphereChecker::FclSphereChecker(std::shared_ptr<const RobotModel> robot)
        : robot_(std::move(robot)), impl_(std::make_unique<Impl>())
    {
        if (!robot_)
            throw Error("FclSphereChecker: null robot model");
        const auto &spheres = robot_->spheres();
        const auto &links = robot_->collisionLinks();
        impl_->body.setGroupCount(links.size());
        for (std::size_t i = 0; i < spheres.size(); ++i)
        {
            const CollisionSphere &s = spheres[i];
            const std::string linkName = s.collisionLink >= 0 && s.collisionLink < int(links.size())
                                             ? links[std::size_t(s.collisionLink)].name
                                             : "?";
            impl_->body.addElement(std::make_shared<fcl::Sphered>(s.radius), s.collisionLink,
                                   "link '" + linkName + "' sphere " + std::to_string(i));
        }
        impl_->body.setSelfPairs(robot_->selfCollisionPairs());
    }

    FclSphereChecker::~FclSphereChecker() = default;

    bool FclSphereChecker::isValid(const Environment &env, const double *q) const
    {
        return robot_->withinBounds(q) && posedQuery(*robot_, *impl_, env, q, firstContact).empty();
    }

    double FclSphereChecker::distance(const Environment &env, const double *q) const
    {
        requireFinite(*robot_, q, "FclSphereChecker::distance");
        return posedQuery(*robot_, *impl_, env, q, smallestDistance);
    }

    std::string FclSphereChecker::describeCollision(const Environment &env, const double *q) const
    {
        requireFinite(*robot_, q, "FclSphereChecker::describeCollision");
        return posedQuery(*robot_, *impl_, env, q, firstContact);
    }

    // ---------------------------------------------------------------------------------------------------------
    // FclMeshChecker

    struct FclMeshChecker::Impl
    {
        std::mutex mutex;
        Body body;
        SceneCache cache;
        std::vector<int> elementLink;                  ///< links() index per element
        std::vector<Eigen::Isometry3d> elementOrigin;  ///< in the link frame
        std::size_t triangles{0};

        void pose(const RobotModel &robot, const double *q)
        {
            const std::vector<Eigen::Isometry3d> transforms = robot.linkTransformsReference(q);
            for (std::size_t e = 0; e < elementLink.size(); ++e)
                body.pose(e, transforms[std::size_t(elementLink[e])] * elementOrigin[e]);
        }
    };

    FclMeshChecker::FclMeshChecker(std::shared_ptr<const RobotModel> robot)
        : robot_(std::move(robot)), impl_(std::make_unique<Impl>())
    {
        if (!robot_)
            throw Error("FclMeshChecker: null robot model");
        const auto &links = robot_->links();
        const auto &collisionLinks = robot_->collisionLinks();
        // links() index -> collisionLinks() index (the self pairs are over collision links)
        std::vector<int> groupOfLink(links.size(), -1);
        for (std::size_t c = 0; c < collisionLinks.size(); ++c)
            groupOfLink[std::size_t(collisionLinks[c].link)] = int(c);
        impl_->body.setGroupCount(collisionLinks.size());

        // meshes used several times (e.g. gripper fingers) are loaded once
        std::map<std::pair<std::string, std::array<double, 3>>, GeometryPtr> meshes;
        const auto &geometries = robot_->collisionGeometries();
        for (std::size_t g = 0; g < geometries.size(); ++g)
        {
            const CollisionGeometry &geometry = geometries[g];
            GeometryPtr shape;
            std::string kind;
            switch (geometry.type)
            {
                case CollisionGeometry::Type::Sphere:
                    shape = std::make_shared<fcl::Sphered>(geometry.radius);
                    kind = "sphere";
                    break;
                case CollisionGeometry::Type::Box:
                    shape = std::make_shared<fcl::Boxd>(geometry.extents);
                    kind = "box";
                    break;
                case CollisionGeometry::Type::Cylinder:
                    shape = std::make_shared<fcl::Cylinderd>(geometry.radius, geometry.length);
                    kind = "cylinder";
                    break;
                case CollisionGeometry::Type::Mesh:
                {
                    const auto key = std::make_pair(
                        geometry.meshPath,
                        std::array<double, 3>{geometry.scale.x(), geometry.scale.y(), geometry.scale.z()});
                    auto found = meshes.find(key);
                    if (found == meshes.end())
                    {
                        const TriangleMesh mesh = loadMesh(geometry.meshPath, geometry.scale);
                        std::vector<fcl::Triangle> triangles;
                        triangles.reserve(mesh.triangles.size());
                        for (const auto &t : mesh.triangles)
                            triangles.emplace_back(std::size_t(t[0]), std::size_t(t[1]), std::size_t(t[2]));
                        auto model = std::make_shared<fcl::BVHModel<fcl::OBBRSSd>>();
                        if (model->beginModel(int(triangles.size()), int(mesh.vertices.size())) != fcl::BVH_OK ||
                            model->addSubModel(mesh.vertices, triangles) != fcl::BVH_OK ||
                            model->endModel() != fcl::BVH_OK)
                            throw Error("FclMeshChecker: FCL could not build a BVH for mesh '" + geometry.meshPath +
                                        "' of robot '" + robot_->source() + "'");
                        found = meshes.emplace(key, std::move(model)).first;
                    }
                    impl_->triangles += static_cast<const fcl::BVHModel<fcl::OBBRSSd> &>(*found->second).num_tris;
                    shape = found->second;
                    kind = "mesh '" + geometry.meshPath + "'";
                    break;
                }
            }
            // a geometry on a link without spheres (group -1) is checked against obstacles only
            impl_->body.addElement(shape, groupOfLink[std::size_t(geometry.link)],
                                   "link '" + links[std::size_t(geometry.link)].name + "' " + kind);
            impl_->elementLink.push_back(geometry.link);
            impl_->elementOrigin.push_back(geometry.origin);
        }
        impl_->body.setSelfPairs(robot_->selfCollisionPairs());
    }

    FclMeshChecker::~FclMeshChecker() = default;

    std::size_t FclMeshChecker::geometryCount() const
    {
        return impl_->body.size();
    }

    std::size_t FclMeshChecker::triangleCount() const
    {
        return impl_->triangles;
    }

    bool FclMeshChecker::isValid(const Environment &env, const double *q) const
    {
        return robot_->withinBounds(q) && posedQuery(*robot_, *impl_, env, q, firstContact).empty();
    }

    double FclMeshChecker::distance(const Environment &env, const double *q) const
    {
        requireFinite(*robot_, q, "FclMeshChecker::distance");
        return posedQuery(*robot_, *impl_, env, q, smallestDistance);
    }

    std::string FclMeshChecker::describeCollision(const Environment &env, const double *q) const
    {
        requireFinite(*robot_, q, "FclMeshChecker::describeCollision");
        return posedQuery(*robot_, *impl_, env, q, firstContact);
    }
}  // namespace ropras::ompl_ext
