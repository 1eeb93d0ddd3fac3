#ifndef ROPRAS_POMDP_RBSS_SOLVER_H
#define ROPRAS_POMDP_RBSS_SOLVER_H

#include <cmath>
#include <cstdio>
#include <memory>
#include <string>
#include <vector>

#include "ropras/core/Error.h"
#include "ropras/pomdp/MacroAction.h"
#include "ropras/pomdp/Model.h"
#include "ropras/pomdp/ParameterMap.h"
#include "ropras/pomdp/ReferencePolicy.h"
#include "ropras/pomdp/SoftBackup.h"
#include "ropras/pomdp/Solver.h"

namespace ropras::pomdp
{
    /** \brief Parameters of RBSS (Algorithm 3). */
    struct RbssSettings
    {
        double eta{0.2};
        /** \brief C_A: actions sampled from the reference policy at each belief. */
        unsigned actions{4};
        /** \brief C_S: particles of each weighted belief. */
        unsigned particles{4};
        /** \brief D: Estimate-V returns 0 at depth >= D, so the root Q looks D macro levels ahead. */
        unsigned depth{2};
        bool sampleAction{false};

        static RbssSettings fromParameters(const ParameterMap &p)
        {
            RbssSettings s;
            s.eta = p.get("eta", s.eta);
            s.actions = p.getUnsigned("c_a", s.actions);
            s.particles = p.getUnsigned("c_s", s.particles);
            s.depth = p.getUnsigned("depth", s.depth);
            s.sampleAction = p.getCount("sample_action", 0) != 0;
            s.validate();
            return s;
        }

        void validate() const
        {
            if (!(eta > 0.0) || !std::isfinite(eta))
            {
                throw Error("RBSS: eta = " + std::to_string(eta) + " must be > 0");
            }
            if (actions == 0 || particles == 0 || depth == 0)
            {
                throw Error("RBSS: c_a, c_s and depth must all be >= 1");
            }
            const double work = std::pow(static_cast<double>(actions) * particles, depth) * particles;
            if (work > 1e10)
            {
                char text[32];
                std::snprintf(text, sizeof(text), "%.3g", work);
                throw Error("RBSS: (c_a * c_s)^depth * c_s = " + std::string(text) +
                            " is too large (> 1e10); RBSS is a reference implementation for small problems");
            }
        }
    };

    /** \brief Reference-Based Sparse Sampling (Algorithm 3), the analysable reference implementation for
        small problems.

        Estimate-Q(b, a, d): every particle s_i of the weighted belief b steps with a (a macro: the whole
        trajectory is kept); for each i the next belief b'_i holds all next states s'_j with weights
        w_j prod_k Z(o_{i,k} | s'_{j,k}, a_k) (self-normalised importance sampling; a particle whose macro
        ended at a different length gets weight 0); Q = sum_i w_i (r_i + gamma^len_i V(b'_i)) / sum_i w_i,
        terminal branches contribute r_i only. Estimate-V(b, d) = 0 for d >= D, else
        (1/eta) log mean_i exp(eta Q(b, a_i)) over C_A actions a_i ~ pibar(. | b).

        Deviation: the paper weights the C_A actions by nu_i (the belief mass of the particles whose fully
        observable policy gives a_i); here each a_i is generated from a source particle drawn with
        probability proportional to its weight, so a_i ~ pibar(. | b) directly and the C_A actions get
        equal weights (an unbiased Monte Carlo estimate of the same expectation that needs no action
        equality test). Allocates per call (not a hot path); the budget is only validated. */
    template <class M>
    class RbssSolver final : public Solver<M>
    {
    public:
        using State = typename M::State;
        using Action = typename M::Action;
        using Observation = typename M::Observation;

        RbssSolver(std::shared_ptr<const M> model, std::unique_ptr<ReferencePolicy<M>> reference,
                   const RbssSettings &settings)
            : model_(std::move(model)), reference_(std::move(reference)), settings_(settings)
        {
            if (!model_ || !reference_)
            {
                throw Error("RbssSolver: missing model or reference policy");
            }
            settings_.validate();
        }

        std::string name() const override { return "rbss"; }

        /** \brief V-hat at a weighted belief (Estimate-V at depth 0); also fills rootQ()/rootActions(). */
        double estimateValue(const std::vector<State> &particles, const std::vector<double> &weights, Rng &rng)
        {
            stats_ = SearchStatistics{};
            rootQ_.clear();
            rootActions_.clear();
            return estimateV(particles, weights, 0, rng, true);
        }

        const std::vector<double> &rootQ() const { return rootQ_; }

