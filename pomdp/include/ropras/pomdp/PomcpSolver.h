#ifndef ROPRAS_POMDP_POMCP_SOLVER_H
#define ROPRAS_POMDP_POMCP_SOLVER_H

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>
#include <memory>
#include <string>
#include <vector>

#include "ropras/core/Error.h"
#include "ropras/pomdp/MacroAction.h"
#include "ropras/pomdp/Model.h"
#include "ropras/pomdp/ParameterMap.h"
#include "ropras/pomdp/ParticleArena.h"
#include "ropras/pomdp/ReferencePolicy.h"
#include "ropras/pomdp/SearchTree.h"
#include "ropras/pomdp/Solver.h"

namespace ropras::pomdp
{
    /** \brief Parameters of POMCP and R-POMCP. */
    struct PomcpSettings
    {
        /** \brief UCB1 exploration constant c (scale it with the reward range). */
        double explorationConstant{1.0};
        /** \brief Maximum tree depth D (levels below the root); below it the value is 0. */
        unsigned maxDepth{50};
        /** \brief Random rollout length at a new node: min(rolloutSteps, D - depth) primitive steps. */
        unsigned rolloutSteps{1000000};
        /** \brief R-POMCP only: K macro-actions from the reference policy at each new belief node. */
        unsigned macroActionsPerNode{8};
        /** \brief Measure time spent in the model and in the reference policy. */
        bool profile{false};
        /** \brief Memory cap of the tree (MiB): the search stops there and says so (SearchStatistics). */
        double maxTreeMegabytes{detail::DEFAULT_MAX_TREE_MB};

        /** \brief Reads ucb_c, depth, rollout_steps, macro_actions, profile, max_tree_mb; throws ropras::Error for bad
         * values. */
        static PomcpSettings fromParameters(const ParameterMap &p)
        {
            PomcpSettings s;
            s.explorationConstant = p.get("ucb_c", s.explorationConstant);
            s.maxDepth = p.getUnsigned("depth", s.maxDepth);
            s.rolloutSteps = p.getUnsigned("rollout_steps", s.rolloutSteps);
            s.macroActionsPerNode = p.getUnsigned("macro_actions", s.macroActionsPerNode);
            s.profile = p.getCount("profile", 0) != 0;
            s.maxTreeMegabytes = detail::maxTreeMegabytes(p, "POMCP");
            s.validate();
            return s;
        }

        void validate() const
        {
            if (!(explorationConstant >= 0.0) || !std::isfinite(explorationConstant))
            {
                throw Error("POMCP: ucb_c = " + std::to_string(explorationConstant) + " must be >= 0");
            }
            if (macroActionsPerNode == 0)
            {
                throw Error("R-POMCP: macro_actions must be >= 1");
            }
        }
    };

    /** \brief POMCP (Silver & Veness 2010) and R-POMCP over a model M.

        Without a reference policy this is POMCP: at a new belief node every primitive action of the model
        becomes a child, actions are chosen by UCB1 (untried first), a new node returns a random rollout to
        depth D, states are sampled at the root and propagated down (node particles are not needed).
        With a reference policy this is R-POMCP: a new belief node gets K macro-actions from the reference
        policy (each started from a particle of the node), UCB1 over them, macro rewards discounted inside
        and gamma^len after. The executed action is the root child with the highest Q. */
    template <class M>
    class PomcpSolver final : public Solver<M>
    {
    public:
        using State = typename M::State;
        using Action = typename M::Action;

        /** \brief POMCP when \a reference is null, R-POMCP otherwise. */
        PomcpSolver(std::shared_ptr<const M> model, std::unique_ptr<ReferencePolicy<M>> reference,
                    const PomcpSettings &settings, std::string name)
            : model_(std::move(model)), reference_(std::move(reference)), settings_(settings), name_(std::move(name))
        {
            if (!model_)
            {
                throw Error("PomcpSolver: missing model");
            }
            if (!reference_)
            {
                if constexpr (hasActionSet<M>)
                {
                    if (model_->numActions() == 0)
                    {
                        throw Error("POMCP: the model has no actions");
                    }
                }
                else
                {
                    throw Error("POMCP needs a model with numActions()/action(i) or a reference policy");
                }
            }
            settings_.validate();
        }

        std::string name() const override { return name_; }

