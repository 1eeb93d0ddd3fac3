#ifndef ROPRAS_OMPL_EXT_PLANNER_REGISTRY_H
#define ROPRAS_OMPL_EXT_PLANNER_REGISTRY_H

#include <ompl/base/Planner.h>
#include <map>
#include <string>
#include <vector>

namespace ropras::ompl_ext
{
    /** \brief Geometric planners created by name.

        Holds every geometric planner OMPL 1.5.2 ships that can be built from a SpaceInformation alone
        (TSRRT, VFRRT, XXL and QRRT need problem-specific inputs: a task space, a vector field, a
        decomposition, a space hierarchy — create those directly), plus ropras' own planners. Unknown names
        and unknown or unparsable parameters throw ropras::Error listing the valid names. */
    class PlannerRegistry
    {
    public:
        /// the process-wide registry, with OMPL's planners and ropras' own registered
        static PlannerRegistry &instance();

        /// adds (or replaces) a planner allocator under \a name
        void add(const std::string &name, const ompl::base::PlannerAllocator &allocator);
        bool contains(const std::string &name) const;
        std::vector<std::string> names() const;

        /// creates planner \a name for \a si and sets \a params by name (planner->params())
        ompl::base::PlannerPtr create(const std::string &name, const ompl::base::SpaceInformationPtr &si,
                                      const std::map<std::string, std::string> &params = {}) const;
        /// an allocator usable with SimpleSetup::setPlannerAllocator and tools::Benchmark
        ompl::base::PlannerAllocator allocator(const std::string &name,
                                               const std::map<std::string, std::string> &params = {}) const;

    private:
        PlannerRegistry();
        std::map<std::string, ompl::base::PlannerAllocator> allocators_;
    };

    /// sets \a params on \a planner by name; throws ropras::Error listing the planner's parameters on a bad name
    void setPlannerParams(ompl::base::Planner &planner, const std::map<std::string, std::string> &params);
}  // namespace ropras::ompl_ext

#endif
