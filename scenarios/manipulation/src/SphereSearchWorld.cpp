#include "ropras/scenarios/manipulation/SphereSearchWorld.h"

#include <utility>

#include "ropras/core/Error.h"

namespace ropras::scenarios
{
    namespace
    {
        std::shared_ptr<const ompl_ext::RobotModel> robotOf(const std::shared_ptr<const SphereSearchModel> &model)
        {
            if (!model)
            {
                throw Error("SphereSearchWorld: null model");
            }
            return model->arm().robot();
        }
    }  // namespace

    SphereSearchWorld::SphereSearchWorld(std::shared_ptr<const SphereSearchModel> model)
        : model_(std::move(model)), bullet_(robotOf(model_))
    {
        for (const auto &o : model_->config().obstacles)
        {
            bullet_.addSphere(Eigen::Vector3d(o[0], o[1], o[2]), o[3]);
        }
    }

    pomdp::StepResult<SphereSearchModel::State, SphereSearchModel::Observation> SphereSearchWorld::step(
        const Action &action, pomdp::Rng &rng)
    {
        pomdp::StepResult<State, Observation> out;
        out.next = state_;
        double target[ARM_DOF];
        model_->proposeMotion(state_, action, rng, target);
        double fraction = 1.0;
        const bool valid = bullet_.motionValid(state_.q, target, model_->config().resolution, &fraction);
        if (valid)
        {
            SphereSearchModel::setJoints(out.next, target);
        }
        else if (!model_->config().collisionTerminal)
        {
            SphereSearchModel::moveAlong(state_.q, target, fraction, out.next.q);
        }
        model_->finishStep(out, !valid, rng);
        state_ = out.next;
        return out;
    }
}  // namespace ropras::scenarios
