#include "ropras/scenarios/crossing/CrossingModel.h"

#include <algorithm>
#include <string>

#include "ropras/core/Error.h"

namespace ropras::scenarios
{
    namespace
    {
        constexpr double PI = 3.14159265358979323846;

        /// squared distance from p to the box (centre c, half extents h)
        double boxDistanceSquared(const double *p, const CrossingTable &t) noexcept
        {
            double d2 = 0.0;
            for (int k = 0; k < 3; ++k)
            {
                const double e =
                    std::abs(p[k] - t.center[static_cast<std::size_t>(k)]) - t.halfExtents[static_cast<std::size_t>(k)];
                if (e > 0.0)
                {
                    d2 += e * e;
                }
            }
            return d2;
        }

        std::uint64_t mix(std::uint64_t h, std::int64_t v) noexcept
        {
            h ^= static_cast<std::uint64_t>(v) + 0x9e3779b97f4a7c15ULL + (h << 6) + (h >> 2);
            return h;
        }
    }  // namespace

    CrossingModel::CrossingModel(const CrossingConfig &config, std::vector<CrossingSphere> spheres)
        : config_(config), spheres_(std::move(spheres))
    {
        const std::string where = "scenario " + config_.scenario + ": ";
        if (spheres_.empty())
        {
            throw Error(where + "the robot has no collision spheres");
        }
        for (const double s : config_.linearSpeeds)
        {
            for (const double w : config_.angularSpeeds)
            {
                twists_.push_back({s, w});
            }
            for (const double w : config_.angularSpeeds)
            {
                twists_.push_back({-s, -w});
            }
        }
        twists_.push_back({config_.straightSpeed, 0.0});
        if (twists_.size() > 255)
        {
            throw Error(where + "keys \"linear_speeds\" and \"angular_speeds\" give " + std::to_string(twists_.size()) +
                        " actions, at most 255 are supported");
        }
        for (const auto &b : spheres_)
        {
            boundingRadius_ = std::max(boundingRadius_, std::hypot(b.x, b.y) + b.radius);
        }
        substeps_ = static_cast<std::size_t>(std::max(1.0, std::round(config_.actionDuration / config_.substep)));
        dt_ = config_.actionDuration / static_cast<double>(substeps_);
        gaussianNorm_ = 1.0;
        for (const double s : config_.observationSigma)
        {
            gaussianNorm_ /= std::sqrt(2.0 * PI) * s;
        }
        State start;
        start.x = config_.start[0];
        start.y = config_.start[1];
        start.theta = config_.start[2];
        start.px = config_.labLo[0] - 100.0;  // far away: test the tables and walls only
        start.py = config_.labLo[1] - 100.0;
        if (contact(start) != CrossingEvent::None)
        {
            throw Error(where + "key \"start\" puts the robot in collision with a table or a wall");
        }
    }

    CrossingEvent CrossingModel::contact(const State &s) const noexcept
    {
        const double c = std::cos(s.theta), sn = std::sin(s.theta);
        const double R = boundingRadius_;
        const double pr = config_.pedestrianRadius;
        const double dpx = s.x - s.px, dpy = s.y - s.py;
        if (dpx * dpx + dpy * dpy < (R + pr) * (R + pr))
        {
            for (const auto &b : spheres_)
            {
                const double x = s.x + c * b.x - sn * b.y - s.px;
                const double y = s.y + sn * b.x + c * b.y - s.py;
                const double z = b.z - config_.pedestrianHeight;
                const double limit = b.radius + pr;
                if (x * x + y * y + z * z < limit * limit)
                {
                    return CrossingEvent::Pedestrian;
                }
            }
        }
        const bool nearWall = s.x - R < config_.labLo[0] || s.x + R > config_.labHi[0] || s.y - R < config_.labLo[1] ||
                              s.y + R > config_.labHi[1];
        for (const auto &t : config_.tables)
        {
            const double centre[3] = {s.x, s.y, t.center[2]};
            const bool nearTable = boxDistanceSquared(centre, t) < R * R;
            if (!nearTable)
            {
                continue;
            }
            for (const auto &b : spheres_)
            {
                const double p[3] = {s.x + c * b.x - sn * b.y, s.y + sn * b.x + c * b.y, b.z};
                if (boxDistanceSquared(p, t) < b.radius * b.radius)
                {
                    return CrossingEvent::Obstacle;
                }
            }
        }
        if (nearWall)
        {
            for (const auto &b : spheres_)
            {
                const double x = s.x + c * b.x - sn * b.y, y = s.y + sn * b.x + c * b.y;
                if (x - b.radius < config_.labLo[0] || x + b.radius > config_.labHi[0] ||
                    y - b.radius < config_.labLo[1] || y + b.radius > config_.labHi[1])
                {
                    return CrossingEvent::Obstacle;
                }
            }
        }
        return CrossingEvent::None;
    }

