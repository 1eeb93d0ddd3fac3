#ifndef ROPRAS_SCENARIOS_NAVIGATION_MODEL_H
#define ROPRAS_SCENARIOS_NAVIGATION_MODEL_H

#include <cstddef>
#include <cstdint>
#include <vector>

#include "ropras/pomdp/Model.h"
#include "ropras/scenarios/navigation/NavigationConfig.h"

namespace ropras::scenarios
{
    /** \brief The robot position (z = 0 in 2-D). */
    struct NavState
    {
        double p[3]{0.0, 0.0, 0.0};
    };

    /** \brief The position with Gaussian noise inside an observation zone, else None (seen = false). */
    struct NavObservation
    {
        double p[3]{0.0, 0.0, 0.0};
        bool seen{false};
        /// with NavigationConfig::terminationEvidence: the step ended the episode (goal or danger zone)
        bool ended{false};
    };

    /** \brief The POMDP model of the navigation scenarios (Light-Dark, Maze2D, Random3D): a sphere robot of
        radius r moving in axis steps of stepLength; with probability slip another action (uniformly among
        the others) executes; a move that leaves the bounds or makes the sphere touch a wall or obstacle box
        is blocked (the robot stays). Reward: stepReward every step, plus dangerReward (terminal) when the
        centre enters a danger zone, else goalReward (terminal) when it enters the goal box. Observation:
        the position + N(0, sigma) per axis when the centre is in an observation zone, else None.

        Collision here is the model's own geometry: sphere vs axis-aligned boxes, the boxes (grown by r)
        listed per cell of a uniform grid; noexcept, allocation-free, thread-safe. */
    class NavigationModel
    {
    public:
        using State = NavState;
        using Action = std::uint8_t;
        using Observation = NavObservation;

        /// the None observation's key
        static constexpr std::uint64_t NONE_KEY = 0x9e3779b97f4a7c15ULL;

        /** \brief Builds the collision grid of \a config (already validated by parseNavigationConfig). */
        explicit NavigationModel(NavigationConfig config);

        const NavigationConfig &config() const { return config_; }
        int dims() const noexcept { return config_.dims; }

        // --- the Model concept
        pomdp::StepResult<State, Observation> step(const State &s, Action a, pomdp::Rng &rng) const noexcept;
        double observationProbability(const Observation &o, const State &next, Action a) const noexcept;
        State sampleInitialState(pomdp::Rng &rng) const noexcept;
        double discount() const noexcept { return config_.discount; }
        std::size_t numActions() const noexcept { return static_cast<std::size_t>(2 * config_.dims); }
        Action action(std::size_t i) const noexcept { return static_cast<Action>(i); }
        std::uint64_t observationKey(const Observation &o) const noexcept;
        void reinvigorate(State &s, pomdp::Rng &rng) const noexcept;
        bool reachedGoal(const State &s) const noexcept { return config_.goal.contains(s.p); }
        /** \brief With `heuristic_value` on: the value of walking the shortest danger-free lattice path of d
            steps to the goal, goal_reward (gamma rho)^d + step_reward (1 - gamma^d) / (1 - gamma) (rho =
            `heuristic_decay`, 1 by default), d from a BFS distance field (grid of step-length cells, the
            nearest cell); 0 when off or unreachable. With `heuristic_mdp` on instead: the optimal value of the
            fully observed problem with the slip at the nearest lattice point (policy iteration, buildSlipValue; 0
            in walls, danger zones and the goal). Used by the solvers at the leaves of the search (below the
            depth limit / at the end of a rollout). */
        double heuristicValue(const State &s) const noexcept;
        /// BFS distance (steps) of the cell nearest \a p to the goal; -1 when unreachable or off
        long goalDistance(const double *p) const noexcept;
        /// heuristic_mdp: policy iterations of buildSlipValue (0 when off)
        std::size_t slipValueIterations() const noexcept { return slipIterations_; }

        // --- shared with NavigationWorld
        /** \brief The action that really executes: \a a, or with probability slip another one uniformly. */
        Action executedAction(Action a, pomdp::Rng &rng) const noexcept;
        /** \brief \a s moved by action \a a (no collision check). */
        State moved(const State &s, Action a) const noexcept;
        /** \brief Reward, terminal flag and observation of arriving in \a next. */
        void arrive(const State &next, pomdp::Rng &rng, pomdp::StepResult<State, Observation> &out) const noexcept;

        // --- geometry
        /** \brief Outside the bounds, or the sphere touches (distance < r) a wall or obstacle box. */
        bool blocked(const double *p) const noexcept;
        bool inDanger(const double *p) const noexcept;
        bool observable(const double *p) const noexcept;
        /** \brief The episode goes on at \a p: not blocked, not in a danger zone, not in the goal. */
        bool continuesAt(const double *p) const noexcept;

    private:
        static constexpr std::uint16_t UNREACHABLE = 0xFFFF;
        void buildGoalDistance();
        /** \brief heuristic_mdp: V(c) = max_a sum_b P(b | a) (r(c, b) + gamma V(next(c, b))) over the lattice
            of the distance field, P(b | a) = 1 - slip for b = a and slip / (2 dims - 1) for each other action, a
            blocked move stays, danger zones and the goal end the episode. Policy iteration (each policy's values
            from a sparse LU solve, at most 1000), starting from the policy greedy on the shortest path's value,
            until no action improves; throws ropras::Error if a solve fails. */
        void buildSlipValue();
        /// per-axis indices of field cell \a c
        void fieldIndices(std::size_t c, std::size_t *idx) const noexcept;
        /// lattice point of field cell \a c (the distance field's cells, stepLength apart from bounds.lo)
        void fieldPoint(std::size_t c, double *p) const noexcept;
        /// the field cell nearest \a p (clamped to the lattice)
        std::size_t fieldCell(const double *p) const noexcept;
        std::size_t cellOf(const double *p) const noexcept;

        NavigationConfig config_;
        // blocking boxes (walls, then obstacles), flat
        std::vector<NavBox> blockers_;
        // uniform grid: cell size, counts per axis, CSR lists of blocker indices
        double cell_{2.0};
        std::size_t counts_[3]{1, 1, 1};
        std::vector<std::uint32_t> cellStart_;
        std::vector<std::uint32_t> cellBoxes_;
        // goal distance field (heuristic_value): cells of stepLength from bounds.lo, steps to the goal
        std::size_t fieldCounts_[3]{1, 1, 1};
        std::vector<std::uint16_t> goalDistance_;
        // heuristic_mdp: per field cell, the fully observed problem's optimal value (empty when off)
        std::vector<double> slipValue_;
        std::size_t slipIterations_{0};
    };
}  // namespace ropras::scenarios

#endif
