// CollisionChecker: SIMD FK against the double-precision reference FK, verdicts of both backends (single, batch,
// motion) against an independent brute-force check (reference centres + Environment::signedDistance + self
// pairs), the lastValid contract, bad input, and concurrent use.
#include <gtest/gtest.h>

#include <algorithm>
#include <atomic>
#include <cmath>
#include <filesystem>
#include <limits>
#include <random>
#include <string>
#include <thread>
#include <vector>

#include "ropras/core/Error.h"
#include "ropras/ompl_ext/collision/CollisionChecker.h"
#include "ropras/ompl_ext/model/RobotModel.h"
#include "ropras/ompl_ext/scene/PointCloud.h"
#include "ropras/ompl_ext/scene/SceneYaml.h"

using namespace ropras::ompl_ext;

namespace
{
    const std::string SHARED = ROPRAS_SHARED_DIR;

#define REQUIRE_SHARED()                                                                             \
    if (!std::filesystem::exists(SHARED + "/robots"))                                                \
    {                                                                                                \
        GTEST_SKIP() << "../shared not found: " << SHARED << " (these tests need robots/ and mbm/)"; \
    }

    std::shared_ptr<const RobotModel> loadRobot(const std::string &name)
    {
        return RobotModel::fromUrdfFile(SHARED + "/robots/" + name + "/" + name + "_spherized.urdf",
                                        SHARED + "/robots/" + name + "/" + name + ".srdf");
    }

    std::vector<double> randomConfig(const RobotModel &robot, std::mt19937_64 &rng)
    {
        std::vector<double> q(robot.dof());
        for (std::size_t j = 0; j < robot.dof(); ++j)
            q[j] = std::uniform_real_distribution<double>(robot.joints()[j].lower, robot.joints()[j].upper)(rng);
        return q;
    }

    /// independent brute force: min over every sphere of its signed distance to the environment and over
    /// every self-collision sphere pair of their signed distance (reference FK, double precision)
    double referenceMargin(const RobotModel &robot, const Environment &env, const double *q)
    {
        const std::vector<Eigen::Vector3d> c = robot.sphereCentersReference(q);
        const auto &spheres = robot.spheres();
        double margin = std::numeric_limits<double>::infinity();
        for (std::size_t s = 0; s < spheres.size(); ++s)
            margin = std::min(margin, env.signedDistance(c[s], spheres[s].radius));
        const auto &links = robot.collisionLinks();
        for (const auto &pair : robot.selfCollisionPairs())
        {
            const CollisionLink &a = links[static_cast<std::size_t>(pair.first)];
            const CollisionLink &b = links[static_cast<std::size_t>(pair.second)];
            for (int i = a.firstSphere; i < a.firstSphere + a.sphereCount; ++i)
                for (int j = b.firstSphere; j < b.firstSphere + b.sphereCount; ++j)
                {
                    const auto si = static_cast<std::size_t>(i), sj = static_cast<std::size_t>(j);
                    margin = std::min(margin, (c[si] - c[sj]).norm() - spheres[si].radius - spheres[sj].radius);
                }
        }
        return margin;
    }

    Eigen::Isometry3d pose(const Eigen::Vector3d &t, const Eigen::Quaterniond &q = Eigen::Quaterniond::Identity())
    {
        Eigen::Isometry3d p = Eigen::Isometry3d::Identity();
        p.linear() = q.normalized().toRotationMatrix();
        p.translation() = t;
        return p;
    }

    /// random obstacles of every kind in the arm's reach
    Environment clutter(std::uint64_t seed)
    {
        std::mt19937_64 rng(seed);
        std::uniform_real_distribution<double> u(-1.0, 1.0);
        std::normal_distribution<double> n(0.0, 1.0);
        const auto where = [&] { return Eigen::Vector3d(0.8 * u(rng), 0.8 * u(rng), 0.5 + 0.5 * u(rng)); };
        const auto turn = [&] { return Eigen::Quaterniond(n(rng), n(rng), n(rng), n(rng)).normalized(); };
        Environment env;
        for (int i = 0; i < 3; ++i)
            env.addBox("box" + std::to_string(i), pose(where(), turn()),
                       {0.05 + 0.2 * std::abs(u(rng)), 0.05 + 0.2 * std::abs(u(rng)), 0.05 + 0.2 * std::abs(u(rng))});
        for (int i = 0; i < 2; ++i)
            env.addCylinder("cylinder" + std::to_string(i), pose(where(), turn()), 0.03 + 0.1 * std::abs(u(rng)),
                            0.1 + 0.3 * std::abs(u(rng)));
        for (int i = 0; i < 2; ++i)
            env.addSphere("sphere" + std::to_string(i), where(), 0.03 + 0.1 * std::abs(u(rng)));
        env.addCapsule("capsule", pose(where(), turn()), 0.05, 0.3);
        std::vector<Eigen::Vector3f> points;
        const Eigen::Vector3d c = where();
        for (int i = 0; i < 200; ++i)
            points.emplace_back((c + 0.15 * Eigen::Vector3d(u(rng), u(rng), u(rng))).cast<float>());
        env.addPointCloud("cloud", PointCloud::build(points, 0.01f));
        env.addBox("floor", pose({0, 0, -0.1}), {2.0, 2.0, 0.1});  // top at z = -0.05, below panda_link0
        return env;
    }

