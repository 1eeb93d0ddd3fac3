#include "ropras/ompl_ext/ompl/PlannerRegistry.h"

#include <algorithm>
#include <cctype>
#include <cerrno>
#include <cmath>
#include <cstdlib>

#include <ompl/base/GenericParam.h>
#include <ompl/geometric/planners/AnytimePathShortening.h>
#include <ompl/geometric/planners/cforest/CForest.h>
#include <ompl/geometric/planners/est/BiEST.h>
#include <ompl/geometric/planners/est/EST.h>
#include <ompl/geometric/planners/est/ProjEST.h>
#include <ompl/geometric/planners/fmt/BFMT.h>
#include <ompl/geometric/planners/fmt/FMT.h>
#include <ompl/geometric/planners/informedtrees/ABITstar.h>
#include <ompl/geometric/planners/informedtrees/AITstar.h>
#include <ompl/geometric/planners/informedtrees/BITstar.h>
#include <ompl/geometric/planners/kpiece/BKPIECE1.h>
#include <ompl/geometric/planners/kpiece/KPIECE1.h>
#include <ompl/geometric/planners/kpiece/LBKPIECE1.h>
#include <ompl/geometric/planners/pdst/PDST.h>
#include <ompl/geometric/planners/prm/LazyPRM.h>
#include <ompl/geometric/planners/prm/LazyPRMstar.h>
#include <ompl/geometric/planners/prm/PRM.h>
#include <ompl/geometric/planners/prm/PRMstar.h>
#include <ompl/geometric/planners/prm/SPARS.h>
#include <ompl/geometric/planners/prm/SPARStwo.h>
#include <ompl/geometric/planners/rlrt/BiRLRT.h>
#include <ompl/geometric/planners/rlrt/RLRT.h>
#include <ompl/geometric/planners/rrt/BiTRRT.h>
#include <ompl/geometric/planners/rrt/InformedRRTstar.h>
#include <ompl/geometric/planners/rrt/LBTRRT.h>
#include <ompl/geometric/planners/rrt/LazyLBTRRT.h>
#include <ompl/geometric/planners/rrt/LazyRRT.h>
#include <ompl/geometric/planners/rrt/RRT.h>
#include <ompl/geometric/planners/rrt/RRTConnect.h>
#include <ompl/geometric/planners/rrt/RRTXstatic.h>
#include <ompl/geometric/planners/rrt/RRTsharp.h>
#include <ompl/geometric/planners/rrt/RRTstar.h>
#include <ompl/geometric/planners/rrt/SORRTstar.h>
#include <ompl/geometric/planners/rrt/TRRT.h>
#include <ompl/geometric/planners/rrt/pRRT.h>
#include <ompl/geometric/planners/sbl/SBL.h>
#include <ompl/geometric/planners/sbl/pSBL.h>
#include <ompl/geometric/planners/sst/SST.h>
#include <ompl/geometric/planners/stride/STRIDE.h>
#include <iomanip>
#include <limits>
#include <mutex>
#include <sstream>

#include "planners/JointRRTConnect.h"
#include "ropras/core/Error.h"
#include "ropras/core/NameList.h"

namespace ropras::ompl_ext
{
    namespace
    {
        template <typename P>
        ompl::base::PlannerAllocator make()
        {
            return [](const ompl::base::SpaceInformationPtr &si) { return std::make_shared<P>(si); };
        }

        std::mutex registryMutex;

        /// \a text as a whole number (strtod must read all of it); false otherwise
        bool parseNumber(const std::string &text, double &value)
        {
            if (text.empty() || std::isspace(static_cast<unsigned char>(text[0])))
                return false;
            char *end = nullptr;
            errno = 0;
            value = std::strtod(text.c_str(), &end);
            return end == text.c_str() + text.size() && errno != ERANGE;
        }

        /// OMPL's numeric range suggestion "lo:step:hi" or "lo:hi" -> lo, hi; false for "0,1" and enumerations
        bool numericRange(const std::string &suggestion, double &lo, double &hi)
        {
            const auto first = suggestion.find(':');
            const auto last = suggestion.rfind(':');
            return first != std::string::npos && parseNumber(suggestion.substr(0, first), lo) &&
                   parseNumber(suggestion.substr(last + 1), hi) && std::isfinite(lo) && std::isfinite(hi);
        }

        std::string shortNumber(double v)
        {
            std::ostringstream s;
            s << v;
            return s.str();
        }

        template <typename... T>
        bool isParamOfType(const ompl::base::GenericParam &param)
        {
            return (... || (dynamic_cast<const ompl::base::SpecificParam<T> *>(&param) != nullptr));
        }

