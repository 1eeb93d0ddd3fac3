#include "ropras/scenarios/manipulation/RayDetectPlanning.h"

#include <algorithm>
#include <cmath>
#include <string>
#include <utility>

#include "ropras/core/Error.h"
#include "ropras/ompl_ext/kinematics/CollisionFreePredicate.h"
#include "ropras/ompl_ext/scene/EnvironmentQueries.h"
#include "ropras/scenarios/manipulation/ArmPlanning.h"
#include "ropras/scenarios/manipulation/BallIk.h"

namespace ropras::scenarios
{
    namespace
    {
        /// solutions kept per target
        constexpr std::size_t POOL_SIZE = 8;

        Eigen::Vector3d vec(const std::array<double, 3> &v)
        {
            return Eigen::Vector3d(v[0], v[1], v[2]);
        }

        std::uint64_t mix(std::uint64_t h, std::int64_t v) noexcept
        {
            h ^= static_cast<std::uint64_t>(v) + 0x9e3779b97f4a7c15ULL + (h << 6) + (h >> 2);
            h *= 0xbf58476d1ce4e5b9ULL;
            return h ^ (h >> 31);
        }
    }  // namespace

    RayDetectTargetSpace::RayDetectTargetSpace(std::shared_ptr<const RayDetectModel> model,
                                               std::shared_ptr<const ompl_ext::Environment> planningScene)
        : model_(std::move(model)), scene_(std::move(planningScene))
    {
        if (!model_ || !scene_)
        {
            throw Error("RayDetectTargetSpace: null model or scene");
        }
    }

    RayDetectTarget RayDetectTargetSpace::goal(const RayDetectModel::State &) const
    {
        RayDetectTarget t;
        t.kind = RayDetectTarget::Kind::Goal;
        t.point = model_->config().goalPoint;
        return t;
    }

    RayDetectTarget RayDetectTargetSpace::informative(const RayDetectModel::State &particle, std::size_t i) const
    {
        RayDetectTarget t;
        t.kind = RayDetectTarget::Kind::Look;
        t.object = static_cast<int>(i % RAY_DETECT_OBSTACLES);
        const double *pose = particle.poses[t.object];
        t.point = {{pose[0], pose[1], pose[2]}};
        return t;
    }

    double RayDetectTargetSpace::distance(const RayDetectModel::State &agent, const RayDetectTarget &target) const
    {
        const Eigen::Vector3d ee = model_->endEffector(agent);
        if (target.kind == RayDetectTarget::Kind::Configuration)
        {
            return (ee - model_->arm().endEffectorPosition(target.q.data())).norm();
        }
        return (ee - vec(target.point)).norm();
    }

    std::uint64_t RayDetectTargetSpace::cell(const RayDetectModel::State &particle, std::size_t k) const
    {
        const double c = model_->config().entropyCell;
        std::uint64_t h = 0x9e3779b97f4a7c15ULL;
        for (std::size_t i = 0; i < 3; ++i)
        {
            const double v = std::floor(particle.poses[k][i] / c);
            h = mix(h, static_cast<std::int64_t>(std::isfinite(v) ? std::fmax(-1e15, std::fmin(1e15, v)) : 0.0));
        }
        return h;
    }

    std::uint64_t RayDetectTargetSpace::entropyBin(const RayDetectModel::State &particle) const
    {
        std::uint64_t h = 0;
        for (std::size_t k = 0; k < RAY_DETECT_OBSTACLES; ++k)
        {
            h = mix(h, static_cast<std::int64_t>(cell(particle, k)));
        }
        return h;
    }

    double RayDetectTargetSpace::beliefEntropy(pomdp::BeliefView<RayDetectModel::State> belief) const
    {
        thread_local std::vector<std::uint64_t> bins;
        double sum = 0.0;
        for (std::size_t k = 0; k < RAY_DETECT_OBSTACLES; ++k)
        {
            bins.clear();
            for (const auto &particle : belief)
            {
                bins.push_back(cell(particle, k));
            }
            sum += pomdp::normalizedEntropy(bins, 0);
        }
        return sum / static_cast<double>(RAY_DETECT_OBSTACLES);
    }

