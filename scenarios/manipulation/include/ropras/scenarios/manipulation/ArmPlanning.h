#ifndef ROPRAS_SCENARIOS_MANIPULATION_ARM_PLANNING_H
#define ROPRAS_SCENARIOS_MANIPULATION_ARM_PLANNING_H

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
#include "ropras/scenarios/manipulation/PandaArm.h"
#include "ropras/scenarios/manipulation/SphereSearchModel.h"

namespace ropras::scenarios
{
    /** \brief A reference-plan target of the arm scenarios (an informative state): a workspace ball the end
        effector must reach (the goal, the light), or a joint configuration (epsilon-greedy exploration). */
    struct ArmTarget
    {
        enum class Kind
        {
            Point,
            Configuration
        };
        Kind kind{Kind::Point};
        std::array<double, 3> point{{0.0, 0.0, 0.0}};  ///< Point: the ball's centre (m)
        double radius{0.0};                            ///< Point: the ball's radius (m)
        std::array<double, ARM_DOF> q{};               ///< Configuration
    };

    /** \brief Goal configurations for workspace balls: inverse kinematics (position of the end effector,
        damped least squares with seeded random restarts) for points drawn uniformly within
        \a radiusFraction of the ball's radius, collision-free in a given environment. Successful solutions
        are kept per ball (up to \a poolSize): once the pool is full, a query returns the one nearest (joint-space
        L2) to the query's seed, the particle's configuration (\a nearest, the default), or one at random (the
        environment of the arm scenarios' planner is static, so a solution stays valid). Nearest: the reference
        plan then goes to the arm's own IK branch, a short motion, instead of to a far one that often needs the
        whole per-plan time limit (doc/scenario-sphere-search.md, "Target configurations"). Not thread-safe (one
        per reference policy). */
    class ArmGoalSampler
    {
    public:
        struct Settings
        {
            std::size_t restarts{10};    ///< IK random restarts per point
            std::size_t points{4};       ///< points tried per query
            double radiusFraction{0.6};  ///< points within this share of the ball's radius of its centre
            std::size_t poolSize{8};     ///< solutions kept per ball
            bool nearest{true};          ///< a full pool answers with its solution nearest to the seed, else at random
        };

        ArmGoalSampler(std::shared_ptr<const PandaArm> arm, std::shared_ptr<const ompl_ext::Environment> environment,
                       const Settings &settings, std::uint64_t seed);

        /** \brief A collision-free configuration whose end effector is in the ball (\a center, \a radius), the
            first IK attempt seeded with \a seed; false when none was found. noexcept (IK outcomes are values). */
        bool solve(const double *seed, const std::array<double, 3> &center, double radius, double *q) noexcept;

        /// the solutions pooled for the ball centred at \a center (empty when none)
        std::vector<std::array<double, ARM_DOF>> pooled(const std::array<double, 3> &center) const;

        /// IK solves run so far (for statistics and tests)
        std::size_t solves() const { return solves_; }

    private:
        struct Pool
        {
            std::array<double, 3> center;
            std::vector<std::array<double, ARM_DOF>> solutions;
        };

        /// the pooled solution answered for \a seed (Settings::nearest)
        std::size_t pick(const Pool &pool, const double *seed) noexcept;

        std::shared_ptr<const PandaArm> arm_;
        std::shared_ptr<const ompl_ext::Environment> environment_;
        Settings settings_;
        ompl_ext::InverseKinematics ik_;
        ompl_ext::IkWorkspace workspace_;
        ompl_ext::IkOptions options_;
        ompl_ext::ConfigurationPredicate valid_;
        core::Rng rng_;
        std::vector<Pool> pools_;
        std::size_t solves_{0};
    };

    /** \brief The informative states of Sphere-Search for the sampling heuristics: the goal is the ball of
        the particle's goal, the one informative state the light; distance = the end effector's (workspace)
        distance; the entropy bins are the two goal indices (H = the binary entropy of the goal marginal);
        free samples are uniform collision-free configurations (epsilon-greedy). */
    class SphereSearchTargetSpace final : public pomdp::TargetSpace<SphereSearchModel::State, ArmTarget>
    {
    public:
        SphereSearchTargetSpace(std::shared_ptr<const SphereSearchModel> model,
                                std::shared_ptr<const ompl_ext::Environment> planningEnvironment);

        ArmTarget goal(const SphereSearchModel::State &particle) const override;
        std::size_t numInformative(const SphereSearchModel::State &) const override { return 1; }
        ArmTarget informative(const SphereSearchModel::State &particle, std::size_t i) const override;
        double distance(const SphereSearchModel::State &agent, const ArmTarget &target) const override;
        std::uint64_t entropyBin(const SphereSearchModel::State &particle) const override
        {
            return static_cast<std::uint64_t>(particle.goal);
        }
        std::size_t numEntropyBins() const override { return 2; }
        bool sampleFree(pomdp::Rng &rng, ArmTarget &out) const override;

    private:
        std::shared_ptr<const SphereSearchModel> model_;
        std::shared_ptr<const ompl_ext::Environment> environment_;
    };

    /** \brief PathToMacroAction of the arm scenarios, "motion path up to a predefined length": the joint path
        (\a count x ARM_DOF waypoints, row-major) cut into steps of L2 norm <= \a step (discretizeJointPath),
        the first \a macroLength of them appended to \a out as joint displacements dq (\a waypointActions: as
        the points themselves, ArmAction::waypoint). \a scratch is reused. Returns false when nothing was
        appended. */
    bool jointPathToArmActions(const double *waypoints, std::size_t count, double step, std::size_t macroLength,
                               bool waypointActions, std::vector<double> &scratch, std::vector<ArmAction> &out);

    /** \brief The OMPL planning adapter of the arm scenarios: the configuration is the state's joints; a
        Point target's configuration comes from an ArmGoalSampler (IK in the planner's environment); a
        planned path becomes PathToMacroAction "motion path up to a predefined length": the path cut into
        steps of L2 norm <= \a step (discretizeJointPath), the first \a macroLength of them, as joint
        displacements dq (\a waypoints: as the points themselves, ArmAction::waypoint). The sampler is mutable: one
       adapter per reference policy (one thread). A particle inside the planning margin is planned for in the
       true world by the reference policy (OmplReferencePolicy::setTrueEnvironment). */
    class ArmPlanningAdapter final : public pomdp::OmplPlanningAdapter<SphereSearchModel::State, ArmAction, ArmTarget>
    {
    public:
        /** \brief Throws ropras::Error for a non-positive step or a macroLength of 0. */
        ArmPlanningAdapter(std::unique_ptr<ArmGoalSampler> sampler, double step, std::size_t macroLength,
                           bool waypoints = false);

        void configuration(const SphereSearchModel::State &state, double *q) const override;
        bool targetConfiguration(const SphereSearchModel::State &start, const ArmTarget &target,
                                 double *q) const override;
        bool pathToMacroAction(const SphereSearchModel::State &start, const double *waypoints, std::size_t count,
                               std::vector<ArmAction> &out) const override;

    private:
        std::unique_ptr<ArmGoalSampler> sampler_;
        double step_;
        std::size_t macroLength_;
        bool waypoints_;
        mutable std::vector<double> points_;
    };
}  // namespace ropras::scenarios

#endif
