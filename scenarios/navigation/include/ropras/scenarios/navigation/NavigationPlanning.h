#ifndef ROPRAS_SCENARIOS_NAVIGATION_PLANNING_H
#define ROPRAS_SCENARIOS_NAVIGATION_PLANNING_H

#include <array>
#include <memory>
#include <string>
#include <vector>

#include "ropras/ompl_ext/model/RobotModel.h"
#include "ropras/ompl_ext/scene/Environment.h"
#include "ropras/pomdp/OmplReferencePolicy.h"
#include "ropras/pomdp/TargetSpace.h"
#include "ropras/scenarios/ModelScenario.h"
#include "ropras/scenarios/navigation/NavigationModel.h"

namespace ropras::scenarios
{
    /** \brief A target of the navigation sampling heuristics: a position (z = 0 in 2-D). */
    using NavTarget = std::array<double, 3>;

    /** \brief The informative states of a navigation scenario: goal = goal-box centre, informative =
        observation-zone centres, distance = Euclidean, entropy bin = the 1 m cell of the position,
        sampleFree = a uniform point that the reference planner accepts as a goal: the robot's sphere clears the
        walls and obstacles grown by obstacle_margin and the danger zones grown by danger_margin (the planner's
        boxes, navigationEnvironment), so uniform targets are not wasted on plans that fail at the goal. */
    class NavigationTargetSpace final : public pomdp::TargetSpace<NavState, NavTarget>
    {
    public:
        explicit NavigationTargetSpace(std::shared_ptr<const NavigationModel> model);

        NavTarget goal(const NavState &) const override { return goal_; }
        std::size_t numInformative(const NavState &) const override { return informative_.size(); }
        NavTarget informative(const NavState &, std::size_t i) const override { return informative_[i]; }
        double distance(const NavState &a, const NavTarget &t) const override;
        std::uint64_t entropyBin(const NavState &p) const override;
        std::size_t numEntropyBins() const override { return bins_[0] * bins_[1] * bins_[2]; }
        bool sampleFree(pomdp::Rng &rng, NavTarget &out) const override;

    private:
        std::shared_ptr<const NavigationModel> model_;
        NavTarget goal_{};
        std::vector<NavTarget> informative_;
        std::vector<NavBox> plannerBoxes_;  ///< what the planner sees, grown by the margins
        std::size_t bins_[3]{1, 1, 1};
    };

    /** \brief OMPL adapter of the navigation robot: configuration = position; target configuration = the
        target; PathToMacroAction = discretizeJointPath (step = the action length, at most macroLength
        points), then a staircase of axis actions: from the current lattice point, repeatedly the axis with
        the largest remaining difference to the next point while it exceeds half a step; at most
        macroLength actions.

        Obstacles: the policy's base environment grows the danger zones by danger_margin and the walls and
        obstacles by obstacle_margin; the environment with everything at its true size is the policy's true
        environment (OmplReferencePolicy::setTrueEnvironment), so a particle inside a margin can still plan its
        way out. */
    class NavigationPlanningAdapter final : public pomdp::OmplPlanningAdapter<NavState, std::uint8_t, NavTarget>
    {
    public:
        NavigationPlanningAdapter(std::shared_ptr<const NavigationModel> model, std::size_t macroLength);

        void configuration(const NavState &state, double *q) const override;
        bool targetConfiguration(const NavState &start, const NavTarget &target, double *q) const override;
        bool pathToMacroAction(const NavState &start, const double *waypoints, std::size_t count,
                               std::vector<std::uint8_t> &out) const override;

    private:
        std::shared_ptr<const NavigationModel> model_;
        std::size_t macroLength_;
    };

    /** \brief The planner's robot: loads scenarios/<folder>/robot.urdf (embedded) and checks that its
        prismatic joints' limits equal the bounds and its one sphere's radius equals robot_radius; throws
        ropras::Error naming the file and the mismatch. */
    std::shared_ptr<const ompl_ext::RobotModel> loadNavigationRobot(const NavigationConfig &config,
                                                                    const std::string &folder);

    /** \brief The planner's obstacles: walls and obstacles (grown by \a obstacleMargin per side) AND danger
        zones (grown by \a dangerMargin per side) as boxes, so reference paths keep clear of danger zones and,
        with a margin, of what the robot would get stuck on; a negative margin = the configuration's
        danger_margin / obstacle_margin; 2-D boxes span z in [-1, 1]. */
    std::shared_ptr<const ompl_ext::Environment> navigationEnvironment(const NavigationConfig &config,
                                                                       double dangerMargin = -1.0,
                                                                       double obstacleMargin = -1.0);

    /** \brief The scenario \a name from its effective configuration \a json (parsed and validated here) and
        the robot of scenarios/<folder>/robot.urdf. */
    std::unique_ptr<Scenario> makeNavigationScenario(const std::string &name, const std::string &description,
                                                     const std::string &folder, const nlohmann::json &json);

    /** \brief The parts of that scenario (what makeNavigationScenario wraps). */
    ScenarioParts<NavigationModel> navigationParts(const std::string &name, const std::string &description,
                                                   const std::string &folder, const nlohmann::json &json);

    /** \brief Shortest number of primitive steps from \a start to the goal with deterministic actions (no
        slip) in the model, avoiding danger zones when \a avoidDanger (BFS over the action lattice);
        0 if the goal is unreachable. */
    std::size_t shortestGoalSteps(const NavigationModel &model, const NavState &start, bool avoidDanger = true);
}  // namespace ropras::scenarios

#endif
