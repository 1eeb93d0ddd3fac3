#ifndef ROPRAS_SCENARIOS_BULLET_COLLISION_WORLD_H
#define ROPRAS_SCENARIOS_BULLET_COLLISION_WORLD_H

#include <Eigen/Core>
#include <cstddef>
#include <memory>

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

        void setAgentPosition(std::size_t agent, const Eigen::Vector3d &position);
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