    std::vector<SimdBackend> backends()
    {
        std::vector<SimdBackend> b{SimdBackend::Scalar};
        if (simdBackendAvailable(SimdBackend::Avx2))
            b.push_back(SimdBackend::Avx2);
        return b;
    }

    void checkCenters(const std::string &robotName, std::uint64_t seed)
    {
        const auto robot = loadRobot(robotName);
        const std::size_t dof = robot->dof(), ns = robot->spheres().size();
        for (SimdBackend backend : backends())
        {
            CollisionChecker checker(robot, backend);
            const int w = checker.width();
            std::mt19937_64 rng(seed);
            std::vector<float> single(4 * ns), batch(4 * ns * static_cast<std::size_t>(w));
            std::vector<double> qs(dof * static_cast<std::size_t>(w));
            double worstSingle = 0.0, worstBatch = 0.0;
            const int configs = 10000;
            for (int k = 0; k < configs; k += w)
            {
                for (int i = 0; i < w; ++i)
                {
                    const auto q = randomConfig(*robot, rng);
                    std::copy(q.begin(), q.end(), qs.begin() + static_cast<std::ptrdiff_t>(i * dof));
                }
                checker.sphereCentersBatch(qs.data(), batch.data());
                for (int i = 0; i < w; ++i)
                {
                    const double *q = qs.data() + i * dof;
                    const auto ref = robot->sphereCentersReference(q);
                    checker.sphereCenters(q, single.data());
                    for (std::size_t s = 0; s < ns; ++s)
                    {
                        const Eigen::Vector3d a(single[4 * s], single[4 * s + 1], single[4 * s + 2]);
                        worstSingle = std::max(worstSingle, (a - ref[s]).norm());
                        const Eigen::Vector3d b(batch[(4 * s) * w + i], batch[(4 * s + 1) * w + i],
                                                batch[(4 * s + 2) * w + i]);
                        worstBatch = std::max(worstBatch, (b - ref[s]).norm());
                        ASSERT_FLOAT_EQ(single[4 * s + 3], static_cast<float>(robot->spheres()[s].radius));
                        ASSERT_FLOAT_EQ(batch[(4 * s + 3) * w + i], static_cast<float>(robot->spheres()[s].radius));
                    }
                }
            }
            EXPECT_LT(worstSingle, 1e-5) << robotName << " " << simdBackendName(backend);
            EXPECT_LT(worstBatch, 1e-5) << robotName << " " << simdBackendName(backend);
            EXPECT_GT(worstSingle, 0.0);  // the comparison really ran on float results
        }
    }

    struct VerdictStats
    {
        int valid{0}, invalid{0}, nearContact{0};
    };

