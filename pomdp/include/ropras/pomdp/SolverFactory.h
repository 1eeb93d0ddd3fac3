#ifndef ROPRAS_POMDP_SOLVER_FACTORY_H
#define ROPRAS_POMDP_SOLVER_FACTORY_H

#include <functional>
#include <map>
#include <memory>
#include <set>
#include <string>
#include <vector>

#include "ropras/core/Error.h"
#include "ropras/core/NameList.h"
#include "ropras/pomdp/BPlanSolver.h"
#include "ropras/pomdp/ParameterMap.h"
#include "ropras/pomdp/ParticleFilter.h"
#include "ropras/pomdp/PomcpSolver.h"
#include "ropras/pomdp/RandomMacroPolicy.h"
#include "ropras/pomdp/RbssSolver.h"
#include "ropras/pomdp/ReferencePolicy.h"
#include "ropras/pomdp/RopRas3Solver.h"
#include "ropras/pomdp/Solver.h"

namespace ropras::pomdp
{
    /** \brief What a model contributes so that every solver can run on it by name. */
    template <class M>
    struct ModelComponents
    {
        using PolicyFactory = std::function<std::unique_ptr<ReferencePolicy<M>>(const ParameterMap &)>;

        std::shared_ptr<const M> model;
        /** \brief The informed reference policy (sampling heuristic + connector / motion planner): used by
            ropras3, rpomcp, bplan and rbss. */
        PolicyFactory referencePolicy;
        /** \brief Ref-Basic's uniform reference policy. Empty = RandomMacroPolicy with the parameters
            macro_min / macro_max (default 1 / 1) over the model's action set. */
        PolicyFactory basicReferencePolicy;
        /** \brief Model-specific parameter defaults (e.g. ucb_c scaled to the reward range, depth); user
            parameters override them. */
        std::map<std::string, double> defaults;
        /** \brief Per solver name: defaults for that solver only, taking precedence over \a defaults (e.g. a
            scenario whose ROP-RAS3 searches one macro level while R-POMCP keeps its deeper tree); user
            parameters override them too. */
        std::map<std::string, std::map<std::string, double>> solverDefaults;
    };

    namespace detail
    {
        template <class M>
        std::unique_ptr<ReferencePolicy<M>> informedPolicy(const ModelComponents<M> &c, const ParameterMap &p,
                                                           const std::string &solver)
        {
            if (!c.referencePolicy)
            {
                throw Error("solver " + solver + " needs a reference policy, but the model provides none");
            }
            return c.referencePolicy(p);
        }

        template <class M>
        std::unique_ptr<ReferencePolicy<M>> basicPolicy(const ModelComponents<M> &c, const ParameterMap &p)
        {
            if (c.basicReferencePolicy)
            {
                return c.basicReferencePolicy(p);
            }
            if constexpr (hasActionSet<M>)
            {
                const auto lo = p.getUnsigned("macro_min", 1);
                const auto hi = p.getUnsigned("macro_max", lo);
                return std::make_unique<RandomMacroPolicy<M>>(c.model, lo, hi);
            }
            else
            {
                throw Error("refbasic needs a model with an action set or a basic reference policy");
            }
        }

        template <class M>
        using SolverBuilder = std::unique_ptr<Solver<M>> (*)(const ModelComponents<M> &, const ParameterMap &);