    bool RayDetectTargetSpace::sampleFree(pomdp::Rng &rng, RayDetectTarget &out) const
    {
        const PandaArm &arm = model_->arm();
        out.kind = RayDetectTarget::Kind::Configuration;
        for (int attempt = 0; attempt < 100; ++attempt)
        {
            for (std::size_t j = 0; j < ARM_DOF; ++j)
            {
                out.q[j] = rng.uniform(arm.lower(j), arm.upper(j));
            }
            if (arm.checker()->isValid(*scene_, out.q.data()))
            {
                return true;
            }
        }
        return false;
    }

    RayDetectGoalSampler::RayDetectGoalSampler(std::shared_ptr<const RayDetectModel> model,
                                               std::shared_ptr<const ompl_ext::Environment> planningScene,
                                               std::uint64_t seed)
        : model_(std::move(model)),
          working_(planningScene ? *planningScene : ompl_ext::Environment()),
          ik_(model_ ? model_->arm().endEffectorChain() : throw Error("RayDetectGoalSampler: null model")),
          workspace_(ik_.makeWorkspace()),
          rng_(seed),
          pools_(1 + RAY_DETECT_OBSTACLES)
    {
        if (!planningScene || working_.objectCount() != RAY_DETECT_OBSTACLES)
        {
            throw Error("RayDetectGoalSampler: the planning scene must hold the 4 obstacles");
        }
        const RayDetectConfig &c = model_->config();
        goalOptions_.restarts = c.ikRestarts;
        goalOptions_.positionTolerance = 1e-4;
        goalOptions_.validate();
        lookOptions_.restarts = c.ikRestarts;
        lookOptions_.positionTolerance = 1e-3;
        lookOptions_.orientationTolerance = c.lookAxisTolerance;
        lookOptions_.validate();
        free_ = ompl_ext::collisionFreePredicate(*model_->arm().checker(), working_);
    }

    bool RayDetectGoalSampler::valid(const double *q, int object) const noexcept
    {
        if (!model_->arm().checker()->isValid(working_, q))
        {
            return false;
        }
        if (object < 0)
        {
            return true;
        }
        Eigen::Vector3d origin, direction;
        model_->ray(q, origin, direction);
        const auto hit = ompl_ext::firstHit(working_, origin, origin + model_->config().rayLength * direction);
        return hit.hit && hit.object == object;
    }

    bool RayDetectGoalSampler::fromPool(std::size_t pool, int object, double *q) noexcept
    {
        auto &solutions = pools_[pool];
        if (solutions.empty())
        {
            return false;
        }
        // a random rotation of the pool, so that the particles' solutions vary
        const std::size_t first = rng_.uniformIndex(solutions.size());
        for (std::size_t i = 0; i < solutions.size(); ++i)
        {
            const auto &s = solutions[(first + i) % solutions.size()];
            if (valid(s.data(), object))
            {
                std::copy(s.begin(), s.end(), q);
                return true;
            }
        }
        return false;
    }

    void RayDetectGoalSampler::remember(std::size_t pool, const double *q)
    {
        auto &solutions = pools_[pool];
        std::array<double, ARM_DOF> s{};
        std::copy(q, q + ARM_DOF, s.begin());
        if (solutions.size() < POOL_SIZE)
        {
            solutions.push_back(s);
        }
        else
        {
            solutions[rng_.uniformIndex(POOL_SIZE)] = s;
        }
    }

    bool RayDetectGoalSampler::solveGoal(const double *seed, double *q) noexcept
    {
        const RayDetectConfig &c = model_->config();
        return solvePositionInBall(ik_, vec(c.goalPoint), c.ikRadiusFraction * c.goalRadius, c.ikPoints, seed, rng_,
                                   workspace_, goalOptions_, &free_, q, &solves_);
    }

