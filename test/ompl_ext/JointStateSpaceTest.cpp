// JointStateSpace's default sampler (JointStateSampler): uniform within the bounds, reproducible from a seed,
// independent between samplers, and overridable as any OMPL space's sampler.
#include "ropras/ompl_ext/ompl/JointStateSpace.h"

#include <gtest/gtest.h>
#include <ompl/base/ScopedState.h>

#include <algorithm>
#include <cmath>
#include <memory>
#include <random>
#include <vector>

#include "ropras/core/Rng.h"
#include "ropras/ompl_ext/ompl/JointStateSampler.h"

using ropras::ompl_ext::JointStateSampler;
using ropras::ompl_ext::JointStateSpace;

namespace
{
    /// seven joints with the Panda's limits
    std::shared_ptr<JointStateSpace> pandaLikeSpace()
    {
        const double low[7] = {-2.8973, -1.7628, -2.8973, -3.0718, -2.8973, -0.0175, -2.8973};
        const double high[7] = {2.8973, 1.7628, 2.8973, -0.0698, 2.8973, 3.7525, 2.8973};
        auto space = std::make_shared<JointStateSpace>(7);
        ompl::base::RealVectorBounds bounds(7);
        for (int i = 0; i < 7; ++i)
        {
            bounds.setLow(i, low[i]);
            bounds.setHigh(i, high[i]);
        }
        space->setBounds(bounds);
        space->setup();
        return space;
    }

    double *values(ompl::base::State *s)
    {
        return s->as<ompl::base::RealVectorStateSpace::StateType>()->values;
    }
}  // namespace

TEST(JointStateSpace, KeepsEachStatesValuesInItsOwnBlock)
{
    // JointStateSpace allocates each state as one block (header + values): the values sit right behind the
    // state, and every StateSpace operation (copy, clone, equality, interpolation, serialization, ScopedState)
    // behaves as on OMPL's own RealVectorStateSpace with the same bounds.
    auto space = pandaLikeSpace();
    const unsigned dof = space->getDimension();
    ompl::base::RealVectorStateSpace reference(dof);
    reference.setBounds(space->getBounds());
    reference.setup();
    std::mt19937 rng(4);
    std::uniform_real_distribution<double> u(0.0, 1.0);
    std::vector<ompl::base::State *> states;
    for (int i = 0; i < 200; ++i)
    {
        ompl::base::State *s = space->allocState();
        const char *begin = reinterpret_cast<const char *>(s);
        const char *valuesAt = reinterpret_cast<const char *>(values(s));
        EXPECT_GE(valuesAt, begin + sizeof(ompl::base::RealVectorStateSpace::StateType));
        EXPECT_LE(valuesAt, begin + 64) << "the values share the state's block";
        for (unsigned k = 0; k < dof; ++k)
            values(s)[k] = u(rng);
        states.push_back(s);
    }
    ompl::base::State *r1 = reference.allocState(), *r2 = reference.allocState(), *r3 = reference.allocState();
    ompl::base::State *mid = space->allocState();
    std::vector<char> buffer(space->getSerializationLength());
    for (std::size_t i = 0; i + 1 < states.size(); ++i)
    {
        ompl::base::State *a = states[i], *b = states[i + 1];
        reference.copyState(r1, a);
        reference.copyState(r2, b);
        EXPECT_DOUBLE_EQ(space->distance(a, b), reference.distance(r1, r2));
        space->interpolate(a, b, 0.3, mid);
        reference.interpolate(r1, r2, 0.3, r3);
        for (unsigned k = 0; k < dof; ++k)
            EXPECT_DOUBLE_EQ(values(mid)[k], r3->as<ompl::base::RealVectorStateSpace::StateType>()->values[k]);
        ompl::base::State *clone = space->cloneState(a);
        EXPECT_TRUE(space->equalStates(clone, a));
        EXPECT_FALSE(space->equalStates(clone, b));
        space->serialize(buffer.data(), b);
        space->deserialize(clone, buffer.data());
        EXPECT_TRUE(space->equalStates(clone, b));
        space->freeState(clone);
    }
    ompl::base::ScopedState<> scoped(space);
    scoped[0] = 0.25;
    scoped[1] = 0.75;
    ompl::base::ScopedState<> copy = scoped;
    EXPECT_EQ(copy[1], 0.75);
    reference.freeState(r1);
    reference.freeState(r2);
    reference.freeState(r3);
    space->freeState(mid);
    for (ompl::base::State *s : states)
        space->freeState(s);
}