        PlanResult<Action> plan(BeliefView<State> belief, const Budget &budget, Rng &rng) override
        {
            if (belief.empty())
            {
                throw Error("rbss: plan() called with an empty belief");
            }
            detail::BudgetGuard guard(budget);
            std::vector<State> particles(settings_.particles);
            for (auto &p : particles)
            {
                p = belief[rng.uniformIndex(belief.size)];
            }
            const std::vector<double> weights(settings_.particles, 1.0);
            const double v = estimateValue(particles, weights, rng);
            PlanResult<Action> result;
            stats_.rootValue = v;
            stats_.seconds = guard.elapsed();
            stats_.simulations = 1;
            result.statistics = stats_;
            if (rootQ_.empty())
            {
                return result;
            }
            std::size_t best = 0;
            for (std::size_t i = 1; i < rootQ_.size(); ++i)
            {
                if (rootQ_[i] > rootQ_[best])
                {
                    best = i;
                }
            }
            if (settings_.sampleAction)
            {
                const double top = settings_.eta * rootQ_[best];
                double total = 0.0;
                for (double q : rootQ_)
                {
                    total += std::exp(settings_.eta * q - top);
                }
                double u = rng.uniform01() * total;
                for (std::size_t i = 0; i < rootQ_.size(); ++i)
                {
                    u -= std::exp(settings_.eta * rootQ_[i] - top);
                    if (u < 0.0)
                    {
                        best = i;
                        break;
                    }
                }
            }
            result.action = rootActions_[best];
            result.valid = true;
            return result;
        }

    private:
        struct Trajectory
        {
            std::vector<State> states;
            std::vector<Observation> observations;
            double reward{0.0};
            double discount{1.0};
            bool terminal{false};
        };

        std::size_t sampleWeighted(const std::vector<double> &weights, double total, Rng &rng) const
        {
            double u = rng.uniform01() * total;
            for (std::size_t i = 0; i < weights.size(); ++i)
            {
                u -= weights[i];
                if (u < 0.0)
                {
                    return i;
                }
            }
            return weights.size() - 1;
        }

        double estimateV(const std::vector<State> &particles, const std::vector<double> &weights, unsigned d, Rng &rng,
                         bool root)
        {
            if (d >= settings_.depth)
            {
                return 0.0;
            }
            ++stats_.beliefNodes;
            stats_.maxDepth = std::max<std::size_t>(stats_.maxDepth, d);
            double total = 0.0;
            for (double w : weights)
            {
                total += w;
            }
            std::vector<double> qs;
            std::vector<Action> macro;
            for (unsigned i = 0; i < settings_.actions; ++i)
            {
                const std::size_t source = sampleWeighted(weights, total, rng);
                macro.clear();
                ++stats_.referenceRequested;
                if (!reference_->sample(particles[source], BeliefView<State>{particles.data(), particles.size()}, rng,
                                        macro) ||
                    macro.empty())
                {
                    ++stats_.referenceFailed;
                    continue;
                }
                ++stats_.actionNodes;
                qs.push_back(estimateQ(particles, weights, macro, d, rng));
                if (root)
                {
                    rootQ_.push_back(qs.back());
                    rootActions_.push_back(macro);
                }
            }
            if (qs.empty())
            {
                return 0.0;
            }
            return softValue(qs.data(), nullptr, qs.size(), settings_.eta);
        }

        double estimateQ(const std::vector<State> &particles, const std::vector<double> &weights,
                         const std::vector<Action> &macro, unsigned d, Rng &rng)
        {
            const M &model = *model_;
            const double gamma = model.discount();
            const std::size_t n = particles.size();
            std::vector<Trajectory> traj(n);
            for (std::size_t i = 0; i < n; ++i)
            {
                State s = particles[i];
                for (const auto &a : macro)
                {
                    auto step = model.step(s, a, rng);
                    ++stats_.modelSteps;
                    traj[i].reward += traj[i].discount * step.reward;
                    traj[i].discount *= gamma;
                    traj[i].states.push_back(step.next);
                    traj[i].observations.push_back(step.observation);
                    s = std::move(step.next);
                    if (step.terminal)
                    {
                        traj[i].terminal = true;
                        break;
                    }
                }
            }
            double numerator = 0.0;
            double denominator = 0.0;
            std::vector<State> nextParticles(n);
            std::vector<double> nextWeights(n);
            for (std::size_t j = 0; j < n; ++j)
            {
                nextParticles[j] = traj[j].states.back();
            }
            for (std::size_t i = 0; i < n; ++i)
            {
                if (!(weights[i] > 0.0))
                {
                    continue;
                }
                double value = traj[i].reward;
                if (!traj[i].terminal)
                {
                    double mass = 0.0;
                    for (std::size_t j = 0; j < n; ++j)
                    {
                        double w = weights[j];
                        if (traj[j].terminal || traj[j].states.size() != traj[i].states.size())
                        {
                            w = 0.0;
                        }
                        for (std::size_t k = 0; k < traj[i].observations.size() && w > 0.0; ++k)
                        {
                            w *= model.observationProbability(traj[i].observations[k], traj[j].states[k], macro[k]);
                        }
                        nextWeights[j] = w;
                        mass += w;
                    }
                    if (mass > 0.0)
                    {
                        value += traj[i].discount * estimateV(nextParticles, nextWeights, d + 1, rng, false);
                    }
                }
                numerator += weights[i] * value;
                denominator += weights[i];
            }
            return denominator > 0.0 ? numerator / denominator : 0.0;
        }

        std::shared_ptr<const M> model_;
        std::unique_ptr<ReferencePolicy<M>> reference_;
        RbssSettings settings_;
        SearchStatistics stats_;
        std::vector<double> rootQ_;
        std::vector<MacroAction<Action>> rootActions_;
    };
}  // namespace ropras::pomdp

#endif
