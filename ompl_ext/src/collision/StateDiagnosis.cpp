#include "ropras/ompl_ext/collision/StateDiagnosis.h"

#include <cmath>
#include <sstream>

#include "ropras/ompl_ext/collision/FclReferenceChecker.h"

namespace ropras::ompl_ext
{
    std::string explainInvalidState(const CollisionChecker &checker, const Environment &env, const double *q)
    {
        if (checker.isValid(env, q))
            return "";
        const RobotModel &robot = checker.robot();
        std::ostringstream why;
        why.precision(6);
        for (std::size_t i = 0; i < robot.dof(); ++i)
        {
            const PlanningJoint &joint = robot.joints()[i];
            const bool bounded = joint.type != JointType::Continuous;
            if (std::isfinite(q[i]) && (!bounded || (q[i] >= joint.lower && q[i] <= joint.upper)))
                continue;
            why << (why.tellp() > 0 ? "; " : "") << "joint '" << joint.name << "' = " << q[i];
            if (std::isfinite(q[i]))
                why << " is outside its limits [" << joint.lower << ", " << joint.upper << "]";
            else
                why << " is not a finite number";
        }
        if (why.tellp() > 0)
            return "outside the joint limits: " + why.str();
        const FclSphereChecker reference(checker.robotPtr());
        const std::string contact = reference.describeCollision(env, q);
        if (!contact.empty())
            return "in collision: " + contact;
        why << "in collision for the float kernels, within rounding of contact (FCL signed distance "
            << reference.distance(env, q) << " m)";
        return why.str();
    }
}  // namespace ropras::ompl_ext
