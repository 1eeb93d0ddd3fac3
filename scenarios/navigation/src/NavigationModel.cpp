#include "ropras/scenarios/navigation/NavigationModel.h"

#include <algorithm>
#include <cmath>
#include <deque>

namespace ropras::scenarios
{
    namespace
    {
        constexpr double INV_SQRT_2PI = 0.3989422804014327;
    }

    NavigationModel::NavigationModel(NavigationConfig config) : config_(std::move(config))
    {
        blockers_ = config_.walls;
        blockers_.insert(blockers_.end(), config_.obstacles.begin(), config_.obstacles.end());
        const double r = config_.robotRadius;
        cell_ = collisionGridCell(config_);
        for (int k = 0; k < 3; ++k)
            counts_[k] = gridPointsAlong(config_, cell_, k);
        const std::size_t cells = counts_[0] * counts_[1] * counts_[2];
        std::vector<std::vector<std::uint32_t>> lists(cells);
        for (std::size_t b = 0; b < blockers_.size(); ++b)
        {
            std::size_t lo[3] = {0, 0, 0}, hi[3] = {0, 0, 0};
            for (int k = 0; k < config_.dims; ++k)
            {
                const double a = (blockers_[b].lo[k] - r - config_.bounds.lo[k]) / cell_;
                const double z = (blockers_[b].hi[k] + r - config_.bounds.lo[k]) / cell_;
                lo[k] = static_cast<std::size_t>(std::clamp(std::floor(a), 0.0, static_cast<double>(counts_[k] - 1)));
                hi[k] = static_cast<std::size_t>(std::clamp(std::floor(z), 0.0, static_cast<double>(counts_[k] - 1)));
            }
            for (std::size_t i = lo[0]; i <= hi[0]; ++i)
                for (std::size_t j = lo[1]; j <= hi[1]; ++j)
                    for (std::size_t l = lo[2]; l <= hi[2]; ++l)
                        lists[(l * counts_[1] + j) * counts_[0] + i].push_back(static_cast<std::uint32_t>(b));
        }
        cellStart_.assign(cells + 1, 0);
        for (std::size_t c = 0; c < cells; ++c)
        {
            cellStart_[c + 1] = cellStart_[c] + static_cast<std::uint32_t>(lists[c].size());
            cellBoxes_.insert(cellBoxes_.end(), lists[c].begin(), lists[c].end());
        }
        if (config_.heuristicValue)
        {
            buildGoalDistance();
            if (config_.heuristicMdp)
            {
                buildSlipValue();
            }
        }
    }

    void NavigationModel::buildGoalDistance()
    {
        for (int k = 0; k < 3; ++k)
            fieldCounts_[k] = gridPointsAlong(config_, config_.stepLength, k);
        const std::size_t n = fieldCounts_[0] * fieldCounts_[1] * fieldCounts_[2];
        goalDistance_.assign(n, UNREACHABLE);
        std::vector<std::uint8_t> free(n, 0);
        std::deque<std::size_t> queue;
        double p[3];
        for (std::size_t c = 0; c < n; ++c)
        {
            fieldPoint(c, p);
            free[c] = !blocked(p) && !inDanger(p);
            if (free[c] && config_.goal.contains(p))
            {
                goalDistance_[c] = 0;
                queue.push_back(c);
            }
        }
        const std::size_t stride[3] = {1, fieldCounts_[0], fieldCounts_[0] * fieldCounts_[1]};
        while (!queue.empty())
        {
            const std::size_t c = queue.front();
            queue.pop_front();
            std::size_t idx[3];
            fieldIndices(c, idx);
            for (int a = 0; a < 2 * config_.dims; ++a)
            {
                const int k = a / 2;
                if (a % 2 == 0 ? idx[k] + 1 >= fieldCounts_[k] : idx[k] == 0)
                {
                    continue;
                }
                const std::size_t d = a % 2 == 0 ? c + stride[k] : c - stride[k];
                if (free[d] && goalDistance_[d] == UNREACHABLE && goalDistance_[c] + 1 < UNREACHABLE)
                {
                    goalDistance_[d] = static_cast<std::uint16_t>(goalDistance_[c] + 1);
                    queue.push_back(d);
                }
            }
        }
    }

    void NavigationModel::fieldIndices(std::size_t c, std::size_t *idx) const noexcept
    {
        idx[0] = c % fieldCounts_[0];
        idx[1] = (c / fieldCounts_[0]) % fieldCounts_[1];
        idx[2] = c / (fieldCounts_[0] * fieldCounts_[1]);
    }

