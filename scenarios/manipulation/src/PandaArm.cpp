#include "ropras/scenarios/manipulation/PandaArm.h"

#include <algorithm>
#include <cmath>
#include <map>
#include <mutex>

#include "ropras/core/Error.h"
#include "ropras/scenarios/ScenarioRegistry.h"

namespace ropras::scenarios
{
    namespace
    {
        constexpr const char *URDF_PATH = "robots/panda/panda.urdf";
        constexpr const char *SRDF_PATH = "robots/panda/panda.srdf";
    }  // namespace

    std::shared_ptr<const ompl_ext::RobotModel> loadEmbeddedPanda()
    {
        static const std::shared_ptr<const ompl_ext::RobotModel> robot = []
        {
            auto model =
                ompl_ext::RobotModel::fromUrdfString(embeddedFile(URDF_PATH), ".", URDF_PATH, embeddedFile(SRDF_PATH));
            if (model->dof() != ARM_DOF)
            {
                throw Error(std::string("embedded ") + URDF_PATH + " has " + std::to_string(model->dof()) +
                            " planning joints, expected " + std::to_string(ARM_DOF));
            }
            return model;
        }();
        return robot;
    }

    std::shared_ptr<const PandaArm> sharedPandaArm(const std::string &endEffector)
    {
        static std::mutex mutex;
        static std::map<std::string, std::shared_ptr<const PandaArm>> arms;
        const std::lock_guard<std::mutex> lock(mutex);
        auto &arm = arms[endEffector];
        if (!arm)
        {
            arm = std::make_shared<const PandaArm>(endEffector);
        }
        return arm;
    }

    PandaArm::PandaArm(const std::string &endEffector)
        : robot_(loadEmbeddedPanda()),
          checker_(std::make_shared<const ompl_ext::CollisionChecker>(robot_)),
          chain_(robot_, endEffector)
    {
    }

    void PandaArm::clamp(double *q) const noexcept
    {
        for (std::size_t j = 0; j < ARM_DOF; ++j)
        {
            q[j] = std::min(std::max(q[j], lower(j)), upper(j));
        }
    }

    void PandaArm::proposeMotion(const double *q, const double *dq, bool waypoint, double sigma, pomdp::Rng &rng,
                                 double *target) const noexcept
    {
        for (std::size_t j = 0; j < ARM_DOF; ++j)
        {
            target[j] = (waypoint ? 0.0 : q[j]) + dq[j] + sigma * rng.normal();
        }
        clamp(target);
    }

    void PandaArm::interpolate(const double *q0, const double *q1, double fraction, double *out) noexcept
    {
        for (std::size_t j = 0; j < ARM_DOF; ++j)
        {
            out[j] = fraction >= 1.0 ? q1[j] : q0[j] + fraction * (q1[j] - q0[j]);
        }
    }

    std::size_t PandaArm::motionSamples(const double *q0, const double *q1, double resolution) noexcept
    {
        double largest = 0.0;
        for (std::size_t j = 0; j < ARM_DOF; ++j)
        {
            largest = std::max(largest, std::abs(q1[j] - q0[j]));
        }
        const double steps = std::ceil(largest / resolution);
        return steps >= 1.0 && steps < 1e8 ? static_cast<std::size_t>(steps) : 1;
    }

    void PandaArm::requireWithinLimits(const double *q, const std::string &prefix) const
    {
        for (std::size_t j = 0; j < ARM_DOF; ++j)
        {
            if (q[j] < lower(j) || q[j] > upper(j))
            {
                throw Error(prefix + "joint " + std::to_string(j + 1) + " = " + std::to_string(q[j]) +
                            " is outside its limits [" + std::to_string(lower(j)) + ", " + std::to_string(upper(j)) +
                            "]");
            }
        }
    }
}  // namespace ropras::scenarios