    /// every backend's single and batch verdicts == brute force (except near contact)
    VerdictStats checkVerdicts(const std::shared_ptr<const RobotModel> &robot, const Environment &env, int configs,
                               std::uint64_t seed)
    {
        VerdictStats stats;
        std::mt19937_64 rng(seed);
        const std::size_t dof = robot->dof();
        std::vector<double> qs;
        std::vector<double> margins;
        for (int k = 0; k < configs; ++k)
        {
            const auto q = randomConfig(*robot, rng);
            qs.insert(qs.end(), q.begin(), q.end());
            margins.push_back(referenceMargin(*robot, env, q.data()));
        }
        std::vector<std::unique_ptr<CollisionChecker>> checkers;
        for (SimdBackend b : backends())
            checkers.push_back(std::make_unique<CollisionChecker>(robot, b));
        std::vector<std::vector<char>> batchVerdicts;
        for (const auto &checker : checkers)
        {
            std::unique_ptr<bool[]> v(new bool[static_cast<std::size_t>(configs)]);
            const std::size_t nValid =
                checker->isValidBatch(env, qs.data(), static_cast<std::size_t>(configs), v.get());
            batchVerdicts.emplace_back(v.get(), v.get() + configs);
            EXPECT_EQ(nValid, static_cast<std::size_t>(std::count(v.get(), v.get() + configs, true)));
        }
        for (int k = 0; k < configs; ++k)
        {
            const double *q = qs.data() + static_cast<std::size_t>(k) * dof;
            const double margin = margins[static_cast<std::size_t>(k)];
            std::vector<bool> verdicts;
            for (std::size_t c = 0; c < checkers.size(); ++c)
            {
                verdicts.push_back(checkers[c]->isValid(env, q));
                verdicts.push_back(batchVerdicts[c][static_cast<std::size_t>(k)] != 0);
            }
            // backends agree with each other even near contact? not required (float rounding); with the truth:
            if (std::abs(margin) < 1e-4)
            {
                ++stats.nearContact;
                continue;
            }
            const bool truth = margin > 0.0;
            (truth ? stats.valid : stats.invalid) += 1;
            for (std::size_t v = 0; v < verdicts.size(); ++v)
                EXPECT_EQ(verdicts[v], truth) << "config " << k << " verdict " << v << " margin " << margin;
        }
        return stats;
    }
}  // namespace

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

namespace
{
    struct MotionStats
    {
        int valid{0}, invalid{0}, skipped{0};
    };

    /// motions q0 -> q1 vs dense sampling of the reference at the same samples (k / n, k = 1..n)
    MotionStats checkMotions(const std::shared_ptr<const RobotModel> &robot, const Environment &env, int motions,
                             double maxDelta, double resolution, std::uint64_t seed)
    {
        MotionStats stats;
        std::mt19937_64 rng(seed);
        std::uniform_real_distribution<double> u(-maxDelta, maxDelta);
        const std::size_t dof = robot->dof();
        std::vector<std::unique_ptr<CollisionChecker>> checkers;
        for (SimdBackend b : backends())
            checkers.push_back(std::make_unique<CollisionChecker>(robot, b));
        for (int attempt = 0; attempt < 100 * motions && stats.valid + stats.invalid + stats.skipped < motions;
             ++attempt)
        {
            const auto q0 = randomConfig(*robot, rng);
            if (referenceMargin(*robot, env, q0.data()) < 1e-4)
                continue;  // the start must be valid
            std::vector<double> q1(dof);
            for (std::size_t j = 0; j < dof; ++j)
                q1[j] = std::clamp(q0[j] + u(rng), robot->joints()[j].lower, robot->joints()[j].upper);
            double step = 0.0;
            for (std::size_t j = 0; j < dof; ++j)
                step = std::max(step, std::abs(q1[j] - q0[j]));
            const long n = std::max(1L, static_cast<long>(std::ceil(step / resolution)));
            long firstBad = -1;
            bool near = false;
            std::vector<double> q(dof);
            for (long k = 1; k <= n; ++k)
            {
                const double t = static_cast<double>(k) / static_cast<double>(n);
                for (std::size_t j = 0; j < dof; ++j)
                    q[j] = q0[j] + t * (q1[j] - q0[j]);
                const double m = referenceMargin(*robot, env, q.data());
                if (std::abs(m) < 1e-4)
                    near = true;
                if (m <= 0.0 && firstBad < 0)
                    firstBad = k;
                if (near)
                    break;
            }
            if (near)
            {
                ++stats.skipped;
                continue;
            }
            const bool truth = firstBad < 0;
            (truth ? stats.valid : stats.invalid) += 1;
            const double expectedLast = truth ? 1.0 : static_cast<double>(firstBad - 1) / static_cast<double>(n);
            for (const auto &checker : checkers)
            {
                double last = -1.0;
                EXPECT_EQ(checker->isMotionValid(env, q0.data(), q1.data(), resolution, &last), truth)
                    << simdBackendName(checker->backend());
                if (!truth)
                {
                    EXPECT_NEAR(last, expectedLast, 1e-12)
                        << simdBackendName(checker->backend()) << " n " << n << " first invalid sample " << firstBad;
                }
                EXPECT_EQ(checker->isMotionValid(env, q0.data(), q1.data(), resolution), truth);
            }
        }
        return stats;
    }
}  // namespace