TEST(JointStateSpace, DefaultSamplerIsJointStateSamplerUnlessAnAllocatorIsSet)
{
    auto space = pandaLikeSpace();
    EXPECT_NE(dynamic_cast<JointStateSampler *>(space->allocStateSampler().get()), nullptr);
    space->setStateSamplerAllocator([](const ompl::base::StateSpace *s)
                                    { return std::make_shared<ompl::base::RealVectorStateSampler>(s); });
    ompl::base::StateSamplerPtr sampler = space->allocStateSampler();
    EXPECT_EQ(dynamic_cast<JointStateSampler *>(sampler.get()), nullptr) << "a sampler allocator takes precedence";
    EXPECT_NE(dynamic_cast<ompl::base::RealVectorStateSampler *>(sampler.get()), nullptr);
}

TEST(JointStateSpace, SamplesAreUniformWithinTheBounds)
{
    auto space = pandaLikeSpace();
    const auto &bounds = space->getBounds();
    JointStateSampler sampler(space.get());
    sampler.setSeed(7);
    ompl::base::State *state = space->allocState();
    const int n = 100000, binCount = 20;
    std::vector<double> sum(7, 0.0), sumSq(7, 0.0), cross(6, 0.0);
    std::vector<std::vector<int>> bins(7, std::vector<int>(binCount, 0));
    for (int i = 0; i < n; ++i)
    {
        sampler.sampleUniform(state);
        for (int k = 0; k < 7; ++k)
        {
            const double v = values(state)[k];
            ASSERT_GE(v, bounds.low[k]) << "joint " << k;
            ASSERT_LT(v, bounds.high[k]) << "joint " << k;
            const double u = (v - bounds.low[k]) / (bounds.high[k] - bounds.low[k]);  // in [0, 1)
            sum[k] += u;
            sumSq[k] += u * u;
            if (k > 0)
                cross[k - 1] +=
                    (u - 0.5) *
                    ((values(state)[k - 1] - bounds.low[k - 1]) / (bounds.high[k - 1] - bounds.low[k - 1]) - 0.5);
            ++bins[k][std::min(binCount - 1, static_cast<int>(u * binCount))];
        }
    }
    for (int k = 0; k < 7; ++k)
    {
        const double mean = sum[k] / n;
        EXPECT_NEAR(mean, 0.5, 4.0 * std::sqrt(1.0 / 12.0 / n)) << "joint " << k;
        EXPECT_NEAR(sumSq[k] / n - mean * mean, 1.0 / 12.0, 0.002) << "joint " << k;
        double chi2 = 0.0;
        for (int count : bins[k])
            chi2 += (count - n / double(binCount)) * (count - n / double(binCount)) / (n / double(binCount));
        EXPECT_LT(chi2, 43.8) << "joint " << k << ": chi-square, 19 degrees of freedom, above its 0.1 % quantile";
        if (k > 0)  // neighbouring joints uncorrelated: correlation within 4 standard errors of 0
        {
            EXPECT_LT(std::abs(cross[k - 1] / n * 12.0), 4.0 / std::sqrt(n)) << "joints " << k - 1 << ", " << k;
        }
    }
    space->freeState(state);
}

