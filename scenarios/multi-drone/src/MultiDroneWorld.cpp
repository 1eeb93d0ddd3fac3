#include "ropras/scenarios/multi-drone/MultiDroneWorld.h"

#include <utility>

#include "ropras/core/Error.h"

namespace ropras::scenarios
{
    MultiDroneWorld::MultiDroneWorld(std::shared_ptr<const MultiDroneModel> model) : model_(std::move(model))
    {
        if (!model_)
        {
            throw Error("MultiDroneWorld: null model");
        }
        const auto &config = model_->config();
        for (std::size_t d = 0; d < MULTI_DRONE_COUNT; ++d)
        {
            const auto &p = config.starts[d];
            bullet_.addAgent(config.droneRadius, Eigen::Vector3d(p[0], p[1], p[2]));
        }
    }

    void MultiDroneWorld::reset(const State &initial)
    {
        state_ = initial;
        for (std::size_t d = 0; d < MULTI_DRONE_COUNT; ++d)
        {
            bullet_.setAgentPosition(d, Eigen::Vector3d(initial.drone[d][0], initial.drone[d][1], initial.drone[d][2]));
        }
    }

    bool MultiDroneWorld::blocked(std::size_t d, const double *p) const
    {
        return bullet_.collides(d, Eigen::Vector3d(p[0], p[1], p[2]));
    }

    pomdp::StepResult<MultiDroneModel::State, MultiDroneModel::Observation> MultiDroneWorld::step(const Action &action,
                                                                                                  pomdp::Rng &rng)
    {
        pomdp::StepResult<State, Observation> out;
        out.next = state_;
        double p[3];
        const std::size_t d = MultiDroneModel::droneOf(action);
        if (model_->proposeMove(state_, action, p) && !blocked(d, p))
        {
            MultiDroneModel::setDrone(out.next, d, p);
            bullet_.setAgentPosition(d, Eigen::Vector3d(p[0], p[1], p[2]));
        }
        model_->finishStep(out, rng);
        state_ = out.next;
        return out;
    }
}  // namespace ropras::scenarios
