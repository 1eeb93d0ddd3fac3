#ifndef ROPRAS_SCENARIOS_MODEL_SCENARIO_H
#define ROPRAS_SCENARIOS_MODEL_SCENARIO_H

#include <algorithm>
#include <array>
#include <cstdint>
#include <functional>
#include <map>
#include <memory>
#include <nlohmann/json.hpp>
#include <set>
#include <string>
#include <utility>
#include <vector>

#include "ropras/core/Error.h"
#include "ropras/core/NameList.h"
#include "ropras/pomdp/Episode.h"
#include "ropras/pomdp/OmplPathPlanner.h"
#include "ropras/pomdp/ParticleFilter.h"
#include "ropras/pomdp/SamplingHeuristic.h"
#include "ropras/pomdp/SolverFactory.h"
#include "ropras/pomdp/World.h"
#include "ropras/scenarios/Scenario.h"

namespace ropras::scenarios
{
    /** \brief A point drawn in pictures (x, y, z; z = 0 in 2-D). */
    using Point3 = std::array<double, 3>;

    /** \brief Everything a scenario over model type M supplies to ModelScenario. */
    template <class M>
    struct ScenarioParts
    {
        using State = typename M::State;
        /** \brief The informed reference policy of one episode (ropras3, rpomcp, bplan): built from the run
            settings (heuristic, epsilon, planner), reading its own parameters from \a params (e.g.
            plan_time, macro_length), its planner seeded with \a seed. Throws ropras::Error on bad settings. */
        using PolicyFactory = std::function<std::unique_ptr<pomdp::ReferencePolicy<M>>(
            const RunSettings &settings, const pomdp::ParameterMap &params, std::uint64_t seed)>;

        std::string name;
        std::string description;
        std::shared_ptr<const M> model;
        PolicyFactory referencePolicy;
        /// Ref-Basic's policy; empty = random macros (parameters macro_min, macro_max)
        PolicyFactory basicReferencePolicy;
        /// a fresh world for one episode (e.g. a Bullet collision world built from the scene)
        std::function<std::unique_ptr<pomdp::World<M>>()> world;
        /// the positions to draw for a state (one robot, or several drones and a target)
        std::function<void(const State &, std::vector<Point3> &)> points;
        /// names of those positions, e.g. {"robot"} or {"drone1", ..., "target"}
        std::vector<std::string> pointLabels;
        /// the robot's URDF as an embedded file (e.g. "navigation/maze2d/robot.urdf"); with `configuration`,
        /// recordings carry the robot's joint values per step (key "robot"), which `ropras view` poses by FK
        std::string robotUrdf;
        /// the robot's planning-joint values (in the URDF's planning order) in a state; empty = not recorded
        std::function<void(const State &, std::vector<double> &)> configuration;
        /// optional: what a step ended in, by name (e.g. "pedestrian-collision"; "" = nothing), recorded as the
        /// recording's "events"
        std::function<std::string(const State &)> event;
        /// optional: the sensor rays of a state ([origin, end] segments), recorded per step as the recording's
        /// "rays" ({"step", "segments"}; drawn by `ropras view`)
        std::function<void(const State &, std::vector<std::array<Point3, 2>> &)> rays;
        /// optional: the episode filter's depletion recovery (empty = pomdp::IgnoreObservationRecovery)
        std::function<std::unique_ptr<pomdp::DepletionRecovery<M>>()> recovery;
        /// solver and filter parameter defaults of this scenario (the user's --param values override them)
        std::map<std::string, double> defaults;
        /// per solver name: its own defaults, taking precedence over \a defaults (config key "solver_defaults")
        std::map<std::string, std::map<std::string, double>> solverDefaults;
        std::size_t horizon{100};
        double defaultPlanSeconds{0.1};
        nlohmann::json config;
        nlohmann::json scene;
    };

