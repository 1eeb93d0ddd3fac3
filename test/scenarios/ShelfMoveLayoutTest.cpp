// Shelf-Move's grasps between close cans: approaches turned about the vertical (planning.grasp_yaws) and the
// layouts whose cans can be cleared grasp after grasp down to the target (graspable_layout).
#include <gtest/gtest.h>

#include <cmath>
#include <memory>
#include <nlohmann/json.hpp>
#include <string>

#include "ShelfMoveTestUtil.h"
#include "ropras/core/Error.h"
#include "ropras/scenarios/manipulation/ShelfMovePlanning.h"

namespace ropras::scenarios
{
    namespace
    {
        using State = ShelfMoveModel::State;

        std::shared_ptr<const ShelfMoveModel> makeModel(const nlohmann::json &json)
        {
            return test::makeShelfMoveModel(json);
        }

        const std::shared_ptr<const ShelfMoveModel> &model()
        {
            return test::shelfMoveModel();
        }

        /// the note's packed front: the target at the back, one can before it and two beside that one
        nlohmann::json packedFrontJson()
        {
            auto json = test::shelfMoveJson();
            json["cans"] = {{0.8, 0, 0.64}, {0.62, 0, 0.64}, {0.70, 0.08, 0.64}, {0.70, -0.08, 0.64}};
            return json;
        }

        /// the packed front, grasped and placed with the approach straight along +x only (grasp_yaws [0])
        nlohmann::json straightPackedFrontJson()
        {
            auto json = packedFrontJson();
            json["planning"]["grasp_yaws"] = {0};
            return json;
        }

        /// the packed front as the true world of seed 7100's failed episode drew it: cans 1 and 2 1.7 cm apart
        void squeeze(State &s)
        {
            s.can[1][0] = 0.685;
            s.can[1][1] = 0.001;
            s.can[2][0] = 0.684;
            s.can[2][1] = 0.078;
        }
    }  // namespace

    TEST(ShelfMoveModel, AGraspableLayoutIsOneWhoseCansCanBeTakenOffOneAfterAnotherUntilTheTarget)
    {
        pomdp::Rng rng(23);
        EXPECT_TRUE(model()->graspableLayout(model()->trueInitialState(), rng)) << "the default layout";
        const auto packed = makeModel(straightPackedFrontJson());
        State s = packed->trueInitialState();
        EXPECT_TRUE(packed->graspableLayout(s, rng)) << "the packed front as configured";
        squeeze(s);
        ASSERT_TRUE(packed->validState(s)) << "physically possible: the cans do not touch";
        EXPECT_FALSE(packed->graspableLayout(s, rng)) << "no straight approach fits between cans 1 and 2";
        State held = packed->trueInitialState();
        held.held = 1;
        EXPECT_FALSE(packed->graspableLayout(held, rng)) << "a layout is judged with nothing held";
    }

