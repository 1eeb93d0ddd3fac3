#include "ropras/ompl_ext/scene/PointCloud.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <random>
#include <tuple>

#include "ropras/core/Error.h"

using ropras::ompl_ext::PointCloud;

namespace
{
    /// the same float predicate as the grid query, over every point
    bool bruteIntersects(const std::vector<Eigen::Vector3f> &points, float radius, float x, float y, float z, float r)
    {
        const float reach = r + radius;
        for (const auto &p : points)
        {
            const float dx = p.x() - x, dy = p.y() - y, dz = p.z() - z;
            if (dx * dx + dy * dy + dz * dz <= reach * reach)
                return true;
        }
        return false;
    }

    double bruteDistance(const std::vector<Eigen::Vector3f> &points, float pointRadius, const Eigen::Vector3d &c,
                         double r)
    {
        double best = std::numeric_limits<double>::infinity();
        for (const auto &p : points)
            best = std::min(best, (p.cast<double>() - c).norm());
        return best - r - double(pointRadius);
    }

    std::vector<Eigen::Vector3f> randomCloud(std::mt19937 &rng, std::size_t n, const Eigen::Vector3f &lo,
                                             const Eigen::Vector3f &hi)
    {
        std::vector<Eigen::Vector3f> points(n);
        for (auto &p : points)
            for (int i = 0; i < 3; ++i)
                p[i] = std::uniform_real_distribution<float>(lo[i], hi[i])(rng);
        return points;
    }

    /// grid answers vs brute force for random spheres around (and beyond) the cloud
    void crossCheck(const std::vector<Eigen::Vector3f> &points, float pointRadius, float cellSize, std::mt19937 &rng,
                    int queries, float maxRadius)
    {
        const auto cloud = PointCloud::build(points, pointRadius, cellSize);
        ASSERT_EQ(cloud->size(), points.size());
        Eigen::Vector3f lo = cloud->boundsMin().array() - 0.3f, hi = cloud->boundsMax().array() + 0.3f;
        int hits = 0;
        for (int k = 0; k < queries; ++k)
        {
            Eigen::Vector3f c;
            for (int i = 0; i < 3; ++i)
                c[i] = std::uniform_real_distribution<float>(lo[i], hi[i])(rng);
            const float r = std::uniform_real_distribution<float>(0.0f, maxRadius)(rng);
            const bool expected = bruteIntersects(points, pointRadius, c.x(), c.y(), c.z(), r);
            ASSERT_EQ(cloud->intersectsSphere(c.x(), c.y(), c.z(), r), expected)
                << "query " << k << " centre " << c.transpose() << " radius " << r;
            hits += expected;
            const double d = cloud->signedDistance(c.cast<double>(), double(r));
            ASSERT_NEAR(d, bruteDistance(points, pointRadius, c.cast<double>(), double(r)), 1e-12) << "query " << k;
            if (std::abs(d) > 1e-5)
            {
                ASSERT_EQ(expected, d <= 0.0) << "query " << k << " distance " << d;
            }
        }
        // the queries must exercise both answers
        EXPECT_GT(hits, queries / 20);
        EXPECT_LT(hits, queries - queries / 20);
    }
}  // namespace

TEST(PointCloud, MatchesBruteForceOnRandomClouds)
{
    std::mt19937 rng(1234);
    const auto points = randomCloud(rng, 3000, Eigen::Vector3f(-0.5f, -0.2f, 0.0f), Eigen::Vector3f(0.7f, 0.4f, 0.9f));
    crossCheck(points, 0.005f, 0.0f, rng, 4000, 0.08f);
}

TEST(PointCloud, MatchesBruteForceWithExplicitCellSizes)
{
    std::mt19937 rng(99);
    const auto points = randomCloud(rng, 800, Eigen::Vector3f(0.0f, 0.0f, 0.0f), Eigen::Vector3f(1.0f, 1.0f, 1.0f));
    for (float cell : {0.01f, 0.05f, 0.3f, 5.0f})
        crossCheck(points, 0.0f, cell, rng, 1500, 0.15f);
}

TEST(PointCloud, MatchesBruteForceOnFlatAndClusteredClouds)
{
    std::mt19937 rng(7);
    // a table top: all points at one height (zero extent along z)
    auto flat = randomCloud(rng, 2000, Eigen::Vector3f(-0.6f, -0.4f, 0.75f), Eigen::Vector3f(0.6f, 0.4f, 0.75f));
    crossCheck(flat, 0.01f, 0.0f, rng, 3000, 0.1f);
    // two far-apart clusters plus duplicates
    auto clusters = randomCloud(rng, 500, Eigen::Vector3f(0.0f, 0.0f, 0.0f), Eigen::Vector3f(0.05f, 0.05f, 0.05f));
    auto far = randomCloud(rng, 500, Eigen::Vector3f(3.0f, 3.0f, 3.0f), Eigen::Vector3f(3.05f, 3.05f, 3.05f));
    clusters.insert(clusters.end(), far.begin(), far.end());
    clusters.insert(clusters.end(), far.begin(), far.begin() + 50);
    crossCheck(clusters, 0.002f, 0.0f, rng, 3000, 2.0f);
}