TEST(CollisionCheckerTest, PandaMotionsMatchDenseReferenceSampling)
{
    REQUIRE_SHARED();
    const auto robot = loadRobot("panda");
    const MotionStats s = checkMotions(robot, clutter(600), 250, 0.8, 1.0 / 32.0, 601);
    EXPECT_GT(s.valid, 30);
    EXPECT_GT(s.invalid, 30);
    EXPECT_LT(s.skipped, 25);
    // a coarse resolution (fewer samples than lanes) and a fine one
    const MotionStats coarse = checkMotions(robot, clutter(602), 100, 0.8, 0.2, 603);
    EXPECT_GT(coarse.invalid, 5);
    const MotionStats fine = checkMotions(robot, clutter(604), 40, 0.5, 0.005, 605);
    EXPECT_GT(fine.invalid + fine.valid, 20);
}

TEST(CollisionCheckerTest, Ur5MotionsMatchDenseReferenceSampling)
{
    REQUIRE_SHARED();
    const auto robot = loadRobot("ur5");
    const MotionStats s = checkMotions(robot, clutter(610), 150, 0.8, 1.0 / 32.0, 611);
    EXPECT_GT(s.valid, 10);
    EXPECT_GT(s.invalid, 10);
}

TEST(CollisionCheckerTest, LastValidFractionContract)
{
    REQUIRE_SHARED();
    const auto robot = loadRobot("panda");
    // joint 1 sweeps the arm through a wall: the first invalid sample decides lastValid exactly
    std::vector<double> q0{-1.2, 0.3, 0.0, -1.5, 0.0, 1.8, 0.8}, q1{1.2, 0.3, 0.0, -1.5, 0.0, 1.8, 0.8};
    Environment env;
    env.addBox("wall", pose({0.5, 0.0, 0.5}), {0.3, 0.05, 1.0});
    const double res = 1.0 / 32.0;
    const long n = static_cast<long>(std::ceil(2.4 / res));
    long firstBad = -1;
    for (long k = 1; k <= n && firstBad < 0; ++k)
    {
        std::vector<double> q(q0);
        q[0] = q0[0] + (q1[0] - q0[0]) * static_cast<double>(k) / static_cast<double>(n);
        if (referenceMargin(*robot, env, q.data()) <= 0.0)
            firstBad = k;
    }
    ASSERT_GT(firstBad, 1);
    ASSERT_LT(firstBad, n);
    for (SimdBackend b : backends())
    {
        CollisionChecker checker(robot, b);
        double last = -1.0;
        EXPECT_FALSE(checker.isMotionValid(env, q0.data(), q1.data(), res, &last));
        EXPECT_DOUBLE_EQ(last, static_cast<double>(firstBad - 1) / static_cast<double>(n));
        // every sample up to lastValid is valid, the next one is not
        std::vector<double> q(q0);
        q[0] = q0[0] + (q1[0] - q0[0]) * last;
        EXPECT_TRUE(checker.isValid(env, q.data()));
        q[0] = q0[0] + (q1[0] - q0[0]) * (last + 1.0 / static_cast<double>(n));
        EXPECT_FALSE(checker.isValid(env, q.data()));
        // the reverse motion stops on the other side of the wall
        double lastBack = -1.0;
        EXPECT_FALSE(checker.isMotionValid(env, q1.data(), q0.data(), res, &lastBack));
        EXPECT_GT(lastBack, 0.0);
        EXPECT_LT(lastBack + last, 1.0);
        // an invalid start: assumed valid unless checkStart
        std::vector<double> inWall(q0);
        inWall[0] = q0[0] + (q1[0] - q0[0]) * static_cast<double>(firstBad) / static_cast<double>(n);
        double lastFromWall = -1.0;
        EXPECT_FALSE(checker.isMotionValid(env, inWall.data(), q0.data(), res, &lastFromWall, true));
        EXPECT_EQ(lastFromWall, 0.0);
        // a zero-length motion checks q1 only
        EXPECT_TRUE(checker.isMotionValid(env, q0.data(), q0.data(), res));
        EXPECT_FALSE(checker.isMotionValid(env, inWall.data(), inWall.data(), res, &lastFromWall));
        EXPECT_EQ(lastFromWall, 0.0);
    }
}