    TEST(ShelfMoveModel, WithGraspableLayoutTheInitialBeliefDrawsOnlyGraspableLayouts)
    {
        auto json = straightPackedFrontJson();
        const auto free = makeModel(json);
        json["graspable_layout"] = true;
        const auto graspable = makeModel(json);
        pomdp::Rng draws(41), judge(43);
        std::size_t rejected = 0;
        const int n = 40;
        for (int i = 0; i < n; ++i)
        {
            const State s = graspable->sampleInitialState(draws);
            ASSERT_TRUE(graspable->validState(s));
            EXPECT_TRUE(graspable->graspableLayout(s, judge)) << "draw " << i;
            rejected += !free->graspableLayout(free->sampleInitialState(draws), judge);
        }
        // without the key, some draws of this layout cannot be cleared by straight grasps (initial_can_sigma 0.03)
        EXPECT_GT(rejected, 0u);
        // the configured layout itself must be graspable
        json["cans"][1] = {0.685, 0.001, 0.64};
        json["cans"][2] = {0.684, 0.078, 0.64};
        try
        {
            makeModel(json);
            ADD_FAILURE() << "no error for an ungraspable configured layout";
        }
        catch (const Error &e)
        {
            EXPECT_NE(std::string(e.what()).find("key \"cans\""), std::string::npos) << e.what();
            EXPECT_NE(std::string(e.what()).find("graspable_layout"), std::string::npos) << e.what();
        }
        json = straightPackedFrontJson();
        json["graspable_layout"] = "yes";
        EXPECT_THROW(makeModel(json), Error);
    }
    TEST(ShelfMoveModel, GraspYawsTurnTheApproachAndFindGraspsBetweenCloseCans)
    {
        auto json = packedFrontJson();
        json["planning"]["grasp_yaws"] = {0, 15, -15, 30, -30};
        const auto turned = makeModel(json);
        ShelfMoveIk ik(turned, 24, 5);
        const auto rotations = ik.graspOrientations();
        ASSERT_EQ(rotations.size(), 10u);
        const double PI = 3.14159265358979323846;
        for (std::size_t i = 0; i < rotations.size(); ++i)
        {
            const Eigen::Matrix3d &r = rotations[i];
            EXPECT_LT((r.transpose() * r - Eigen::Matrix3d::Identity()).norm(), 1e-12);
            EXPECT_NEAR(r.determinant(), 1.0, 1e-12);
            EXPECT_NEAR(std::abs(r.col(0).z()), 1.0, 1e-12) << "x vertical";
            const double yaw = std::atan2(r.col(2).y(), r.col(2).x());  // the approach is +x turned by the yaw
            EXPECT_NEAR(yaw, ik.graspYaws()[i / 2], 1e-12);
            EXPECT_NEAR(r.col(2).z(), 0.0, 1e-12);
        }
        EXPECT_NEAR(ik.graspYaws()[3], 30.0 * PI / 180.0, 1e-12);
        ShelfMoveIk other(turned, 4, 1);
        EXPECT_THROW(other.setGraspYaws({}), Error);
        EXPECT_THROW(other.setGraspYaws({0.0, std::nan("")}), Error);
        other.setGraspYaws({0.25});
        ASSERT_EQ(other.graspOrientations().size(), 2u);
        EXPECT_NEAR(std::atan2(other.graspOrientations()[0].col(2).y(), other.graspOrientations()[0].col(2).x()), 0.25,
                    1e-12);
        // the packed front squeezed: no straight grasp of cans 1 and 2; turned ones exist, and the model's own grasp
        // rule (graspableCan) accepts the IK's configuration
        State s = turned->trueInitialState();
        squeeze(s);
        const auto scene = turned->makeScene(s, true);
        int found = 0;
        for (int k = 1; k <= 2; ++k)
        {
            const ShelfTarget grasp = ShelfMoveTargetSpace::grasp(s, k);
            double q[ARM_DOF];
            ShelfMoveIk straight(makeModel(straightPackedFrontJson()), 24, 5);
            EXPECT_FALSE(straight.solve(s, grasp, *scene, q)) << "can " << k;
            if (!ik.solve(s, grasp, *scene, q))
            {
                continue;
            }
            ++found;
            State at = s;
            ShelfMoveModel::setJoints(at, q);
            EXPECT_TRUE(turned->validState(at));
            EXPECT_EQ(turned->graspableCan(at), k);
        }
        EXPECT_GE(found, 1);
        pomdp::Rng rng(3);
        EXPECT_TRUE(turned->graspableLayout(s, rng)) << "graspable_layout judges with the configured yaws";
        // bad values name the key
        for (const nlohmann::json &bad :
             {nlohmann::json::array(), nlohmann::json({100}), nlohmann::json({"x"}), nlohmann::json(15)})
        {
            json["planning"]["grasp_yaws"] = bad;
            try
            {
                makeModel(json);
                ADD_FAILURE() << "no error for grasp_yaws " << bad.dump();
            }
            catch (const Error &e)
            {
                EXPECT_NE(std::string(e.what()).find("grasp_yaws"), std::string::npos) << e.what();
            }
        }
    }
}  // namespace ropras::scenarios
