#ifndef ROPRAS_POMDP_PARAMETER_MAP_H
#define ROPRAS_POMDP_PARAMETER_MAP_H

#include <map>
#include <set>
#include <string>
#include <vector>

namespace ropras::pomdp
{
    /** \brief Named numeric parameters of solvers and models ("eta" -> 0.2), e.g. from `--param eta=0.2`.

        Readers take values with get(); once every reader is done, requireAllUsed() throws ropras::Error
        naming any parameter nobody read (a misspelt name is an error, never silently ignored). Values must
        be finite. */
    class ParameterMap
    {
    public:
        ParameterMap() = default;

        /** \brief Parses "name=value" strings; throws ropras::Error on a malformed entry, a non-numeric or
            non-finite value, or a duplicate name. */
        static ParameterMap parse(const std::vector<std::string> &entries);

        /** \brief Sets \a name; throws ropras::Error for an empty name or a non-finite value. */
        void set(const std::string &name, double value);

        bool contains(const std::string &name) const { return values_.count(name) != 0; }

        /** \brief The value of \a name or \a fallback; marks \a name as used. */
        double get(const std::string &name, double fallback) const;

        /// the largest count getCount() accepts unless given a smaller \a max
        static constexpr double MAX_COUNT = 1e15;
        /// the largest count read into an `unsigned` setting: 2^32 - 1
        static constexpr double MAX_UNSIGNED = 4294967295.0;

        /** \brief Like get() for a count: throws ropras::Error if the value is negative, not an integer or above
            \a max (MAX_UNSIGNED for settings stored as `unsigned`, so that none is silently truncated). */
        std::size_t getCount(const std::string &name, std::size_t fallback, double max = MAX_COUNT) const;

        /** \brief getCount() for a setting stored as `unsigned` (\a max at most MAX_UNSIGNED, so that nothing is
            truncated). */
        unsigned getUnsigned(const std::string &name, unsigned fallback, double max = MAX_UNSIGNED) const
        {
            return static_cast<unsigned>(getCount(name, fallback, max < MAX_UNSIGNED ? max : MAX_UNSIGNED));
        }

        /** \brief Throws ropras::Error naming every parameter that no get() read and listing the valid names
            (those read, and \a exempt) (\a context names the reader, e.g. "solver ropras3 on model tiger");
            names in \a exempt are not checked. */
        void requireAllUsed(const std::string &context, const std::set<std::string> &exempt = {}) const;

        const std::map<std::string, double> &values() const { return values_; }

    private:
        std::map<std::string, double> values_;
        mutable std::set<std::string> used_;
    };
}  // namespace ropras::pomdp

#endif