        template <typename T>
        bool integerBounds(const ompl::base::GenericParam &param, double &lo, double &hi)
        {
            if (dynamic_cast<const ompl::base::SpecificParam<T> *>(&param) == nullptr)
                return false;
            lo = static_cast<double>(std::numeric_limits<T>::min());
            hi = static_cast<double>(std::numeric_limits<T>::max());
            return true;
        }

        /** \brief Whether \a param was declared with an integer type; if so, that type's range in [lo, hi], within
            +-2^53 (beyond it a double no longer holds every whole number). */
        bool integerRange(const ompl::base::GenericParam &param, double &lo, double &hi)
        {
            if (!(integerBounds<char>(param, lo, hi) || integerBounds<int>(param, lo, hi) ||
                  integerBounds<unsigned int>(param, lo, hi) || integerBounds<long>(param, lo, hi) ||
                  integerBounds<unsigned long>(param, lo, hi) || integerBounds<long long>(param, lo, hi) ||
                  integerBounds<unsigned long long>(param, lo, hi)))
                return false;
            lo = std::max(lo, -9007199254740992.0);
            hi = std::min(hi, 9007199254740992.0);
            return true;
        }

        /** A numeric parameter takes only finite numbers (whole ones for an integer parameter, 0/1/true/false for
            a bool), and nothing below the lower end of OMPL's range suggestion (range=-1 would otherwise silently
            mean "automatic"); a suggested upper end of at most 1 (a probability, goal_bias) is a bound too. Other
            parameters (strings, enumerations) are left to OMPL's own parser. */
        void checkParameterValue(const ompl::base::Planner &planner, const ompl::base::GenericParam &param,
                                 const std::string &value)
        {
            const bool boolean = isParamOfType<bool>(param);
            double integerLo = 0.0, integerHi = 0.0;
            const bool integer = integerRange(param, integerLo, integerHi);
            const bool real = isParamOfType<float, double, long double>(param);
            if (!boolean && !integer && !real)
                return;
            const std::string where =
                "planner " + planner.getName() + ": parameter '" + param.getName() + "' = '" + value + "'";
            if (boolean)
            {
                if (value != "0" && value != "1" && value != "true" && value != "false")
                    throw Error(where + " must be 0, 1, true or false");
                return;
            }
            double v = 0.0;
            if (!parseNumber(value, v))
                throw Error(where + " is not a number");
            // (OMPL's own parser cannot read "inf" or "nan" either: it throws "Failed converting string to real
            // number", naming nothing)
            if (!std::isfinite(v))
                throw Error(where + " must be a finite number");
            // the parameter's own default counts as valid, whatever the suggestion says (PRM's
            // max_nearest_neighbors is 0, below its suggested 8:1000)
            double current = 0.0;
            const bool hasDefault = parseNumber(param.getValue(), current) && std::isfinite(current);
            if (integer && v != std::floor(v))
                throw Error(where + " must be a whole number");
            if (integer)
            {
                // OMPL reads integers with std::stoi / stoul, which stop at an exponent ("1e6" would be 1) and wrap
                // what does not fit the declared type (2^32 as unsigned would be 0)
                if (v < integerLo || v > integerHi)
                {
                    std::ostringstream range;
                    range << std::fixed << std::setprecision(0) << "[" << integerLo << ", " << integerHi << "]";
                    throw Error(where + " must be a whole number in " + range.str());
                }
                const std::size_t digits = value[0] == '-' || value[0] == '+' ? 1 : 0;
                if (digits == value.size() || value.find_first_not_of("0123456789", digits) != std::string::npos)
                    throw Error(where + " must be written as a whole number in digits (no exponent or point)");
            }
            const std::string suggestion = param.getRangeSuggestion();
            double lo = 0.0, hi = 0.0;
            if (numericRange(suggestion, lo, hi))
            {
                if (hasDefault)
                {
                    lo = std::min(lo, current);
                    hi = std::max(hi, current);
                }
                if (v < lo)
                    throw Error(where + " must be >= " + shortNumber(lo) + " (OMPL's range for it: " + suggestion +
                                ")");
                if (hi <= 1.0 && v > hi)
                    throw Error(where + " must be <= " + shortNumber(hi) + " (OMPL's range for it: " + suggestion +
                                ")");
            }
        }
    }  // namespace

    // Own planners register themselves from their translation units through this hook.
    void registerOwnPlanners(PlannerRegistry &registry);

