#ifndef ROPRAS_SCENARIOS_NAVIGATION_CONFIG_H
#define ROPRAS_SCENARIOS_NAVIGATION_CONFIG_H

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <map>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

namespace ropras::scenarios
{
    /** \brief An axis-aligned box [lo, hi] (m). In 2-D scenarios z spans [-1, 1] (the robot moves at z = 0). */
    struct NavBox
    {
        std::array<double, 3> lo{{0.0, 0.0, 0.0}};
        std::array<double, 3> hi{{0.0, 0.0, 0.0}};

        std::array<double, 3> center() const
        {
            return {{0.5 * (lo[0] + hi[0]), 0.5 * (lo[1] + hi[1]), 0.5 * (lo[2] + hi[2])}};
        }
        /// whether the point lies in the box (boundary included)
        bool contains(const double *p) const noexcept
        {
            return p[0] >= lo[0] && p[0] <= hi[0] && p[1] >= lo[1] && p[1] <= hi[1] && p[2] >= lo[2] && p[2] <= hi[2];
        }
        /// the box grown by \a margin per side on the first \a dims axes
        NavBox grown(double margin, int dims) const noexcept
        {
            NavBox b = *this;
            for (int k = 0; k < dims; ++k)
            {
                b.lo[k] -= margin;
                b.hi[k] += margin;
            }
            return b;
        }
        /// Euclidean distance from the point to the box (0 inside)
        double distance(const double *p) const noexcept
        {
            double d2 = 0.0;
            for (int k = 0; k < 3; ++k)
            {
                const double e = std::max({0.0, lo[k] - p[k], p[k] - hi[k]});
                d2 += e * e;
            }
            return std::sqrt(d2);
        }
    };

    /** \brief Everything that defines a navigation problem (Light-Dark, Maze2D, Random3D): the effective
        configuration after overrides, validated. The JSON keys are documented in doc/scenarios.md. */
    struct NavigationConfig
    {
        std::string scenario;    ///< name for error messages
        int dims{2};             ///< 2 or 3
        NavBox bounds;           ///< the robot centre stays inside
        double stepLength{0.5};  ///< m per primitive action
        double slip{0.0};        ///< probability of executing a different action (uniformly among the others)
        double robotRadius{0.2};
        double stepReward{-0.1};
        double goalReward{100.0};
        double dangerReward{-2000.0};
        NavBox goal;
        std::vector<NavBox> walls;             ///< block motion
        std::vector<NavBox> obstacles;         ///< block motion
        std::vector<NavBox> dangerZones;       ///< entering: dangerReward, terminal
        std::vector<NavBox> observationZones;  ///< light stripe / landmarks: position observed
        double observationSigma{0.1};
        /// the model's likelihood of a seen position (the episode filter's, RBSS's) is 0 beyond this many
        /// observation_sigma on any axis (0 = a plain Gaussian, else >= 3): a belief none of whose particles is that
        /// close to what was seen counts as depleted; use with depletion_recovery "observation"
        double observationCutoff{0.0};
        double observationBin{1.0};
        std::vector<std::array<double, 3>> starts;  ///< initial belief: one of them uniformly ...
        double initialSigma{0.0};                   ///< ... plus N(0, initialSigma) per axis
        double reinvigorateSigma{0.0};              ///< particle reinvigoration jitter per axis (m)
        double discount{0.99};
        std::size_t horizon{60};
        double planSeconds{0.1};          ///< default planning time per call
        double referencePlanTime{0.003};  ///< per-plan OMPL time limit of the reference policy (s)
        double planResolution{0.1};       ///< motion-check resolution of the reference planner (m)
        double dangerMargin{0.0};         ///< the planner sees danger zones grown by this much per side (m)
        double obstacleMargin{0.0};       ///< the planner sees walls and obstacles grown by this much per side (m)
        /// "depletion_recovery": true = "observation" (NavigationRecovery), false = "ignore" (keep the particles)
        bool recoverFromObservation{false};
        bool heuristicValue{false};  ///< leaf value from the goal distance field (NavigationModel::heuristicValue)
        /// per-step factor rho in (0, 1] on the goal reward of that leaf value: goal_reward (gamma rho)^d; 1 = the
        /// discounted shortest path walked for certain, below 1 the farther goal is the less certain one
        double heuristicDecay{1.0};
        /// "heuristic_mdp": with heuristicValue, the leaf value is the optimal value of the fully observed problem
        /// with the slip (value iteration over the lattice: a position from which every way on passes close to a
        /// danger zone is worth less) instead of the shortest path's; needs heuristicDecay 1
        bool heuristicMdp{false};
        /// the belief uses "the episode went on" as evidence (no particle stays in the goal or a danger zone);
        /// false = the paper's observation space R^n u {None} only
        bool terminationEvidence{false};
        double plannerRange{2.0};  ///< VectorizedRRTConnect extension step (m)
        /// VectorizedRRTConnect's dynamic-domain radius (m; its dd_radius); 0 = the planner's own default (5, made
        /// for joint spaces in radians)
        double plannerDdRadius{0.0};
        std::map<std::string, double> defaults;  ///< solver / filter parameter defaults
        /// per solver name: its own defaults, before `defaults` (key solver_defaults; may be absent)
        std::map<std::string, std::map<std::string, double>> solverDefaults;
        nlohmann::json json;  ///< the effective configuration
    };

    /** \brief Reads and validates a navigation configuration; throws ropras::Error naming \a scenario, the key
        and the value for a missing key, a wrong type, a non-finite value, a negative size, a box outside the
        bounds, a start outside the bounds, in collision, in a danger zone or in the goal. */
    NavigationConfig parseNavigationConfig(const std::string &scenario, const nlohmann::json &json);

    /// the model's collision grid cell (m): at least 2, at least 4 robot radii
    inline double collisionGridCell(const NavigationConfig &c)
    {
        return std::max(2.0, 4.0 * c.robotRadius);
    }
    /// points along \a axis of a grid of \a cell-sized cells from bounds.lo: floor(extent / cell) + 1 (1 beyond dims)
    std::size_t gridPointsAlong(const NavigationConfig &c, double cell, int axis);
    /// points of that grid over every axis, as a double (no overflow for absurd bounds or cells)
    double gridPoints(const NavigationConfig &c, double cell);

    /** \brief The scene for `ropras render` (format: doc/scenarios.md). */
    nlohmann::json navigationScene(const NavigationConfig &config);

    /** \brief A box as JSON ([[lo...], [hi...]], dims entries each). */
    nlohmann::json boxToJson(const NavBox &box, int dims);
}  // namespace ropras::scenarios

#endif
