#ifndef ROPRAS_POMDP_ROP_RAS3_SOLVER_H
#define ROPRAS_POMDP_ROP_RAS3_SOLVER_H

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>
#include <memory>
#include <string>
#include <utility>
#include <vector>

#include "ropras/core/Error.h"
#include "ropras/pomdp/BeliefView.h"
#include "ropras/pomdp/MacroAction.h"
#include "ropras/pomdp/Model.h"
#include "ropras/pomdp/ParticleArena.h"
#include "ropras/pomdp/ReferencePolicy.h"
#include "ropras/pomdp/RopRas3Settings.h"
#include "ropras/pomdp/SearchTree.h"
#include "ropras/pomdp/SoftBackup.h"
#include "ropras/pomdp/Solver.h"

namespace ropras::pomdp
{
    /** \brief ROP-RAS3 (Algorithm 2 of the paper) over a model M.

        Depth-first Simulate from the root: sample a particle s of the node; below depth D return a rollout;
        otherwise ActionProgressiveWiden (a new macro from the reference policy, started at s, iff
        |C(b)| <= beta_a N(b)^alpha_a, else a uniformly chosen existing child), run the macro with the
        generative model, bin the macro observation (MacroStepResult::observationKey), add s' to the child's
        particles (with fill_particles K > 0, a child created within depth D also gets up to K particles of b
        moved through the macro that see the same observation, fillBelief()), recurse, and Backup: N(b)++,
        N(ba)++, Q(ba) += (r - Q)/N(ba) with r = macro reward + gamma^len V(child), and the soft value update
        softValueUpdate() (value_backup 0) or currentSoftValue() over the children (value_backup 1; value_backup 2
        also makes Q(ba) of the children's current values, freshChild()). The executed action is read off the
        root with pi*(a|b) ~ pibar(a|b) exp(eta Q(b,a)): children were drawn from pibar, so this is argmax Q
        (default) or a softmax sample over the children.

        Deviations (documented in doc/pomdp.md): observation widening is replaced by binning (as in the
        paper's implementation); value_backup = 1 (RopRas3Settings::ValueBackup::CURRENT) computes V from
        the children's current Q instead of the running mean; when the reference policy fails at a node without
        children the simulation returns a rollout from s without a backup at that node; terminal outcomes do not
        create a child.

        All tree storage (nodes, macro pool, particle arena) is flat and reused across plan() calls. */
    template <class M>
    class RopRas3Solver final : public Solver<M>
    {
    public:
        using State = typename M::State;
        using Action = typename M::Action;

        RopRas3Solver(std::shared_ptr<const M> model, std::unique_ptr<ReferencePolicy<M>> reference,
                      const RopRas3Settings &settings, std::string name = "ropras3")
            : model_(std::move(model)), reference_(std::move(reference)), settings_(settings), name_(std::move(name))
        {
            if (!model_ || !reference_)
            {
                throw Error("RopRas3Solver: missing model or reference policy");
            }
            settings_.validate();
        }

        std::string name() const override { return name_; }

        const RopRas3Settings &settings() const { return settings_; }

        PlanResult<Action> plan(BeliefView<State> belief, const Budget &budget, Rng &rng) override
        {
            if (belief.empty())
            {
                throw Error(name_ + ": plan() called with an empty belief");
            }
            detail::BudgetGuard guard(budget);
            reset();
            stats_ = SearchStatistics{};
            const std::uint32_t root = newBeliefNode(0);
            arena_.assign(beliefs_[root].particles, belief.particles, belief.size);
            std::size_t done = 0;
            while (!guard.exhausted(done))
            {
                if (done > 0 && treeFull())  // at least one simulation, even when the root alone fills the cap
                {
                    stats_.memoryCapped = 1;
                    break;
                }
                simulate(root, 0, rng);
                ++done;
            }
            stats_.treeBytes = treeBytes();
            stats_.simulations = done;
            stats_.seconds = guard.elapsed();
            stats_.beliefNodes = beliefs_.size();
            stats_.actionNodes = actions_.size();
            stats_.rootValue = beliefs_[root].value;
            const std::uint32_t best = selectRootAction(rng);
            return detail::planResultOf(stats_, macroPool_, best == NONE ? nullptr : &actions_[best]);
        }

        /** \brief Root children after the last plan(): (Q, N) pairs, for tests and diagnostics. */
        std::vector<std::pair<double, std::uint32_t>> rootChildren() const
        {
            std::vector<std::pair<double, std::uint32_t>> out;
            if (beliefs_.empty())
            {
                return out;
            }
            for (const std::uint32_t a : childArena_.view(beliefs_[0].children))
            {
                out.emplace_back(actions_[a].q, actions_[a].visits);
            }
            return out;
        }

