// CollisionChecker: SIMD FK against the double-precision reference FK, verdicts of both backends (single, batch,
// motion) against an independent brute-force check (reference centres + Environment::signedDistance + self
// pairs), the lastValid contract, bad input, and concurrent use.
#include <gtest/gtest.h>

#include <atomic>
#include <filesystem>
#include <thread>

#include "CollisionCheckerTestUtil.h"
#include "ropras/core/Error.h"

using namespace ropras::test;

TEST(CollisionCheckerTest, BackendsAreReported)
{
    EXPECT_TRUE(simdBackendAvailable(SimdBackend::Scalar));
    EXPECT_TRUE(simdBackendAvailable(SimdBackend::Best));
    EXPECT_STREQ(simdBackendName(SimdBackend::Scalar), "scalar");
    EXPECT_STREQ(simdBackendName(SimdBackend::Avx2), "avx2");
    EXPECT_THROW(CollisionChecker(nullptr), ropras::Error);
}

TEST(CollisionCheckerTest, PandaSphereCentersMatchReferenceFk)
{
    REQUIRE_SHARED();
    checkCenters("panda", 101);
}

TEST(CollisionCheckerTest, Ur5SphereCentersMatchReferenceFk)
{
    REQUIRE_SHARED();
    checkCenters("ur5", 102);
}

TEST(CollisionCheckerTest, BestBackendIsTheWidestCompiled)
{
    REQUIRE_SHARED();
    CollisionChecker checker(loadRobot("panda"));
    EXPECT_EQ(checker.backend(), simdBackendAvailable(SimdBackend::Avx2) ? SimdBackend::Avx2 : SimdBackend::Scalar);
    EXPECT_EQ(checker.width(), 8);
    if (!simdBackendAvailable(SimdBackend::Avx2))
        EXPECT_THROW(CollisionChecker(loadRobot("panda"), SimdBackend::Avx2), ropras::Error);
    else
        EXPECT_EQ(CollisionChecker(loadRobot("panda"), SimdBackend::Avx2).backend(), SimdBackend::Avx2);
    EXPECT_EQ(CollisionChecker(loadRobot("panda"), SimdBackend::Scalar).backend(), SimdBackend::Scalar);
}

TEST(CollisionCheckerTest, PandaVerdictsMatchBruteForceInClutter)
{
    REQUIRE_SHARED();
    const auto robot = loadRobot("panda");
    int valid = 0, invalid = 0, near = 0;
    for (std::uint64_t scene = 0; scene < 4; ++scene)
    {
        const VerdictStats s = checkVerdicts(robot, clutter(200 + scene), 1500, 300 + scene);
        valid += s.valid;
        invalid += s.invalid;
        near += s.nearContact;
    }
    EXPECT_GT(valid, 600);
    EXPECT_GT(invalid, 600);
    EXPECT_LT(near, 30) << "configurations within 1e-4 m of contact";
    std::cout << "panda clutter: " << valid << " valid, " << invalid << " invalid, " << near << " near contact\n";
}

TEST(CollisionCheckerTest, Ur5VerdictsMatchBruteForceInClutter)
{
    REQUIRE_SHARED();
    const auto robot = loadRobot("ur5");
    const VerdictStats s = checkVerdicts(robot, clutter(211), 3000, 311);
    EXPECT_GT(s.valid, 300);
    EXPECT_GT(s.invalid, 300);
    EXPECT_LT(s.nearContact, 15);
}

TEST(CollisionCheckerTest, SelfCollisionInEmptyWorldMatchesBruteForce)
{
    REQUIRE_SHARED();
    for (const char *name : {"panda", "ur5"})
    {
        const auto robot = loadRobot(name);
        const VerdictStats s = checkVerdicts(robot, Environment(), 3000, 400);
        EXPECT_GT(s.invalid, 30) << name << ": random configurations must include self-collisions";
        EXPECT_GT(s.valid, 1000) << name;
        EXPECT_LT(s.nearContact, 15) << name;
    }
}

TEST(CollisionCheckerTest, PandaVerdictsMatchBruteForceInMbmScenes)
{
    REQUIRE_SHARED();
    const auto robot = loadRobot("panda");
    int valid = 0, invalid = 0, near = 0;
    for (const char *category : {"bookshelf_small", "cage", "table_under_pick"})
    {
        const Environment env = loadPlanningScene(SHARED + "/mbm/panda/" + category + "/scene0001.yaml");
        const VerdictStats s = checkVerdicts(robot, env, 1000, 500);
        valid += s.valid;
        invalid += s.invalid;
        near += s.nearContact;
    }
    EXPECT_GT(valid, 300);
    EXPECT_GT(invalid, 300);
    EXPECT_LT(near, 15);
}

