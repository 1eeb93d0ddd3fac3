#include <urdf_model/model.h>

#include <algorithm>
#include <cmath>
#include <set>

#include "model/JointValues.h"
#include "model/ModelText.h"
#include "model/RobotModelBuilder.h"
#include "model/SrdfGroups.h"
#include "model/UrdfSanity.h"

namespace ropras::ompl_ext
{
    namespace
    {
        constexpr double PI = 3.14159265358979323846;
        using model_text::fmt;
        using model_text::joinNames;
    }  // namespace

    void RobotModelBuilder::choosePlanningJoints(const urdf::ModelInterface &urdf)
    {
        auto &joints = model_->urdfJoints_;
        std::vector<std::string> candidates;  // movable, non-mimic joints in document order
        for (const UrdfJoint &j : joints)
        {
            if (j.type != JointType::Fixed && !urdf.joints_.at(j.name)->mimic)
            {
                candidates.push_back(j.name);
            }
        }
        std::vector<double> lower, upper;
        jointLimits(urdf, lower, upper);

        resolveGroups(candidates);
        std::vector<std::string> chosen = chosenJoints(candidates);
        std::set<std::string> seen;
        for (const std::string &name : chosen)
        {
            const int idx = findJoint(name);
            if (idx < 0 || std::find(candidates.begin(), candidates.end(), name) == candidates.end())
            {
                std::string why = idx < 0                                ? "is not a joint of the URDF"
                                  : joints[idx].type == JointType::Fixed ? "is a fixed joint"
                                                                         : "is a mimic joint";
                fail("planning joint '" + name + "' " + why + "; valid planning joints: " + joinNames(candidates));
            }
            if (!seen.insert(name).second)
            {
                fail("planning joint '" + name + "' is listed twice");
            }
            PlanningJoint pj;
            pj.name = name;
            pj.type = joints[idx].type;
            pj.lower = lower[idx];
            pj.upper = upper[idx];
            pj.urdfJoint = idx;
            joints[idx].variable = static_cast<int>(model_->joints_.size());
            model_->joints_.push_back(pj);
        }
        holdJoints(lower, upper);
    }

    void RobotModelBuilder::jointLimits(const urdf::ModelInterface &urdf, std::vector<double> &lower,
                                        std::vector<double> &upper) const
    {
        const auto &joints = model_->urdfJoints_;
        lower.assign(joints.size(), 0.0);
        upper.assign(joints.size(), 0.0);
        for (std::size_t i = 0; i < joints.size(); ++i)
        {
            const urdf::Joint &uj = *urdf.joints_.at(joints[i].name);
            if (joints[i].type == JointType::Continuous)
            {
                lower[i] = -PI;
                upper[i] = PI;
            }
            else if (joints[i].type != JointType::Fixed)
            {
                if (!uj.limits)
                {
                    fail("joint '" + uj.name + "' has no <limit>");
                }
                lower[i] = uj.limits->lower;
                upper[i] = uj.limits->upper;
                if (!std::isfinite(lower[i]) || !std::isfinite(upper[i]) || lower[i] > upper[i])
                {
                    fail("joint '" + uj.name + "' has invalid limits [" + fmt(lower[i]) + ", " + fmt(upper[i]) + "]");
                }
                failIf(urdf_sanity::limitProblem(uj.name, joints[i].type, lower[i], upper[i]));
            }
        }
    }

    int RobotModelBuilder::findJoint(const std::string &name) const
    {
        const auto &joints = model_->urdfJoints_;
        for (std::size_t i = 0; i < joints.size(); ++i)
        {
            if (joints[i].name == name)
            {
                return static_cast<int>(i);
            }
        }
        return -1;
    }

    void RobotModelBuilder::resolveGroups(const std::vector<std::string> &candidates)
    {
        for (const SrdfGroup &group : srdf_.groups)
        {
            try
            {
                std::vector<std::string> &movable = model_->groups_[group.name];
                for (const int j : srdfGroupJoints(srdf_, group.name, model_->links_, model_->urdfJoints_, srdfName_))
                {
                    const std::string &name = model_->urdfJoints_[j].name;
                    if (std::find(candidates.begin(), candidates.end(), name) != candidates.end())
                        movable.push_back(name);
                }
            }
            catch (const Error &e)
            {
                model_->groups_.erase(group.name);
                if (options_.strict || group.name == options_.group)
                    throw;
                model_->warnings_.push_back(std::string(e.what()) + "; the group is skipped");
            }
        }
    }