        template <class M>
        const std::map<std::string, SolverBuilder<M>> &solverTable()
        {
            static const std::map<std::string, SolverBuilder<M>> table{
                {"ropras3",
                 [](const ModelComponents<M> &c, const ParameterMap &p) -> std::unique_ptr<Solver<M>>
                 {
                     const auto settings = RopRas3Settings::fromParameters(p);
                     return std::make_unique<RopRas3Solver<M>>(c.model, informedPolicy(c, p, "ropras3"), settings,
                                                               "ropras3");
                 }},
                {"refbasic",
                 [](const ModelComponents<M> &c, const ParameterMap &p) -> std::unique_ptr<Solver<M>>
                 {
                     const auto settings = RopRas3Settings::fromParameters(p);
                     return std::make_unique<RopRas3Solver<M>>(c.model, basicPolicy(c, p), settings, "refbasic");
                 }},
                {"pomcp",
                 [](const ModelComponents<M> &c, const ParameterMap &p) -> std::unique_ptr<Solver<M>> {
                     return std::make_unique<PomcpSolver<M>>(c.model, nullptr, PomcpSettings::fromParameters(p),
                                                             "pomcp");
                 }},
                {"rpomcp",
                 [](const ModelComponents<M> &c, const ParameterMap &p) -> std::unique_ptr<Solver<M>>
                 {
                     const auto settings = PomcpSettings::fromParameters(p);
                     return std::make_unique<PomcpSolver<M>>(c.model, informedPolicy(c, p, "rpomcp"), settings,
                                                             "rpomcp");
                 }},
                {"bplan",
                 [](const ModelComponents<M> &c, const ParameterMap &p) -> std::unique_ptr<Solver<M>>
                 {
                     const auto attempts = p.getUnsigned("attempts", 10);
                     p.getCount("profile", 0);  // accepted: B-plan always times its reference calls
                     return std::make_unique<BPlanSolver<M>>(c.model, informedPolicy(c, p, "bplan"), attempts);
                 }},
                {"rbss",
                 [](const ModelComponents<M> &c, const ParameterMap &p) -> std::unique_ptr<Solver<M>>
                 {
                     const auto settings = RbssSettings::fromParameters(p);
                     p.getCount("profile", 0);  // accepted: RBSS reports no per-call timing
                     return std::make_unique<RbssSolver<M>>(c.model, informedPolicy(c, p, "rbss"), settings);
                 }},
            };
            return table;
        }
    }  // namespace detail

    /** \brief Names of the solvers makeSolver() knows. */
    template <class M>
    std::vector<std::string> solverNames()
    {
        std::vector<std::string> names;
        for (const auto &entry : detail::solverTable<M>())
        {
            names.push_back(entry.first);
        }
        return names;
    }

    /** \brief The defaults that apply to solver \a solver: its own (ModelComponents::solverDefaults) over the
        shared ones. */
    template <class M>
    std::map<std::string, double> defaultsFor(const ModelComponents<M> &components, const std::string &solver)
    {
        std::map<std::string, double> out;
        const auto own = components.solverDefaults.find(solver);
        if (own != components.solverDefaults.end())
        {
            out = own->second;
        }
        out.insert(components.defaults.begin(), components.defaults.end());  // keeps the solver's own values
        return out;
    }

    /** \brief \a params with solver \a solver's defaults (defaultsFor()) filled in for names the user did not
        give. */
    template <class M>
    ParameterMap withDefaults(const ModelComponents<M> &components, const ParameterMap &params,
                              const std::string &solver = std::string())
    {
        ParameterMap merged = params;
        for (const auto &entry : defaultsFor(components, solver))
        {
            if (!merged.contains(entry.first))
            {
                merged.set(entry.first, entry.second);
            }
        }
        return merged;
    }

    /** \brief The names of solver \a solver's defaults (defaultsFor()) that the user did not set in \a params:
        a solver may leave them unread (e.g. ucb_c for B-plan) without an error. */
    template <class M>
    std::set<std::string> unreadDefaultsAllowed(const ModelComponents<M> &components, const ParameterMap &params,
                                                const std::string &solver)
    {
        std::set<std::string> exempt;
        for (const auto &entry : defaultsFor(components, solver))
        {
            if (!params.contains(entry.first))
            {
                exempt.insert(entry.first);
            }
        }
        return exempt;
    }

    /** \brief Builds solver \a name (ropras3, refbasic, pomcp, rpomcp, bplan, rbss) for a model. \a params
        must already contain that solver's defaults (withDefaults()). Unknown solver names throw ropras::Error,
        and so does a parameter that neither the solver, its reference policy, the particle filter
        (ParticleFilterSettings::fromParameters) nor the model's defaults know: a misspelt name ("dpth") is an
        error listing the valid names, never silently the default. */
    template <class M>
    std::unique_ptr<Solver<M>> makeSolver(const std::string &name, const ModelComponents<M> &components,
                                          const ParameterMap &params)
    {
        if (!components.model)
        {
            throw Error("makeSolver: the model components have no model");
        }
        const auto &table = detail::solverTable<M>();
        const auto it = table.find(name);
        if (it == table.end())
        {
            throw Error("unknown solver \"" + name + "\" (known: " + joinKeys(table) + ")");
        }
        auto solver = it->second(components, params);
        ParticleFilterSettings::fromParameters(params);  // the filter's names are valid for every solver
        // the model's defaults (shared and this solver's): not read by every solver
        params.requireAllUsed("solver " + name, unreadDefaultsAllowed(components, ParameterMap{}, name));
        return solver;
    }
}  // namespace ropras::pomdp

#endif