    /** \brief The sampling heuristic named by \a settings ("uniform" or "dynamic", then epsilon-greedy when
        epsilon > 0) over \a space; throws ropras::Error for another name or an epsilon outside [0, 1]. */
    template <class State, class Target>
    std::unique_ptr<pomdp::SamplingHeuristic<State, Target>> makeSamplingHeuristic(
        const RunSettings &settings, std::shared_ptr<const pomdp::TargetSpace<State, Target>> space)
    {
        std::unique_ptr<pomdp::SamplingHeuristic<State, Target>> h;
        if (settings.heuristic == "uniform")
        {
            h = std::make_unique<pomdp::UniformHeuristic<State, Target>>(space);
        }
        else if (settings.heuristic == "dynamic")
        {
            h = std::make_unique<pomdp::DynamicHeuristic<State, Target>>(space);
        }
        else
        {
            throw Error("unknown sampling heuristic \"" + settings.heuristic + "\" (known: uniform, dynamic)");
        }
        if (!(settings.epsilon >= 0.0 && settings.epsilon <= 1.0))
        {
            throw Error("epsilon = " + std::to_string(settings.epsilon) + " is not in [0, 1]");
        }
        if (settings.epsilon > 0.0)
        {
            h = std::make_unique<pomdp::EpsilonGreedyHeuristic<State, Target>>(space, std::move(h), settings.epsilon);
        }
        return h;
    }

    /** \brief The scale of a scenario's space for VectorizedRRTConnect, whose defaults are made for joint spaces in
        radians: its extension step `range` and dynamic-domain radius `dd_radius`; 0 keeps the planner's own. */
    struct PlannerScale
    {
        double range{0.0};
        double ddRadius{0.0};
    };

    /** \brief OmplPathPlannerSettings of a reference policy: the planner named by \a settings, the scenario's
        per-plan time limit \a planTime and motion resolution, overridden by the parameters plan_time,
        plan_iterations, shortcut and planner.NAME (a planner parameter; planner.seed is refused). VectorizedRRTConnect
        also gets \a scale (where planner.range or planner.dd_radius do not override it) and is seeded with \a seed;
        other planners have neither parameter. */
    inline pomdp::OmplPathPlannerSettings referencePlannerSettings(const RunSettings &settings,
                                                                   const pomdp::ParameterMap &params, double planTime,
                                                                   double resolution, std::uint64_t seed,
                                                                   const PlannerScale &scale = PlannerScale())
    {
        pomdp::OmplPathPlannerSettings s;
        s.planner = settings.planner;
        s.timeLimit = planTime;
        s.resolution = resolution;
        s.readParameters(params);
        if (s.plannerParams.count("seed") != 0)
        {
            throw Error("parameter \"planner.seed\": the reference planner is seeded from the run's seed (--seed)");
        }
        if (s.planner == "VectorizedRRTConnect")
        {
            s.plannerParams["seed"] = std::to_string(seed % 4294967291ULL + 1);
            if (scale.range > 0.0)
            {
                s.plannerParams.emplace("range", std::to_string(scale.range));
            }
            if (scale.ddRadius > 0.0)
            {
                s.plannerParams.emplace("dd_radius", std::to_string(scale.ddRadius));
            }
        }
        s.validate();
        return s;
    }

    /** \brief Records an episode as JSON for `ropras render` and `ropras view` (format: doc/scenarios.md). */
    template <class M>
    class EpisodeRecorder final : public pomdp::EpisodeObserver<M>
    {
    public:
        using typename pomdp::EpisodeObserver<M>::State;
        using typename pomdp::EpisodeObserver<M>::Action;
        using typename pomdp::EpisodeObserver<M>::Observation;

        EpisodeRecorder(const ScenarioParts<M> &parts, const RecordSettings &settings, nlohmann::json &out)
            : parts_(parts), settings_(settings), out_(out)
        {
            out_["labels"] = parts_.pointLabels;
            out_["trajectory"] = nlohmann::json::array();
            out_["rewards"] = nlohmann::json::array();
            out_["plans"] = nlohmann::json::array();
            out_["beliefs"] = nlohmann::json::array();
            if (parts_.configuration && !parts_.robotUrdf.empty())
            {
                out_["robot"] = {{"urdf", "embedded:" + parts_.robotUrdf}, {"configurations", nlohmann::json::array()}};
            }
            if (parts_.event)
            {
                out_["events"] = nlohmann::json::array();
            }
            if (parts_.rays)
            {
                out_["rays"] = nlohmann::json::array();
            }
        }

