#include "ropras/scenarios/manipulation/RayDetectWorld.h"

#include <utility>

#include "ropras/core/Error.h"

namespace ropras::scenarios
{
    RayDetectWorld::RayDetectWorld(std::shared_ptr<const RayDetectModel> model) : model_(std::move(model))
    {
        if (!model_)
        {
            throw Error("RayDetectWorld: null model");
        }
        reset(model_->nominalState());
    }

    void RayDetectWorld::reset(const State &initial)
    {
        const RayDetectConfig &c = model_->config();
        state_ = initial;
        bullet_ = std::make_unique<ArmBulletWorld>(model_->arm().robot());
        // the 4 obstacles first: Bullet obstacle k is obstacle k of the state (solid boxes), and obstacle
        // RAYS + k its ray box (the same box as triangles, seen only by rays)
        for (std::size_t k = 0; k < RAY_DETECT_OBSTACLES; ++k)
        {
            const auto &e = c.obstacles[k].extents;
            bullet_->addBox(rayDetectPose(initial.poses[k]), Eigen::Vector3d(e[0], e[1], e[2]), false);
        }
        const auto &t = c.tableCenter;
        const auto &te = c.tableExtents;
        bullet_->addBox(Eigen::Isometry3d(Eigen::Translation3d(t[0], t[1], t[2])), Eigen::Vector3d(te[0], te[1], te[2]),
                        false);
        const auto &g = c.targetCenter;
        bullet_->addCylinder(Eigen::Isometry3d(Eigen::Translation3d(g[0], g[1], g[2])), c.targetRadius, c.targetLength,
                             false);
        for (std::size_t k = 0; k < RAY_DETECT_OBSTACLES; ++k)
        {
            const auto &e = c.obstacles[k].extents;
            bullet_->addRayBox(rayDetectPose(initial.poses[k]), Eigen::Vector3d(e[0], e[1], e[2]));
        }
    }

    RayDetectModel::Detection RayDetectWorld::detect(const double *q) const
    {
        RayDetectModel::Detection d;
        Eigen::Vector3d direction;
        model_->ray(q, d.origin, direction);
        const double length = model_->config().rayLength;
        d.end = d.origin + length * direction;
        d.distance = length;
        double fraction = 0.0;
        // a ray that starts inside an obstacle (open fingers straddling a thin box) sees it at distance 0
        constexpr int RAYS = static_cast<int>(RAY_DETECT_OBSTACLES) + 2;  // after the boxes, the table and the can
        int hit = bullet_->containing(d.origin);
        if (hit < 0 || hit >= static_cast<int>(RAY_DETECT_OBSTACLES))
        {
            fraction = 1.0;
            hit = bullet_->rayTest(d.origin, d.end, &fraction);
            hit = hit >= RAYS ? hit - RAYS : -1;
        }
        if (hit >= 0 && hit < static_cast<int>(RAY_DETECT_OBSTACLES))
        {
            d.object = hit;
            d.distance = fraction * length;
            d.end = d.origin + d.distance * direction;
        }
        return d;
    }

    pomdp::StepResult<RayDetectModel::State, RayDetectModel::Observation> RayDetectWorld::step(const Action &action,
                                                                                               pomdp::Rng &rng)
    {
        pomdp::StepResult<State, Observation> out;
        out.next = state_;
        double target[ARM_DOF];
        model_->proposeMotion(state_, action, rng, target);
        double fraction = 1.0;
        if (bullet_->motionValid(state_.q, target, model_->config().resolution, &fraction))
        {
            RayDetectModel::setJoints(out.next, target);
        }
        else
        {
            for (std::size_t j = 0; j < ARM_DOF; ++j)
            {
                out.next.q[j] = state_.q[j] + fraction * (target[j] - state_.q[j]);
            }
        }
        model_->finishStep(out, detect(out.next.q), rng);
        state_ = out.next;
        return out;
    }
}  // namespace ropras::scenarios
