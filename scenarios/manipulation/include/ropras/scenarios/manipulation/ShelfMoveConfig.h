#ifndef ROPRAS_SCENARIOS_MANIPULATION_SHELF_MOVE_CONFIG_H
#define ROPRAS_SCENARIOS_MANIPULATION_SHELF_MOVE_CONFIG_H

#include <array>
#include <cstddef>
#include <map>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "ropras/scenarios/manipulation/PandaArm.h"

namespace ropras::scenarios
{
    /// the cans of Shelf-Move (the paper's 4 cylinders: the target and 3 movable obstacles)
    constexpr std::size_t SHELF_CANS = 4;

    /** \brief The parameters of Shelf-Move (scenarios/manipulation/shelf-move/default.json; every key is
        described in doc/scenario-shelf-move.md). Lengths in m, angles in rad. */
    struct ShelfMoveConfig
    {
        std::array<double, ARM_DOF> start{};           ///< "start": the true initial configuration
        std::string endEffector{"panda_grasptarget"};  ///< "end_effector"
        /// "shelf": static boxes [x, y, z, size_x, size_y, size_z] (centre, full extents): boards and walls
        std::vector<std::array<double, 6>> shelf;
        double canRadius{0.03};  ///< "can_radius"
        double canLength{0.14};  ///< "can_length"
        /// "held_clearance": the held can's collision geometry is a chain of spheres along its axis, this far inside
        /// its side and ends (so that it can leave its board and be set down on a slot)
        double heldClearance{0.006};
        std::array<std::array<double, 3>, SHELF_CANS> cans{};  ///< "cans": true centres (upright)
        std::size_t targetCan{0};                              ///< "target_can": index into cans
        std::vector<std::array<double, 3>> slots;              ///< "slots": can centres where a release lands
        std::size_t reservedSlot{1};                           ///< "reserved_slot": the target's slot (index)
        std::array<double, 3> approach{{1.0, 0.0, 0.0}};       ///< "grasp_approach": world approach axis
        double graspOffset{0.015};          ///< "grasp_offset": the can's axis this far beyond the EE along its z
        double graspTolerance{0.02};        ///< "grasp_tolerance": EE to the can's axis for a grasp
        double graspAxisTolerance{0.2};     ///< "grasp_axis_tolerance": EE x axis to vertical (rad)
        double placeTolerance{0.04};        ///< "place_tolerance": held can centre to a slot centre
        double senseDistance{0.15};         ///< "sense_distance": EE to a can centre for a detection
        double canObservationNoise{0.04};   ///< "can_observation_noise": U(-w, w) per axis
        double observationSoftening{0.01};  ///< "observation_softening": Gaussian tail outside the box (m)
        double step{0.1};                   ///< "step": L2 norm of a primitive dq
        bool waypointActions{true};         ///< "action_mode": "waypoint" (true) or "delta"
        bool repairOnDepletion{true};       ///< "depletion_recovery": "repair" (ShelfMoveRecovery) or "ignore"
        double transitionSigma{0.001};      ///< "transition_sigma": N(0, s) per joint and step
        double observationSigma{0.02};      ///< "observation_sigma": N(0, s) per observed joint
        double initialSigma{0.001};         ///< "initial_sigma": joints in b0
        double initialCanSigma{0.03};       ///< "initial_can_sigma": can x and y in b0
        /// "graspable_layout": b0 and the true world draw only layouts whose cans can be taken off one after another
        /// until the target is grasped (ShelfMoveModel::graspableLayout); false (default): every physically valid draw
        bool graspableLayout{false};
        double reinvigorateSigma{0.001};      ///< "reinvigorate_sigma": joint jitter per particle
        double reinvigorateCanSigma{0.005};   ///< "reinvigorate_can_sigma": can x, y jitter per particle
        double reinvigorateProbability{0.1};  ///< "reinvigorate_probability": share of particles jittered
        double stepReward{-0.1};              ///< "step_reward"
        double goalReward{800.0};             ///< "goal_reward" (terminal)
        double discount{0.9999};              ///< "discount"
        std::size_t horizon{3000};            ///< "horizon"
        double resolution{0.02};              ///< "resolution": motion-check step (rad, per joint)
        double observationCanBin{0.04};       ///< "observation_can_bin": bin of observed can positions
        double observationJointBin{0.0};      ///< "observation_joint_bin": 0 = joints not binned
        double entropyBin{0.02};              ///< "entropy_bin": cell of can positions for H(b)
        // "planning": the reference policy
        double planSeconds{1.0};         ///< "planning.plan_seconds": default time budget per call
        double referencePlanTime{0.05};  ///< "planning.reference_plan_time": per reference plan (s)
        double planningMargin{0.01};     ///< "planning.margin": the planner's shelf boxes grown by this
        double plannerRange{0.5};        ///< "planning.planner_range": VectorizedRRTConnect range (rad)
        std::size_t ikRestarts{8};       ///< "planning.ik_restarts": IK random restarts per target
        double senseFraction{0.7};       ///< "planning.sense_fraction": sensing points at this share of sense_distance
        double blockingHalfwidth{0.13};  ///< "planning.blocking_halfwidth": a can in front of the target within this
                                         ///< lateral distance blocks its grasp (the hand's half-width + a can radius)
        double placeLift{0.005};         ///< "planning.place_lift": release this far above the slot centre
        /// "planning.grasp_yaws": the approach's turns about the vertical that grasp and place IK try (degrees)
        std::vector<double> graspYaws{0.0, 15.0, -15.0, 30.0, -30.0};
        // "world": what really happens (ShelfMoveWorld, Bullet rigid-body dynamics) or the model as its own world
        bool bulletWorld{true};           ///< "world.type": "bullet" (default) or "model"
        double canMass{0.2};              ///< "world.can_mass" (kg)
        double canFriction{0.5};          ///< "world.can_friction": Bullet friction coefficient of the cans
        double canRestitution{0.0};       ///< "world.can_restitution"
        double shelfFriction{0.5};        ///< "world.shelf_friction": of the boards, walls and floor
        double gravity{9.81};             ///< "world.gravity" (m/s^2, along -z)
        bool pushCans{false};             ///< "world.push_cans": the arm pushes cans instead of being blocked
        double timeStep{1.0 / 240.0};     ///< "world.time_step": Bullet's fixed step (s)
        double pushJointSpeed{0.5};       ///< "world.push_joint_speed": fastest joint while pushing (rad/s)
        double settleSeconds{3.0};        ///< "world.settle_seconds": longest settling after a release (s)
        double settleSpeed{0.005};        ///< "world.settle_speed": settled below this speed (m/s) ...
        double settleAngularSpeed{0.05};  ///< "world.settle_angular_speed": ... and this one (rad/s)
        double tipAngle{0.2};             ///< "world.tip_angle": a settled can tilted more is reported tipped (rad)
        double reportDistance{0.002};     ///< "world.report_distance": a release that settles this far from the
                                          ///< model's snap is reported as moved (m)
        std::map<std::string, double> defaults;  ///< "defaults": solver / filter / policy parameters
        nlohmann::json json;                     ///< the effective configuration

        /** \brief Reads and validates every key of \a json: throws ropras::Error naming \a scenario, the key
            and the value (missing, unknown, wrong type, non-finite, out of range). */
        static ShelfMoveConfig fromJson(const nlohmann::json &json, const std::string &scenario);
    };
}  // namespace ropras::scenarios

#endif