        void onStart(const State &trueState, const std::vector<State> &particles) override
        {
            out_["trajectory"].push_back(pointsOf(trueState));
            addConfiguration(trueState);
            addRays(0, trueState);
            addBelief(0, particles);
        }
        void onPlan(std::size_t step, const std::vector<Action> &macro, const pomdp::SearchStatistics &s) override
        {
            out_["plans"].push_back({{"step", step}, {"length", macro.size()}, {"simulations", s.simulations}});
        }
        void onStep(std::size_t step, const Action &, const pomdp::StepResult<State, Observation> &result,
                    const std::vector<State> &particles) override
        {
            out_["trajectory"].push_back(pointsOf(result.next));
            addConfiguration(result.next);
            addRays(step, result.next);
            out_["rewards"].push_back(result.reward);
            if (parts_.event)
            {
                const std::string name = parts_.event(result.next);
                if (!name.empty())
                {
                    out_["events"].push_back({{"step", step}, {"event", name}});
                }
            }
            last_ = particles;
            lastStep_ = step;
            if (settings_.beliefEvery > 0 && step % settings_.beliefEvery == 0)
            {
                addBelief(step, particles);
            }
        }
        /** \brief Adds the final belief unless it was just recorded. */
        void finish()
        {
            if (lastStep_ > 0 && (settings_.beliefEvery == 0 || lastStep_ % settings_.beliefEvery != 0))
            {
                addBelief(lastStep_, last_);
            }
        }

    private:
        nlohmann::json pointsOf(const State &s)
        {
            scratch_.clear();
            parts_.points(s, scratch_);
            return scratch_;
        }
        void addConfiguration(const State &s)
        {
            if (out_.contains("robot"))
            {
                joints_.clear();
                parts_.configuration(s, joints_);
                out_["robot"]["configurations"].push_back(joints_);
            }
        }
        void addRays(std::size_t step, const State &s)
        {
            if (parts_.rays)
            {
                segments_.clear();
                parts_.rays(s, segments_);
                out_["rays"].push_back({{"step", step}, {"segments", segments_}});
            }
        }
        void addBelief(std::size_t step, const std::vector<State> &particles)
        {
            nlohmann::json list = nlohmann::json::array();
            const std::size_t n = particles.size();
            const std::size_t keep = std::min(n, settings_.maxParticles);
            for (std::size_t i = 0; i < keep; ++i)
            {
                list.push_back(pointsOf(particles[i * n / keep]));
            }
            out_["beliefs"].push_back({{"step", step}, {"particles", std::move(list)}});
        }

        const ScenarioParts<M> &parts_;
        RecordSettings settings_;
        nlohmann::json &out_;
        std::vector<Point3> scratch_;
        std::vector<double> joints_;
        std::vector<std::array<Point3, 2>> segments_;
        std::vector<State> last_;
        std::size_t lastStep_{0};
    };

    /** \brief Writes the search trees of the planning calls \a settings names (writeTreeFiles(): JSON and HTML) and
       forwards every event to \a inner (optional, e.g. an EpisodeRecorder). */
    template <class M>
    class TreeDumper final : public pomdp::EpisodeObserver<M>
    {
    public:
        using typename pomdp::EpisodeObserver<M>::State;
        using typename pomdp::EpisodeObserver<M>::Action;
        using typename pomdp::EpisodeObserver<M>::Observation;

        TreeDumper(const TreeDumpSettings &settings, pomdp::EpisodeObserver<M> *inner)
            : settings_(settings), inner_(inner)
        {
        }

        void onStart(const State &trueState, const std::vector<State> &particles) override
        {
            if (inner_)
                inner_->onStart(trueState, particles);
        }
        void onPlan(std::size_t step, const std::vector<Action> &macro, const pomdp::SearchStatistics &s) override
        {
            if (inner_)
                inner_->onPlan(step, macro, s);
        }
        bool wantsTree(std::size_t plan) const override { return settings_.wants(plan); }
        void onTree(std::size_t plan, std::size_t step, const pomdp::TreeSnapshot &tree) override
        {
            writeTreeFiles(settings_.fileName(plan), tree, plan, step);
        }
        void onStep(std::size_t step, const Action &a, const pomdp::StepResult<State, Observation> &result,
                    const std::vector<State> &particles) override
        {
            if (inner_)
                inner_->onStep(step, a, result, particles);
        }

    private:
        const TreeDumpSettings &settings_;
        pomdp::EpisodeObserver<M> *inner_;
    };

