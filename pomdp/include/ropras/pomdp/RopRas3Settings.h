#ifndef ROPRAS_POMDP_ROP_RAS3_SETTINGS_H
#define ROPRAS_POMDP_ROP_RAS3_SETTINGS_H

#include <cmath>
#include <cstddef>
#include <string>

#include "ropras/core/Error.h"
#include "ropras/pomdp/ParameterMap.h"
#include "ropras/pomdp/SearchTree.h"

namespace ropras::pomdp
{
    /** \brief Parameters of ROP-RAS3 (and Ref-Basic, which is ROP-RAS3 with a uniform reference policy). */
    struct RopRas3Settings
    {
        /** \brief Temperature eta > 0 of the reference-based backup. */
        double eta{0.2};
        /** \brief Action progressive widening: a new child iff |C(b)| <= betaA * N(b)^alphaA. */
        double betaA{6.0};
        double alphaA{0.05};
        /** \brief D: nodes at depth > D (macro levels below the root, root = 0) return a rollout. */
        unsigned maxDepth{50};
        /** \brief Primitive steps of the rollout below depth D (0 = value 0 / heuristic value only). */
        unsigned rolloutSteps{10};
        /** \brief Whether the rollout below depth D ends with the model's heuristic value (default) or with 0.
            Off for a model whose heuristic misleads the tree (Ray-Detect's straight-line distance to the goal now
            and then keeps the arm pressed against a box between it and the goal, doc/scenario-ray-detect.md). */
        bool heuristicLeaf{true};
        /** \brief Cap on the particles kept per belief node (uniform subsample); 0 = keep all (the paper). */
        unsigned maxParticlesPerNode{0};
        /** \brief Belief fill: a belief node bao created by a simulation within depth D (a leaf below D is not
            filled) also gets up to fillParticles particles drawn from b, moved through a by the model and kept
            when they end the macro alive with the node's observation key. 0 = off (Algorithm 2: a node holds
            only the particles that simulations brought, so a node deep in the tree holds one or two, and every
            macro planned there is planned for the very state it is then valued on). */
        unsigned fillParticles{0};
        /** \brief Observation progressive widening (Algorithm 2, lines 6-10) over the binned macro observations:
            a macro observation whose key has no child yet gets a new child iff |C(ba)| <= betaO N(ba)^alphaO,
            else the particle joins an existing child drawn w.p. M(bao) / sum M (M counts the observations that
            created or matched the child). betaO = 0: no widening, every new key gets a child (binning only). */
        double betaO{0.0};
        double alphaO{0.5};
        /** \brief What identifies a macro observation: SEQUENCE = the whole sequence of binned primitive
            observations, LAST = the last non-empty one alone. */
        enum class MacroObservation
        {
            SEQUENCE = 0,
            LAST = 1
        };
        MacroObservation macroObservation{MacroObservation::SEQUENCE};
        /** \brief A new macro (planned from the sampled particle s) is first executed from a second particle
            drawn independently from the node (true), not from s itself (false, Algorithm 2 as written): the
            first return then estimates Q(b, a) = E_{s ~ b} R(s, a) without the bias of a plan evaluated on the
            state it was planned from. */
        bool independentEvaluation{false};
        /** \brief Executed action: false = argmax Q (default), true = sample pi*(a|b) ~ exp(eta Q). */
        bool sampleAction{false};
        /** \brief Choice among existing children when no new one is due: false = uniform (Algorithm 2, i.e. the
            reference policy's own frequencies), true = UCB1, argmax Q(ba) + ucbC sqrt(ln N(b) / N(ba)) (unvisited
            children first), as POMCP / R-POMCP choose. An ablation: it departs from the paper's search. */
        bool ucbSelection{false};
        /** \brief UCB1's exploration constant (the reward range's order); used only with ucbSelection. */
        double ucbC{1.0};
        /** \brief How V(b) is backed up: RUNNING = Algorithm 2's Backup line, a running mean of exp(eta Q) over
            the Q(b, a) of every past visit (stale estimates included, so one early lucky return keeps V near it
            for ~(1/eta) log N); CURRENT = Theorem 1 over the children's current estimates,
            V(b) = (1/eta) log sum_a N(ba)/N(b) exp(eta Q(b, a)). The two agree while the Q(b, a) stay fixed.
            FRESH = CURRENT, and Q(b, a) too is made of the children as they stand instead of a running mean of past
            returns: Q(b, a) = (sum of the macro rewards + sum_o D(bao) V(bao)) / N(ba), D(bao) the summed
            discounts of the visits that entered bao (a leaf child, valued by rollouts, keeps its sampled returns). */
        enum class ValueBackup
        {
            RUNNING = 0,
            CURRENT = 1,
            FRESH = 2
        };
        ValueBackup valueBackup{ValueBackup::RUNNING};
        /** \brief value_backup CURRENT / FRESH: each Q(b, a) enters Theorem 1 shrunk towards the node's mean
            m(b) = sum_a N(ba) Q(b, a) / N(b) as (N(ba) Q(b, a) + k m(b)) / (N(ba) + k), k = qPrior pseudo-visits
            (the posterior mean of Q(b, a) under a prior centred on the mean of the node's sampled children). 0 = off.
            A child valued by one or two returns otherwise enters the soft maximum at face value: with rewards of +800
            and eta = 0.01, seven children of true Q 80 of which one returned +800 give V(b) = 606, far above their
            mean (114) and their true Q (80). */
        double qPrior{0.0};
        /** \brief Measure time spent in the model and in the reference policy (two clock reads per call). */
        bool profile{false};
        /** \brief Memory cap of the tree (MiB): the search stops there and says so (SearchStatistics). */
        double maxTreeMegabytes{detail::DEFAULT_MAX_TREE_MB};