        /** \brief The tree of the last plan() in breadth-first order, with pi* ~ exp(eta Q) per node. */
        bool treeSnapshot(TreeSnapshot &out) const override
        {
            if (beliefs_.empty())
            {
                out = TreeSnapshot{};
                return false;
            }
            std::vector<std::uint32_t> order = detail::beginSnapshot(out, name_, stats_);
            for (std::size_t i = 0; i < order.size(); ++i)
            {
                const BeliefNode &node = beliefs_[order[i]];
                out.beliefs[i].key = node.key;
                out.beliefs[i].visits = node.visits;
                out.beliefs[i].value = node.value;
                out.beliefs[i].particles = node.particles.size;
                for (const std::uint32_t a : childArena_.view(node.children))
                {
                    detail::snapshotAction(out, static_cast<std::uint32_t>(i), actions_[a], macroPool_, beliefs_,
                                           order);
                }
            }
            fillSoftPolicy(out, settings_.eta);
            return true;
        }

    private:
        static constexpr std::uint32_t NONE = std::numeric_limits<std::uint32_t>::max();

        struct BeliefNode
        {
            std::uint64_t key{0};
            std::uint32_t nextSibling{NONE};
            std::uint32_t visits{0};
            double value{0.0};
            /** \brief Widening: a new child is due while visits >= widenAt, i.e. |C| <= beta N^alpha. */
            double widenAt{0.0};
            typename ParticleArena<State>::Segment particles;
            /** \brief The action children (indices into actions_), contiguous for O(1) uniform choice. */
            ParticleArena<std::uint32_t>::Segment children;
        };

        /// value_backup FRESH: an action's summed macro rewards and sum over its children of D(bao) V(bao)
        struct ActionSums
        {
            double reward{0.0};
            double children{0.0};
        };

        struct ActionNode
        {
            std::uint32_t macroOffset{0};
            std::uint32_t macroLength{0};
            std::uint32_t firstChild{NONE};
            std::uint32_t visits{0};
            double q{0.0};
        };

        void reset()
        {
            beliefs_.clear();
            actions_.clear();
            macroPool_.clear();
            arena_.clear();
            childArena_.clear();
            observationCounts_.clear();
            inflow_.clear();
            actionSums_.clear();
        }

        /// bytes the tree uses (sizes, not capacities: the pools keep their capacity from one plan() to the next)
        std::size_t treeBytes() const noexcept
        {
            return beliefs_.size() * sizeof(BeliefNode) + actions_.size() * sizeof(ActionNode) +
                   macroPool_.size() * sizeof(Action) + arena_.usedBytes() + childArena_.usedBytes() +
                   observationCounts_.size() * sizeof(std::uint32_t) + inflow_.size() * sizeof(double) +
                   actionSums_.size() * sizeof(ActionSums);
        }

        bool treeFull() const noexcept
        {
            const std::size_t largest = std::max({beliefs_.size(), actions_.size(), macroPool_.size(),
                                                  arena_.storedParticles(), childArena_.storedParticles()});
            return detail::treeFull(treeBytes(), largest, settings_.maxTreeMegabytes);
        }

        std::uint32_t newBeliefNode(std::uint64_t key)
        {
            beliefs_.emplace_back();
            beliefs_.back().key = key;
            return static_cast<std::uint32_t>(beliefs_.size() - 1);
        }

        double rollout(const State &s, Rng &rng) noexcept
        {
            if (!settings_.profile)
            {
                return rolloutValue(*model_, s, settings_.rolloutSteps, rng, settings_.heuristicLeaf);
            }
            const auto start = detail::Clock::now();
            const double v = rolloutValue(*model_, s, settings_.rolloutSteps, rng, settings_.heuristicLeaf);
            stats_.modelSeconds += detail::secondsSince(start);
            return v;
        }

        /** \brief ActionProgressiveWiden; NONE when a new macro was due, the reference failed and there is
            no child to fall back on. */
        std::uint32_t progressiveWiden(std::uint32_t b, const State &s, Rng &rng, bool &created)
        {
            created = false;
            // |C| <= beta N^alpha  <=>  N >= (|C| / beta)^(1 / alpha); the threshold is recomputed only when
            // a child is added (N = 0 admits the first child for any alpha > 0, as 0^alpha = 0).
            if (static_cast<double>(beliefs_[b].visits) >= beliefs_[b].widenAt)
            {
                const std::uint32_t fresh = newAction(b, s, rng);
                if (fresh != NONE)
                {
                    created = true;
                    return fresh;
                }
            }
            if (beliefs_[b].children.size == 0)
            {
                return NONE;
            }
            return settings_.ucbSelection ? ucbChild(b) : childArena_.sample(beliefs_[b].children, rng);
        }

