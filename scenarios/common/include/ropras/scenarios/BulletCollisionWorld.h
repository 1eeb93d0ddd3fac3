#ifndef ROPRAS_SCENARIOS_BULLET_COLLISION_WORLD_H
#define ROPRAS_SCENARIOS_BULLET_COLLISION_WORLD_H

#include <Eigen/Core>
#include <Eigen/Geometry>
#include <cstddef>
#include <cstdint>
#include <memory>
#include <vector>

namespace ropras::scenarios
{
    /** \brief The physics side of a scenario's world: a Bullet collision world (btCollisionWorld, dynamic
        AABB tree broadphase, GJK/EPA narrowphase) holding static obstacles and movable spherical agents.

        Worlds use it to decide what really happens when an agent moves; the planner's model uses its own
        fast geometry. Bullet stays private (pimpl): this header needs Eigen only. Not thread-safe: one
        instance per episode. */
    class BulletCollisionWorld
    {
    public:
        /** \brief \a contactMargin: two shapes closer than this (m) count as touching (>= 0). */
        explicit BulletCollisionWorld(double contactMargin = 0.0);
        ~BulletCollisionWorld();
        BulletCollisionWorld(const BulletCollisionWorld &) = delete;
        BulletCollisionWorld &operator=(const BulletCollisionWorld &) = delete;

        /** \brief A static axis-aligned box obstacle; returns its index. Throws ropras::Error for a non-finite
            centre or a non-positive half extent. */
        std::size_t addBox(const Eigen::Vector3d &center, const Eigen::Vector3d &halfExtents);
        /** \brief A static sphere obstacle; returns its index. */
        std::size_t addSphere(const Eigen::Vector3d &center, double radius);
        /** \brief A movable sphere (robot, drone) at \a position; returns its agent index. */
        std::size_t addAgent(double radius, const Eigen::Vector3d &position);

        /** \brief A movable rigid body made of spheres (a Bullet compound of btSphereShapes): each
            (centre in the body frame, radius); returns its agent index. Throws ropras::Error for no sphere, a
            non-finite centre or pose, or a non-positive radius. */
        std::size_t addRigidAgent(const std::vector<std::pair<Eigen::Vector3d, double>> &spheres,
                                  const Eigen::Isometry3d &pose);

        /** \brief What an agent placed at a pose would touch: a static obstacle, and which other agents (bit i
            = agent i, for agents 0..63). */
        struct Touching
        {
            bool obstacle{false};
            std::uint64_t agents{0};
            bool any() const { return obstacle || agents != 0; }
        };
        /** \brief What agent \a agent placed at \a pose would touch (its stored pose is left unchanged). */
        Touching touching(std::size_t agent, const Eigen::Isometry3d &pose) const;

        void setAgentPosition(std::size_t agent, const Eigen::Vector3d &position);
        /** \brief Moves agent \a agent to \a pose (position and orientation). */
        void setAgentPose(std::size_t agent, const Eigen::Isometry3d &pose);
        Eigen::Vector3d agentPosition(std::size_t agent) const;

        /** \brief Whether agent \a agent placed at \a position would touch a static obstacle or another agent
            (the agent's stored position is left unchanged). */
        bool collides(std::size_t agent, const Eigen::Vector3d &position) const;

        std::size_t obstacleCount() const;
        std::size_t agentCount() const;

    private:
        struct Impl;
        std::unique_ptr<Impl> impl_;
    };
}  // namespace ropras::scenarios

#endif
