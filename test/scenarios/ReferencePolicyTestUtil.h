#ifndef ROPRAS_TEST_SCENARIOS_REFERENCE_POLICY_TEST_UTIL_H
#define ROPRAS_TEST_SCENARIOS_REFERENCE_POLICY_TEST_UTIL_H
// A scenario's own reference policy (ScenarioParts::referencePolicy), opened as the OmplReferencePolicy it is, so
// that a test can read its statistics and the environment its planner used.

#include <gtest/gtest.h>

#include <cstdint>
#include <memory>
#include <string>

#include "ropras/pomdp/OmplReferencePolicy.h"
#include "ropras/scenarios/ModelScenario.h"

namespace ropras::scenarios::test
{
    template <class M, class Target>
    struct OmplPolicyOf
    {
        std::unique_ptr<pomdp::ReferencePolicy<M>> owner;
        pomdp::OmplReferencePolicy<M, Target> *ompl{nullptr};  ///< owner, or null when it is another policy
    };

    /// the reference policy of \a parts with the \a heuristic and the default parameters, built with \a seed
    template <class Target, class M>
    OmplPolicyOf<M, Target> omplReferencePolicy(const ScenarioParts<M> &parts, const std::string &heuristic,
                                                std::uint64_t seed,
                                                const pomdp::ParameterMap &params = pomdp::ParameterMap())
    {
        RunSettings settings;
        settings.heuristic = heuristic;
        OmplPolicyOf<M, Target> out;
        out.owner = parts.referencePolicy(settings, params, seed);
        out.ompl = dynamic_cast<pomdp::OmplReferencePolicy<M, Target> *>(out.owner.get());
        EXPECT_NE(out.ompl, nullptr) << parts.name << ": the reference policy is not an OmplReferencePolicy";
        return out;
    }
}  // namespace ropras::scenarios::test

#endif