    std::vector<std::string> RobotModelBuilder::chosenJoints(const std::vector<std::string> &candidates)
    {
        std::string group = options_.group;
        if (group.empty() && options_.planningJoints.empty() && model_->groups_.count(options_.requestGroup))
            group = options_.requestGroup;
        if (group.empty())
            return options_.planningJoints.empty() ? candidates : options_.planningJoints;
        if (!options_.planningJoints.empty())
            fail("give the planning joints or a planning group ('" + group + "'), not both");
        if (srdf_.groups.empty())
            fail("planning group '" + group + "' needs an SRDF that defines groups" +
                 (hasSrdf_ ? " ('" + srdfName_ + "' defines none)" : std::string(" (no SRDF given)")));
        if (model_->groups_.count(group) == 0)  // not defined: the resolver's message lists the groups
            srdfGroupJoints(srdf_, group, model_->links_, model_->urdfJoints_, srdfName_);
        const std::vector<std::string> &joints = model_->groups_.at(group);
        if (joints.empty())
            fail("planning group '" + group + "' of SRDF '" + srdfName_ + "' has no movable joint");
        model_->group_ = group;
        return joints;
    }

    void RobotModelBuilder::holdJoints(const std::vector<double> &lower, const std::vector<double> &upper)
    {
        auto &joints = model_->urdfJoints_;
        for (std::size_t i = 0; i < joints.size(); ++i)
        {
            if (joints[i].type != JointType::Fixed && joints[i].variable < 0)
            {
                joints[i].heldValue = std::clamp(0.0, lower[i], upper[i]);
            }
        }
        std::vector<std::string> unknown;
        for (const auto &[name, value] : options_.jointState)
        {
            const int idx = findJoint(name);
            if (idx < 0)
                unknown.push_back(name);
            else if (joints[idx].type != JointType::Fixed && joints[idx].variable < 0 &&
                     options_.heldJointValues.count(name) == 0)
                holdJoint(idx, value, lower[idx], upper[idx], "the joint state's");
        }
        if (!unknown.empty())
        {
            const std::string what = "the joint state names joints the URDF does not have: " + joinNames(unknown);
            if (options_.strict)
                fail(what);
            model_->warnings_.push_back("URDF '" + urdfName_ + "': " + what + "; they are ignored");
        }
        for (const auto &[name, value] : options_.heldJointValues)
        {
            const int idx = findJoint(name);
            if (idx < 0)
            {
                std::vector<std::string> movable;
                for (const UrdfJoint &j : joints)
                {
                    if (j.type != JointType::Fixed)
                    {
                        movable.push_back(j.name);
                    }
                }
                fail("held joint '" + name + "' is not a joint of the URDF; movable joints: " + joinNames(movable));
            }
            if (joints[idx].type == JointType::Fixed)
            {
                fail("held joint '" + name + "' is a fixed joint");
            }
            if (joints[idx].variable >= 0)
            {
                fail("held joint '" + name + "' is a planning joint; give values only for joints not planned");
            }
            holdJoint(idx, value, lower[idx], upper[idx], "held joint");
        }
    }

    void RobotModelBuilder::holdJoint(int idx, double value, double lower, double upper, const std::string &what)
    {
        UrdfJoint &joint = model_->urdfJoints_[idx];
        if (!options_.strict)
        {
            const std::string warning =
                fitJointValue(joint.name, joint.type, lower, upper, options_.limitTolerance, value);
            if (!warning.empty())
                model_->warnings_.push_back("URDF '" + urdfName_ + "': held " + warning);
        }
        const bool inLimits = joint.type == JointType::Continuous
                                  ? std::isfinite(value)
                                  : (std::isfinite(value) && value >= lower && value <= upper);
        if (!inLimits)
        {
            fail(what + " '" + joint.name + "' value " + fmt(value) + " is outside its limits [" + fmt(lower) + ", " +
                 fmt(upper) + "]");
        }
        joint.heldValue = value;
    }
}  // namespace ropras::ompl_ext
