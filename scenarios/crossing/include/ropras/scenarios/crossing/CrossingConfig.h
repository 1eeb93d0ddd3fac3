#ifndef ROPRAS_SCENARIOS_CROSSING_CONFIG_H
#define ROPRAS_SCENARIOS_CROSSING_CONFIG_H

#include <array>
#include <cstddef>
#include <map>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

namespace ropras::scenarios
{
    /** \brief An axis-aligned table (a box standing in the lab). */
    struct CrossingTable
    {
        std::array<double, 3> center{};
        std::array<double, 3> halfExtents{};
    };

    /** \brief The reference planner's and the lookahead tracker's settings (key "planning"). */
    struct CrossingPlanningConfig
    {
        double planSeconds{0.3};         ///< default planning time per call (s)
        double referencePlanTime{0.01};  ///< per reference plan (s)
        double resolution{0.05};         ///< motion-check resolution in (x, y, theta)
        double plannerRange{0.5};        ///< VectorizedRRTConnect extension step
        double pedestrianMargin{0.05};   ///< the planner's pedestrian sphere grows by this (m)
        double pedestrianSweep{0.0};     ///< the planner's pedestrian spans this many steps ahead (capsule)
        std::size_t pathNodes{5};        ///< the tracker follows the first path_nodes waypoints
        double lookahead{0.5};           ///< lookahead distance along the path (m)
        double distanceWeight{1.0};      ///< tracker cost per m to the lookahead point
        double headingWeight{0.5};       ///< tracker cost per rad of heading error
    };

    /** \brief Every parameter of stretch-crossing (scenarios/crossing/stretch-crossing/default.json;
        doc/scenario-stretch-crossing.md gives each one's meaning and source). */
    struct CrossingConfig
    {
        std::string scenario{"stretch-crossing"};
        std::array<double, 2> labLo{-1.9, -2.0}, labHi{1.9, 2.0};
        double wallThickness{0.2};
        double wallHeight{2.0};
        std::vector<CrossingTable> tables;
        double lift{0.5};
        double arm{0.0};
        std::array<double, 3> start{};       ///< x, y, theta
        std::array<double, 3> startSigma{};  ///< initial belief N(0, sigma) on x, y, theta
        std::array<double, 2> goal{};
        double goalTolerance{0.1};
        std::array<double, 2> pedestrianStart{};
        double pedestrianSigma{0.1};
        double pedestrianRadius{0.2};
        double pedestrianHeight{0.0};
        std::array<double, 2> pedestrianStep{};  ///< per primitive step (m)
        double worldPedestrianSpeedNoise{0.2};   ///< the world's per-step speed factor 1 + U(-n, n)
        double actionDuration{0.7};
        double substep{0.1};
        double wheelBase{0.31966};
        double wheelAcceleration{0.12};
        double wheelSpeedLimit{0.3};
        std::vector<double> linearSpeeds;
        std::vector<double> angularSpeeds;
        double straightSpeed{0.3};
        std::array<double, 2> speedNoise{};        ///< N(0, sigma) on v and omega, once per action
        std::array<double, 3> observationSigma{};  ///< on x, y, theta
        std::array<double, 3> observationBin{};    ///< search-tree bins of x, y, theta
        double goalReward{800}, collisionReward{-800}, closeReward{-20}, closeDistance{0.3}, stepReward{-1};
        double discount{0.99};
        std::size_t horizon{75};
        std::array<double, 4> reinvigorateSigma{};  ///< x, y, theta, pedestrian position
        bool heuristicValue{true};
        double heuristicSpeed{0.2};
        std::vector<std::array<double, 2>> landmarks;
        double targetYaw{1.5707963267948966};
        CrossingPlanningConfig planning;
        std::map<std::string, double> defaults;
        nlohmann::json json;  ///< the effective configuration

        /** \brief Reads and checks every key of \a json (default.json with the user's overrides): throws
            ropras::Error naming \a scenario, the key and the value for a missing, unknown, non-numeric,
            non-finite or out-of-range value (negative sizes, a start, goal, landmark or pedestrian outside the
            lab or in a table, close_distance <= 0, discount outside (0, 1), ...). */
        static CrossingConfig fromJson(const nlohmann::json &json, const std::string &scenario);

        /** \brief Number of primitive actions: 2 x |linear_speeds| x |angular_speeds| + 1. */
        std::size_t numActions() const { return 2 * linearSpeeds.size() * angularSpeeds.size() + 1; }
    };
}  // namespace ropras::scenarios

#endif
