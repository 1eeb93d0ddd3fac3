#ifndef ROPRAS_SCENARIOS_CONFIG_READER_H
#define ROPRAS_SCENARIOS_CONFIG_READER_H

#include <cstddef>
#include <map>
#include <nlohmann/json.hpp>
#include <set>
#include <string>
#include <vector>

namespace ropras::scenarios
{
    /** \brief Reads the keys of a scenario's effective configuration (default.json with the user's
        overrides). Every failure throws ropras::Error "scenario NAME: key "KEY" PROBLEM", naming the value:
        a missing key, another JSON type, a non-finite number, a value out of its range. Nested keys are
        named with a dot ("planning.plan_seconds"): sub() reads an object key with a prefix. */
    class ConfigReader
    {
    public:
        /** \brief Throws when \a json is not an object. \a prefix is prepended to every key in messages. */
        ConfigReader(std::string scenario, const nlohmann::json &json, std::string prefix = "");

        [[noreturn]] void fail(const std::string &key, const std::string &problem) const;

        /// throws for a key of the object that is not in \a known
        void requireKnown(const std::set<std::string> &known) const;
        const nlohmann::json &at(const std::string &key) const;
        /// the reader of the object at \a key (keys named "key.inner")
        ConfigReader sub(const std::string &key) const;

        double number(const std::string &key) const;
        /// \a value (found under \a key) as a finite number
        double number(const std::string &key, const nlohmann::json &value) const;
        double positive(const std::string &key) const;
        double nonNegative(const std::string &key) const;
        /// a number in [lo, hi]
        double within(const std::string &key, double lo, double hi) const;
        /// an integer in [lo, hi]
        std::size_t count(const std::string &key, std::size_t lo, std::size_t hi) const;
        bool boolean(const std::string &key) const;
        /// one of the strings \a choices (the message lists them)
        std::string choice(const std::string &key, const std::vector<std::string> &choices) const;
        /// an array of exactly \a n finite numbers (n = 0: any length >= 1)
        std::vector<double> numbers(const std::string &key, std::size_t n) const;
        /// an array of arrays of \a n finite numbers each (may be empty)
        std::vector<std::vector<double>> rows(const std::string &key, std::size_t n) const;
        /** \brief The optional key "solver_defaults", {solver: {parameter: number}}: per-solver parameter
            defaults (empty when absent; the solver names are checked by ModelScenario). */
        std::map<std::string, std::map<std::string, double>> solverDefaults() const;

        const std::string &scenario() const { return scenario_; }

    private:
        std::vector<double> numbersOf(const std::string &key, const nlohmann::json &value, std::size_t n) const;

        std::string scenario_;
        const nlohmann::json &json_;
        std::string prefix_;
    };
}  // namespace ropras::scenarios

#endif