        PlanResult<Action> plan(BeliefView<State> belief, const Budget &budget, Rng &rng) override
        {
            if (belief.empty())
            {
                throw Error(name_ + ": plan() called with an empty belief");
            }
            detail::BudgetGuard guard(budget);
            beliefs_.clear();
            actions_.clear();
            macroPool_.clear();
            arena_.clear();
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
                const State s = arena_.sample(beliefs_[root].particles, rng);
                simulate(s, root, 0, rng);
                ++done;
            }
            stats_.treeBytes = treeBytes();
            stats_.simulations = done;
            stats_.seconds = guard.elapsed();
            stats_.beliefNodes = beliefs_.size();
            stats_.actionNodes = actions_.size();
            std::uint32_t best = NONE;
            double bestQ = -std::numeric_limits<double>::infinity();
            for (std::uint32_t a = beliefs_[root].firstAction; a != NONE; a = actions_[a].nextSibling)
            {
                if (actions_[a].visits > 0 && actions_[a].q > bestQ)
                {
                    bestQ = actions_[a].q;
                    best = a;
                }
            }
            stats_.rootValue = best == NONE ? 0.0 : bestQ;
            return detail::planResultOf(stats_, macroPool_, best == NONE ? nullptr : &actions_[best]);
        }

        /** \brief Root children after the last plan(): (Q, N) pairs. */
        std::vector<std::pair<double, std::uint32_t>> rootChildren() const
        {
            std::vector<std::pair<double, std::uint32_t>> out;
            if (!beliefs_.empty())
            {
                for (std::uint32_t a = beliefs_[0].firstAction; a != NONE; a = actions_[a].nextSibling)
                {
                    out.emplace_back(actions_[a].q, actions_[a].visits);
                }
            }
            return out;
        }