    void NavigationModel::fieldPoint(std::size_t c, double *p) const noexcept
    {
        std::size_t idx[3];
        fieldIndices(c, idx);
        for (int k = 0; k < 3; ++k)
        {
            p[k] = k < config_.dims ? config_.bounds.lo[k] + static_cast<double>(idx[k]) * config_.stepLength : 0.0;
        }
    }

    std::size_t NavigationModel::fieldCell(const double *p) const noexcept
    {
        std::size_t c = 0, stride = 1;
        for (int k = 0; k < config_.dims; ++k)
        {
            const double f = std::round((p[k] - config_.bounds.lo[k]) / config_.stepLength);
            c += stride * static_cast<std::size_t>(std::clamp(f, 0.0, static_cast<double>(fieldCounts_[k] - 1)));
            stride *= fieldCounts_[k];
        }
        return c;
    }

    long NavigationModel::goalDistance(const double *p) const noexcept
    {
        if (goalDistance_.empty())
        {
            return -1;
        }
        const std::size_t c = fieldCell(p);
        return goalDistance_[c] == UNREACHABLE ? -1 : static_cast<long>(goalDistance_[c]);
    }

    double NavigationModel::heuristicValue(const State &s) const noexcept
    {
        if (!slipValue_.empty())
        {
            return slipValue_[fieldCell(s.p)];
        }
        const long d = goalDistance(s.p);
        if (d < 0)
        {
            return 0.0;
        }
        const double g = config_.discount;
        const double gd = std::pow(g, static_cast<double>(d));
        const double rd =
            config_.heuristicDecay == 1.0 ? 1.0 : std::pow(config_.heuristicDecay, static_cast<double>(d));
        return config_.goalReward * gd * rd + config_.stepReward * (1.0 - gd) / (1.0 - g);
    }

    std::size_t NavigationModel::cellOf(const double *p) const noexcept
    {
        std::size_t idx[3] = {0, 0, 0};
        for (int k = 0; k < config_.dims; ++k)
        {
            const double f = std::floor((p[k] - config_.bounds.lo[k]) / cell_);
            idx[k] = static_cast<std::size_t>(std::clamp(f, 0.0, static_cast<double>(counts_[k] - 1)));
        }
        return (idx[2] * counts_[1] + idx[1]) * counts_[0] + idx[0];
    }

    bool NavigationModel::blocked(const double *p) const noexcept
    {
        for (int k = 0; k < config_.dims; ++k)
        {
            if (!(p[k] >= config_.bounds.lo[k] && p[k] <= config_.bounds.hi[k]))
            {
                return true;  // also NaN
            }
        }
        const double r2 = config_.robotRadius * config_.robotRadius;
        const std::size_t c = cellOf(p);
        for (std::uint32_t i = cellStart_[c]; i < cellStart_[c + 1]; ++i)
        {
            const NavBox &b = blockers_[cellBoxes_[i]];
            double d2 = 0.0;
            for (int k = 0; k < 3; ++k)
            {
                const double e = std::max(0.0, std::max(b.lo[k] - p[k], p[k] - b.hi[k]));
                d2 += e * e;
            }
            if (d2 < r2)
            {
                return true;
            }
        }
        return false;
    }

    bool NavigationModel::inDanger(const double *p) const noexcept
    {
        for (const auto &b : config_.dangerZones)
        {
            if (b.contains(p))
            {
                return true;
            }
        }
        return false;
    }

    bool NavigationModel::continuesAt(const double *p) const noexcept
    {
        return !blocked(p) && !inDanger(p) && !config_.goal.contains(p);
    }

    bool NavigationModel::observable(const double *p) const noexcept
    {
        for (const auto &b : config_.observationZones)
        {
            if (b.contains(p))
            {
                return true;
            }
        }
        return false;
    }

    NavigationModel::Action NavigationModel::executedAction(Action a, pomdp::Rng &rng) const noexcept
    {
        if (config_.slip > 0.0 && rng.bernoulli(config_.slip))
        {
            const auto k = static_cast<Action>(rng.uniformIndex(numActions() - 1));
            return k >= a ? static_cast<Action>(k + 1) : k;
        }
        return a;
    }

    NavState NavigationModel::moved(const State &s, Action a) const noexcept
    {
        State next = s;
        const int axis = a / 2;
        if (axis < config_.dims)
        {
            next.p[axis] += (a % 2 == 0 ? 1.0 : -1.0) * config_.stepLength;
        }
        return next;
    }

