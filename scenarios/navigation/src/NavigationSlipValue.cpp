// heuristic_mdp: the leaf value as the optimal value of the fully observed problem with the slip.
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>
#include <vector>

// GCC 12 flags Eigen's AVX-512 packet transpose (inside SparseLU's dense kernels) as maybe uninitialized: a false
// positive in Eigen's code, silenced for its headers only.
#pragma GCC diagnostic push
#pragma GCC diagnostic ignored "-Wmaybe-uninitialized"
#include <Eigen/SparseCore>
#include <Eigen/SparseLU>
#pragma GCC diagnostic pop

#include "ropras/core/Error.h"
#include "ropras/scenarios/navigation/NavigationModel.h"

namespace ropras::scenarios
{
    namespace
    {
        /// one action's outcome from a cell: the reward of arriving, and the cell whose value follows (none:
        /// the episode ends)
        struct Outcome
        {
            double reward;
            std::uint32_t next;
        };
        constexpr std::uint32_t ENDS = std::numeric_limits<std::uint32_t>::max();

        constexpr std::size_t MAX_ITERATIONS = 1000;

        /** Policy iteration over \a cells (field cell indices; \a value indexed by field cell, holding the start
            values) with \a m actions each (\a outcomes: m per cell, in the order of \a cells): action a executes
            with probability 1 - slip, each other one with slip / (m - 1). Returns the iterations. */
        std::size_t policyIteration(const std::vector<std::uint32_t> &cells, const std::vector<Outcome> &outcomes,
                                    int m, double gamma, double slip, std::vector<double> &value)
        {
            const double keep = 1.0 - slip;
            const double other = slip / static_cast<double>(m - 1);
            const std::size_t n = value.size();
            // Policy iteration: the greedy policy of the current values, its values solved exactly (a sparse system:
            // a chain that stays among cells that never reach the goal converges only as gamma^k under sweeps), until
            // no action improves by more than a relative 1e-12.
            const std::size_t rows = cells.size();
            std::vector<std::int32_t> rowOf(n, -1);
            for (std::size_t i = 0; i < rows; ++i)
                rowOf[cells[i]] = static_cast<std::int32_t>(i);
            const auto backup = [&](std::size_t i, int a)
            {
                const Outcome *o = &outcomes[i * static_cast<std::size_t>(m)];
                double sum = 0.0;
                for (int b = 0; b < m; ++b)
                    sum +=
                        (b == a ? keep : other) * (o[b].reward + (o[b].next == ENDS ? 0.0 : gamma * value[o[b].next]));
                return sum;
            };
            std::vector<std::uint8_t> policy(rows, 0);
            const auto improve = [&]
            {
                bool changed = false;
                for (std::size_t i = 0; i < rows; ++i)
                {
                    double current = backup(i, policy[i]);
                    for (int a = 0; a < m; ++a)
                    {
                        const double candidate = backup(i, a);
                        if (candidate > current + 1e-12 * (1.0 + std::abs(current)))
                        {
                            current = candidate;
                            policy[i] = static_cast<std::uint8_t>(a);
                            changed = true;
                        }
                    }
                }
                return changed;
            };
            std::vector<Eigen::Triplet<double>> triplets;
            Eigen::VectorXd rhs(static_cast<Eigen::Index>(rows));
            Eigen::SparseMatrix<double> system(static_cast<Eigen::Index>(rows), static_cast<Eigen::Index>(rows));
            Eigen::SparseLU<Eigen::SparseMatrix<double>> lu;
            const auto evaluate = [&]  // (I - gamma P_policy) v = r_policy
            {
                triplets.clear();
                for (std::size_t i = 0; i < rows; ++i)
                {
                    const Outcome *o = &outcomes[i * static_cast<std::size_t>(m)];
                    double r = 0.0;
                    triplets.emplace_back(i, i, 1.0);  // duplicates (a blocked move stays) are summed
                    for (int b = 0; b < m; ++b)
                    {
                        const double pb = b == policy[i] ? keep : other;
                        r += pb * o[b].reward;
                        if (o[b].next != ENDS && pb > 0.0)
                            triplets.emplace_back(i, rowOf[o[b].next], -gamma * pb);
                    }
                    rhs[static_cast<Eigen::Index>(i)] = r;
                }
                system.setFromTriplets(triplets.begin(), triplets.end());
                lu.compute(system);               // the pattern too: without the slip it changes with the policy
                if (lu.info() != Eigen::Success)  // I - gamma P is diagonally dominant for gamma < 1: not expected
                    throw Error("heuristic_mdp: the sparse LU of a policy's values failed: " + lu.lastErrorMessage());
                const Eigen::VectorXd v = lu.solve(rhs);
                for (std::size_t i = 0; i < rows; ++i)
                    value[cells[i]] = v[static_cast<Eigen::Index>(i)];
            };
            std::size_t iterations = 0;
            for (; iterations < MAX_ITERATIONS; ++iterations)
            {
                if (!improve() && iterations > 0)
                    break;
                evaluate();
            }
            return iterations;
        }
    }  // namespace

    void NavigationModel::buildSlipValue()
    {
        const std::size_t n = goalDistance_.size();
        const int m = 2 * config_.dims;
        const double gamma = config_.discount;

        // The cells whose value is searched (free, not in a danger zone or the goal), each with its m outcomes.
        std::vector<std::uint32_t> cells;
        std::vector<Outcome> outcomes;
        std::vector<double> value(n, 0.0);
        double p[3], q[3];
        for (std::size_t c = 0; c < n; ++c)
        {
            fieldPoint(c, p);
            if (!continuesAt(p))
            {
                continue;
            }
            cells.push_back(static_cast<std::uint32_t>(c));
            // start from the shortest path's value (slipValue_ is still empty here): the first greedy policy heads
            // for the goal
            State at;
            std::copy(p, p + 3, at.p);
            value[c] = heuristicValue(at);
            for (int a = 0; a < m; ++a)
            {
                std::copy(p, p + 3, q);
                q[a / 2] += (a % 2 == 0 ? 1.0 : -1.0) * config_.stepLength;
                Outcome o{config_.stepReward, static_cast<std::uint32_t>(c)};  // blocked: stays
                if (!blocked(q))
                {
                    const bool danger = inDanger(q);
                    if (danger || config_.goal.contains(q))
                    {
                        o.reward += danger ? config_.dangerReward : config_.goalReward;
                        o.next = ENDS;
                    }
                    else
                    {
                        // the nearest lattice point (q itself unless the bounds are not a whole number of steps)
                        const std::size_t d = fieldCell(q);
                        fieldPoint(d, q);
                        o.next = static_cast<std::uint32_t>(continuesAt(q) ? d : c);
                    }
                }
                outcomes.push_back(o);
            }
        }

        slipIterations_ = policyIteration(cells, outcomes, m, gamma, config_.slip, value);
        slipValue_ = std::move(value);
    }
}  // namespace ropras::scenarios