TEST(JointStateSpace, SameSeedSameSamplesAndTheFormulaIsOmpls)
{
    auto space = pandaLikeSpace();
    const auto &bounds = space->getBounds();
    JointStateSampler a(space.get()), b(space.get());
    a.setSeed(42);
    b.setSeed(42);
    ropras::core::Rng reference(42);
    ompl::base::State *sa = space->allocState(), *sb = space->allocState();
    for (int i = 0; i < 100; ++i)
    {
        a.sampleUniform(sa);
        b.sampleUniform(sb);
        for (int k = 0; k < 7; ++k)
        {
            ASSERT_EQ(values(sa)[k], values(sb)[k]);
            // OMPL's formula, low + (high - low) * u, joint by joint in order
            ASSERT_EQ(values(sa)[k], bounds.low[k] + (bounds.high[k] - bounds.low[k]) * reference.uniform01());
        }
    }
    b.setSeed(43);
    b.sampleUniform(sb);
    a.sampleUniform(sa);
    EXPECT_FALSE(space->equalStates(sa, sb)) << "another seed, other samples";
    space->freeState(sa);
    space->freeState(sb);
}

TEST(JointStateSpace, SamplersTakeDistinctSeedsFromOmplsSequence)
{
    // each sampler seeds itself from its own ompl::RNG, which takes the next seed of OMPL's global sequence:
    // two samplers of one space draw different streams
    auto space = pandaLikeSpace();
    ompl::base::StateSamplerPtr a = space->allocStateSampler(), b = space->allocStateSampler();
    ompl::base::State *sa = space->allocState(), *sb = space->allocState();
    int equal = 0;
    for (int i = 0; i < 10; ++i)
    {
        a->sampleUniform(sa);
        b->sampleUniform(sb);
        equal += space->equalStates(sa, sb) ? 1 : 0;
    }
    EXPECT_EQ(equal, 0);
    space->freeState(sa);
    space->freeState(sb);
}

TEST(JointStateSpace, BoundsChangedAfterTheSamplerIsMadeAreHonoured)
{
    auto space = pandaLikeSpace();
    JointStateSampler sampler(space.get());
    sampler.setSeed(1);
    ompl::base::RealVectorBounds narrow(7);
    narrow.setLow(0.25);
    narrow.setHigh(0.5);
    space->setBounds(narrow);
    ompl::base::State *state = space->allocState();
    for (int i = 0; i < 1000; ++i)
    {
        sampler.sampleUniform(state);
        for (int k = 0; k < 7; ++k)
        {
            ASSERT_GE(values(state)[k], 0.25);
            ASSERT_LT(values(state)[k], 0.5);
        }
    }
    space->freeState(state);
}

TEST(JointStateSpace, DistanceMatchesOmplsForEveryDimensionCount)
{
    // four joints per vector step, the rest one by one: every remainder, and more than one vector step
    ropras::core::Rng rng(5);
    for (unsigned dimension = 1; dimension <= 11; ++dimension)
    {
        JointStateSpace space(dimension);
        ompl::base::RealVectorStateSpace reference(dimension);
        ompl::base::RealVectorBounds bounds(dimension);
        bounds.setLow(-4.0);
        bounds.setHigh(4.0);
        space.setBounds(bounds);
        reference.setBounds(bounds);
        ompl::base::State *a = space.allocState(), *b = space.allocState();
        ompl::base::State *ra = reference.allocState(), *rb = reference.allocState();
        for (int i = 0; i < 50; ++i)
        {
            for (unsigned k = 0; k < dimension; ++k)
            {
                ra->as<ompl::base::RealVectorStateSpace::StateType>()->values[k] = rng.uniform(-4.0, 4.0);
                rb->as<ompl::base::RealVectorStateSpace::StateType>()->values[k] = rng.uniform(-4.0, 4.0);
            }
            space.copyState(a, ra);
            space.copyState(b, rb);
            const double expected = reference.distance(ra, rb);
            ASSERT_NEAR(space.distance(a, b), expected, 1e-14 * expected) << dimension << " joints";
            ASSERT_EQ(space.distance(a, a), 0.0);
        }
        space.freeState(a);
        space.freeState(b);
        reference.freeState(ra);
        reference.freeState(rb);
    }
}
