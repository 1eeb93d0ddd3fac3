#include "ropras/ompl_ext/ompl/JointStateSampler.h"

namespace ropras::ompl_ext
{
    JointStateSampler::JointStateSampler(const ompl::base::StateSpace *space)
        : ompl::base::RealVectorStateSampler(space), generator_(rng_.getLocalSeed())
    {
    }

    void JointStateSampler::sampleUniform(ompl::base::State *state)
    {
        const ompl::base::RealVectorBounds &bounds = space_->as<ompl::base::RealVectorStateSpace>()->getBounds();
        double *values = state->as<ompl::base::RealVectorStateSpace::StateType>()->values;
        const double *low = bounds.low.data();
        const double *high = bounds.high.data();
        const std::size_t dimension = bounds.low.size();
        for (std::size_t i = 0; i < dimension; ++i)
            values[i] = low[i] + (high[i] - low[i]) * generator_.uniform01();
    }
}  // namespace ropras::ompl_ext