TEST(CollisionCheckerTest, ObstacleHitsAreTheEnvironmentPartOfTheVerdicts)
{
    // obstacleHitsBatch against a brute force over the obstacles only (reference centres + signedDistance, no self
    // pairs): a hit is an obstacle contact; a configuration that only self-collides is invalid but not a hit. Rows
    // out of their limits or not finite are hits. 1001 rows: full blocks and a last block of one row.
    REQUIRE_SHARED();
    const auto robot = loadRobot("panda");
    const Environment env = loadPlanningScene(SHARED + "/mbm/panda/cage/scene0001.yaml");
    const std::size_t dof = robot->dof(), count = 1001;
    std::mt19937_64 rng(720);
    std::vector<double> qs;
    std::vector<double> obstacleMargin, fullMargin;
    for (std::size_t k = 0; k < count; ++k)
    {
        auto q = randomConfig(*robot, rng);
        if (k % 97 == 3)
            q[k % dof] = k % 2 == 0 ? std::numeric_limits<double>::quiet_NaN() : robot->joints()[k % dof].upper + 1e-6;
        qs.insert(qs.end(), q.begin(), q.end());
        obstacleMargin.push_back(referenceObstacleMargin(*robot, env, robot->sphereCentersReference(q.data())));
        fullMargin.push_back(referenceMargin(*robot, env, q.data()));
    }
    for (SimdBackend b : backends())
    {
        CollisionChecker checker(robot, b);
        std::unique_ptr<bool[]> hit(new bool[count]), valid(new bool[count]);
        const std::size_t nHit = checker.obstacleHitsBatch(env, qs.data(), count, hit.get());
        checker.isValidBatch(env, qs.data(), count, valid.get());
        EXPECT_EQ(nHit, static_cast<std::size_t>(std::count(hit.get(), hit.get() + count, true)));
        int hits = 0, misses = 0, selfOnly = 0;
        for (std::size_t k = 0; k < count; ++k)
        {
            if (hit[k])
            {
                EXPECT_FALSE(valid[k]) << "a hit is invalid, row " << k;
            }
            if (k % 97 == 3)
            {
                EXPECT_TRUE(hit[k]) << "bad row " << k;
                continue;
            }
            if (std::abs(obstacleMargin[k]) < 1e-4 || std::abs(fullMargin[k]) < 1e-4)
                continue;
            EXPECT_EQ(hit[k], obstacleMargin[k] < 0.0) << "row " << k << " obstacle margin " << obstacleMargin[k];
            (hit[k] ? hits : misses) += 1;
            if (obstacleMargin[k] > 0.0 && fullMargin[k] < 0.0)
            {
                ++selfOnly;
                EXPECT_FALSE(valid[k]) << "row " << k << " self-collides";
                // the single-row path too (a block of one)
                bool one = true;
                EXPECT_EQ(checker.obstacleHitsBatch(env, qs.data() + k * dof, 1, &one), 0u);
                EXPECT_FALSE(one);
            }
        }
        std::cout << "cage scene0001, " << simdBackendName(b) << ": " << hits << " hits, " << misses << " misses, "
                  << selfOnly << " only self-colliding\n";
        EXPECT_GT(hits, 100);
        EXPECT_GT(misses, 100);
        EXPECT_GT(selfOnly, 20) << "random configurations must include some that only self-collide";
    }
}

