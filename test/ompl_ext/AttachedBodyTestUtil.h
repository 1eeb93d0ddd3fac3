#ifndef ROPRAS_TEST_ATTACHED_BODY_TEST_UTIL_H
#define ROPRAS_TEST_ATTACHED_BODY_TEST_UTIL_H

// The arm, the held can and the FCL agreement check shared by the attached-body and particle-scene tests.
#include <gtest/gtest.h>

#include <filesystem>
#include <iostream>
#include <memory>
#include <random>
#include <string>
#include <vector>

#include "ropras/ompl_ext/collision/CrossCheck.h"
#include "ropras/ompl_ext/model/RobotModel.h"
#include "ropras/ompl_ext/scene/AttachedBody.h"

namespace ropras::test
{
    /// the project's 6-DoF arm (robots/ropras_arm)
    inline std::shared_ptr<const ompl_ext::RobotModel> arm()
    {
        static const auto model = ompl_ext::RobotModel::fromUrdfFile(
            (std::filesystem::path(ROPRAS_SOURCE_DIR) / "robots/ropras_arm/ropras_arm.urdf").string());
        return model;
    }

    inline Eigen::Isometry3d translation(double x, double y, double z)
    {
        Eigen::Isometry3d t = Eigen::Isometry3d::Identity();
        t.translation() = Eigen::Vector3d(x, y, z);
        return t;
    }

    /// a can (cylinder r 3 cm, 12 cm long) held 10 cm beyond the link along its z
    inline ompl_ext::AttachedBody can(const std::string &name, const std::string &link,
                                      std::vector<std::string> touch = {})
    {
        ompl_ext::AttachedBody body;
        body.name = name;
        body.link = link;
        body.pose = translation(0.0, 0.0, 0.10);
        body.shapes = {ompl_ext::Shape::cylinder(0.03, 0.12)};
        body.touchLinks = std::move(touch);
        return body;
    }

    inline std::vector<double> randomConfiguration(const ompl_ext::RobotModel &robot, std::mt19937_64 &rng)
    {
        std::vector<double> q(robot.dof());
        ompl_ext::sampleConfiguration(robot, rng, q.data());
        return q;
    }

    /// every backend agrees with the FCL reference outside the contact tolerance, batch verdicts match single ones
    inline void expectAgreement(const std::string &what, const ompl_ext::CrossCheckReport &report)
    {
        for (const ompl_ext::BackendAgreement &b : report.backends)
        {
            std::cout << "[ info ] " << what << ": " << ompl_ext::simdBackendName(b.backend) << " agree " << b.agree
                      << ", near contact " << b.nearContact << ", disagreements " << b.disagreements
                      << ", batch mismatches " << b.batchMismatches << " (FCL valid " << report.referenceValid << " of "
                      << report.configurations << ")\n";
            EXPECT_EQ(b.disagreements, 0u) << what;
            EXPECT_EQ(b.batchMismatches, 0u) << what;
        }
        for (const std::string &e : report.examples)
            ADD_FAILURE() << what << ": " << e;
    }
}  // namespace ropras::test

#endif