        /** \brief UCB1 over the children of \a b (the first unvisited child, if any). */
        std::uint32_t ucbChild(std::uint32_t b) const noexcept
        {
            const double logN = std::log(static_cast<double>(std::max<std::uint32_t>(beliefs_[b].visits, 1)));
            std::uint32_t best = NONE;
            double bestScore = -std::numeric_limits<double>::infinity();
            for (const std::uint32_t a : childArena_.view(beliefs_[b].children))
            {
                if (actions_[a].visits == 0)
                {
                    return a;
                }
                const double score =
                    actions_[a].q + settings_.ucbC * std::sqrt(logN / static_cast<double>(actions_[a].visits));
                if (score > bestScore)
                {
                    bestScore = score;
                    best = a;
                }
            }
            return best;
        }

        std::uint32_t newAction(std::uint32_t b, const State &s, Rng &rng)
        {
            scratch_.clear();
            ++stats_.referenceRequested;
            bool ok;
            if (settings_.profile)
            {
                const auto start = detail::Clock::now();
                ok = reference_->sample(s, arena_.view(beliefs_[b].particles), rng, scratch_);
                stats_.referenceSeconds += detail::secondsSince(start);
            }
            else
            {
                ok = reference_->sample(s, arena_.view(beliefs_[b].particles), rng, scratch_);
            }
            if (!ok || scratch_.empty())
            {
                ++stats_.referenceFailed;
                return NONE;
            }
            ActionNode action;
            action.macroOffset = static_cast<std::uint32_t>(macroPool_.size());
            action.macroLength = static_cast<std::uint32_t>(scratch_.size());
            macroPool_.insert(macroPool_.end(), scratch_.begin(), scratch_.end());
            actions_.push_back(action);
            const auto index = static_cast<std::uint32_t>(actions_.size() - 1);
            childArena_.add(beliefs_[b].children, index, 0, rng);
            beliefs_[b].widenAt = widenThreshold(beliefs_[b].children.size);
            return index;
        }

        /** \brief Visits at which the next child is admitted when a node has \a children (cached table). */
        double widenThreshold(std::uint32_t children)
        {
            while (widenTable_.size() <= children)
            {
                widenTable_.push_back(computeWidenThreshold(static_cast<std::uint32_t>(widenTable_.size())));
            }
            return widenTable_[children];
        }

        double computeWidenThreshold(std::uint32_t children) const noexcept
        {
            const double ratio = static_cast<double>(children) / settings_.betaA;
            if (settings_.alphaA == 0.0)
            {
                return ratio <= 1.0 ? 0.0 : std::numeric_limits<double>::infinity();
            }
            if (ratio == 0.0)
            {
                return 0.0;
            }
            return std::pow(ratio, 1.0 / settings_.alphaA);
        }

        /** \brief The observation child of action \a a for the macro observation \a key: the child with that
            key, else a new one (binning; with observation widening only while |C(ba)| <= beta_o N(ba)^alpha_o,
            otherwise an existing child drawn w.p. M(bao) / sum M). */
        std::uint32_t childFor(std::uint32_t a, std::uint64_t key, Rng &rng)
        {
            if (settings_.betaO == 0.0)
            {
                return detail::observationChild(beliefs_, actions_[a].firstChild, key);
            }
            // M(bao) lives in observationCounts_ (indexed like beliefs_), kept only with widening: the nodes stay
            // 64 bytes
            std::uint32_t children = 0, total = 0;
            for (std::uint32_t c = actions_[a].firstChild; c != NONE; c = beliefs_[c].nextSibling)
            {
                if (beliefs_[c].key == key)
                {
                    ++observationCounts_[c];
                    return c;
                }
                ++children;
                total += observationCounts_[c];
            }
            if (children > 0 &&
                static_cast<double>(children) >
                    settings_.betaO * std::pow(static_cast<double>(actions_[a].visits), settings_.alphaO))
            {
                auto u = static_cast<std::uint32_t>(rng.uniformIndex(total));
                for (std::uint32_t c = actions_[a].firstChild; c != NONE; c = beliefs_[c].nextSibling)
                {
                    if (u < observationCounts_[c])
                    {
                        return c;
                    }
                    u -= observationCounts_[c];
                }
            }
            const std::uint32_t c = detail::observationChild(beliefs_, actions_[a].firstChild, key);
            observationCounts_.resize(beliefs_.size(), 0);
            observationCounts_[c] = 1;
            return c;
        }

