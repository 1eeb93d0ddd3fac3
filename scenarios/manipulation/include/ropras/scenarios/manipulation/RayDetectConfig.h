#ifndef ROPRAS_SCENARIOS_MANIPULATION_RAY_DETECT_CONFIG_H
#define ROPRAS_SCENARIOS_MANIPULATION_RAY_DETECT_CONFIG_H

#include <array>
#include <cstddef>
#include <map>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "ropras/scenarios/manipulation/PandaArm.h"

namespace ropras::scenarios
{
    /** \brief The number of uncertain obstacles of Ray-Detect (the paper: four obstacles on the table). */
    constexpr std::size_t RAY_DETECT_OBSTACLES = 4;

    /** \brief A box obstacle of Ray-Detect: its pose (x, y, z m, roll, pitch, yaw rad; R = Rz(yaw) Ry(pitch)
        Rx(roll), VAMP's static-XYZ Euler) and full extents (m). */
    struct RayDetectBox
    {
        std::array<double, 6> pose{};
        std::array<double, 3> extents{};
    };

    /** \brief The parameters of Ray-Detect (scenarios/manipulation/ray-detect/default.json; every key is
        described in doc/scenario-ray-detect.md). */
    struct RayDetectConfig
    {
        std::array<double, ARM_DOF> start{};           ///< "start": the initial configuration (rad)
        std::string endEffector{"panda_grasptarget"};  ///< "end_effector": the detector's link (ray along +z)
        std::array<double, 3> tableCenter{};           ///< "table.center"
        std::array<double, 3> tableExtents{};          ///< "table.extents" (full, m)
        std::array<double, 3> targetCenter{};          ///< "target.center": the can (a z-axis cylinder)
        double targetRadius{0.03};                     ///< "target.radius"
        double targetLength{0.12};                     ///< "target.length"
        std::array<RayDetectBox, RAY_DETECT_OBSTACLES> obstacles{};  ///< "obstacles": nominal (true-mean) boxes
        std::array<double, 3> goalPoint{};                           ///< "goal_point": the reach point (m)
        double goalRadius{0.05};                                     ///< "goal_radius"
        double rayLength{1.0};                                       ///< "ray_length" (m)
        double step{0.05};                                           ///< "step": L2 norm of a primitive dq
        bool waypointActions{false};                                 ///< "action_mode": "delta" / "waypoint"
        double transitionSigma{0.02};                                ///< "transition_sigma" (rad)
        double observationSigma{0.02};                               ///< "observation_sigma" (rad, joints)
        double positionNoise{0.02};                ///< "observation_position_noise": U(-a, a) m per axis
        double angleNoise{0.04};                   ///< "observation_angle_noise": U(-a, a) rad per angle
        double mismatchLikelihood{1e-3};           ///< "mismatch_likelihood": weight of a wrong detection id
        double initialSigmaJoints{0.0};            ///< "initial_sigma_joints": N(0, s) per joint in b0
        std::array<double, 6> initialSigmaPose{};  ///< "initial_sigma_pose": per pose component in b0
        double reinvigorateSigma{0.005};           ///< "reinvigorate_sigma": joint jitter (rad)
        double reinvigoratePositionSigma{0.005};   ///< "reinvigorate_position_sigma" (m)
        double reinvigorateAngleSigma{0.01};       ///< "reinvigorate_angle_sigma" (rad)
        double stepReward{-0.2};                   ///< "step_reward"
        double goalReward{300.0};                  ///< "goal_reward" (terminal)
        double discount{0.999};                    ///< "discount"
        std::size_t horizon{800};                  ///< "horizon"
        double resolution{0.02};                   ///< "resolution": motion-check step (rad)
        double observationDistanceBin{0.1};        ///< "observation_distance_bin" (m)
        double entropyCell{0.02};                  ///< "entropy_cell" (m): the Dynamic heuristic's bins
        bool heuristicValue{true};                 ///< "heuristic_value"
        double heuristicEndEffectorStep{0.02};     ///< "heuristic_ee_step": m of EE travel per step
        bool reachableGoal{true};                  ///< "reachable_goal": b0 and the world draw only reachable goals
        // "planning": the reference policy
        double planSeconds{0.5};                 ///< "planning.plan_seconds"
        double referencePlanTime{0.01};          ///< "planning.reference_plan_time"
        double planningMargin{0.01};             ///< "planning.margin": planner's obstacles grown by this (m)
        double plannerRange{0.5};                ///< "planning.planner_range"
        std::size_t ikRestarts{10};              ///< "planning.ik_restarts"
        std::size_t ikPoints{4};                 ///< "planning.ik_points"
        double ikRadiusFraction{0.6};            ///< "planning.ik_radius_fraction"
        double lookStandoff{0.35};               ///< "planning.look_standoff": m from an obstacle's centre
        std::array<double, 3> lookFrom{};        ///< "planning.look_from": look positions lie toward this point
        double lookAxisTolerance{0.03};          ///< "planning.look_axis_tolerance" (rad)
        std::map<std::string, double> defaults;  ///< "defaults"
        nlohmann::json json;                     ///< the effective configuration

        /** \brief Reads and validates every key of \a json: throws ropras::Error naming \a scenario, the key
            and the value (missing, unknown, wrong type, non-finite, out of range). */
        static RayDetectConfig fromJson(const nlohmann::json &json, const std::string &scenario);
    };
}  // namespace ropras::scenarios

#endif
