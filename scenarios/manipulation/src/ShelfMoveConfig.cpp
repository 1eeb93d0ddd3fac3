#include "ropras/scenarios/manipulation/ShelfMoveConfig.h"

#include <algorithm>
#include <cmath>
#include <string>

#include "ropras/scenarios/ConfigReader.h"
#include "ropras/scenarios/manipulation/ArmStartKeys.h"

namespace ropras::scenarios
{
    namespace
    {
        /// the "world" keys (doc/scenario-shelf-move.md, "World")
        void readWorld(const ConfigReader &w, ShelfMoveConfig &c)
        {
            w.requireKnown({"type", "can_mass", "can_friction", "can_restitution", "shelf_friction", "gravity",
                            "push_cans", "time_step", "push_joint_speed", "settle_seconds", "settle_speed",
                            "settle_angular_speed", "tip_angle", "report_distance"});
            const std::string type = w.choice("type", {"bullet", "model"});
            c.bulletWorld = type == "bullet";
            c.canMass = w.within("can_mass", 1e-3, 100.0);
            c.canFriction = w.within("can_friction", 0.0, 10.0);
            c.canRestitution = w.within("can_restitution", 0.0, 1.0);
            c.shelfFriction = w.within("shelf_friction", 0.0, 10.0);
            c.gravity = w.within("gravity", 0.0, 100.0);
            c.pushCans = w.boolean("push_cans");
            c.timeStep = w.within("time_step", 1e-4, 0.05);
            c.pushJointSpeed = w.within("push_joint_speed", 1e-3, 10.0);
            c.settleSeconds = w.within("settle_seconds", 0.01, 60.0);
            c.settleSpeed = w.within("settle_speed", 1e-5, 1.0);
            c.settleAngularSpeed = w.within("settle_angular_speed", 1e-5, 10.0);
            c.tipAngle = w.within("tip_angle", 1e-3, 1.5);
            c.reportDistance = w.within("report_distance", 1e-5, 0.1);
        }
    }  // namespace