        /** \brief The tree of the last plan() in breadth-first order: value = max Q over visited children,
            pi* = the children's visit shares. */
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
                auto &b = out.beliefs[i];
                b.key = node.key;
                b.visits = node.visits;
                b.particles = node.particles.size;
                b.value = 0.0;
                bool any = false;
                for (std::uint32_t a = node.firstAction; a != NONE; a = actions_[a].nextSibling)
                {
                    auto &action = detail::snapshotAction(out, static_cast<std::uint32_t>(i), actions_[a], macroPool_,
                                                          beliefs_, order);
                    action.piStar = node.visits > 0 ? static_cast<double>(action.visits) / node.visits : 0.0;
                    if (action.visits > 0 && (!any || action.q > out.beliefs[i].value))
                    {
                        out.beliefs[i].value = action.q;
                        any = true;
                    }
                }
            }
            return true;
        }

    private:
        static constexpr std::uint32_t NONE = std::numeric_limits<std::uint32_t>::max();

        struct BeliefNode
        {
            std::uint64_t key{0};
            std::uint32_t nextSibling{NONE};
            std::uint32_t firstAction{NONE};
            std::uint32_t visits{0};
            bool expanded{false};
            typename ParticleArena<State>::Segment particles;
        };

        struct ActionNode
        {
            std::uint32_t macroOffset{0};
            std::uint32_t macroLength{0};
            std::uint32_t nextSibling{NONE};
            std::uint32_t firstChild{NONE};
            std::uint32_t visits{0};
            double q{0.0};
        };

        /// bytes the tree uses (sizes, not capacities: the pools keep their capacity from one plan() to the next)
        std::size_t treeBytes() const noexcept
        {
            return beliefs_.size() * sizeof(BeliefNode) + actions_.size() * sizeof(ActionNode) +
                   macroPool_.size() * sizeof(Action) + arena_.usedBytes();
        }

        bool treeFull() const noexcept
        {
            const std::size_t largest =
                std::max({beliefs_.size(), actions_.size(), macroPool_.size(), arena_.storedParticles()});
            return detail::treeFull(treeBytes(), largest, settings_.maxTreeMegabytes);
        }

        std::uint32_t newBeliefNode(std::uint64_t key)
        {
            beliefs_.emplace_back();
            beliefs_.back().key = key;
            return static_cast<std::uint32_t>(beliefs_.size() - 1);
        }

        void addAction(std::uint32_t b, const Action *macro, std::size_t length)
        {
            ActionNode action;
            action.macroOffset = static_cast<std::uint32_t>(macroPool_.size());
            action.macroLength = static_cast<std::uint32_t>(length);
            macroPool_.insert(macroPool_.end(), macro, macro + length);
            action.nextSibling = beliefs_[b].firstAction;
            actions_.push_back(action);
            beliefs_[b].firstAction = static_cast<std::uint32_t>(actions_.size() - 1);
        }

        void expand(std::uint32_t b, const State &s, Rng &rng)
        {
            beliefs_[b].expanded = true;
            if (!reference_)
            {
                if constexpr (hasActionSet<M>)
                {
                    const std::size_t n = model_->numActions();
                    for (std::size_t i = n; i-- > 0;)
                    {
                        const Action a = model_->action(i);
                        addAction(b, &a, 1);
                    }
                }
                return;
            }
            for (unsigned k = 0; k < settings_.macroActionsPerNode; ++k)
            {
                scratch_.clear();
                ++stats_.referenceRequested;
                const auto view = arena_.view(beliefs_[b].particles);
                const State &start = view.empty() ? s : view[rng.uniformIndex(view.size)];
                bool ok;
                if (settings_.profile)
                {
                    const auto t0 = detail::Clock::now();
                    ok = reference_->sample(start, view, rng, scratch_);
                    stats_.referenceSeconds += detail::secondsSince(t0);
                }
                else
                {
                    ok = reference_->sample(start, view, rng, scratch_);
                }
                if (!ok || scratch_.empty())
                {
                    ++stats_.referenceFailed;
                    continue;
                }
                addAction(b, scratch_.data(), scratch_.size());
            }
        }

        double rollout(const State &s, unsigned depth, Rng &rng) noexcept
        {
            const unsigned toDepth = depth >= settings_.maxDepth ? 0u : settings_.maxDepth - depth;
            const unsigned steps = std::min(toDepth, settings_.rolloutSteps);
            if (!settings_.profile)
            {
                return rolloutValue(*model_, s, steps, rng);
            }
            const auto t0 = detail::Clock::now();
            const double v = rolloutValue(*model_, s, steps, rng);
            stats_.modelSeconds += detail::secondsSince(t0);
            return v;
        }

        std::uint32_t selectUcb(std::uint32_t b, Rng &rng) const
        {
            const double logN = std::log(static_cast<double>(beliefs_[b].visits > 0 ? beliefs_[b].visits : 1));
            std::uint32_t best = NONE;
            double bestScore = -std::numeric_limits<double>::infinity();
            std::uint32_t ties = 0;
            for (std::uint32_t a = beliefs_[b].firstAction; a != NONE; a = actions_[a].nextSibling)
            {
                const ActionNode &action = actions_[a];
                if (action.visits == 0)
                {
                    return a;
                }
                const double score =
                    action.q + settings_.explorationConstant * std::sqrt(logN / static_cast<double>(action.visits));
                if (score > bestScore)
                {
                    bestScore = score;
                    best = a;
                    ties = 1;
                }
                else if (score == bestScore && rng.uniformIndex(++ties) == 0)
                {
                    best = a;
                }
            }
            return best;
        }

        double simulate(const State &s, std::uint32_t b, unsigned depth, Rng &rng) noexcept
        {
            if (depth > settings_.maxDepth)
            {
                return 0.0;
            }
            if (depth > stats_.maxDepth)
            {
                stats_.maxDepth = depth;
            }
            // the root asks again while every plan it asked for failed: the call must end with an action if any
            // plan succeeds (deeper, a node without actions is a leaf)
            if (!beliefs_[b].expanded || (b == 0 && beliefs_[b].firstAction == NONE))
            {
                expand(b, s, rng);
                if (b != 0)
                {
                    return rollout(s, depth, rng);
                }
            }
            const std::uint32_t a = selectUcb(b, rng);
            if (a == NONE)
            {
                return rollout(s, depth, rng);
            }
            const auto macro = detail::macroOf(macroPool_, actions_[a]);
            const auto step = detail::executeMacroCounted(*model_, s, macro, rng, settings_.profile, stats_);
            double r = step.reward;
            if (!step.terminal)
            {
                const std::uint32_t c = childFor(a, step.observationKey);
                if (reference_)
                {
                    arena_.add(beliefs_[c].particles, step.next, 0, rng);
                }
                r += step.discount * simulate(step.next, c, depth + 1, rng);
            }
            ++beliefs_[b].visits;
            ActionNode &action = actions_[a];
            ++action.visits;
            action.q += (r - action.q) / static_cast<double>(action.visits);
            return r;
        }

        std::uint32_t childFor(std::uint32_t a, std::uint64_t key)
        {
            return detail::observationChild(beliefs_, actions_[a].firstChild, key);
        }

        std::shared_ptr<const M> model_;
        std::unique_ptr<ReferencePolicy<M>> reference_;
        PomcpSettings settings_;
        std::string name_;
        std::vector<BeliefNode> beliefs_;
        std::vector<ActionNode> actions_;
        std::vector<Action> macroPool_;
        std::vector<Action> scratch_;
        ParticleArena<State> arena_;
        SearchStatistics stats_;
    };
}  // namespace ropras::pomdp

#endif