TEST(CollisionCheckerTest, EverySampleOfAMotionIsChecked)
{
    // one joint swings a 3 mm tip sphere on a circle of radius 0.5 m; a 3 mm obstacle on the circle touches the tip
    // at exactly one sample of a motion at 1/32 rad (its neighbours are 2 * 0.5 * sin(1/64) = 15.6 mm away): for
    // every motion length of 1-70 samples and every sample, the motion is invalid and lastValid stops just before it
    const std::string urdf =
        "<robot name=\"swing\"><link name=\"base\"/><link name=\"arm\"><collision><origin xyz=\"0.5 0 0\"/>"
        "<geometry><sphere radius=\"0.003\"/></geometry></collision></link>"
        "<joint name=\"j\" type=\"revolute\"><parent link=\"base\"/><child link=\"arm\"/><axis xyz=\"0 0 1\"/>"
        "<limit lower=\"-3\" upper=\"3\" effort=\"1\" velocity=\"1\"/></joint></robot>";
    const auto robot = RobotModel::fromUrdfString(urdf, ".", "swing.urdf");
    const double res = 1.0 / 32.0, q0 = -1.0;
    std::size_t motions = 0;
    for (SimdBackend b : backends())
    {
        const CollisionChecker checker(robot, b);
        for (long n = 1; n <= 70; ++n)
        {
            const double q1 = q0 + static_cast<double>(n) * res;  // exactly n steps
            for (long k = 1; k <= n; ++k)
            {
                const double at = q0 + (q1 - q0) * static_cast<double>(k) / static_cast<double>(n);
                Environment env;
                env.addSphere("dot", {0.5 * std::cos(at), 0.5 * std::sin(at), 0.0}, 0.003);
                double last = -1.0;
                ASSERT_FALSE(checker.isMotionValid(env, &q0, &q1, res, &last))
                    << simdBackendName(b) << ": " << n << " samples, the one in contact: " << k;
                ASSERT_DOUBLE_EQ(last, static_cast<double>(k - 1) / static_cast<double>(n))
                    << simdBackendName(b) << ": " << n << " samples, the one in contact: " << k;
                ++motions;
            }
            // the obstacle halfway between two samples is missed at this resolution (the contract: samples only)
            Environment between;
            const double mid = q0 + res * 0.5;
            between.addSphere("dot", {0.5 * std::cos(mid), 0.5 * std::sin(mid), 0.0}, 0.003);
            EXPECT_TRUE(checker.isMotionValid(between, &q0, &q1, res)) << n;
        }
    }
    EXPECT_EQ(motions, backends().size() * (70u * 71u / 2u));
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

namespace
{
    /// a small arm with every joint type, skew axes and non-trivial origins (no ../shared needed)
    const char *const ALL_JOINTS_URDF = R"(<?xml version="1.0"?>
<robot name="all_joints">
  <link name="base"><collision><geometry><sphere radius="0.05"/></geometry></collision></link>
  <link name="a"><collision><origin xyz="0.1 0 0.05"/><geometry><sphere radius="0.04"/></geometry></collision>
                 <collision><origin xyz="0.2 0.01 0.05"/><geometry><sphere radius="0.03"/></geometry></collision></link>
  <link name="b"><collision><origin xyz="0 0.1 0"/><geometry><sphere radius="0.03"/></geometry></collision></link>
  <link name="c"><collision><origin xyz="0.05 0 0.02"/><geometry><sphere radius="0.02"/></geometry></collision>
                 <collision><origin xyz="0.1 0 0.02"/><geometry><sphere radius="0.02"/></geometry></collision></link>
  <link name="d"><collision><origin xyz="0 0 0.08"/><geometry><sphere radius="0.025"/></geometry></collision></link>
  <joint name="j_rev" type="revolute"><parent link="base"/><child link="a"/>
    <origin xyz="0 0 0.1" rpy="0.3 -0.2 0.1"/><axis xyz="0.2 0.3 0.9"/><limit lower="-2.5" upper="2.5" effort="1" velocity="1"/></joint>
  <joint name="j_pri" type="prismatic"><parent link="a"/><child link="b"/>
    <origin xyz="0.3 0 0" rpy="0 1.5707963267948966 0"/><axis xyz="1 -1 0.5"/><limit lower="-0.2" upper="0.4" effort="1" velocity="1"/></joint>
  <joint name="j_cont" type="continuous"><parent link="b"/><child link="c"/>
    <origin xyz="0 0.2 0" rpy="-0.4 0 0.7"/><axis xyz="0 1 0"/></joint>
  <joint name="j_fix" type="fixed"><parent link="c"/><child link="d"/><origin xyz="0.15 0 0" rpy="0 0 0.5"/></joint>
</robot>)";

    /// largest distance of the batch and single sphere centres of 8 rows \a qs from the reference FK
    double worstCentreError(const RobotModel &robot, const CollisionChecker &checker, const std::vector<double> &qs)
    {
        const std::size_t ns = robot.spheres().size(), dof = robot.dof();
        std::vector<float> single(4 * ns), batch(4 * ns * 8);
        checker.sphereCentersBatch(qs.data(), batch.data());
        double worst = 0.0;
        for (std::size_t i = 0; i < 8; ++i)
        {
            const auto ref = robot.sphereCentersReference(qs.data() + dof * i);
            checker.sphereCenters(qs.data() + dof * i, single.data());
            for (std::size_t s = 0; s < ns; ++s)
            {
                const Eigen::Vector3d fromSingle(single[4 * s], single[4 * s + 1], single[4 * s + 2]);
                const Eigen::Vector3d fromBatch(batch[(4 * s) * 8 + i], batch[(4 * s + 1) * 8 + i],
                                                batch[(4 * s + 2) * 8 + i]);
                worst = std::max({worst, (fromSingle - ref[s]).norm(), (fromBatch - ref[s]).norm()});
            }
        }
        return worst;
    }
}  // namespace

