#include "ropras/ompl_ext/kinematics/IkTarget.h"

#include <cmath>
#include <sstream>
#include <string>

#include "ropras/core/Error.h"

namespace ropras::ompl_ext
{
    namespace
    {
        template <class V>
        std::string show(const V &v)
        {
            std::ostringstream ss;
            ss.precision(10);
            ss << '(';
            for (Eigen::Index i = 0; i < v.size(); ++i)
                ss << (i ? ", " : "") << v[i];
            ss << ')';
            return ss.str();
        }

        void checkFinite(const Eigen::Vector3d &v, const char *what)
        {
            if (!v.allFinite())
                throw Error(std::string("IK target: ") + what + " " + show(v) + " is not finite");
        }

        Eigen::Vector3d unitAxis(const Eigen::Vector3d &v, const char *what)
        {
            checkFinite(v, what);
            const double n = v.norm();
            if (!(n > 1e-12))
                throw Error(std::string("IK target: ") + what + " " + show(v) + " is zero; it needs a direction");
            return v / n;
        }
    }  // namespace

    IkTarget IkTarget::position(const Eigen::Vector3d &position)
    {
        checkFinite(position, "position");
        IkTarget t;
        t.kind_ = IkTargetKind::Position;
        t.position_ = position;
        return t;
    }

    IkTarget IkTarget::positionAxis(const Eigen::Vector3d &position, const Eigen::Vector3d &approach,
                                    const Eigen::Vector3d &toolAxis)
    {
        IkTarget t = IkTarget::position(position);
        t.kind_ = IkTargetKind::PositionAxis;
        t.approach_ = unitAxis(approach, "approach axis");
        t.toolAxis_ = unitAxis(toolAxis, "tool axis");
        return t;
    }

    IkTarget IkTarget::pose(const Eigen::Vector3d &position, const Eigen::Quaterniond &orientation)
    {
        IkTarget t = IkTarget::position(position);
        const Eigen::Vector4d c = orientation.coeffs();  // x, y, z, w
        if (!c.allFinite() || std::abs(c.norm() - 1.0) > 1e-6)
            throw Error(
                "IK target: orientation quaternion (w, x, y, z) = " + show(Eigen::Vector4d(c[3], c[0], c[1], c[2])) +
                " has norm " + std::to_string(c.norm()) + "; it must be a unit quaternion");
        t.kind_ = IkTargetKind::Pose;
        t.orientation_ = orientation.normalized();
        return t;
    }

    IkTarget IkTarget::pose(const Eigen::Isometry3d &pose)
    {
        const Eigen::Matrix3d r = pose.linear();
        if (!pose.matrix().allFinite() || (r.transpose() * r - Eigen::Matrix3d::Identity()).norm() > 1e-6 ||
            r.determinant() < 0.0)
            throw Error("IK target: the pose's rotation is not orthonormal with determinant +1 (or not finite)");
        return IkTarget::pose(pose.translation(), Eigen::Quaterniond(r).normalized());
    }
}  // namespace ropras::ompl_ext
