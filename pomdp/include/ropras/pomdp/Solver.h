#ifndef ROPRAS_POMDP_SOLVER_H
#define ROPRAS_POMDP_SOLVER_H

#include <chrono>
#include <string>

#include "ropras/pomdp/BeliefView.h"
#include "ropras/pomdp/Budget.h"
#include "ropras/pomdp/MacroAction.h"
#include "ropras/pomdp/Rng.h"
#include "ropras/pomdp/SearchStatistics.h"
#include "ropras/pomdp/TreeSnapshot.h"

namespace ropras::pomdp
{
    /** \brief Outcome of one planning call: the macro-action to execute (primitive actions in order) and the
        search statistics. \c valid is false when the solver could not produce any action (e.g. every
        reference plan failed); that is a value, not an exception. */
    template <class Action>
    struct PlanResult
    {
        MacroAction<Action> action;
        bool valid{false};
        SearchStatistics statistics;
    };

    /** \brief Common interface of the online solvers over a model type M (ROP-RAS3, Ref-Basic, POMCP,
        R-POMCP, B-plan, RBSS). The virtual call is per planning call; the search loops inside are templates
        over M. plan() throws ropras::Error only for bad input (empty belief, invalid budget). */
    template <class M>
    class Solver
    {
    public:
        using State = typename M::State;
        using Action = typename M::Action;

        virtual ~Solver() = default;

        virtual std::string name() const = 0;

        /** \brief Plans from the unweighted particle belief \a belief within \a budget. */
        virtual PlanResult<Action> plan(BeliefView<State> belief, const Budget &budget, Rng &rng) = 0;

        /** \brief Copies the search tree of the last plan() into \a out; false (default) for solvers without a
            tree (B-plan, RBSS) or before the first plan. */
        virtual bool treeSnapshot(TreeSnapshot &out) const
        {
            (void)out;
            return false;
        }
    };

    namespace detail
    {
        using Clock = std::chrono::steady_clock;

        inline double secondsSince(Clock::time_point start) noexcept
        {
            return std::chrono::duration<double>(Clock::now() - start).count();
        }

        /** \brief Stops a search loop when the budget is used up. */
        class BudgetGuard
        {
        public:
            explicit BudgetGuard(const Budget &budget) : budget_(budget), start_(Clock::now()) { budget.validate(); }

            bool exhausted(std::size_t simulationsDone) const noexcept
            {
                if (budget_.simulations > 0 && simulationsDone >= budget_.simulations)
                {
                    return true;
                }
                return budget_.seconds > 0.0 && secondsSince(start_) >= budget_.seconds;
            }

            double elapsed() const noexcept { return secondsSince(start_); }

        private:
            Budget budget_;
            Clock::time_point start_;
        };
    }  // namespace detail
}  // namespace ropras::pomdp

#endif