        std::uint64_t macroKey(const MacroStepResult<State, typename M::Observation> &step) const noexcept
        {
            return settings_.macroObservation == RopRas3Settings::MacroObservation::LAST ? step.lastObservationKey
                                                                                         : step.observationKey;
        }

        double simulate(std::uint32_t b, unsigned depth, Rng &rng) noexcept
        {
            const State s = arena_.sample(beliefs_[b].particles, rng);
            if (depth > settings_.maxDepth)
            {
                return rollout(s, rng);
            }
            if (depth > stats_.maxDepth)
            {
                stats_.maxDepth = depth;
            }
            bool created = false;
            const std::uint32_t a = progressiveWiden(b, s, rng, created);
            if (a == NONE)
            {
                return rollout(s, rng);
            }
            const auto macro = detail::macroOf(macroPool_, actions_[a]);
            const State &start =
                created && settings_.independentEvaluation ? arena_.sample(beliefs_[b].particles, rng) : s;
            const auto step = detail::executeMacroCounted(*model_, start, macro, rng, settings_.profile, stats_);
            const bool fresh = settings_.valueBackup == RopRas3Settings::ValueBackup::FRESH;
            double r = step.reward;
            if (!step.terminal)
            {
                const std::uint32_t c = childFor(a, macroKey(step), rng);
                const bool createdChild = beliefs_[c].particles.size == 0;
                arena_.add(beliefs_[c].particles, step.next, settings_.maxParticlesPerNode, rng);
                // a leaf below depth D (valued by a rollout from one particle) has no use for a belief
                if (createdChild && settings_.fillParticles > 0 && depth < settings_.maxDepth)
                {
                    fillBelief(b, a, c, rng);
                }
                const double before = beliefs_[c].value;
                const std::uint32_t visitsBefore = beliefs_[c].visits;
                const double v = simulate(c, depth + 1, rng);
                r += step.discount * v;
                if (fresh)
                {
                    freshChild(a, c, before, visitsBefore, v, step.discount);
                }
            }
            BeliefNode &node = beliefs_[b];
            ActionNode &action = actions_[a];
            ++node.visits;
            ++action.visits;
            if (fresh)
            {
                ActionSums &sums = sumsOf(a);
                sums.reward += step.reward;
                action.q = (sums.reward + sums.children) / static_cast<double>(action.visits);
            }
            else
            {
                action.q += (r - action.q) / static_cast<double>(action.visits);
            }
            node.value = settings_.valueBackup == RopRas3Settings::ValueBackup::RUNNING
                             ? softValueUpdate(node.value, action.q, node.visits, settings_.eta)
                             : currentSoftValue(b);
            return node.value;
        }

        /** \brief Belief fill (RopRas3Settings::fillParticles) of the new node \a c = b a o: particles of \a b
            moved through \a a, kept when they end it alive with c's observation key. */
        void fillBelief(std::uint32_t b, std::uint32_t a, std::uint32_t c, Rng &rng) noexcept
        {
            const auto macro = detail::macroOf(macroPool_, actions_[a]);
            const std::uint64_t key = beliefs_[c].key;
            // a capped node keeps a uniform subsample: more draws than its cap would only replace kept ones
            const unsigned cap = settings_.maxParticlesPerNode;
            const unsigned draws = cap > 0 ? std::min(settings_.fillParticles, cap) : settings_.fillParticles;
            // the memory cap, checked before every simulation, once more here: a fill adds up to K particles
            if (treeFull())
            {
                return;
            }
            for (unsigned k = 0; k < draws; ++k)
            {
                const State p = arena_.sample(beliefs_[b].particles, rng);
                const auto step = detail::executeMacroCounted(*model_, p, macro, rng, settings_.profile, stats_);
                ++stats_.fillTried;
                if (!step.terminal && macroKey(step) == key)
                {
                    arena_.add(beliefs_[c].particles, step.next, settings_.maxParticlesPerNode, rng);
                    ++stats_.fillKept;
                }
            }
        }

