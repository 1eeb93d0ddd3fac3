#include "ropras/scenarios/manipulation/ArmPlanning.h"

#include <cmath>
#include <limits>
#include <string>
#include <utility>

#include "ropras/core/Error.h"
#include "ropras/ompl_ext/kinematics/CollisionFreePredicate.h"
#include "ropras/scenarios/manipulation/BallIk.h"

namespace ropras::scenarios
{
    ArmGoalSampler::ArmGoalSampler(std::shared_ptr<const PandaArm> arm,
                                   std::shared_ptr<const ompl_ext::Environment> environment, const Settings &settings,
                                   std::uint64_t seed)
        : arm_(std::move(arm)),
          environment_(std::move(environment)),
          settings_(settings),
          ik_(arm_->endEffectorChain()),
          workspace_(ik_.makeWorkspace()),
          rng_(seed)
    {
        if (!environment_)
        {
            throw Error("ArmGoalSampler: null environment");
        }
        options_.restarts = settings_.restarts;
        options_.positionTolerance = 1e-4;
        options_.validate();
        valid_ = ompl_ext::collisionFreePredicate(*arm_->checker(), *environment_);
    }

    std::vector<std::array<double, ARM_DOF>> ArmGoalSampler::pooled(const std::array<double, 3> &center) const
    {
        for (const auto &p : pools_)
        {
            if (p.center == center)
            {
                return p.solutions;
            }
        }
        return {};
    }

    std::size_t ArmGoalSampler::pick(const Pool &pool, const double *seed) noexcept
    {
        if (!settings_.nearest)
        {
            return rng_.uniformIndex(pool.solutions.size());
        }
        std::size_t best = 0;
        double bestD2 = std::numeric_limits<double>::infinity();
        for (std::size_t k = 0; k < pool.solutions.size(); ++k)
        {
            double d2 = 0.0;
            for (std::size_t j = 0; j < ARM_DOF; ++j)
            {
                const double d = pool.solutions[k][j] - seed[j];
                d2 += d * d;
            }
            if (d2 < bestD2)
            {
                bestD2 = d2;
                best = k;
            }
        }
        return best;
    }

    bool ArmGoalSampler::solve(const double *seed, const std::array<double, 3> &center, double radius,
                               double *q) noexcept
    {
        Pool *pool = nullptr;
        for (auto &p : pools_)
        {
            if (p.center == center)
            {
                pool = &p;
            }
        }
        if (pool == nullptr)
        {
            pools_.push_back(Pool{center, {}});
            pool = &pools_.back();
        }
        if (pool->solutions.size() >= settings_.poolSize)
        {
            const auto &chosen = pool->solutions[pick(*pool, seed)];
            std::copy(chosen.begin(), chosen.end(), q);
            return true;
        }
        if (solvePositionInBall(ik_, Eigen::Vector3d(center[0], center[1], center[2]),
                                settings_.radiusFraction * radius, settings_.points, seed, rng_, workspace_, options_,
                                &valid_, q, &solves_))
        {
            std::array<double, ARM_DOF> solution{};
            std::copy(q, q + ARM_DOF, solution.begin());
            pool->solutions.push_back(solution);
            return true;
        }
        if (!pool->solutions.empty())
        {
            const auto &chosen = pool->solutions[pick(*pool, seed)];
            std::copy(chosen.begin(), chosen.end(), q);
            return true;
        }
        return false;
    }

    SphereSearchTargetSpace::SphereSearchTargetSpace(std::shared_ptr<const SphereSearchModel> model,
                                                     std::shared_ptr<const ompl_ext::Environment> planningEnvironment)
        : model_(std::move(model)), environment_(std::move(planningEnvironment))
    {
        if (!model_ || !environment_)
        {
            throw Error("SphereSearchTargetSpace: null model or environment");
        }
    }

    ArmTarget SphereSearchTargetSpace::goal(const SphereSearchModel::State &particle) const
    {
        ArmTarget t;
        t.point = model_->goalCenter(particle.goal);
        t.radius = model_->config().goalRadius;
        return t;
    }

    ArmTarget SphereSearchTargetSpace::informative(const SphereSearchModel::State &, std::size_t) const
    {
        ArmTarget t;
        t.point = model_->config().light;
        t.radius = model_->config().lightRadius;
        return t;
    }

    double SphereSearchTargetSpace::distance(const SphereSearchModel::State &agent, const ArmTarget &target) const
    {
        const Eigen::Vector3d ee = model_->endEffector(agent);
        if (target.kind == ArmTarget::Kind::Configuration)
        {
            return (ee - model_->arm().endEffectorPosition(target.q.data())).norm();
        }
        return (ee - Eigen::Vector3d(target.point[0], target.point[1], target.point[2])).norm();
    }

    bool SphereSearchTargetSpace::sampleFree(pomdp::Rng &rng, ArmTarget &out) const
    {
        const PandaArm &arm = model_->arm();
        out.kind = ArmTarget::Kind::Configuration;
        for (int attempt = 0; attempt < 100; ++attempt)
        {
            for (std::size_t j = 0; j < ARM_DOF; ++j)
            {
                out.q[j] = rng.uniform(arm.lower(j), arm.upper(j));
            }
            if (arm.checker()->isValid(*environment_, out.q.data()))
            {
                return true;
            }
        }
        return false;
    }

    ArmPlanningAdapter::ArmPlanningAdapter(std::unique_ptr<ArmGoalSampler> sampler, double step,
                                           std::size_t macroLength, bool waypoints)
        : sampler_(std::move(sampler)), step_(step), macroLength_(macroLength), waypoints_(waypoints)
    {
        if (!sampler_)
        {
            throw Error("ArmPlanningAdapter: null goal sampler");
        }
        if (!(step > 0.0) || !std::isfinite(step))
        {
            throw Error("arm planning: step " + std::to_string(step) + " must be > 0");
        }
        if (macroLength == 0)
        {
            throw Error("arm planning: parameter macro_length must be >= 1");
        }
    }

    void ArmPlanningAdapter::configuration(const SphereSearchModel::State &state, double *q) const
    {
        std::copy(state.q, state.q + ARM_DOF, q);
    }

    bool ArmPlanningAdapter::targetConfiguration(const SphereSearchModel::State &start, const ArmTarget &target,
                                                 double *q) const
    {
        if (target.kind == ArmTarget::Kind::Configuration)
        {
            std::copy(target.q.begin(), target.q.end(), q);
            return true;
        }
        return sampler_->solve(start.q, target.point, target.radius, q);
    }

    bool ArmPlanningAdapter::pathToMacroAction(const SphereSearchModel::State &, const double *waypoints,
                                               std::size_t count, std::vector<ArmAction> &out) const
    {
        return jointPathToArmActions(waypoints, count, step_, macroLength_, waypoints_, points_, out);
    }

    bool jointPathToArmActions(const double *waypoints, std::size_t count, double step, std::size_t macroLength,
                               bool waypointActions, std::vector<double> &scratch, std::vector<ArmAction> &out)
    {
        scratch.clear();
        const std::size_t n = pomdp::discretizeJointPath(waypoints, count, ARM_DOF, step, macroLength, scratch);
        const double *previous = waypoints;
        for (std::size_t i = 0; i < n; ++i)
        {
            const double *point = &scratch[i * ARM_DOF];
            ArmAction a;
            for (std::size_t j = 0; j < ARM_DOF; ++j)
            {
                a.dq[j] = waypointActions ? point[j] : point[j] - previous[j];
            }
            a.waypoint = waypointActions;
            out.push_back(a);
            previous = point;
        }
        return n > 0;
    }
}  // namespace ropras::scenarios