TEST(CollisionCheckerTest, EveryJointTypeMatchesReferenceFk)
{
    const auto robot = RobotModel::fromUrdfString(ALL_JOINTS_URDF, ".", "all_joints.urdf");
    ASSERT_EQ(robot->dof(), 3u);
    std::mt19937_64 rng(900);
    std::uniform_real_distribution<double> u(0.0, 1.0);
    for (SimdBackend backend : backends())
    {
        CollisionChecker checker(robot, backend);
        std::vector<double> qs(3 * 8);
        double worst = 0.0;
        for (int k = 0; k < 2000; ++k)
        {
            for (int i = 0; i < 8; ++i)
            {
                qs[3 * i] = -2.5 + 5.0 * u(rng);
                qs[3 * i + 1] = -0.2 + 0.6 * u(rng);
                // continuous: any finite value, also far from zero (range reduction in double)
                qs[3 * i + 2] = (k % 4 == 0 ? 1000.0 : 10.0) * (2.0 * u(rng) - 1.0);
            }
            worst = std::max(worst, worstCentreError(*robot, checker, qs));
        }
        EXPECT_LT(worst, 1e-5) << simdBackendName(backend);
        // the continuous joint accepts any finite value; the prismatic one is bounded
        std::vector<double> q{0.1, 0.1, 1e4};
        EXPECT_TRUE(checker.isValid(Environment(), q.data()));
        q[1] = 0.41;
        EXPECT_FALSE(checker.isValid(Environment(), q.data()));
    }
}

namespace
{
    /** \brief Two arms on one base (a tree, not a chain): the second arm's first frame does not follow its parent
        in the frame order, so both FK paths must reload the parent's frame. The arms reach each other
        (self-collision pairs across the branches). */
    const char *const TWO_ARMS_URDF = R"(<?xml version="1.0"?>
<robot name="two_arms">
  <link name="base"><collision><geometry><sphere radius="0.06"/></geometry></collision></link>
  <link name="l1"><collision><origin xyz="0 0 0.1"/><geometry><sphere radius="0.04"/></geometry></collision>
                  <collision><origin xyz="0 0 0.2"/><geometry><sphere radius="0.04"/></geometry></collision></link>
  <link name="l2"><collision><origin xyz="0.1 0 0"/><geometry><sphere radius="0.035"/></geometry></collision>
                  <collision><origin xyz="0.2 0 0"/><geometry><sphere radius="0.03"/></geometry></collision></link>
  <link name="l3"><collision><origin xyz="0.08 0.02 0"/><geometry><sphere radius="0.03"/></geometry></collision></link>
  <link name="r1"><collision><origin xyz="0 0 0.1"/><geometry><sphere radius="0.04"/></geometry></collision>
                  <collision><origin xyz="0 0 0.2"/><geometry><sphere radius="0.04"/></geometry></collision></link>
  <link name="r2"><collision><origin xyz="-0.1 0 0"/><geometry><sphere radius="0.035"/></geometry></collision>
                  <collision><origin xyz="-0.2 0 0"/><geometry><sphere radius="0.03"/></geometry></collision></link>
  <link name="r3"><collision><origin xyz="0 0 0.05"/><geometry><sphere radius="0.03"/></geometry></collision></link>
  <joint name="left_1" type="revolute"><parent link="base"/><child link="l1"/>
    <origin xyz="0 0.15 0.05" rpy="0 0 0"/><axis xyz="0 0 1"/><limit lower="-3" upper="3" effort="1" velocity="1"/></joint>
  <joint name="left_2" type="revolute"><parent link="l1"/><child link="l2"/>
    <origin xyz="0 0 0.25" rpy="1.5707963267948966 0 0"/><axis xyz="0 0 1"/><limit lower="-2" upper="2" effort="1" velocity="1"/></joint>
  <joint name="left_3" type="revolute"><parent link="l2"/><child link="l3"/>
    <origin xyz="0.25 0 0" rpy="0.2 -0.3 0.4"/><axis xyz="0.3 0.8 0.1"/><limit lower="-2.5" upper="2.5" effort="1" velocity="1"/></joint>
  <joint name="right_1" type="revolute"><parent link="base"/><child link="r1"/>
    <origin xyz="0 -0.15 0.05" rpy="0 0 3.141592653589793"/><axis xyz="0 0 1"/><limit lower="-3" upper="3" effort="1" velocity="1"/></joint>
  <joint name="right_2" type="revolute"><parent link="r1"/><child link="r2"/>
    <origin xyz="0 0 0.25" rpy="-1.5707963267948966 0 0"/><axis xyz="0 0 1"/><limit lower="-2" upper="2" effort="1" velocity="1"/></joint>
  <joint name="right_3" type="prismatic"><parent link="r2"/><child link="r3"/>
    <origin xyz="-0.25 0 0" rpy="0 0.5 0"/><axis xyz="0 1 0"/><limit lower="-0.1" upper="0.15" effort="1" velocity="1"/></joint>
</robot>)";
}  // namespace