        /// the largest fill_particles accepted (each filled particle costs one macro execution per new node)
        static constexpr double MAX_FILL_PARTICLES = 100000.0;

        /** \brief Reads eta, beta_a, alpha_a, beta_o, alpha_o, macro_observation, independent_eval, depth,
            rollout_steps, heuristic_leaf, max_particles, fill_particles, sample_action, ucb_select, ucb_c,
            value_backup, q_prior, profile, max_tree_mb; throws ropras::Error for out-of-range values. */
        static RopRas3Settings fromParameters(const ParameterMap &p)
        {
            RopRas3Settings s;
            s.eta = p.get("eta", s.eta);
            s.betaA = p.get("beta_a", s.betaA);
            s.alphaA = p.get("alpha_a", s.alphaA);
            s.maxDepth = p.getUnsigned("depth", s.maxDepth);
            s.rolloutSteps = p.getUnsigned("rollout_steps", s.rolloutSteps);
            s.maxParticlesPerNode = p.getUnsigned("max_particles", s.maxParticlesPerNode);
            s.fillParticles = p.getUnsigned("fill_particles", s.fillParticles, MAX_FILL_PARTICLES);
            s.heuristicLeaf = p.getCount("heuristic_leaf", s.heuristicLeaf ? 1 : 0, 1) != 0;
            s.betaO = p.get("beta_o", s.betaO);
            s.alphaO = p.get("alpha_o", s.alphaO);
            const auto mode = p.getCount("macro_observation", static_cast<std::size_t>(s.macroObservation), 1);
            s.macroObservation = static_cast<MacroObservation>(mode);
            s.independentEvaluation = p.getCount("independent_eval", s.independentEvaluation ? 1 : 0, 1) != 0;
            s.sampleAction = p.getCount("sample_action", 0) != 0;
            s.ucbSelection = p.getCount("ucb_select", 0, 1) != 0;
            s.ucbC = p.get("ucb_c", s.ucbC);
            const auto backup = p.getCount("value_backup", static_cast<std::size_t>(s.valueBackup), 2);
            s.valueBackup = static_cast<ValueBackup>(backup);
            s.qPrior = p.get("q_prior", s.qPrior);
            s.profile = p.getCount("profile", 0) != 0;
            s.maxTreeMegabytes = detail::maxTreeMegabytes(p, "ROP-RAS3");
            s.validate();
            return s;
        }

        void validate() const
        {
            if (!(eta > 0.0) || !std::isfinite(eta))
            {
                throw Error("ROP-RAS3: eta = " + std::to_string(eta) + " must be > 0");
            }
            if (!(betaA > 0.0) || !std::isfinite(betaA) || !(alphaA >= 0.0) || !std::isfinite(alphaA))
            {
                throw Error("ROP-RAS3: beta_a = " + std::to_string(betaA) + ", alpha_a = " + std::to_string(alphaA) +
                            " must be > 0 and >= 0");
            }
            if (!(ucbC >= 0.0) || !std::isfinite(ucbC))
            {
                throw Error("ROP-RAS3: ucb_c = " + std::to_string(ucbC) + " must be >= 0");
            }
            if (!(qPrior >= 0.0) || !std::isfinite(qPrior))
            {
                throw Error("ROP-RAS3: q_prior = " + std::to_string(qPrior) + " must be >= 0 (pseudo-visits; 0 = off)");
            }
            if (qPrior > 0.0 && valueBackup == ValueBackup::RUNNING)
            {
                throw Error("ROP-RAS3: q_prior = " + std::to_string(qPrior) +
                            " needs value_backup 1 or 2 (the running backup of value_backup 0 does not use it; with "
                            "value_backup 0 set q_prior=0 too: a scenario's solver defaults may set it)");
            }
            if (!(betaO >= 0.0) || !std::isfinite(betaO) || !(alphaO >= 0.0) || !std::isfinite(alphaO))
            {
                throw Error("ROP-RAS3: beta_o = " + std::to_string(betaO) + ", alpha_o = " + std::to_string(alphaO) +
                            " must be >= 0 (beta_o = 0: observation binning without widening)");
            }
        }
    };
}  // namespace ropras::pomdp

#endif