TEST(PointCloud, SinglePointAndEmptyCloud)
{
    const auto one = PointCloud::build({Eigen::Vector3f(1.0f, 2.0f, 3.0f)}, 0.1f);
    EXPECT_TRUE(one->intersectsSphere(1.0f, 2.0f, 3.25f, 0.2f));
    EXPECT_FALSE(one->intersectsSphere(1.0f, 2.0f, 3.35f, 0.2f));
    EXPECT_NEAR(one->signedDistance(Eigen::Vector3d(1.0, 2.0, 4.0), 0.5), 0.4, 1e-6);
    EXPECT_NEAR(one->signedDistance(Eigen::Vector3d(1.0, 2.0, 3.0), 0.5), -0.6, 1e-6);

    const auto empty = PointCloud::build({}, 0.1f);
    EXPECT_EQ(empty->size(), 0u);
    EXPECT_FALSE(empty->intersectsSphere(0.0f, 0.0f, 0.0f, 100.0f));
    EXPECT_EQ(empty->signedDistance(Eigen::Vector3d::Zero(), 1.0), std::numeric_limits<double>::infinity());
}

TEST(PointCloud, SortedByCellKeepsEveryPoint)
{
    std::mt19937 rng(3);
    const auto points = randomCloud(rng, 1000, Eigen::Vector3f(-1, -1, -1), Eigen::Vector3f(1, 1, 1));
    const auto cloud = PointCloud::build(points, 0.0f);
    auto key = [](const Eigen::Vector3f &p) { return std::make_tuple(p.x(), p.y(), p.z()); };
    std::vector<std::tuple<float, float, float>> a, b;
    for (const auto &p : points)
        a.push_back(key(p));
    for (const auto &p : cloud->points())
        b.push_back(key(p));
    std::sort(a.begin(), a.end());
    std::sort(b.begin(), b.end());
    EXPECT_EQ(a, b);
    Eigen::Vector3f lo = points[0], hi = points[0];
    for (const auto &p : points)
    {
        lo = lo.cwiseMin(p);
        hi = hi.cwiseMax(p);
    }
    EXPECT_EQ(cloud->boundsMin(), lo);
    EXPECT_EQ(cloud->boundsMax(), hi);
}

TEST(PointCloud, RejectsBadInput)
{
    const float nan = std::numeric_limits<float>::quiet_NaN();
    const float inf = std::numeric_limits<float>::infinity();
    try
    {
        PointCloud::build({Eigen::Vector3f(0, 0, 0), Eigen::Vector3f(1, nan, 0)}, 0.1f);
        FAIL() << "a NaN point was accepted";
    }
    catch (const ropras::Error &e)
    {
        EXPECT_NE(std::string(e.what()).find("point 1"), std::string::npos) << e.what();
    }
    EXPECT_THROW(PointCloud::build({Eigen::Vector3f(inf, 0, 0)}, 0.1f), ropras::Error);
    EXPECT_THROW(PointCloud::build({Eigen::Vector3f(0, 0, 0)}, -0.1f), ropras::Error);
    EXPECT_THROW(PointCloud::build({Eigen::Vector3f(0, 0, 0)}, nan), ropras::Error);
    EXPECT_THROW(PointCloud::build({Eigen::Vector3f(0, 0, 0)}, 0.1f, nan), ropras::Error);
    // a cell size that would need an absurd grid
    EXPECT_THROW(PointCloud::build({Eigen::Vector3f(0, 0, 0), Eigen::Vector3f(10, 10, 10)}, 0.0f, 1e-4f),
                 ropras::Error);

    // non-finite queries: contact (the conservative answer), and signedDistance refuses
    const auto cloud = PointCloud::build({Eigen::Vector3f(0, 0, 0)}, 0.1f);
    EXPECT_TRUE(cloud->intersectsSphere(nan, 0.0f, 0.0f, 0.1f));
    EXPECT_TRUE(cloud->intersectsSphere(0.0f, 0.0f, 0.0f, nan));
    EXPECT_THROW(cloud->signedDistance(Eigen::Vector3d(0, std::nan(""), 0), 0.1), ropras::Error);
    // negative reach never touches
    EXPECT_FALSE(cloud->intersectsSphere(0.0f, 0.0f, 0.0f, -1.0f));
}