TEST(CollisionCheckerTest, NanAndOutOfLimitConfigurationsAreInvalid)
{
    REQUIRE_SHARED();
    const auto robot = loadRobot("panda");
    const double nan = std::numeric_limits<double>::quiet_NaN();
    const double inf = std::numeric_limits<double>::infinity();
    const Environment env = clutter(700);
    std::mt19937_64 rng(701);
    for (SimdBackend b : backends())
    {
        CollisionChecker checker(robot, b);
        std::vector<double> good{0.0, -0.5, 0.0, -2.0, 0.0, 1.5, 0.7};
        ASSERT_TRUE(checker.isValid(Environment(), good.data()));
        for (std::size_t j = 0; j < robot->dof(); ++j)
        {
            for (double bad : {nan, inf, -inf, robot->joints()[j].upper + 1e-9, robot->joints()[j].lower - 1e-9})
            {
                std::vector<double> q(good);
                q[j] = bad;
                EXPECT_FALSE(checker.isValid(Environment(), q.data())) << "joint " << j << " value " << bad;
                double last = -1.0;
                EXPECT_FALSE(checker.isMotionValid(Environment(), good.data(), q.data(), 1.0 / 32, &last));
                EXPECT_EQ(last, 0.0);
                EXPECT_FALSE(checker.isMotionValid(Environment(), q.data(), good.data(), 1.0 / 32));
            }
        }
        // bad resolutions
        EXPECT_FALSE(checker.isMotionValid(Environment(), good.data(), good.data(), 0.0));
        EXPECT_FALSE(checker.isMotionValid(Environment(), good.data(), good.data(), -1.0));
        EXPECT_FALSE(checker.isMotionValid(Environment(), good.data(), good.data(), nan));
        // a batch mixing bad rows with random ones: bad rows invalid, the others as isValid says
        const std::size_t count = 37;
        std::vector<double> qs;
        for (std::size_t k = 0; k < count; ++k)
        {
            auto q = randomConfig(*robot, rng);
            if (k % 5 == 0)
                q[k % 7] = (k % 2 == 0) ? nan : 1e6;
            qs.insert(qs.end(), q.begin(), q.end());
        }
        std::unique_ptr<bool[]> v(new bool[count]);
        checker.isValidBatch(env, qs.data(), count, v.get());
        for (std::size_t k = 0; k < count; ++k)
        {
            if (k % 5 == 0)
                EXPECT_FALSE(v[k]);
            else
                EXPECT_EQ(v[k], checker.isValid(env, qs.data() + k * robot->dof())) << k;
        }
        // FK of NaN does not crash and produces no finite garbage claim of validity
        std::vector<float> out(4 * robot->spheres().size());
        std::vector<double> q(good);
        q[3] = nan;
        checker.sphereCenters(q.data(), out.data());
    }
}

TEST(CollisionCheckerTest, ConcurrentChecksGiveTheSameVerdicts)
{
    REQUIRE_SHARED();
    const auto robot = loadRobot("panda");
    const Environment env = clutter(800);
    const CollisionChecker checker(robot);
    std::mt19937_64 rng(801);
    const std::size_t count = 800, dof = robot->dof();
    std::vector<double> qs;
    for (std::size_t k = 0; k < count; ++k)
    {
        const auto q = randomConfig(*robot, rng);
        qs.insert(qs.end(), q.begin(), q.end());
    }
    std::vector<char> serial(count), serialMotion(count - 1);
    std::vector<double> serialLast(count - 1);
    for (std::size_t k = 0; k < count; ++k)
        serial[k] = checker.isValid(env, qs.data() + k * dof);
    for (std::size_t k = 0; k + 1 < count; ++k)
        serialMotion[k] =
            checker.isMotionValid(env, qs.data() + k * dof, qs.data() + (k + 1) * dof, 0.05, &serialLast[k]);
    std::atomic<int> mismatches{0};
    std::vector<std::thread> threads;
    for (int t = 0; t < 4; ++t)
        threads.emplace_back(
            [&, t]
            {
                for (int rep = 0; rep < 2; ++rep)
                {
                    std::unique_ptr<bool[]> v(new bool[count]);
                    checker.isValidBatch(env, qs.data(), count, v.get());
                    for (std::size_t k = 0; k < count; ++k)
                    {
                        const std::size_t i = (k + static_cast<std::size_t>(t) * 97) % count;
                        if (checker.isValid(env, qs.data() + i * dof) != static_cast<bool>(serial[i]) ||
                            v[i] != static_cast<bool>(serial[i]))
                            ++mismatches;
                        if (i + 1 < count)
                        {
                            double last = -1.0;
                            const bool ok =
                                checker.isMotionValid(env, qs.data() + i * dof, qs.data() + (i + 1) * dof, 0.05, &last);
                            if (ok != static_cast<bool>(serialMotion[i]) || (!ok && last != serialLast[i]))
                                ++mismatches;
                        }
                    }
                }
            });
    for (auto &th : threads)
        th.join();
    EXPECT_EQ(mismatches.load(), 0);
    EXPECT_GT(std::count(serial.begin(), serial.end(), 1), 50);
    EXPECT_GT(std::count(serial.begin(), serial.end(), 0), 50);
}

TEST(CollisionCheckerTest, EnvironmentChangesAreSeen)
{
    REQUIRE_SHARED();
    const auto robot = loadRobot("panda");
    CollisionChecker checker(robot);
    std::vector<double> q{0.0, -0.5, 0.0, -2.0, 0.0, 1.5, 0.7};
    const auto centres = robot->sphereCentersReference(q.data());
    Environment env;
    const int id = env.addSphere("ball", {3, 3, 3}, 0.05);
    EXPECT_TRUE(checker.isValid(env, q.data()));
    // move the ball onto each sphere of the hand in turn: a per-object move the kernels must see
    const Environment before = env;
    env.setObjectPose(id, pose(centres.back()));
    EXPECT_FALSE(checker.isValid(env, q.data()));
    EXPECT_TRUE(checker.isValid(before, q.data()));
}