    double CrossingModel::pedestrianClearance(const State &s) const noexcept
    {
        const double pr = config_.pedestrianRadius;
        const double centre = std::hypot(s.x - s.px, s.y - s.py);
        const double bound = centre - boundingRadius_ - pr;
        if (bound > config_.closeDistance)
        {
            return bound;
        }
        const double c = std::cos(s.theta), sn = std::sin(s.theta);
        double best = std::numeric_limits<double>::infinity();
        for (const auto &b : spheres_)
        {
            const double x = s.x + c * b.x - sn * b.y - s.px;
            const double y = s.y + sn * b.x + c * b.y - s.py;
            const double z = b.z - config_.pedestrianHeight;
            best = std::fmin(best, std::sqrt(x * x + y * y + z * z) - b.radius);
        }
        return best - pr;
    }

    void CrossingModel::predict(State &s, Action a) const noexcept
    {
        const CrossingTwist &t = twists_[a % twists_.size()];
        double vl = s.v - 0.5 * s.w * config_.wheelBase, vr = s.v + 0.5 * s.w * config_.wheelBase;
        const double tl = clampSpeed(t.v - 0.5 * t.w * config_.wheelBase);
        const double tr = clampSpeed(t.v + 0.5 * t.w * config_.wheelBase);
        for (std::size_t i = 0; i < substeps_; ++i)
        {
            driveSubstep(s, vl, vr, tl, tr);
        }
    }

    double CrossingModel::observationProbability(const Observation &o, const State &next, Action) const noexcept
    {
        const double dx = (o.x - next.x) / config_.observationSigma[0];
        const double dy = (o.y - next.y) / config_.observationSigma[1];
        const double dt = wrapAngle(o.theta - next.theta) / config_.observationSigma[2];
        return gaussianNorm_ * std::exp(-0.5 * (dx * dx + dy * dy + dt * dt));
    }

    CrossingModel::State CrossingModel::sampleInitialState(pomdp::Rng &rng) const noexcept
    {
        State s;
        for (int attempt = 0; attempt < 100; ++attempt)
        {
            s = State{};
            s.x = config_.start[0] + config_.startSigma[0] * rng.normal();
            s.y = config_.start[1] + config_.startSigma[1] * rng.normal();
            s.theta = wrapAngle(config_.start[2] + config_.startSigma[2] * rng.normal());
            s.px = config_.pedestrianStart[0] + config_.pedestrianSigma * rng.normal();
            s.py = config_.pedestrianStart[1] + config_.pedestrianSigma * rng.normal();
            movePedestrian(s, 0.0);  // inside the lab
            if (contact(s) == CrossingEvent::None)
            {
                break;
            }
        }
        return s;
    }

    std::uint64_t CrossingModel::observationKey(const Observation &o) const noexcept
    {
        const auto cell = [](double v, double bin)
        { return static_cast<std::int64_t>(std::floor(std::fmin(std::fmax(v / bin, -1e15), 1e15))); };
        std::uint64_t h = 0x51ed27a3ULL;
        h = mix(h, cell(o.x, config_.observationBin[0]));
        h = mix(h, cell(o.y, config_.observationBin[1]));
        h = mix(h, cell(o.theta + PI, config_.observationBin[2]));
        return h;
    }

    void CrossingModel::reinvigorate(State &s, pomdp::Rng &rng) const noexcept
    {
        State j = s;
        j.x += config_.reinvigorateSigma[0] * rng.normal();
        j.y += config_.reinvigorateSigma[1] * rng.normal();
        j.theta = wrapAngle(j.theta + config_.reinvigorateSigma[2] * rng.normal());
        j.px += config_.reinvigorateSigma[3] * rng.normal();
        j.py += config_.reinvigorateSigma[3] * rng.normal();
        movePedestrian(j, 0.0);
        if (contact(j) == CrossingEvent::None)
        {
            s = j;
        }
    }

    double CrossingModel::heuristicValue(const State &s) const noexcept
    {
        if (!config_.heuristicValue)
        {
            return 0.0;
        }
        const double d =
            std::fmax(0.0, std::hypot(s.x - config_.goal[0], s.y - config_.goal[1]) - config_.goalTolerance);
        const double n = std::ceil(d / (config_.heuristicSpeed * config_.actionDuration));
        const double g = std::pow(config_.discount, n);
        return config_.goalReward * g + config_.stepReward * (1.0 - g) / (1.0 - config_.discount);
    }
}  // namespace ropras::scenarios