    PlannerRegistry::PlannerRegistry()
    {
        namespace og = ompl::geometric;
        allocators_ = {
            {"ABITstar", make<og::ABITstar>()},
            {"AITstar", make<og::AITstar>()},
            {"AnytimePathShortening", make<og::AnytimePathShortening>()},
            {"BFMT", make<og::BFMT>()},
            {"BiEST", make<og::BiEST>()},
            {"BiRLRT", make<og::BiRLRT>()},
            {"BiTRRT", make<og::BiTRRT>()},
            {"BITstar", make<og::BITstar>()},
            {"BKPIECE1", make<og::BKPIECE1>()},
            {"CForest", make<og::CForest>()},
            {"EST", make<og::EST>()},
            {"FMT", make<og::FMT>()},
            {"InformedRRTstar", make<og::InformedRRTstar>()},
            {"KPIECE1", make<og::KPIECE1>()},
            {"LazyLBTRRT", make<og::LazyLBTRRT>()},
            {"LazyPRM", make<og::LazyPRM>()},
            {"LazyPRMstar", make<og::LazyPRMstar>()},
            {"LazyRRT", make<og::LazyRRT>()},
            {"LBKPIECE1", make<og::LBKPIECE1>()},
            {"LBTRRT", make<og::LBTRRT>()},
            {"PDST", make<og::PDST>()},
            {"PRM", make<og::PRM>()},
            {"PRMstar", make<og::PRMstar>()},
            {"ProjEST", make<og::ProjEST>()},
            {"pRRT", make<og::pRRT>()},
            {"pSBL", make<og::pSBL>()},
            {"RLRT", make<og::RLRT>()},
            {"RRT", make<og::RRT>()},
            {"RRTConnect", make<JointRRTConnect>()},  // OMPL's, with SIMD nearest neighbours
            {"RRTsharp", make<og::RRTsharp>()},
            {"RRTstar", make<og::RRTstar>()},
            {"RRTXstatic", make<og::RRTXstatic>()},
            {"SBL", make<og::SBL>()},
            {"SORRTstar", make<og::SORRTstar>()},
            {"SPARS", make<og::SPARS>()},
            {"SPARStwo", make<og::SPARStwo>()},
            {"SST", make<og::SST>()},
            {"STRIDE", make<og::STRIDE>()},
            {"TRRT", make<og::TRRT>()},
        };
    }

    PlannerRegistry &PlannerRegistry::instance()
    {
        static PlannerRegistry *registry = []
        {
            auto *r = new PlannerRegistry();
            registerOwnPlanners(*r);
            return r;
        }();
        return *registry;
    }

    void PlannerRegistry::add(const std::string &name, const ompl::base::PlannerAllocator &allocator)
    {
        if (name.empty() || !allocator)
            throw Error("PlannerRegistry::add: a planner needs a name and an allocator (got name '" + name + "')");
        std::lock_guard<std::mutex> lock(registryMutex);
        allocators_[name] = allocator;
    }

    bool PlannerRegistry::contains(const std::string &name) const
    {
        std::lock_guard<std::mutex> lock(registryMutex);
        return allocators_.count(name) != 0;
    }

    std::vector<std::string> PlannerRegistry::names() const
    {
        std::lock_guard<std::mutex> lock(registryMutex);
        std::vector<std::string> out;
        for (const auto &entry : allocators_)
            out.push_back(entry.first);
        return out;
    }

    ompl::base::PlannerAllocator PlannerRegistry::allocator(const std::string &name,
                                                            const std::map<std::string, std::string> &params) const
    {
        ompl::base::PlannerAllocator base;
        {
            std::lock_guard<std::mutex> lock(registryMutex);
            auto it = allocators_.find(name);
            if (it != allocators_.end())
                base = it->second;
        }
        if (!base)
            throw Error("unknown planner '" + name + "'; known planners: " + joinNames(names()));
        return [base, params](const ompl::base::SpaceInformationPtr &si)
        {
            ompl::base::PlannerPtr planner = base(si);
            setPlannerParams(*planner, params);
            return planner;
        };
    }

    ompl::base::PlannerPtr PlannerRegistry::create(const std::string &name, const ompl::base::SpaceInformationPtr &si,
                                                   const std::map<std::string, std::string> &params) const
    {
        if (!si)
            throw Error("PlannerRegistry::create('" + name + "'): null SpaceInformation");
        return allocator(name, params)(si);
    }

    void setPlannerParams(ompl::base::Planner &planner, const std::map<std::string, std::string> &params)
    {
        for (const auto &[key, value] : params)
        {
            if (!planner.params().hasParam(key))
            {
                std::vector<std::string> known;
                planner.params().getParamNames(known);
                throw Error("planner " + planner.getName() + " has no parameter '" + key +
                            "'; its parameters: " + joinNames(known));
            }
            checkParameterValue(planner, *planner.params().getParams().at(key), value);
            bool set = false;
            try
            {
                set = planner.params().setParam(key, value);
            }
            catch (const std::exception &e)  // OMPL's number parser throws std::runtime_error, naming nothing
            {
                throw Error("planner " + planner.getName() + ": parameter '" + key + "' = '" + value +
                            "': " + e.what());
            }
            if (!set)
                throw Error("planner " + planner.getName() + ": cannot set parameter '" + key + "' to '" + value + "'");
        }
    }
}  // namespace ropras::ompl_ext