    bool RayDetectGoalSampler::solveLook(const RayDetectModel::State &particle, int object, double *q) noexcept
    {
        const RayDetectConfig &c = model_->config();
        const double *pose = particle.poses[object];
        const Eigen::Vector3d centre(pose[0], pose[1], pose[2]);
        Eigen::Vector3d away = vec(c.lookFrom) - centre;
        if (!(away.norm() > 1e-6))
        {
            away = Eigen::Vector3d::UnitZ();
        }
        const Eigen::Vector3d origin = centre + c.lookStandoff * away.normalized();
        const auto target = ompl_ext::IkTarget::positionAxis(origin, centre - origin);
        const ompl_ext::ConfigurationPredicate sees = [this, object](const double *x) { return valid(x, object); };
        for (std::size_t attempt = 0; attempt < c.ikPoints; ++attempt)
        {
            ++solves_;
            const auto result = ik_.solve(target, particle.q, rng_, workspace_, q, lookOptions_, &sees);
            if (result.status == ompl_ext::IkStatus::Solved)
            {
                return true;
            }
        }
        return false;
    }

    bool RayDetectGoalSampler::solve(const RayDetectModel::State &particle, const RayDetectTarget &target,
                                     double *q) noexcept
    {
        if (target.kind == RayDetectTarget::Kind::Configuration)
        {
            std::copy(target.q.begin(), target.q.end(), q);
            return true;
        }
        poseRayDetectObstacles(particle, working_);
        const bool look = target.kind == RayDetectTarget::Kind::Look;
        const int object = look ? target.object : -1;
        if (look && (object < 0 || object >= static_cast<int>(RAY_DETECT_OBSTACLES)))
        {
            return false;
        }
        const std::size_t pool = look ? 1 + static_cast<std::size_t>(object) : 0;
        // a full pool answers alone (IK only while it fills or when no kept solution fits this particle)
        if (fromPool(pool, object, q) && pools_[pool].size() >= POOL_SIZE)
        {
            return true;
        }
        const bool solved = look ? solveLook(particle, object, q) : solveGoal(particle.q, q);
        if (solved)
        {
            remember(pool, q);
            return true;
        }
        return fromPool(pool, object, q);
    }

    RayDetectPlanningAdapter::RayDetectPlanningAdapter(std::unique_ptr<RayDetectGoalSampler> sampler, double step,
                                                       std::size_t macroLength, bool waypoints)
        : sampler_(std::move(sampler)), step_(step), macroLength_(macroLength), waypoints_(waypoints)
    {
        if (!sampler_)
        {
            throw Error("RayDetectPlanningAdapter: null goal sampler");
        }
        if (!(step > 0.0) || !std::isfinite(step))
        {
            throw Error("ray-detect planning: step " + std::to_string(step) + " must be > 0");
        }
        if (macroLength == 0)
        {
            throw Error("ray-detect planning: parameter macro_length must be >= 1");
        }
    }

    void RayDetectPlanningAdapter::configuration(const RayDetectModel::State &state, double *q) const
    {
        std::copy(state.q, state.q + ARM_DOF, q);
    }

    bool RayDetectPlanningAdapter::targetConfiguration(const RayDetectModel::State &start,
                                                       const RayDetectTarget &target, double *q) const
    {
        return sampler_->solve(start, target, q);
    }

    bool RayDetectPlanningAdapter::pathToMacroAction(const RayDetectModel::State &, const double *waypoints,
                                                     std::size_t count, std::vector<ArmAction> &out) const
    {
        return jointPathToArmActions(waypoints, count, step_, macroLength_, waypoints_, points_, out);
    }

    bool RayDetectPlanningAdapter::poseObstacles(const RayDetectModel::State &particle,
                                                 ompl_ext::Environment &working) const
    {
        poseRayDetectObstacles(particle, working);
        return true;
    }
}  // namespace ropras::scenarios
