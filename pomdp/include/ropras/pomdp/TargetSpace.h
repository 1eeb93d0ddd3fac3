#ifndef ROPRAS_POMDP_TARGET_SPACE_H
#define ROPRAS_POMDP_TARGET_SPACE_H

#include <cstddef>
#include <cstdint>

#include "ropras/pomdp/BeliefView.h"
#include "ropras/pomdp/Rng.h"

namespace ropras::pomdp
{
    /** \brief What a model tells the sampling heuristics about targets (the paper's "informative states":
        the goal, and states with observations or rewards, e.g. landmarks).

        Targets may depend on the hidden part of a particle (an uncertain goal or landmark position is part
        of the state), so every query takes the particle it is about. \c Target is whatever the model's
        connector (motion planner, macro builder) consumes: a configuration, a landmark id, an action. */
    template <class State, class Target>
    class TargetSpace
    {
    public:
        virtual ~TargetSpace() = default;

        /** \brief Required: the goal target according to \a particle. */
        virtual Target goal(const State &particle) const = 0;

        /** \brief Required: number of informative (non-goal) targets according to \a particle (may be 0). */
        virtual std::size_t numInformative(const State &particle) const = 0;

        /** \brief Required: informative target \a i < numInformative(particle). */
        virtual Target informative(const State &particle, std::size_t i) const = 0;

        /** \brief Required by DynamicHeuristic: distance from the agent in \a agent to \a target (>= 0). */
        virtual double distance(const State &agent, const Target &target) const = 0;

        /** \brief Required by DynamicHeuristic: the bin of \a particle for the belief entropy H(b). */
        virtual std::uint64_t entropyBin(const State &particle) const = 0;

        /** \brief Required by DynamicHeuristic: the number of possible entropy bins (H is normalised by its
            log; 0 = unknown, then the number of particles is used). */
        virtual std::size_t numEntropyBins() const = 0;

        /** \brief Optional (DynamicHeuristic): H(b) in [0, 1] computed by the model itself (e.g. an average of
            per-object entropies); a negative value (the default) means: use the histogram of entropyBin. */
        virtual double beliefEntropy(BeliefView<State> belief) const
        {
            (void)belief;
            return -1.0;
        }
        /** \brief Optional (EpsilonGreedyHeuristic): a target uniformly from free space; false if unsupported. */
        virtual bool sampleFree(Rng &rng, Target &out) const
        {
            (void)rng;
            (void)out;
            return false;
        }
    };
}  // namespace ropras::pomdp

#endif
