// GCC 12 reports a false -Wmaybe-uninitialized inside Eigen's AVX-512 4x4 products (-march=native builds).
#if defined(__GNUC__) && !defined(__clang__)
#pragma GCC diagnostic ignored "-Wmaybe-uninitialized"
#endif

#include "ropras/ompl_ext/model/RobotModel.h"

#include <algorithm>
#include <cmath>
#include <filesystem>

#include "model/JointValues.h"
#include "model/ModelText.h"
#include "model/RobotModelBuilder.h"
#include "model/UrdfPose.h"
#include "ropras/core/Error.h"
#include "ropras/core/InputFile.h"

namespace ropras::ompl_ext
{
    namespace
    {
        using model_text::joinNames;
        using urdf_pose::jointMotion;
    }  // namespace

    std::shared_ptr<const RobotModel> RobotModel::fromUrdfFile(const std::string &urdfPath, const std::string &srdfPath,
                                                               const Options &options)
    {
        const std::string urdfXml = readInputFile(urdfPath, "URDF");
        const std::string srdfXml = srdfPath.empty() ? std::string() : readInputFile(srdfPath, "SRDF");
        if (!srdfPath.empty() && srdfXml.find_first_not_of(" \t\r\n") == std::string::npos)
        {
            throw Error("SRDF '" + srdfPath + "': the file is empty");
        }
        std::error_code ec;
        const std::filesystem::path dir = std::filesystem::absolute(urdfPath, ec).parent_path();
        RobotModelBuilder builder(dir.string(), urdfPath, srdfPath, options);
        return builder.build(urdfXml, srdfXml);
    }

    std::shared_ptr<const RobotModel> RobotModel::fromUrdfString(const std::string &urdfXml, const std::string &baseDir,
                                                                 const std::string &sourceName,
                                                                 const std::string &srdfXml, const Options &options)
    {
        RobotModelBuilder builder(baseDir, sourceName, sourceName + " (SRDF)", options);
        return builder.build(urdfXml, srdfXml);
    }

    std::vector<double> RobotModel::planningValues(const std::map<std::string, double> &jointValues,
                                                   const std::string &context, std::vector<std::string> *warnings) const
    {
        std::vector<std::string> unknown;
        for (const auto &entry : jointValues)
            if (std::none_of(urdfJoints_.begin(), urdfJoints_.end(),
                             [&](const UrdfJoint &j) { return j.name == entry.first; }))
                unknown.push_back(entry.first);
        if (strict_ && !unknown.empty())
            throw Error(context + ": names joint '" + unknown.front() + "', which robot '" + name_ + "' (" + source_ +
                        ") does not have");
        if (!unknown.empty() && warnings)  // MoveIt ignores joints outside the planning group
            warnings->push_back(context + ": names joints robot '" + name_ + "' (" + source_ +
                                ") does not have, ignored: " + joinNames(unknown));
        std::vector<double> q(joints_.size());
        for (std::size_t i = 0; i < joints_.size(); ++i)
        {
            auto it = jointValues.find(joints_[i].name);
            if (it == jointValues.end())
                throw Error(context + ": does not give planning joint '" + joints_[i].name + "'");
            q[i] = it->second;
            if (strict_)
                continue;
            const PlanningJoint &j = joints_[i];
            const std::string warning = fitJointValue(j.name, j.type, j.lower, j.upper, limitTolerance_, q[i]);
            if (!warning.empty() && warnings)
                warnings->push_back(context + ": " + warning);
        }
        return q;
    }

    int RobotModel::jointIndex(const std::string &name) const
    {
        for (std::size_t i = 0; i < joints_.size(); ++i)
        {
            if (joints_[i].name == name)
            {
                return static_cast<int>(i);
            }
        }
        std::vector<std::string> names;
        for (const PlanningJoint &j : joints_)
        {
            names.push_back(j.name);
        }
        throw Error("robot '" + name_ + "' (" + source_ + "): no planning joint '" + name +
                    "'; planning joints: " + joinNames(names));
    }

    int RobotModel::linkIndex(const std::string &name) const
    {
        for (std::size_t i = 0; i < links_.size(); ++i)
        {
            if (links_[i].name == name)
            {
                return static_cast<int>(i);
            }
        }
        throw Error("robot '" + name_ + "' (" + source_ + "): no link '" + name + "'");
    }

    std::vector<double> RobotModel::defaultConfiguration() const
    {
        std::vector<double> q;
        q.reserve(joints_.size());
        for (const PlanningJoint &j : joints_)
        {
            q.push_back(std::clamp(0.0, j.lower, j.upper));
        }
        return q;
    }

    bool RobotModel::withinBounds(const double *q) const noexcept
    {
        for (std::size_t i = 0; i < joints_.size(); ++i)
        {
            const double v = q[i];
            if (!std::isfinite(v))
            {
                return false;
            }
            if (joints_[i].type != JointType::Continuous && (v < joints_[i].lower || v > joints_[i].upper))
            {
                return false;
            }
        }
        return true;
    }

    std::vector<Eigen::Isometry3d> RobotModel::linkTransformsReference(const double *q) const
    {
        // links_ is in topological order (parents first), so one pass suffices.
        std::vector<Eigen::Isometry3d> out(links_.size(), Eigen::Isometry3d::Identity());
        for (std::size_t i = 0; i < links_.size(); ++i)
        {
            const int pj = links_[i].parentJoint;
            if (pj < 0)
            {
                out[i] = basePose_;
                continue;
            }
            const UrdfJoint &j = urdfJoints_[pj];
            const double v = j.variable >= 0 ? q[j.variable] : j.heldValue;
            out[i] = out[j.parentLink] * j.origin * jointMotion(j.type, j.axis, v);
        }
        return out;
    }

    std::vector<Eigen::Vector3d> RobotModel::sphereCentersReference(const double *q) const
    {
        const std::vector<Eigen::Isometry3d> t = linkTransformsReference(q);
        std::vector<Eigen::Vector3d> out;
        out.reserve(spheres_.size());
        for (const CollisionSphere &s : spheres_)
        {
            out.push_back(t[collisionLinks_[s.collisionLink].link] * s.centerInLink);
        }
        return out;
    }
}  // namespace ropras::ompl_ext
