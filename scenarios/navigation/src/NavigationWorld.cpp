#include "ropras/scenarios/navigation/NavigationWorld.h"

#include "ropras/core/Error.h"

namespace ropras::scenarios
{
    namespace
    {
        Eigen::Vector3d vec(const std::array<double, 3> &a)
        {
            return Eigen::Vector3d(a[0], a[1], a[2]);
        }
    }  // namespace

    NavigationWorld::NavigationWorld(std::shared_ptr<const NavigationModel> model) : model_(std::move(model))
    {
        if (!model_)
        {
            throw Error("NavigationWorld: null model");
        }
        const auto &c = model_->config();
        bullet_ = std::make_unique<BulletCollisionWorld>();
        for (const auto *list : {&c.walls, &c.obstacles})
        {
            for (const auto &b : *list)
            {
                Eigen::Vector3d half = 0.5 * (vec(b.hi) - vec(b.lo));
                bullet_->addBox(vec(b.center()), half);
            }
        }
        agent_ = bullet_->addAgent(c.robotRadius, vec(c.starts.front()));
    }

    void NavigationWorld::reset(const State &initial)
    {
        state_ = initial;
        bullet_->setAgentPosition(agent_, Eigen::Vector3d(initial.p[0], initial.p[1], initial.p[2]));
    }

    bool NavigationWorld::blocked(const double *p) const
    {
        const auto &c = model_->config();
        for (int k = 0; k < c.dims; ++k)
        {
            if (!(p[k] >= c.bounds.lo[k] && p[k] <= c.bounds.hi[k]))
            {
                return true;
            }
        }
        return bullet_->collides(agent_, Eigen::Vector3d(p[0], p[1], p[2]));
    }

    pomdp::StepResult<NavState, NavObservation> NavigationWorld::step(const Action &action, pomdp::Rng &rng)
    {
        State next = model_->moved(state_, model_->executedAction(action, rng));
        if (blocked(next.p))
        {
            next = state_;
        }
        pomdp::StepResult<State, Observation> out;
        model_->arrive(next, rng, out);
        state_ = next;
        bullet_->setAgentPosition(agent_, Eigen::Vector3d(next.p[0], next.p[1], next.p[2]));
        return out;
    }
}  // namespace ropras::scenarios