        /** \brief value_backup FRESH: action \a a's sum over its children of D(bao) V(bao) after child \a c
            returned \a v. A child that was backed up (its visits grew) moves the sum by its change of value
            over its earlier inflow; a leaf (a rollout, no backup) adds its sampled return. */
        void freshChild(std::uint32_t a, std::uint32_t c, double before, std::uint32_t visitsBefore, double v,
                        double discount)
        {
            ActionSums &sums = sumsOf(a);
            if (beliefs_[c].visits == visitsBefore)
            {
                sums.children += discount * v;
                return;
            }
            if (inflow_.size() < beliefs_.size())
            {
                inflow_.resize(beliefs_.size(), 0.0);  // amortised, like the node pools; capacity kept across plans
            }
            sums.children += inflow_[c] * (beliefs_[c].value - before) + discount * beliefs_[c].value;
            inflow_[c] += discount;
        }

        /// value_backup FRESH: the sums of action \a a (the side pool grows with actions_, keeping its capacity)
        ActionSums &sumsOf(std::uint32_t a)
        {
            if (actionSums_.size() < actions_.size())
            {
                actionSums_.resize(actions_.size());
            }
            return actionSums_[a];
        }

        /** \brief Theorem 1 over the current children, (1/eta) log sum_a N(ba)/N(b) exp(eta Q(b, a)) (softValueOf;
            every backup at b increments one child, so sum N(ba) = N(b)), each Q shrunk by q_prior pseudo-visits
            towards the children's visit-weighted mean (RopRas3Settings::qPrior). One exp per child: kept exact rather
            than updated incrementally from V, whose rounding error would grow relative to the sum as the
            children's Q fall. */
        double currentSoftValue(std::uint32_t b) const noexcept
        {
            const BeliefView<std::uint32_t> children = childArena_.view(beliefs_[b].children);
            const double k = settings_.qPrior;
            double mean = 0.0;
            if (k > 0.0)
            {
                double visits = 0.0;
                for (std::size_t i = 0; i < children.size; ++i)
                {
                    const ActionNode &a = actions_[children[i]];
                    mean += static_cast<double>(a.visits) * a.q;
                    visits += static_cast<double>(a.visits);
                }
                mean = visits > 0.0 ? mean / visits : 0.0;
            }
            return softValueOf(
                children.size,
                [&](std::size_t i)
                {
                    const ActionNode &a = actions_[children[i]];
                    const double n = static_cast<double>(a.visits);
                    const double q = k > 0.0 ? (n * a.q + k * mean) / (n + k) : a.q;
                    return std::pair<double, double>(q, n);
                },
                settings_.eta);
        }

        std::uint32_t selectRootAction(Rng &rng) const
        {
            const BeliefNode &root = beliefs_[0];
            std::uint32_t best = NONE;
            double bestQ = -std::numeric_limits<double>::infinity();
            double maxQ = -std::numeric_limits<double>::infinity();
            for (const std::uint32_t a : childArena_.view(root.children))
            {
                if (actions_[a].visits == 0)
                {
                    continue;
                }
                if (actions_[a].q > bestQ)
                {
                    bestQ = actions_[a].q;
                    best = a;
                }
                maxQ = std::max(maxQ, settings_.eta * actions_[a].q);
            }
            if (!settings_.sampleAction || best == NONE)
            {
                return best;
            }
            double total = 0.0;
            for (const std::uint32_t a : childArena_.view(root.children))
            {
                if (actions_[a].visits > 0)
                {
                    total += std::exp(settings_.eta * actions_[a].q - maxQ);
                }
            }
            double u = rng.uniform01() * total;
            for (const std::uint32_t a : childArena_.view(root.children))
            {
                if (actions_[a].visits > 0)
                {
                    u -= std::exp(settings_.eta * actions_[a].q - maxQ);
                    if (u < 0.0)
                    {
                        return a;
                    }
                }
            }
            return best;
        }

        std::shared_ptr<const M> model_;
        std::unique_ptr<ReferencePolicy<M>> reference_;
        RopRas3Settings settings_;
        std::string name_;
        std::vector<BeliefNode> beliefs_;
        std::vector<ActionNode> actions_;
        std::vector<Action> macroPool_;
        std::vector<Action> scratch_;
        ParticleArena<State> arena_;
        ParticleArena<std::uint32_t> childArena_;
        SearchStatistics stats_;
        std::vector<double> widenTable_;
        /// M(bao) per belief node (observation widening only)
        std::vector<std::uint32_t> observationCounts_;
        /// value_backup FRESH only: D(bao) per belief node (summed discounts of its backed-up entries), sums per action
        std::vector<double> inflow_;
        std::vector<ActionSums> actionSums_;
    };
}  // namespace ropras::pomdp

#endif