TEST(CollisionCheckerTest, BranchingRobotMatchesReferenceFkAndBruteForce)
{
    const auto robot = RobotModel::fromUrdfString(TWO_ARMS_URDF, ".", "two_arms.urdf");
    ASSERT_EQ(robot->dof(), 6u);
    // sphere centres of both paths against the reference FK, over the whole joint range
    std::mt19937_64 rng(950);
    for (SimdBackend backend : backends())
    {
        CollisionChecker checker(robot, backend);
        std::vector<double> qs;
        double worst = 0.0;
        for (int k = 0; k < 500; ++k)
        {
            qs.clear();
            for (int i = 0; i < 8; ++i)
            {
                const auto q = randomConfig(*robot, rng);
                qs.insert(qs.end(), q.begin(), q.end());
            }
            worst = std::max(worst, worstCentreError(*robot, checker, qs));
        }
        EXPECT_LT(worst, 1e-5) << simdBackendName(backend);
    }
    // verdicts of every path against the brute force: the arms against each other, then with obstacles
    const VerdictStats self = checkVerdicts(robot, Environment(), 3000, 951);
    EXPECT_GT(self.invalid, 100) << "random configurations must include arm-against-arm contacts";
    EXPECT_GT(self.valid, 1000);
    EXPECT_LT(self.nearContact, 15);
    Environment env;
    env.addSphere("ball", {0.25, 0.0, 0.35}, 0.08);
    env.addBox("plate", pose({0.0, 0.0, 0.55}), {0.4, 0.3, 0.02});
    const VerdictStats world = checkVerdicts(robot, env, 3000, 952);
    EXPECT_GT(world.invalid, self.invalid);
    EXPECT_GT(world.valid, 500);
    EXPECT_LT(world.nearContact, 15);
}

