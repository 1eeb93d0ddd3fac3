#include "ropras/scenarios/crossing/CrossingWorld.h"

#include <utility>
#include <vector>

#include "ropras/core/Error.h"

namespace ropras::scenarios
{
    namespace
    {
        Eigen::Isometry3d basePose(const CrossingState &s)
        {
            Eigen::Isometry3d pose = Eigen::Isometry3d::Identity();
            pose.translation() = Eigen::Vector3d(s.x, s.y, 0.0);
            pose.linear() = Eigen::AngleAxisd(s.theta, Eigen::Vector3d::UnitZ()).toRotationMatrix();
            return pose;
        }
    }  // namespace

    CrossingWorld::CrossingWorld(std::shared_ptr<const CrossingModel> model) : model_(std::move(model))
    {
        if (!model_)
        {
            throw Error("CrossingWorld: null model");
        }
        const CrossingConfig &c = model_->config();
        // the walls: four boxes outside the lab, overlapping at the corners
        const double t = c.wallThickness, h = 0.5 * c.wallHeight;
        const double cx = 0.5 * (c.labLo[0] + c.labHi[0]), cy = 0.5 * (c.labLo[1] + c.labHi[1]);
        const double hx = 0.5 * (c.labHi[0] - c.labLo[0]) + t, hy = 0.5 * (c.labHi[1] - c.labLo[1]) + t;
        bullet_.addBox({cx, c.labLo[1] - 0.5 * t, h}, {hx, 0.5 * t, h});
        bullet_.addBox({cx, c.labHi[1] + 0.5 * t, h}, {hx, 0.5 * t, h});
        bullet_.addBox({c.labLo[0] - 0.5 * t, cy, h}, {0.5 * t, hy, h});
        bullet_.addBox({c.labHi[0] + 0.5 * t, cy, h}, {0.5 * t, hy, h});
        for (const auto &table : c.tables)
        {
            bullet_.addBox({table.center[0], table.center[1], table.center[2]},
                           {table.halfExtents[0], table.halfExtents[1], table.halfExtents[2]});
        }
        std::vector<std::pair<Eigen::Vector3d, double>> spheres;
        for (const auto &s : model_->spheres())
        {
            spheres.emplace_back(Eigen::Vector3d(s.x, s.y, s.z), s.radius);
        }
        State s;
        s.x = c.start[0];
        s.y = c.start[1];
        s.theta = c.start[2];
        robot_ = bullet_.addRigidAgent(spheres, basePose(s));
        pedestrian_ =
            bullet_.addAgent(c.pedestrianRadius, {c.pedestrianStart[0], c.pedestrianStart[1], c.pedestrianHeight});
    }

    void CrossingWorld::reset(const State &initial)
    {
        state_ = initial;
        bullet_.setAgentPose(robot_, basePose(initial));
        bullet_.setAgentPosition(pedestrian_, {initial.px, initial.py, model_->config().pedestrianHeight});
    }

    CrossingEvent CrossingWorld::contact(const State &s)
    {
        bullet_.setAgentPosition(pedestrian_, {s.px, s.py, model_->config().pedestrianHeight});
        const auto touch = bullet_.touching(robot_, basePose(s));
        if ((touch.agents & (std::uint64_t{1} << pedestrian_)) != 0)
        {
            return CrossingEvent::Pedestrian;
        }
        return touch.obstacle ? CrossingEvent::Obstacle : CrossingEvent::None;
    }

    pomdp::StepResult<CrossingModel::State, CrossingModel::Observation> CrossingWorld::step(const Action &action,
                                                                                            pomdp::Rng &rng)
    {
        const double noise = model_->config().worldPedestrianSpeedNoise;
        const double scale = noise > 0.0 ? 1.0 + rng.uniform(-noise, noise) : 1.0;
        pomdp::StepResult<State, Observation> out;
        model_->simulate(
            state_, action, scale, rng, [this](const State &q) { return contact(q); }, out);
        state_ = out.next;
        reset(state_);
        return out;
    }
}  // namespace ropras::scenarios
