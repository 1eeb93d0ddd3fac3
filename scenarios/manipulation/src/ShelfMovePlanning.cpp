#include "ropras/scenarios/manipulation/ShelfMovePlanning.h"

#include <algorithm>
#include <cmath>
#include <cstring>
#include <utility>

#include "ropras/core/Error.h"
#include "ropras/ompl_ext/kinematics/CollisionFreePredicate.h"

namespace ropras::scenarios
{
    namespace
    {
        constexpr double PI = 3.14159265358979323846;

        std::uint64_t mix(std::uint64_t h, std::int64_t v) noexcept
        {
            h ^= static_cast<std::uint64_t>(v) + 0x9e3779b97f4a7c15ULL + (h << 6) + (h >> 2);
            h *= 0xbf58476d1ce4e5b9ULL;
            return h ^ (h >> 31);
        }

        Eigen::Vector3d centre(const ShelfMoveModel::State &s, int k)
        {
            return Eigen::Vector3d(s.can[k][0], s.can[k][1], s.can[k][2]);
        }

        std::array<double, 3> array3(const Eigen::Vector3d &v)
        {
            return {{v.x(), v.y(), v.z()}};
        }
    }  // namespace

    ShelfMoveIk::ShelfMoveIk(std::shared_ptr<const ShelfMoveModel> model, std::size_t restarts, std::uint64_t seed)
        : model_(std::move(model)),
          ik_(model_ ? model_->arm().endEffectorChain() : throw Error("ShelfMoveIk: null model")),
          workspace_(ik_.makeWorkspace()),
          rng_(seed)
    {
        for (const double degrees : model_->config().graspYaws)
        {
            yaws_.push_back(degrees * PI / 180.0);
        }
        options_.restarts = restarts;
        options_.positionTolerance = 1e-4;
        options_.orientationTolerance = 1e-3;
        options_.validate();
    }

    std::vector<Eigen::Matrix3d> ShelfMoveIk::graspOrientations() const
    {
        const auto &a = model_->config().approach;
        std::vector<Eigen::Matrix3d> out;
        out.reserve(2 * yaws_.size());
        for (const double yaw : yaws_)
        {
            const Eigen::Vector3d z =
                Eigen::AngleAxisd(yaw, Eigen::Vector3d::UnitZ()) * Eigen::Vector3d(a[0], a[1], a[2]);
            for (int i = 0; i < 2; ++i)
            {
                Eigen::Matrix3d r;
                const Eigen::Vector3d x = (i == 0 ? -1.0 : 1.0) * Eigen::Vector3d::UnitZ();
                r.col(0) = x;
                r.col(1) = z.cross(x);
                r.col(2) = z;
                out.push_back(r);
            }
        }
        return out;
    }

    void ShelfMoveIk::setGraspYaws(std::vector<double> yaws)
    {
        if (yaws.empty() || !std::all_of(yaws.begin(), yaws.end(), [](double y) { return std::isfinite(y); }))
        {
            throw Error("ShelfMoveIk: grasp yaws must be a non-empty list of finite angles (rad)");
        }
        yaws_ = std::move(yaws);
    }

    bool ShelfMoveIk::solve(const ShelfMoveModel::State &particle, const ShelfTarget &target,
                            const ompl_ext::Environment &scene, double *q) noexcept
    {
        try
        {
            const ompl_ext::ConfigurationPredicate valid =
                ompl_ext::collisionFreePredicate(*model_->arm().checker(), scene);
            const Eigen::Vector3d p(target.point[0], target.point[1], target.point[2]);
            if (target.kind == ShelfTarget::Kind::Sense)
            {
                const auto &a = model_->config().approach;
                const double rho = model_->config().senseFraction * model_->config().senseDistance;
                for (const double tilt : {0.0, 30.0, 60.0, 90.0})
                {
                    for (const double yaw : {0.0, 30.0, -30.0})
                    {
                        const double t = tilt * PI / 180.0, w = yaw * PI / 180.0;
                        const Eigen::Vector3d back =
                            Eigen::AngleAxisd(w, Eigen::Vector3d::UnitZ()) * Eigen::Vector3d(-a[0], -a[1], 0.0);
                        const Eigen::Vector3d point =
                            p + rho * (std::cos(t) * back + std::sin(t) * Eigen::Vector3d::UnitZ());
                        const auto r = ik_.solve(ompl_ext::IkTarget::position(point), particle.q, rng_, workspace_, q,
                                                 options_, &valid);
                        if (r.status == ompl_ext::IkStatus::Solved)
                        {
                            return true;
                        }
                    }
                }
                return false;
            }
            for (const auto &rotation : graspOrientations())
            {
                // the end effector grasp_offset short of the can centre (grasp) or of the slot (place)
                const Eigen::Vector3d ee = p - model_->config().graspOffset * rotation.col(2);
                const auto r = ik_.solve(ompl_ext::IkTarget::pose(ee, Eigen::Quaterniond(rotation)), particle.q, rng_,
                                         workspace_, q, options_, &valid);
                if (r.status == ompl_ext::IkStatus::Solved)
                {
                    return true;
                }
            }
            return false;
        }
        catch (...)
        {
            return false;
        }
    }