    void NavigationModel::arrive(const State &next, pomdp::Rng &rng,
                                 pomdp::StepResult<State, Observation> &out) const noexcept
    {
        out.next = next;
        out.reward = config_.stepReward;
        out.terminal = false;
        if (inDanger(next.p))
        {
            out.reward += config_.dangerReward;
            out.terminal = true;
        }
        else if (config_.goal.contains(next.p))
        {
            out.reward += config_.goalReward;
            out.terminal = true;
        }
        out.observation = Observation{};
        out.observation.ended = config_.terminationEvidence && out.terminal;
        if (observable(next.p))
        {
            out.observation.seen = true;
            for (int k = 0; k < config_.dims; ++k)
            {
                out.observation.p[k] = next.p[k] + rng.normal(0.0, config_.observationSigma);
            }
        }
    }

    pomdp::StepResult<NavState, NavObservation> NavigationModel::step(const State &s, Action a,
                                                                      pomdp::Rng &rng) const noexcept
    {
        pomdp::StepResult<State, Observation> out;
        State next = moved(s, executedAction(a, rng));
        if (blocked(next.p))
        {
            next = s;
        }
        arrive(next, rng, out);
        return out;
    }

    double NavigationModel::observationProbability(const Observation &o, const State &next, Action) const noexcept
    {
        // a particle in the goal or a danger zone would have ended the episode: impossible when it went on
        if (config_.terminationEvidence && o.ended != (inDanger(next.p) || config_.goal.contains(next.p)))
        {
            return 0.0;
        }
        if (!observable(next.p))
        {
            return o.seen ? 0.0 : 1.0;
        }
        if (!o.seen)
        {
            return 0.0;
        }
        const double sigma = config_.observationSigma;
        const double cutoff = config_.observationCutoff > 0.0 ? config_.observationCutoff : INFINITY;
        double density = 1.0;
        for (int k = 0; k < config_.dims; ++k)
        {
            const double z = (o.p[k] - next.p[k]) / sigma;
            if (!(std::abs(z) <= cutoff))
            {
                return 0.0;  // beyond the cutoff (the belief must have lost the robot), or NaN
            }
            density *= INV_SQRT_2PI / sigma * std::exp(-0.5 * z * z);
        }
        return density;
    }

    NavState NavigationModel::sampleInitialState(pomdp::Rng &rng) const noexcept
    {
        const auto &start = config_.starts[rng.uniformIndex(config_.starts.size())];
        State s;
        for (int k = 0; k < config_.dims; ++k)
        {
            s.p[k] = start[k];
        }
        if (config_.initialSigma > 0.0)
        {
            // Gaussian noise, redrawn (at most 100 times) while the sample is blocked, in danger or in the goal.
            for (int attempt = 0; attempt < 100; ++attempt)
            {
                State t;
                for (int k = 0; k < config_.dims; ++k)
                {
                    t.p[k] = start[k] + rng.normal(0.0, config_.initialSigma);
                }
                if (continuesAt(t.p))
                {
                    return t;
                }
            }
        }
        return s;
    }

    std::uint64_t NavigationModel::observationKey(const Observation &o) const noexcept
    {
        if (!o.seen)
        {
            return o.ended ? NONE_KEY ^ 1u : NONE_KEY;
        }
        std::uint64_t h = o.ended ? 0x84222325cbf29ce5ULL : 0x84222325cbf29ce4ULL;
        for (int k = 0; k < config_.dims; ++k)
        {
            const double cell = std::floor(o.p[k] / config_.observationBin);
            const auto v = static_cast<std::uint64_t>(static_cast<std::int64_t>(std::clamp(cell, -1e9, 1e9)));
            h ^= v + 0x9e3779b97f4a7c15ULL + (h << 6) + (h >> 2);
            h *= 0x100000001b3ULL;
        }
        return h == NONE_KEY ? h + 1 : h;
    }

    void NavigationModel::reinvigorate(State &s, pomdp::Rng &rng) const noexcept
    {
        if (config_.reinvigorateSigma <= 0.0)
        {
            return;
        }
        State t = s;
        for (int k = 0; k < config_.dims; ++k)
        {
            t.p[k] += rng.normal(0.0, config_.reinvigorateSigma);
        }
        if (!blocked(t.p))
        {
            s = t;
        }
    }
}  // namespace ropras::scenarios
