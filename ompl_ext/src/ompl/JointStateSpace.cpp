#include "ropras/ompl_ext/ompl/JointStateSpace.h"

#include <cmath>
#include <cstring>
#include <memory>
#include <new>

#include "ropras/ompl_ext/ompl/JointStateSampler.h"

namespace ropras::ompl_ext
{
    namespace
    {
        /// the identity projection for spaces of one or two joints, writing the coordinates in place
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

        /// bytes before the values: the header rounded up to a double
        constexpr std::size_t HEADER = (sizeof(ompl::base::RealVectorStateSpace::StateType) + alignof(double) - 1) /
                                       alignof(double) * alignof(double);
    }  // namespace

    ompl::base::State *JointStateSpace::allocState() const
    {
        void *block = ::operator new(HEADER + dimension_ * sizeof(double));
        auto *state = new (block) StateType();
        state->values = reinterpret_cast<double *>(static_cast<char *>(block) + HEADER);
        return state;
    }

    void JointStateSpace::freeState(ompl::base::State *state) const
    {
        auto *s = static_cast<StateType *>(state);
        s->~StateType();
        ::operator delete(static_cast<void *>(s));
    }

    double JointStateSpace::distance(const ompl::base::State *state1, const ompl::base::State *state2) const
    {
        const double *a = state1->as<StateType>()->values;
        const double *b = state2->as<StateType>()->values;
        const std::size_t dimension = dimension_;
        // four joints per vector step (one AVX register, or two SSE2 ones), then at most three one by one
        using Double4 = double __attribute__((vector_size(4 * sizeof(double))));
        Double4 sum4{};
        std::size_t i = 0;
        for (; i + 4 <= dimension; i += 4)
        {
            Double4 x, y;
            std::memcpy(&x, a + i, sizeof x);
            std::memcpy(&y, b + i, sizeof y);
            const Double4 d = x - y;
            sum4 += d * d;
        }
        double sum = (sum4[0] + sum4[2]) + (sum4[1] + sum4[3]);
        const auto square = [&](std::size_t k) { return (a[k] - b[k]) * (a[k] - b[k]); };
        switch (dimension - i)
        {
            case 3:
                sum += square(i + 2);
                [[fallthrough]];
            case 2:
                sum += square(i + 1);
                [[fallthrough]];
            case 1:
                sum += square(i);
                break;
            default:
                break;
        }
        return std::sqrt(sum);
    }

    ompl::base::StateSamplerPtr JointStateSpace::allocDefaultStateSampler() const
    {
        return std::make_shared<JointStateSampler>(this);
    }

    void JointStateSpace::registerProjections()
    {
        if (getDimension() <= 2)
            registerDefaultProjection(std::make_shared<JointIdentityProjection>(this));
        else
            ompl::base::RealVectorStateSpace::registerProjections();
    }
}  // namespace ropras::ompl_ext