    ShelfMoveTargetSpace::ShelfMoveTargetSpace(std::shared_ptr<const ShelfMoveModel> model) : model_(std::move(model))
    {
        if (!model_)
        {
            throw Error("ShelfMoveTargetSpace: null model");
        }
    }

    ShelfTarget ShelfMoveTargetSpace::grasp(const ShelfMoveModel::State &particle, int can)
    {
        ShelfTarget t;
        t.kind = ShelfTarget::Kind::Grasp;
        t.can = can;
        t.point = array3(centre(particle, can));
        return t;
    }

    ShelfTarget ShelfMoveTargetSpace::sense(const ShelfMoveModel::State &particle, int can)
    {
        ShelfTarget t = grasp(particle, can);
        t.kind = ShelfTarget::Kind::Sense;
        return t;
    }

    ShelfTarget ShelfMoveTargetSpace::place(int slot) const
    {
        ShelfTarget t;
        t.kind = ShelfTarget::Kind::Place;
        t.slot = slot;
        const auto &s = model_->config().slots[static_cast<std::size_t>(slot)];
        t.point = {{s[0], s[1], s[2] + model_->config().placeLift}};
        return t;
    }

    std::size_t ShelfMoveTargetSpace::otherSlot(std::size_t i) const
    {
        return i < model_->config().reservedSlot ? i : i + 1;
    }

    ShelfTarget ShelfMoveTargetSpace::goal(const ShelfMoveModel::State &particle) const
    {
        const auto &c = model_->config();
        const int target = static_cast<int>(c.targetCan);
        if (particle.held < 0)
        {
            const int blocker = blockingCan(particle);
            return grasp(particle, blocker >= 0 ? blocker : target);
        }
        if (particle.held == target)
        {
            return place(static_cast<int>(c.reservedSlot));
        }
        // an obstacle: the free slot (not the reserved one) nearest to the hand
        const Eigen::Vector3d ee = model_->endEffector(particle);
        int best = static_cast<int>(otherSlot(0));
        double bestDistance = 1e300;
        for (std::size_t i = 0; i + 1 < c.slots.size(); ++i)
        {
            const std::size_t slot = otherSlot(i);
            const auto placed = model_->placedOnSlot(particle, static_cast<std::size_t>(particle.held), slot);
            const double d = (ee - Eigen::Vector3d(c.slots[slot][0], c.slots[slot][1], c.slots[slot][2])).norm();
            if (model_->canPlacementValid(placed, static_cast<std::size_t>(particle.held)) && d < bestDistance)
            {
                best = static_cast<int>(slot);
                bestDistance = d;
            }
        }
        return place(best);
    }

    int ShelfMoveTargetSpace::blockingCan(const ShelfMoveModel::State &particle) const noexcept
    {
        const auto &c = model_->config();
        const int target = static_cast<int>(c.targetCan);
        const Eigen::Vector3d t = centre(particle, target);
        const Eigen::Vector3d ee = model_->endEffector(particle);
        int best = -1;
        double bestDistance = 1e300;
        for (int k = 0; k < static_cast<int>(SHELF_CANS); ++k)
        {
            if (k == target || k == particle.held || parked(particle, k))
            {
                continue;
            }
            const Eigen::Vector3d p = centre(particle, k);
            // in front of the target along the approach (+x), on its board, within the hand's reach sideways
            const bool blocks = p.x() < t.x() && std::abs(p.z() - t.z()) < 0.5 * c.canLength &&
                                std::abs(p.y() - t.y()) < c.blockingHalfwidth;
            const double d = (p - ee).norm();
            if (blocks && d < bestDistance)
            {
                best = k;
                bestDistance = d;
            }
        }
        return best;
    }

    bool ShelfMoveTargetSpace::parked(const ShelfMoveModel::State &particle, int can) const noexcept
    {
        const auto &c = model_->config();
        if (can == particle.held)
        {
            return false;
        }
        const Eigen::Vector3d p = centre(particle, can);
        for (std::size_t slot = 0; slot < c.slots.size(); ++slot)
        {
            const auto &at = c.slots[slot];
            if (slot != c.reservedSlot && (p - Eigen::Vector3d(at[0], at[1], at[2])).norm() <= c.placeTolerance)
            {
                return true;
            }
        }
        return false;
    }

    ShelfMoveTargetSpace::Candidates ShelfMoveTargetSpace::candidates(
        const ShelfMoveModel::State &particle) const noexcept
    {
        Candidates c;
        const int target = static_cast<int>(model_->config().targetCan);
        for (int k = 0; k < static_cast<int>(SHELF_CANS); ++k)
        {
            if (parked(particle, k))
            {
                continue;
            }
            c.sensed[c.numSensed++] = k;
            if (k != target && particle.held < 0)
            {
                c.grasped[c.numGrasped++] = k;
            }
        }
        // holding a can: every slot but the reserved one (the target's goal; an obstacle there would block it)
        c.numPlaced = particle.held < 0 ? 0 : model_->config().slots.size() - 1;
        return c;
    }