    /** \brief A Scenario over model type M from its parts: builds a fresh solver (by name, pomdp::makeSolver),
        particle filter and world per episode and runs pomdp::runEpisode(). Random streams per episode:
        Rng(seed) seeds the filter and solver, and splits off the world's and the reference planner's. */
    template <class M>
    class ModelScenario final : public Scenario
    {
    public:
        explicit ModelScenario(ScenarioParts<M> parts) : parts_(std::move(parts))
        {
            if (!parts_.model || !parts_.referencePolicy || !parts_.world || !parts_.points)
            {
                throw Error("scenario " + parts_.name + ": incomplete parts (model, reference policy, world, points)");
            }
            const auto known = pomdp::solverNames<M>();
            for (const auto &entry : parts_.solverDefaults)
            {
                if (std::find(known.begin(), known.end(), entry.first) == known.end())
                {
                    throw Error("scenario " + parts_.name + ": key \"solver_defaults." + entry.first +
                                "\" names no solver (known: " + joinNames(known) + ")");
                }
            }
        }

        std::string name() const override { return parts_.name; }
        std::string description() const override { return parts_.description; }
        nlohmann::json config() const override { return parts_.config; }
        nlohmann::json scene() const override { return parts_.scene; }
        double defaultPlanSeconds() const override { return parts_.defaultPlanSeconds; }
        std::size_t horizon() const override { return parts_.horizon; }
        const ScenarioParts<M> &parts() const { return parts_; }

        void validate(const RunSettings &settings) const override
        {
            pomdp::Rng rng(1);
            (void)build(settings, rng);
        }

        pomdp::EpisodeResult runEpisode(const RunSettings &settings, std::uint64_t seed, nlohmann::json *recording,
                                        const RecordSettings &record) const override
        {
            pomdp::Rng rng(seed);
            auto parts = build(settings, rng);
            pomdp::ParticleFilter<M> filter(parts_.model, parts.filter, parts_.recovery ? parts_.recovery() : nullptr);
            filter.initialize(rng);
            auto world = parts_.world();
            pomdp::EpisodeSettings episode;
            episode.maxSteps = parts_.horizon;
            episode.budget = settings.budget;
            if (episode.budget.simulations == 0 && episode.budget.seconds == 0.0)
            {
                episode.budget.seconds = parts_.defaultPlanSeconds;
            }
            episode.replanEveryStep = settings.replanEveryStep;
            if (!recording)
            {
                if (!record.tree.dir.empty())
                {
                    TreeDumper<M> dumper(record.tree, nullptr);
                    return pomdp::runEpisode(*parts_.model, *parts.solver, filter, *world, episode, rng, &dumper);
                }
                return pomdp::runEpisode(*parts_.model, *parts.solver, filter, *world, episode, rng);
            }
            *recording = nlohmann::json::object();
            (*recording)["scenario"] = parts_.name;
            (*recording)["seed"] = seed;
            (*recording)["scene"] = parts_.scene;
            EpisodeRecorder<M> recorder(parts_, record, *recording);
            TreeDumper<M> dumper(record.tree, &recorder);
            auto result = pomdp::runEpisode(*parts_.model, *parts.solver, filter, *world, episode, rng, &dumper);
            recorder.finish();
            (*recording)["success"] = result.success;
            (*recording)["steps"] = result.steps;
            (*recording)["discounted_return"] = result.discountedReturn;
            return result;
        }

    private:
        struct Built
        {
            std::unique_ptr<pomdp::Solver<M>> solver;
            pomdp::ParticleFilterSettings filter;
        };

        Built build(const RunSettings &settings, pomdp::Rng &rng) const
        {
            const std::uint64_t plannerSeed = rng.split();
            pomdp::ModelComponents<M> components;
            components.model = parts_.model;
            components.defaults = parts_.defaults;
            components.solverDefaults = parts_.solverDefaults;
            const auto &policy = parts_.referencePolicy;
            components.referencePolicy = [&settings, &policy, plannerSeed](const pomdp::ParameterMap &p)
            { return policy(settings, p, plannerSeed); };
            if (parts_.basicReferencePolicy)
            {
                const auto &basic = parts_.basicReferencePolicy;
                components.basicReferencePolicy = [&settings, &basic, plannerSeed](const pomdp::ParameterMap &p)
                { return basic(settings, p, plannerSeed); };
            }
            const pomdp::ParameterMap merged = pomdp::withDefaults(components, settings.params, settings.solver);
            Built out;
            out.solver = pomdp::makeSolver(settings.solver, components, merged);
            out.filter = pomdp::ParticleFilterSettings::fromParameters(merged);
            merged.requireAllUsed("solver " + settings.solver + " on scenario " + parts_.name,
                                  pomdp::unreadDefaultsAllowed(components, settings.params, settings.solver));
            return out;
        }

        ScenarioParts<M> parts_;
    };
}  // namespace ropras::scenarios

#endif
