#ifndef ROPRAS_SCENARIOS_MANIPULATION_RAY_DETECT_PLANNING_H
#define ROPRAS_SCENARIOS_MANIPULATION_RAY_DETECT_PLANNING_H

#include <array>
#include <cstddef>
#include <cstdint>
#include <memory>
#include <vector>

#include "ropras/core/Rng.h"
#include "ropras/ompl_ext/kinematics/InverseKinematics.h"
#include "ropras/ompl_ext/scene/Environment.h"
#include "ropras/pomdp/OmplReferencePolicy.h"
#include "ropras/pomdp/TargetSpace.h"
#include "ropras/scenarios/manipulation/RayDetectModel.h"

namespace ropras::scenarios
{
    /** \brief A reference-plan target of Ray-Detect (an informative state): the goal ball, a look at obstacle
        \c object (its centre \c point in the particle the target was drawn from), or a configuration
        (epsilon-greedy exploration). */
    struct RayDetectTarget
    {
        enum class Kind
        {
            Goal,
            Look,
            Configuration
        };
        Kind kind{Kind::Goal};
        int object{-1};
        std::array<double, 3> point{{0.0, 0.0, 0.0}};
        std::array<double, ARM_DOF> q{};
    };

    /** \brief The informative states of Ray-Detect for the sampling heuristics: the goal (the reach ball at the
        can), one look per obstacle (at the particle's obstacle centre); distance = the end effector's workspace
        distance to the target's point; H(b) = the mean over the 4 obstacles of the normalised entropy of the
        particles' obstacle positions binned in entropy_cell cubes (1 when spread, 0 when collapsed); free
        samples are uniform configurations, collision-free in the nominal planning scene (epsilon-greedy). */
    class RayDetectTargetSpace final : public pomdp::TargetSpace<RayDetectModel::State, RayDetectTarget>
    {
    public:
        RayDetectTargetSpace(std::shared_ptr<const RayDetectModel> model,
                             std::shared_ptr<const ompl_ext::Environment> planningScene);

        RayDetectTarget goal(const RayDetectModel::State &particle) const override;
        std::size_t numInformative(const RayDetectModel::State &) const override { return RAY_DETECT_OBSTACLES; }
        RayDetectTarget informative(const RayDetectModel::State &particle, std::size_t i) const override;
        double distance(const RayDetectModel::State &agent, const RayDetectTarget &target) const override;
        /// the joint cell of the 4 obstacle positions (used only when beliefEntropy is not)
        std::uint64_t entropyBin(const RayDetectModel::State &particle) const override;
        std::size_t numEntropyBins() const override { return 0; }
        double beliefEntropy(pomdp::BeliefView<RayDetectModel::State> belief) const override;
        bool sampleFree(pomdp::Rng &rng, RayDetectTarget &out) const override;

    private:
        std::uint64_t cell(const RayDetectModel::State &particle, std::size_t k) const;
        std::shared_ptr<const RayDetectModel> model_;
        std::shared_ptr<const ompl_ext::Environment> scene_;
    };

    /** \brief Goal configurations of Ray-Detect in a particle's planning scene: the goal by position IK (damped
        least squares, seeded restarts) for points within ik_radius_fraction of goal_radius; a look at obstacle
        k by position + approach-axis IK: the end effector at look_standoff from the particle's obstacle centre
        toward look_from, its +z axis (the ray) through that centre, accepted when the ray hits obstacle k first.
        Both collision-free in the particle's scene. Recent solutions are kept per target (goal, each obstacle)
        and re-validated in the next particle's scene before any IK is run. Not thread-safe. */
    class RayDetectGoalSampler
    {
    public:
        RayDetectGoalSampler(std::shared_ptr<const RayDetectModel> model,
                             std::shared_ptr<const ompl_ext::Environment> planningScene, std::uint64_t seed);

        /** \brief A configuration for \a target in \a particle's scene (first IK attempt seeded with the
            particle's joints); false when none was found. */
        bool solve(const RayDetectModel::State &particle, const RayDetectTarget &target, double *q) noexcept;
        std::size_t ikSolves() const { return solves_; }

    private:
        bool valid(const double *q, int object) const noexcept;
        bool fromPool(std::size_t pool, int object, double *q) noexcept;
        void remember(std::size_t pool, const double *q);
        bool solveGoal(const double *seed, double *q) noexcept;
        bool solveLook(const RayDetectModel::State &particle, int object, double *q) noexcept;

        std::shared_ptr<const RayDetectModel> model_;
        ompl_ext::Environment working_;
        ompl_ext::InverseKinematics ik_;
        ompl_ext::IkWorkspace workspace_;
        ompl_ext::IkOptions goalOptions_, lookOptions_;
        ompl_ext::ConfigurationPredicate free_;
        core::Rng rng_;
        /// pool 0: the goal; pool 1 + k: looks at obstacle k
        std::vector<std::vector<std::array<double, ARM_DOF>>> pools_;
        std::size_t solves_{0};
    };

    /** \brief The OMPL planning adapter of Ray-Detect: the configuration is the state's joints; the particle's
        obstacles are posed in the planner's scene (poseObstacles: the per-particle scene); a target's
        configuration comes from a RayDetectGoalSampler; PathToMacroAction is jointPathToArmActions (the first
        \a macroLength steps of at most \a step). One adapter per reference policy (one thread). */
    class RayDetectPlanningAdapter final
        : public pomdp::OmplPlanningAdapter<RayDetectModel::State, ArmAction, RayDetectTarget>
    {
    public:
        /** \brief Throws ropras::Error for a null sampler, a non-positive step or a macroLength of 0. */
        RayDetectPlanningAdapter(std::unique_ptr<RayDetectGoalSampler> sampler, double step, std::size_t macroLength,
                                 bool waypoints);

        void configuration(const RayDetectModel::State &state, double *q) const override;
        bool targetConfiguration(const RayDetectModel::State &start, const RayDetectTarget &target,
                                 double *q) const override;
        bool pathToMacroAction(const RayDetectModel::State &start, const double *waypoints, std::size_t count,
                               std::vector<ArmAction> &out) const override;
        bool poseObstacles(const RayDetectModel::State &particle, ompl_ext::Environment &working) const override;

    private:
        std::unique_ptr<RayDetectGoalSampler> sampler_;
        double step_;
        std::size_t macroLength_;
        bool waypoints_;
        mutable std::vector<double> points_;
    };
}  // namespace ropras::scenarios

#endif
