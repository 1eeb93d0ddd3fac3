#ifndef ROPRAS_SCENARIOS_CROSSING_PLANNING_H
#define ROPRAS_SCENARIOS_CROSSING_PLANNING_H

#include <array>
#include <memory>
#include <vector>

#include "ropras/ompl_ext/model/RobotModel.h"
#include "ropras/ompl_ext/scene/Environment.h"
#include "ropras/pomdp/OmplReferencePolicy.h"
#include "ropras/pomdp/TargetSpace.h"
#include "ropras/scenarios/crossing/CrossingModel.h"

namespace ropras::scenarios
{
    /** \brief A target of the crossing's sampling heuristics: a base pose (x, y, theta). */
    using CrossingTarget = std::array<double, 3>;

    /** \brief The informative states of stretch-crossing: goal = (goal, target_yaw); informative = the
        landmarks (detour waypoints left and right of the crossing, yaw target_yaw); distance = Euclidean in
        (x, y); entropy bin = the 0.2 m cell of the particle's pedestrian position (the uncertain part). */
    class CrossingTargetSpace final : public pomdp::TargetSpace<CrossingState, CrossingTarget>
    {
    public:
        explicit CrossingTargetSpace(const CrossingConfig &config);

        CrossingTarget goal(const CrossingState &) const override { return goal_; }
        std::size_t numInformative(const CrossingState &) const override { return informative_.size(); }
        CrossingTarget informative(const CrossingState &, std::size_t i) const override { return informative_[i]; }
        double distance(const CrossingState &a, const CrossingTarget &t) const override;
        std::uint64_t entropyBin(const CrossingState &p) const override;
        std::size_t numEntropyBins() const override { return bins_[0] * bins_[1]; }

    private:
        CrossingTarget goal_{};
        std::vector<CrossingTarget> informative_;
        std::array<double, 2> lo_{};
        std::array<std::size_t, 2> bins_{1, 1};
    };

    /** \brief The reference planner's side of stretch-crossing. The planner is kinematic: it plans the base
        (x, y, theta) of the Stretch robot as three independent joints (no wheel constraint) in the lab with
        the tables and the particle's pedestrian (grown by planning.pedestrian_margin; a sphere where the particle
        puts it now, or a capsule over its next planning.pedestrian_sweep steps). PathToMacroAction is the lookahead
       tracker, which makes the path drivable: the first planning.path_nodes waypoints form a polyline in (x, y); from
       the particle's state (including its twist), repeatedly: the point planning.lookahead ahead of the closest point
       of the polyline is the lookahead point; every one of the 45 twists is predicted with the noise-free drive
        (CrossingModel::predict: the same wheel ramps); the twist minimizing distance_weight x (distance from
        the predicted position to the lookahead point) + heading_weight x (heading error: the angle between
        the predicted heading and the bearing to the lookahead point, forward or backward, whichever is
        smaller) is appended and the prediction advances. It stops after macro_length twists or when the
        predicted base is within goal_tolerance / 2 of the path's end. The path's theta values are not
        tracked (the drive cannot follow them independently). */
    class CrossingPlanningAdapter final
        : public pomdp::OmplPlanningAdapter<CrossingState, CrossingModel::Action, CrossingTarget>
    {
    public:
        /** \brief \a pedestrian: the id of the pedestrian sphere in the policy's environment. Throws
            ropras::Error for macroLength 0. */
        CrossingPlanningAdapter(std::shared_ptr<const CrossingModel> model, std::size_t macroLength, int pedestrian);

        void configuration(const CrossingState &state, double *q) const override;
        bool targetConfiguration(const CrossingState &start, const CrossingTarget &target, double *q) const override;
        bool pathToMacroAction(const CrossingState &start, const double *waypoints, std::size_t count,
                               std::vector<CrossingModel::Action> &out) const override;
        bool poseObstacles(const CrossingState &particle, ompl_ext::Environment &working) const override;

    private:
        std::shared_ptr<const CrossingModel> model_;
        std::size_t macroLength_;
        int pedestrian_;
    };

    /** \brief The Stretch robot (robots/stretch/stretch.urdf, embedded) with base_x, base_y, base_theta as
        planning joints and the lift and arm held at the configuration's "lift" and "arm". Throws
        ropras::Error naming the key when the base joints' limits differ from "lab" or lift / arm lie outside
        their joint limits. */
    std::shared_ptr<const ompl_ext::RobotModel> loadStretchRobot(const CrossingConfig &config);

    /** \brief The robot's collision spheres in the base frame (at base pose 0, lift and arm held). */
    std::vector<CrossingSphere> stretchBaseSpheres(const ompl_ext::RobotModel &robot);

    /** \brief The static lab (walls as boxes outside the lab, the tables) as a shared Environment. */
    std::shared_ptr<const ompl_ext::Environment> crossingLab(const CrossingConfig &config);

    /** \brief An overlay of \a lab with the planner's pedestrian, named "pedestrian" (radius pedestrian_radius +
        planning.pedestrian_margin): a sphere, or with planning.pedestrian_sweep = k > 0 a capsule from the
        pedestrian's position to k steps ahead (where it walks during a macro); at the pedestrian's start. Its id
        is written to \a pedestrianId. */
    /** \brief The pose of the planner's pedestrian object for a pedestrian at (px, py) (see crossingPlanningScene). */
    Eigen::Isometry3d crossingPedestrianPose(const CrossingConfig &config, double px, double py);

    std::shared_ptr<const ompl_ext::Environment> crossingPlanningScene(const CrossingConfig &config,
                                                                       std::shared_ptr<const ompl_ext::Environment> lab,
                                                                       int &pedestrianId);
}  // namespace ropras::scenarios

#endif