    ShelfMoveConfig ShelfMoveConfig::fromJson(const nlohmann::json &json, const std::string &scenario)
    {
        const ConfigReader r(scenario, json);
        r.requireKnown({"start",
                        "depletion_recovery",
                        "end_effector",
                        "shelf",
                        "can_radius",
                        "can_length",
                        "held_clearance",
                        "cans",
                        "target_can",
                        "slots",
                        "reserved_slot",
                        "grasp_approach",
                        "grasp_offset",
                        "grasp_tolerance",
                        "grasp_axis_tolerance",
                        "place_tolerance",
                        "sense_distance",
                        "can_observation_noise",
                        "observation_softening",
                        "step",
                        "action_mode",
                        "transition_sigma",
                        "observation_sigma",
                        "initial_sigma",
                        "initial_can_sigma",
                        "graspable_layout",
                        "reinvigorate_sigma",
                        "reinvigorate_can_sigma",
                        "reinvigorate_probability",
                        "step_reward",
                        "goal_reward",
                        "discount",
                        "horizon",
                        "resolution",
                        "observation_can_bin",
                        "observation_joint_bin",
                        "entropy_bin",
                        "planning",
                        "world",
                        "defaults"});
        ShelfMoveConfig c;
        c.json = json;
        readArmStartKeys(r, c.start, c.endEffector);
        for (const auto &row : r.rows("shelf", 6))
        {
            if (!(row[3] > 0.0 && row[4] > 0.0 && row[5] > 0.0))
            {
                r.fail("shelf", "has a box with a size that is not > 0");
            }
            c.shelf.push_back({{row[0], row[1], row[2], row[3], row[4], row[5]}});
        }
        if (c.shelf.empty() || c.shelf.size() > 64)
        {
            r.fail("shelf", "must list 1 to 64 boxes, not " + std::to_string(c.shelf.size()));
        }
        c.canRadius = r.within("can_radius", 0.005, 0.2);
        c.canLength = r.within("can_length", 0.01, 0.5);
        c.heldClearance = r.within("held_clearance", 0.001, 0.5 * c.canRadius);
        const auto cans = r.rows("cans", 3);
        if (cans.size() != SHELF_CANS)
        {
            r.fail("cans", "must list exactly " + std::to_string(SHELF_CANS) + " can centres [x, y, z], not " +
                               std::to_string(cans.size()));
        }
        for (std::size_t k = 0; k < SHELF_CANS; ++k)
        {
            c.cans[k] = {{cans[k][0], cans[k][1], cans[k][2]}};
        }
        c.targetCan = r.count("target_can", 0, SHELF_CANS - 1);
        for (const auto &row : r.rows("slots", 3))
        {
            c.slots.push_back({{row[0], row[1], row[2]}});
        }
        if (c.slots.empty() || c.slots.size() > 32)
        {
            r.fail("slots", "must list 1 to 32 slots, not " + std::to_string(c.slots.size()));
        }
        c.reservedSlot = r.count("reserved_slot", 0, c.slots.size() - 1);
        const auto approach = r.numbers("grasp_approach", 3);
        const double norm = std::hypot(approach[0], approach[1], approach[2]);
        if (!(norm > 1e-9) || std::abs(approach[2]) > 1e-9 * norm)
        {
            r.fail("grasp_approach", "must be a horizontal direction (z = 0, not zero)");
        }
        c.approach = {{approach[0] / norm, approach[1] / norm, 0.0}};
        c.graspOffset = r.within("grasp_offset", -0.05, 0.1);
        c.graspTolerance = r.within("grasp_tolerance", 1e-4, 0.2);
        c.graspAxisTolerance = r.within("grasp_axis_tolerance", 0.0, 1.5);
        c.placeTolerance = r.within("place_tolerance", 1e-4, 0.3);
        c.senseDistance = r.within("sense_distance", 0.0, 2.0);
        c.canObservationNoise = r.within("can_observation_noise", 1e-4, 1.0);
        c.observationSoftening = r.within("observation_softening", 1e-5, 1.0);
        c.step = r.within("step", 1e-4, 1.0);
        const std::string mode = r.choice("action_mode", {"delta", "waypoint"});
        c.waypointActions = mode == "waypoint";
        c.repairOnDepletion = r.choice("depletion_recovery", {"repair", "ignore"}) == "repair";
        c.transitionSigma = r.within("transition_sigma", 0.0, 1.0);
        c.observationSigma = r.within("observation_sigma", 1e-5, 1.0);
        c.initialSigma = r.within("initial_sigma", 0.0, 1.0);
        c.initialCanSigma = r.within("initial_can_sigma", 0.0, 0.5);
        c.graspableLayout = r.boolean("graspable_layout");
        c.reinvigorateSigma = r.within("reinvigorate_sigma", 0.0, 1.0);
        c.reinvigorateCanSigma = r.within("reinvigorate_can_sigma", 0.0, 0.5);
        c.reinvigorateProbability = r.within("reinvigorate_probability", 0.0, 1.0);
        c.stepReward = r.number("step_reward");
        c.goalReward = r.number("goal_reward");
        c.discount = r.within("discount", 1e-9, 1.0);
        c.horizon = r.count("horizon", 1, 10000000);
        c.resolution = r.within("resolution", 1e-4, 1.0);
        c.observationCanBin = r.within("observation_can_bin", 1e-4, 10.0);
        c.observationJointBin = r.within("observation_joint_bin", 0.0, 10.0);
        c.entropyBin = r.within("entropy_bin", 1e-4, 10.0);
        const ConfigReader p = r.sub("planning");
        p.requireKnown({"plan_seconds", "reference_plan_time", "margin", "planner_range", "ik_restarts",
                        "sense_fraction", "place_lift", "blocking_halfwidth", "grasp_yaws"});
        c.planSeconds = p.positive("plan_seconds");
        c.referencePlanTime = p.positive("reference_plan_time");
        c.planningMargin = p.within("margin", 0.0, 0.1);
        c.plannerRange = p.positive("planner_range");
        c.ikRestarts = p.count("ik_restarts", 0, 10000);
        c.senseFraction = p.within("sense_fraction", 0.0, 1.0);
        c.placeLift = p.within("place_lift", 0.0, 0.1);
        c.blockingHalfwidth = p.within("blocking_halfwidth", 0.0, 1.0);
        c.graspYaws = p.numbers("grasp_yaws", 0);
        if (c.graspYaws.empty() || c.graspYaws.size() > 16)
        {
            p.fail("grasp_yaws", "must list 1 to 16 angles (degrees), not " + std::to_string(c.graspYaws.size()));
        }
        for (const double yaw : c.graspYaws)
        {
            if (!(std::abs(yaw) <= 90.0))
            {
                p.fail("grasp_yaws", "has an angle outside [-90, 90] degrees: " + std::to_string(yaw));
            }
        }
        readWorld(r.sub("world"), c);
        const ConfigReader d = r.sub("defaults");
        for (const auto &item : r.at("defaults").items())
        {
            c.defaults[item.key()] = d.number(item.key());
        }
        return c;
    }
}  // namespace ropras::scenarios
