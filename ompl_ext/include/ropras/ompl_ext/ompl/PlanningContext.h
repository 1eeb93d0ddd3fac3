#ifndef ROPRAS_OMPL_EXT_PLANNING_CONTEXT_H
#define ROPRAS_OMPL_EXT_PLANNING_CONTEXT_H

#include <ompl/base/spaces/RealVectorStateSpace.h>
#include <ompl/geometric/SimpleSetup.h>
#include <map>
#include <memory>
#include <string>

#include "ropras/ompl_ext/collision/CollisionChecker.h"
#include "ropras/ompl_ext/ompl/MotionValidator.h"
#include "ropras/ompl_ext/ompl/StateValidityChecker.h"

namespace ropras::ompl_ext
{
    /** \brief A JointStateSpace (a RealVectorStateSpace, see JointStateSpace.h) with one dimension per planning
        joint, named after the joints, with bounds from the joint limits (continuous joints: [-pi, pi]). */
    std::shared_ptr<ompl::base::RealVectorStateSpace> createStateSpace(const RobotModel &robot);

    /** \brief Settings of makePlanningContext(). */
    struct PlanningContextOptions
    {
        double resolution{MotionValidator::DEFAULT_RESOLUTION};  ///< joint-space motion-check step
        SimdBackend backend{SimdBackend::Best};
        std::string planner;                               ///< empty: SimpleSetup's default choice
        std::map<std::string, std::string> plannerParams;  ///< set by name on the planner
        /// null: a new CollisionChecker for the robot (with \c backend); else this one is shared (it must be for the
        /// same RobotModel; \c backend is then its own): building a checker costs far more than a plan
        std::shared_ptr<const CollisionChecker> checker;
    };

    /** \brief Everything needed to plan for one robot in one environment: a ready SimpleSetup with the
        ropras validity checker and motion validator installed (SpaceInformation already set up).
        Keep it and call `setup->clear()` between queries; swap obstacles with setEnvironment(). */
    struct PlanningContext
    {
        std::shared_ptr<const RobotModel> robot;
        std::shared_ptr<const CollisionChecker> checker;
        std::shared_ptr<StateValidityChecker> validityChecker;
        std::shared_ptr<MotionValidator> motionValidator;
        std::shared_ptr<ompl::geometric::SimpleSetup> setup;

        const ompl::base::SpaceInformationPtr &spaceInformation() const { return setup->getSpaceInformation(); }
        /// replaces the obstacles seen by both validators (O(1)); call between queries
        void setEnvironment(std::shared_ptr<const Environment> environment);
        /// fills an OMPL state from joint values given by name (RobotModel::planningValues: every planning joint
        /// must be named, other URDF joints are ignored, so are unknown names unless the model is strict; what is
        /// ignored, clamped or wrapped is appended to \a warnings)
        void setState(ompl::base::State *state, const std::map<std::string, double> &jointValues,
                      const std::string &context = "joint values", std::vector<std::string> *warnings = nullptr) const;
    };

    PlanningContext makePlanningContext(std::shared_ptr<const RobotModel> robot,
                                        std::shared_ptr<const Environment> environment,
                                        const PlanningContextOptions &options = PlanningContextOptions());
    /// the same from files: URDF, optional SRDF (empty string: none), robot options
    PlanningContext makePlanningContext(const std::string &urdfPath, const std::string &srdfPath,
                                        std::shared_ptr<const Environment> environment,
                                        const RobotModel::Options &robotOptions = RobotModel::Options(),
                                        const PlanningContextOptions &options = PlanningContextOptions());
}  // namespace ropras::ompl_ext

#endif
