#ifndef ROPRAS_POMDP_MODEL_REGISTRY_H
#define ROPRAS_POMDP_MODEL_REGISTRY_H

#include <functional>
#include <map>
#include <memory>
#include <string>
#include <vector>

#include "ropras/pomdp/ParameterMap.h"
#include "ropras/pomdp/SolverRunner.h"

namespace ropras::pomdp
{
    /** \brief Builds a type-erased solver runner for (solver name, parameters); throws ropras::Error for an
        unknown solver or parameter. */
    using RunnerFactory =
        std::function<std::unique_ptr<SolverRunner>(const std::string &solver, const ParameterMap &params)>;

    struct ModelEntry
    {
        std::string name;
        std::string description;
        RunnerFactory factory;
    };

    /** \brief Models by name (model name -> factory of type-erased solver runners). */
    class ModelRegistry
    {
    public:
        /** \brief Adds a model; throws ropras::Error for an empty or duplicate name or a missing factory. */
        void add(ModelEntry entry);

        /** \brief The entry of \a name; throws ropras::Error naming the known models if unknown. */
        const ModelEntry &get(const std::string &name) const;

        std::vector<std::string> names() const;

        std::unique_ptr<SolverRunner> create(const std::string &model, const std::string &solver,
                                             const ParameterMap &params) const
        {
            return get(model).factory(solver, params);
        }

    private:
        std::map<std::string, ModelEntry> entries_;
    };

    /** \brief The process-wide registry, with the built-in models (tiger) registered on first use. */
    ModelRegistry &modelRegistry();

    /** \brief Static registration from another library: `static const ModelRegistrar reg{{name, desc, f}};` */
    struct ModelRegistrar
    {
        explicit ModelRegistrar(ModelEntry entry) { modelRegistry().add(std::move(entry)); }
    };

    /** \brief Convenience: a RunnerFactory for a model type from a function making its components. */
    template <class M>
    RunnerFactory makeRunnerFactory(std::string modelName, std::function<ModelComponents<M>()> components)
    {
        return [modelName, components](const std::string &solver, const ParameterMap &params)
        {
            return std::unique_ptr<SolverRunner>(
                std::make_unique<ModelSolverRunner<M>>(modelName, components(), solver, params));
        };
    }
}  // namespace ropras::pomdp

#endif
