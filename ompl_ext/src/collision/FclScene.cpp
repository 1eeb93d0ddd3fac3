#include "collision/FclScene.h"

#include <fcl/geometry/shape/box.h>
#include <fcl/geometry/shape/capsule.h>
#include <fcl/geometry/shape/cylinder.h>
#include <fcl/geometry/shape/sphere.h>

#include <cstdint>

namespace ropras::ompl_ext::fcl_reference
{
    namespace
    {
        /// everything that determines the FCL scene, in a comparable form
        void sceneSignature(const Environment &env, std::vector<double> &numbers, std::vector<const void *> &clouds)
        {
            numbers.clear();
            clouds.clear();
            for (const Environment *e = &env; e != nullptr; e = e->base())
                for (std::size_t id = 0; id < e->objectCount(); ++id)
                {
                    const auto &shapes = e->objectShapes(int(id));
                    numbers.push_back(double(shapes.size()));
                    for (std::size_t k = 0; k < shapes.size(); ++k)
                    {
                        const Shape &s = shapes[k];
                        const Eigen::Isometry3d pose = e->shapeWorldPose(int(id), k);
                        numbers.push_back(double(int(s.type)));
                        numbers.push_back(s.radius);
                        numbers.push_back(s.length);
                        numbers.insert(numbers.end(), s.extents.data(), s.extents.data() + 3);
                        const Eigen::Matrix<double, 3, 4> affine = pose.affine();
                        numbers.insert(numbers.end(), affine.data(), affine.data() + 12);
                        clouds.push_back(s.cloud.get());
                    }
                }
        }

        void *labelTag(std::size_t index)
        {
            return reinterpret_cast<void *>(std::uintptr_t(index + 1));
        }

        std::shared_ptr<const ObstacleScene> buildScene(const Environment &env)
        {
            auto scene = std::make_shared<ObstacleScene>();
            sceneSignature(env, scene->signature, scene->clouds);
            auto add = [&](GeometryPtr geometry, const Eigen::Isometry3d &pose, std::string label)
            {
                auto object = std::make_unique<fcl::CollisionObjectd>(std::move(geometry), pose);
                object->setUserData(labelTag(scene->labels.size()));
                scene->labels.push_back(std::move(label));
                scene->objects.push_back(std::move(object));
            };
            for (const Environment *e = &env; e != nullptr; e = e->base())
                for (std::size_t id = 0; id < e->objectCount(); ++id)
                {
                    const auto &shapes = e->objectShapes(int(id));
                    for (std::size_t k = 0; k < shapes.size(); ++k)
                    {
                        const Shape &s = shapes[k];
                        const Eigen::Isometry3d pose = e->shapeWorldPose(int(id), k);
                        std::string label = "object '" + e->objectName(int(id)) + "'";
                        if (shapes.size() > 1)
                            label += " primitive " + std::to_string(k);
                        switch (s.type)
                        {
                            case ShapeType::Sphere:
                            case ShapeType::Box:
                            case ShapeType::Cylinder:
                            case ShapeType::Capsule:
                                add(primitiveGeometry(s), pose, label);
                                break;
                            case ShapeType::PointCloud:
                            {
                                if (!s.cloud)
                                    break;
                                auto sphere = std::make_shared<fcl::Sphered>(double(s.cloud->pointRadius()));
                                const auto &points = s.cloud->points();
                                for (std::size_t i = 0; i < points.size(); ++i)
                                {
                                    Eigen::Isometry3d at = Eigen::Isometry3d::Identity();
                                    at.translation() = pose * points[i].cast<double>();
                                    add(sphere, at, label + " point " + std::to_string(i));
                                }
                                break;
                            }
                        }
                    }
                }
            scene->manager = std::make_unique<fcl::DynamicAABBTreeCollisionManagerd>();
            std::vector<fcl::CollisionObjectd *> raw;
            raw.reserve(scene->objects.size());
            for (auto &object : scene->objects)
                raw.push_back(object.get());
            if (!raw.empty())
                scene->manager->registerObjects(raw);
            scene->manager->setup();
            return scene;
        }
    }  // namespace

    GeometryPtr primitiveGeometry(const Shape &s)
    {
        switch (s.type)
        {
            case ShapeType::Sphere:
                return std::make_shared<fcl::Sphered>(s.radius);
            case ShapeType::Box:
                return std::make_shared<fcl::Boxd>(s.extents);
            case ShapeType::Cylinder:
                return std::make_shared<fcl::Cylinderd>(s.radius, s.length);
            case ShapeType::Capsule:
                return std::make_shared<fcl::Capsuled>(s.radius, s.length);
            case ShapeType::PointCloud:
                break;
        }
        return nullptr;
    }

    std::size_t tagLabel(const fcl::CollisionObjectd *object)
    {
        return std::size_t(reinterpret_cast<std::uintptr_t>(object->getUserData())) - 1;
    }

    const ObstacleScene &SceneCache::get(const Environment &env)
    {
        sceneSignature(env, numbers_, clouds_);
        if (!scene_ || scene_->signature != numbers_ || scene_->clouds != clouds_)
            scene_ = buildScene(env);
        return *scene_;
    }
}  // namespace ropras::ompl_ext::fcl_reference
