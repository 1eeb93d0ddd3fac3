#ifndef ROPRAS_SCENARIOS_MULTI_DRONE_PLANNING_H
#define ROPRAS_SCENARIOS_MULTI_DRONE_PLANNING_H

#include <array>
#include <cstddef>
#include <memory>
#include <string>
#include <vector>

#include "ropras/ompl_ext/model/RobotModel.h"
#include "ropras/ompl_ext/scene/Environment.h"
#include "ropras/pomdp/OmplReferencePolicy.h"
#include "ropras/pomdp/SamplingHeuristic.h"
#include "ropras/scenarios/multi-drone/MultiDroneModel.h"

namespace ropras::scenarios
{
    /** \brief A reference-plan target of Multi-Drone Tag: the 12-D goal configuration (x, y, z of drones
        1..4) and which drone chases (its goal is the sampled target location; MULTI_DRONE_COUNT = none, an
        epsilon-greedy exploration target). */
    struct MultiDroneTarget
    {
        std::array<double, 3 * MULTI_DRONE_COUNT> q{};
        std::size_t chaser{MULTI_DRONE_COUNT};
    };

    /** \brief The Multi-Drone sampling heuristic (the paper's exception to Uniform / Dynamic): a target
        location is taken from a belief particle; the drone nearest to it flies there, the other drones
        spread out. How they spread:
        - Spread::Uniform ("uniform"): each to a uniformly random position of the box;
        - Spread::Belief ("dynamic"): each to the target position of another belief particle, so the
          drones fan out over where the belief puts the target (over the whole box while it is unknown,
          around it once it has been seen).
        Every goal keeps at least 2 drone radii + 0.1 m from the goals placed before it (up to 64 draws;
        the uniform draw is the fallback). With probability \a epsilon all four drones get uniform random
        goals (epsilon-greedy exploration). Not thread-safe (one per solver). */
    class MultiDroneHeuristic final : public pomdp::SamplingHeuristic<MultiDroneModel::State, MultiDroneTarget>
    {
    public:
        enum class Spread
        {
            Uniform,
            Belief
        };

        /** \brief Throws ropras::Error for an epsilon outside [0, 1]. */
        MultiDroneHeuristic(const MultiDroneConfig &config, Spread spread, double epsilon);

        bool sample(const MultiDroneModel::State &agent, pomdp::BeliefView<MultiDroneModel::State> belief,
                    pomdp::Rng &rng, MultiDroneTarget &out) override;
        std::string name() const override;

        /** \brief "uniform" -> Uniform, "dynamic" -> Belief; anything else throws ropras::Error. */
        static Spread spreadFromName(const std::string &heuristic);

    private:
        bool place(std::size_t d, const double *p, std::size_t placedMask, const MultiDroneTarget &out) const;
        void uniformPoint(pomdp::Rng &rng, double *p) const;

        MultiDroneConfig config_;
        Spread spread_;
        double epsilon_;
    };

    /** \brief PathToMacroAction etc. for the 12-D drone configuration.

        The path is discretized with discretizeJointPath at the step size (consecutive points at most one
        step apart in 12-D); for every drone, the axis moves that follow its part of the points form a
        staircase (from the drone's current position, for each point repeatedly the axis with the largest
        remaining difference while that difference exceeds half a step). The macro interleaves the four
        staircases, up to \a macroLength actions: the chasing drone takes a share \a chaseShare of the
        actions while it has moves left (a primitive action moves one drone, and the target flees at
        target_step per action, so a chaser that got only every fourth action could never close in), the
        other drones take the rest in turn. Without a chaser (exploration targets) all four take turns.

        The chaser of the current plan comes from targetConfiguration() (OmplReferencePolicy calls it right
        before planning and pathToMacroAction for the same target): the adapter keeps it in a member, so an
        adapter serves one reference policy (one thread) at a time. */
    class MultiDronePlanningAdapter final
        : public pomdp::OmplPlanningAdapter<MultiDroneModel::State, MultiDroneModel::Action, MultiDroneTarget>
    {
    public:
        /** \brief Throws ropras::Error for macroLength 0, a non-positive step or chaseShare outside (0, 1]. */
        MultiDronePlanningAdapter(double stepSize, std::size_t macroLength, double chaseShare);

        void configuration(const MultiDroneModel::State &state, double *q) const override;
        bool targetConfiguration(const MultiDroneModel::State &start, const MultiDroneTarget &target,
                                 double *q) const override;
        bool pathToMacroAction(const MultiDroneModel::State &start, const double *waypoints, std::size_t count,
                               std::vector<MultiDroneModel::Action> &out) const override;

        /// the chaser of the next conversion (set by targetConfiguration(); MULTI_DRONE_COUNT = none)
        void setChaser(std::size_t chaser) const { chaser_ = chaser; }

    private:
        double step_;
        std::size_t macroLength_;
        double chaseShare_;
        mutable std::size_t chaser_{MULTI_DRONE_COUNT};
    };

    /** \brief The drones robot (scenarios/multi-drone/drones.urdf, embedded): 12 prismatic planning joints,
        one sphere per drone, self-collision between every two drones. Throws ropras::Error when its joint
        limits or sphere radius disagree with \a config (keys bounds / drone_radius) or a drone pair is
        missing from the self-collision pairs. */
    std::shared_ptr<const ompl_ext::RobotModel> loadMultiDroneRobot(const MultiDroneConfig &config);
}  // namespace ropras::scenarios

#endif
