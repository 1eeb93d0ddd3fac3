#include "ropras/pomdp/Tiger.h"

#include <memory>

#include "ropras/core/Error.h"
#include "ropras/pomdp/HeuristicReferencePolicy.h"
#include "ropras/pomdp/ModelRegistry.h"
#include "ropras/pomdp/SamplingHeuristic.h"

namespace ropras::pomdp
{
    ModelComponents<TigerModel> tigerComponents(const TigerModel &model)
    {
        ModelComponents<TigerModel> components;
        components.model = std::make_shared<const TigerModel>(model);
        components.referencePolicy = [](const ParameterMap &p) -> std::unique_ptr<ReferencePolicy<TigerModel>>
        {
            using State = TigerModel::State;
            using Target = TigerModel::Action;
            auto space = std::make_shared<const TigerTargetSpace>();
            const auto kind = p.getCount("heuristic", 1);
            const double epsilon = p.get("epsilon", 0.0);
            std::unique_ptr<SamplingHeuristic<State, Target>> heuristic;
            if (kind == 0)
            {
                heuristic = std::make_unique<UniformHeuristic<State, Target>>(space);
            }
            else if (kind == 1)
            {
                heuristic = std::make_unique<DynamicHeuristic<State, Target>>(space);
            }
            else
            {
                throw Error("tiger: parameter heuristic = " + std::to_string(kind) +
                            " is unknown (0 = uniform, 1 = dynamic)");
            }
            if (epsilon > 0.0)
            {
                heuristic =
                    std::make_unique<EpsilonGreedyHeuristic<State, Target>>(space, std::move(heuristic), epsilon);
            }
            auto connector = [](const State &, const Target &target, Rng &, std::vector<TigerModel::Action> &out)
            {
                out.push_back(target);
                return true;
            };
            return std::make_unique<HeuristicReferencePolicy<TigerModel, Target>>(std::move(heuristic), connector,
                                                                                  "one-step");
        };
        // Random rollouts are very pessimistic on Tiger (opening at random costs 45 per step on average);
        // without them and with c = 30 POMCP's closed-loop return is within noise of the optimum (tests).
        components.defaults = {{"ucb_c", 30.0}, {"rollout_steps", 0.0}};
        return components;
    }

    void registerTiger(ModelRegistry &registry)
    {
        registry.add(ModelEntry{"tiger", "Tiger POMDP (gamma 0.95, listen -1 at 0.85, +10/-100; resets after opening)",
                                makeRunnerFactory<TigerModel>("tiger", [] { return tigerComponents(); })});
    }
}  // namespace ropras::pomdp
