#include "ropras/ompl_ext/PlanningContext.h"

#include <cmath>
#include <new>
#include <sstream>

#include "ropras/core/Error.h"
#include "ropras/ompl_ext/PlannerRegistry.h"

namespace ropras::ompl_ext
{
    namespace
    {
        /** The identity projection for spaces of one or two joints. OMPL 1.5.2's own
            RealVectorIdentityProjectionEvaluator, registered by default for such spaces, trips an Eigen assertion in
            Debian's build (it resizes a fixed-size Eigen::Ref), aborting KPIECE1, LBKPIECE1, BKPIECE1, ProjEST, SBL,
            PDST and STRIDE; this one writes the coordinates in place. */
        class JointIdentityProjection : public ompl::base::ProjectionEvaluator
        {
        public:
            explicit JointIdentityProjection(const ompl::base::RealVectorStateSpace *space)
                : ompl::base::ProjectionEvaluator(space), dimension_(space->getDimension())
            {
            }
            unsigned int getDimension() const override { return dimension_; }
            void defaultCellSizes() override
            {
                const auto &bounds = space_->as<ompl::base::RealVectorStateSpace>()->getBounds();
                cellSizes_.resize(dimension_);
                for (unsigned int i = 0; i < dimension_; ++i)
                    cellSizes_[i] = (bounds.high[i] - bounds.low[i]) / 20.0;
                bounds_ = bounds;
            }
            void project(const ompl::base::State *state, Eigen::Ref<Eigen::VectorXd> projection) const override
            {
                const double *values = state->as<ompl::base::RealVectorStateSpace::StateType>()->values;
                for (unsigned int i = 0; i < dimension_; ++i)
                    projection[i] = values[i];
            }

        private:
            unsigned int dimension_;
        };

        /// RealVectorStateSpace whose default projection for one or two joints is JointIdentityProjection
        /// (StateSpace::setup() re-registers the default projections, so it has to happen here), and whose
        /// states are one allocation each: the StateType header with its values right behind it.
        /// RealVectorStateSpace allocates the two separately, so every distance() in a planner's
        /// nearest-neighbour search chases a pointer to a second, unrelated cache line; here both sit together.
        class JointStateSpace : public ompl::base::RealVectorStateSpace
        {
        public:
            using ompl::base::RealVectorStateSpace::RealVectorStateSpace;
            /// bytes before the values: the header rounded up to a double
            static constexpr std::size_t HEADER =
                (sizeof(StateType) + alignof(double) - 1) / alignof(double) * alignof(double);

            ompl::base::State *allocState() const override
            {
                void *block = ::operator new(HEADER + dimension_ * sizeof(double));
                auto *state = new (block) StateType();
                state->values = reinterpret_cast<double *>(static_cast<char *>(block) + HEADER);
                return state;
            }
            void freeState(ompl::base::State *state) const override
            {
                auto *s = static_cast<StateType *>(state);
                s->~StateType();
                ::operator delete(static_cast<void *>(s));
            }
            void registerProjections() override
            {
                if (getDimension() <= 2)
                    registerDefaultProjection(std::make_shared<JointIdentityProjection>(this));
                else
                    ompl::base::RealVectorStateSpace::registerProjections();
            }
        };
    }  // namespace

    std::shared_ptr<ompl::base::RealVectorStateSpace> createStateSpace(const RobotModel &robot)
    {
        if (robot.dof() == 0)
            throw Error("robot '" + robot.name() + "' (" + robot.source() + ") has no planning joints");
        auto space = std::make_shared<JointStateSpace>(robot.dof());
        ompl::base::RealVectorBounds bounds(robot.dof());
        for (std::size_t i = 0; i < robot.dof(); ++i)
        {
            const PlanningJoint &joint = robot.joints()[i];
            bounds.setLow(i, joint.lower);
            bounds.setHigh(i, joint.upper);
            space->setDimensionName(i, joint.name);
        }
        space->setBounds(bounds);
        space->setName(robot.name());
        return space;
    }

    void PlanningContext::setEnvironment(std::shared_ptr<const Environment> environment)
    {
        validityChecker->setEnvironment(environment);
        motionValidator->setEnvironment(std::move(environment));
    }

    void PlanningContext::setState(ompl::base::State *state, const std::map<std::string, double> &jointValues,
                                   const std::string &context) const
    {
        const std::vector<double> q = robot->planningValues(jointValues, context);
        std::copy(q.begin(), q.end(), state->as<ompl::base::RealVectorStateSpace::StateType>()->values);
    }

    PlanningContext makePlanningContext(std::shared_ptr<const RobotModel> robot,
                                        std::shared_ptr<const Environment> environment,
                                        const PlanningContextOptions &options)
    {
        if (!robot)
            throw Error("makePlanningContext: null RobotModel");
        if (!environment)
            throw Error("makePlanningContext: null Environment");
        PlanningContext context;
        context.robot = robot;
        context.checker = std::make_shared<CollisionChecker>(robot, options.backend);
        context.setup = std::make_shared<ompl::geometric::SimpleSetup>(createStateSpace(*robot));
        const auto &si = context.setup->getSpaceInformation();
        context.validityChecker = std::make_shared<StateValidityChecker>(si, context.checker, environment);
        context.motionValidator =
            std::make_shared<MotionValidator>(si, context.checker, environment, options.resolution);
        context.setup->setStateValidityChecker(context.validityChecker);
        si->setMotionValidator(context.motionValidator);
        if (!options.planner.empty())
            context.setup->setPlanner(PlannerRegistry::instance().create(options.planner, si, options.plannerParams));
        else if (!options.plannerParams.empty())
            throw Error("makePlanningContext: planner parameters given without a planner name");
        si->setup();  // SimpleSetup::setup() also needs start and goal; it runs again in solve()
        return context;
    }

    PlanningContext makePlanningContext(const std::string &urdfPath, const std::string &srdfPath,
                                        std::shared_ptr<const Environment> environment,
                                        const RobotModel::Options &robotOptions, const PlanningContextOptions &options)
    {
        return makePlanningContext(RobotModel::fromUrdfFile(urdfPath, srdfPath, robotOptions), std::move(environment),
                                   options);
    }
}  // namespace ropras::ompl_ext