namespace
{
    /** \brief Rows of a batch in every form the batch loader distinguishes: in range, exactly at a limit (valid),
        one ulp past it, NaN, infinite, and continuous angles far from zero (reduced in double). Every verdict of
        isValidBatch must equal isValid on the same row, for both backends and any row count. */
    void checkBatchRows(const std::shared_ptr<const RobotModel> &robot, const Environment &env, std::uint64_t seed)
    {
        const std::size_t dof = robot->dof();
        const double nan = std::numeric_limits<double>::quiet_NaN();
        const double inf = std::numeric_limits<double>::infinity();
        std::mt19937_64 rng(seed);
        std::uniform_real_distribution<double> u(0.0, 1.0);
        std::vector<double> qs;
        const std::size_t count = 8 * 300 + 5;  // full batches, then a tail
        for (std::size_t k = 0; k < count; ++k)
        {
            std::vector<double> q(dof);
            for (std::size_t j = 0; j < dof; ++j)
            {
                const PlanningJoint &joint = robot->joints()[j];
                const bool continuous = joint.type == JointType::Continuous;
                const double lo = continuous ? -3.0 : joint.lower, hi = continuous ? 3.0 : joint.upper;
                q[j] = lo + (hi - lo) * u(rng);
                // one row in four of the batches gets a special value in one joint
                if (k % 4 != 1 || j != (k / 4) % dof)
                    continue;
                switch ((k / 4 / dof) % 6)
                {
                    case 0:
                        q[j] = continuous ? 200.0 * (u(rng) - 0.5) : lo;  // at the limit: valid
                        break;
                    case 1:
                        q[j] = continuous ? 1e4 * (u(rng) - 0.5) : hi;
                        break;
                    case 2:
                        q[j] = continuous ? 1e6 : std::nextafter(hi, inf);  // one ulp past the limit
                        break;
                    case 3:
                        q[j] = continuous ? -1e6 : std::nextafter(lo, -inf);
                        break;
                    case 4:
                        q[j] = nan;
                        break;
                    default:
                        q[j] = (k % 8 < 4) ? inf : -inf;
                        break;
                }
            }
            qs.insert(qs.end(), q.begin(), q.end());
        }
        for (SimdBackend b : backends())
        {
            const CollisionChecker checker(robot, b);
            for (const std::size_t n : {count, std::size_t{8}, std::size_t{13}})
            {
                std::unique_ptr<bool[]> v(new bool[n]);
                const std::size_t nValid = checker.isValidBatch(env, qs.data(), n, v.get());
                std::size_t valid = 0, invalid = 0;
                for (std::size_t k = 0; k < n; ++k)
                {
                    const bool single = checker.isValid(env, qs.data() + k * dof);
                    EXPECT_EQ(v[k], single) << robot->name() << " " << simdBackendName(b) << " row " << k;
                    (single ? valid : invalid) += 1;
                }
                EXPECT_EQ(nValid, valid);
                if (n == count)
                {
                    EXPECT_GT(valid, count / 20) << robot->name();
                    EXPECT_GT(invalid, count / 20) << robot->name();
                }
            }
            // allValid over windows of every length 0..20 at many offsets: true exactly when every row of the
            // window is valid by isValid (windows with and without bad rows, short and full blocks)
            std::vector<char> single(count);
            for (std::size_t k = 0; k < count; ++k)
                single[k] = checker.isValid(env, qs.data() + k * dof) ? 1 : 0;
            std::size_t allTrue = 0, allFalse = 0;
            for (std::size_t start = 0; start + 20 <= count; start += 7)
                for (std::size_t len = 0; len <= 20; ++len)
                {
                    const bool expected = std::all_of(single.begin() + static_cast<std::ptrdiff_t>(start),
                                                      single.begin() + static_cast<std::ptrdiff_t>(start + len),
                                                      [](char c) { return c != 0; });
                    ASSERT_EQ(checker.allValid(env, qs.data() + start * dof, len), expected)
                        << robot->name() << " " << simdBackendName(b) << " rows " << start << " + " << len;
                    (expected ? allTrue : allFalse) += 1;
                }
            EXPECT_GT(allTrue, 300u) << robot->name();  // enough windows of each answer
            EXPECT_GT(allFalse, 300u) << robot->name();
        }
    }
}  // namespace

TEST(CollisionCheckerTest, BatchRowsMatchSingleChecksAtLimitsAndBadValues)
{
    // three joints (the AVX2 loader's short-row path), a continuous one among them
    const auto small = RobotModel::fromUrdfString(ALL_JOINTS_URDF, ".", "all_joints.urdf");
    Environment env;
    env.addSphere("ball", {0.25, 0.2, 0.25}, 0.12);
    checkBatchRows(small, env, 1001);
    if (!std::filesystem::exists(SHARED + "/robots"))
        GTEST_SKIP() << "../shared not found: " << SHARED << " (the Panda part is skipped)";
    checkBatchRows(loadRobot("panda"), clutter(1002), 1003);
    // more obstacles than a call keeps boxes for on the stack: the boxes are computed per batch instead
    Environment crowded = clutter(1004);
    std::mt19937_64 rng(1005);
    std::uniform_real_distribution<double> u(-0.8, 0.8);
    for (int k = 0; k < 80; ++k)
        crowded.addSphere("ball" + std::to_string(k), {u(rng), u(rng), 0.4 + 0.5 * u(rng)}, 0.03);
    checkBatchRows(loadRobot("panda"), crowded, 1006);
}