    std::size_t ShelfMoveTargetSpace::numInformative(const ShelfMoveModel::State &particle) const
    {
        const Candidates c = candidates(particle);
        return c.numGrasped + c.numPlaced + c.numSensed;
    }

    ShelfTarget ShelfMoveTargetSpace::informative(const ShelfMoveModel::State &particle, std::size_t i) const
    {
        const Candidates c = candidates(particle);
        const std::size_t n = c.numGrasped + c.numPlaced + c.numSensed;
        if (n == 0)
        {
            return goal(particle);
        }
        i %= n;
        if (i < c.numGrasped)
        {
            return grasp(particle, c.grasped[i]);
        }
        i -= c.numGrasped;
        if (i < c.numPlaced)
        {
            return place(static_cast<int>(otherSlot(i)));
        }
        return sense(particle, c.sensed[i - c.numPlaced]);
    }

    double ShelfMoveTargetSpace::distance(const ShelfMoveModel::State &agent, const ShelfTarget &target) const
    {
        return (model_->endEffector(agent) - Eigen::Vector3d(target.point[0], target.point[1], target.point[2])).norm();
    }

    std::uint64_t ShelfMoveTargetSpace::entropyBin(const ShelfMoveModel::State &particle) const
    {
        const double bin = model_->config().entropyBin;
        std::uint64_t h = mix(0x243f6a8885a308d3ULL, particle.held + 1);
        for (std::size_t k = 0; k < SHELF_CANS; ++k)
        {
            if (static_cast<int>(k) == particle.held)
            {
                continue;
            }
            for (int a = 0; a < 2; ++a)
            {
                const double c = std::floor(particle.can[k][a] / bin);
                h = mix(h, static_cast<std::int64_t>(std::isfinite(c) ? std::fmax(-1e15, std::fmin(1e15, c)) : 0.0));
            }
        }
        return h;
    }

    ShelfMoveAdapter::ShelfMoveAdapter(std::shared_ptr<const ShelfMoveModel> model, std::unique_ptr<ShelfMoveIk> ik)
        : model_(std::move(model)), ik_(std::move(ik))
    {
        if (!model_ || !ik_)
        {
            throw Error("ShelfMoveAdapter: null model or IK");
        }
    }

    void ShelfMoveAdapter::configuration(const ShelfMoveModel::State &state, double *q) const
    {
        std::copy(state.q, state.q + ARM_DOF, q);
    }

    bool ShelfMoveAdapter::targetConfiguration(const ShelfMoveModel::State &start, const ShelfTarget &target,
                                               double *q) const
    {
        select(start);
        last_ = target;
        return ik_->solve(start, target, *scene_, q);
    }

    void ShelfMoveAdapter::select(const ShelfMoveModel::State &particle) const
    {
        if (!scene_ || std::memcmp(&particle, &sceneOf_, sizeof(particle)) != 0)
        {
            scene_ = model_->makeScene(particle, true);
            sceneOf_ = particle;
            trueScene_ = nullptr;
        }
    }

    std::shared_ptr<const ompl_ext::Environment> ShelfMoveAdapter::environment(
        const ShelfMoveModel::State &particle) const
    {
        select(particle);
        return scene_;
    }

    std::shared_ptr<const ompl_ext::Environment> ShelfMoveAdapter::trueEnvironment(
        const ShelfMoveModel::State &particle) const
    {
        select(particle);
        if (!trueScene_)
        {
            trueScene_ = model_->makeScene(particle, false);
        }
        return trueScene_;
    }

    bool ShelfMoveAdapter::pathToMacroAction(const ShelfMoveModel::State &, const double *waypoints, std::size_t count,
                                             std::vector<ShelfMoveAction> &out) const
    {
        points_.clear();
        const std::size_t n = pomdp::discretizeJointPath(waypoints, count, ARM_DOF, model_->config().step, 0, points_);
        const double *previous = waypoints;
        for (std::size_t i = 0; i < n; ++i)
        {
            const double *point = &points_[i * ARM_DOF];
            ShelfMoveAction a;
            a.waypoint = model_->config().waypointActions;
            for (std::size_t j = 0; j < ARM_DOF; ++j)
            {
                a.dq[j] = a.waypoint ? point[j] : point[j] - previous[j];
            }
            out.push_back(a);
            previous = point;
        }
        if (n > 0 && last_.kind != ShelfTarget::Kind::Sense)
        {
            out.back().event = last_.kind == ShelfTarget::Kind::Grasp ? GripperEvent::Close : GripperEvent::Open;
        }
        return n > 0;
    }
}  // namespace ropras::scenarios
