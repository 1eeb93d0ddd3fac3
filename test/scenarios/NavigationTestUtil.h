// Shared helpers of the navigation scenario tests (Light-Dark, Maze2D, Random3D).
#ifndef ROPRAS_TEST_SCENARIOS_NAVIGATION_TEST_UTIL_H
#define ROPRAS_TEST_SCENARIOS_NAVIGATION_TEST_UTIL_H

#include <gtest/gtest.h>

#include <ompl/util/Console.h>
#include <cmath>
#include <memory>
#include <string>

#include "ropras/scenarios/ModelScenario.h"
#include "ropras/scenarios/ScenarioRegistry.h"
#include "ropras/scenarios/navigation/NavigationModel.h"

namespace ropras::scenarios::test
{
    /// the navigation scenario \a name with \a overrides, as its concrete type
    inline std::unique_ptr<Scenario> navScenario(const std::string &name,
                                                 const nlohmann::json &overrides = nlohmann::json::object())
    {
        ompl::msg::setLogLevel(ompl::msg::LOG_ERROR);  // the reference planner's per-plan messages
        ScenarioOptions options;
        options.overrides = overrides;
        return scenarioRegistry().create(name, options);
    }

    inline const ModelScenario<NavigationModel> &asNav(const Scenario &s)
    {
        return dynamic_cast<const ModelScenario<NavigationModel> &>(s);
    }

    /** The distance field's leaf value d lattice steps from the goal, with Maze2D's and Random3D's rewards (goal
        800, step -0.1) and heuristic_decay rho: goal_reward·γ^d·rho^d + step_reward·(1 − γ^d)/(1 − γ). */
    inline double fieldValue(double g, std::size_t d, double rho = 1.0)
    {
        const double gd = std::pow(g, static_cast<double>(d));
        return 800.0 * gd * std::pow(rho, static_cast<double>(d)) - 0.1 * (1.0 - gd) / (1.0 - g);
    }

    inline NavState at(double x, double y, double z = 0.0)
    {
        NavState s;
        s.p[0] = x;
        s.p[1] = y;
        s.p[2] = z;
        return s;
    }
}  // namespace ropras::scenarios::test

#endif
