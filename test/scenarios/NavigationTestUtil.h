// Shared helpers of the navigation scenario tests (Light-Dark, Maze2D, Random3D).
#ifndef ROPRAS_TEST_SCENARIOS_NAVIGATION_TEST_UTIL_H
#define ROPRAS_TEST_SCENARIOS_NAVIGATION_TEST_UTIL_H

#include <gtest/gtest.h>

#include <ompl/util/Console.h>
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
