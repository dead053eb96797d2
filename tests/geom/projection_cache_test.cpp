#include "core/geom/projection_cache.h"

#include <random>
#include <thread>
#include <vector>

#include <gtest/gtest.h>

#include "tests/geom/geom_reference.h"
#include "tests/support/geom_fixtures.h"

namespace zomeify {
namespace {

bool same(const ClosestPoint& a, const ClosestPoint& b)
{
    return a.point == b.point && a.normal == b.normal && a.barycentric == b.barycentric &&
           a.distance_squared == b.distance_squared && a.triangle == b.triangle && a.feature == b.feature;
}

// Lattice-like query points: a grid around the surface, keyed by their integer coordinates.
struct Query
{
    uint64_t key;
    Vec3 point;
};

std::vector<Query> grid_queries(int n, double step)
{
    std::vector<Query> out;
    for (int i = 0; i < n; ++i)
    {
        for (int j = 0; j < n; ++j)
        {
            for (int k = 0; k < n; ++k)
            {
                const uint64_t key = (uint64_t(i) << 42) | (uint64_t(j) << 21) | uint64_t(k);
                out.push_back({key, step * Vec3(i - n / 2, j - n / 2, k - n / 2)});
            }
        }
    }
    return out;
}

TEST(GeomProjectionCache, ReturnsIdenticalResults)
{
    const SurfaceProjector projector(test::make_torus(1.0, 0.3, 48, 24));
    ProjectionCache cache(projector);
    const std::vector<Query> queries = grid_queries(12, 0.25);
    for (int round = 0; round < 3; ++round)
    {
        for (const Query& q : queries)
        {
            ASSERT_TRUE(same(cache.project(q.key, q.point), projector.project(q.point)));
        }
    }
    const ProjectionCacheStats stats = cache.stats();
    EXPECT_EQ(stats.misses, queries.size());
    EXPECT_EQ(stats.hits, 2 * queries.size());
    EXPECT_EQ(stats.size, queries.size());
    EXPECT_TRUE(cache.find(queries[5].key, queries[5].point).has_value());
    cache.clear();
    EXPECT_FALSE(cache.find(queries[5].key, queries[5].point).has_value());
    EXPECT_EQ(cache.stats().size, 0u);
}

TEST(GeomProjectionCache, KeyCollisionNeverGivesAWrongAnswer)
{
    const SurfaceProjector projector(test::make_icosphere(1.0, 2));
    ProjectionCache cache(projector);
    const Vec3 a(2, 0, 0);
    const Vec3 b(0, 0, -3);
    EXPECT_TRUE(same(cache.project(42, a), projector.project(a)));
    EXPECT_TRUE(same(cache.project(42, b), projector.project(b)));
    EXPECT_TRUE(same(cache.project(42, a), projector.project(a)));
    EXPECT_EQ(cache.stats().hits, 0u);
}

TEST(GeomProjectionCache, StaysWithinItsCapacity)
{
    const SurfaceProjector projector(test::make_icosphere(1.0, 2));
    ProjectionCache cache(projector, {64, 4});
    const std::vector<Query> queries = grid_queries(10, 0.3);
    for (const Query& q : queries)
    {
        ASSERT_TRUE(same(cache.project(q.key, q.point), projector.project(q.point)));
        ASSERT_LE(cache.stats().size, 64u);
    }
    EXPECT_GT(cache.stats().rotations, 0u);
    // A point used all the time survives the churn.
    ProjectionCache hot(projector, {64, 1});
    for (size_t i = 0; i < queries.size(); ++i)
    {
        hot.project(queries[i].key, queries[i].point);
        hot.project(queries[0].key, queries[0].point);
    }
    EXPECT_EQ(hot.stats().hits, queries.size());
}

TEST(GeomProjectionCacheParallel, SafeAndExactUnderFourThreads)
{
    const SurfaceProjector projector(test::make_torus(1.0, 0.3, 48, 24));
    const std::vector<Query> queries = grid_queries(14, 0.2);
    std::vector<ClosestPoint> expected;
    for (const Query& q : queries)
    {
        expected.push_back(projector.project(q.point));
    }
    // Small enough that generations rotate while the threads read and insert.
    ProjectionCache cache(projector, {1024, 8});
    constexpr int kThreads = 4;
    constexpr int kPerThread = 6000;
    std::vector<int> mismatches(kThreads, 0);
    std::vector<std::thread> threads;
    for (int t = 0; t < kThreads; ++t)
    {
        threads.emplace_back([&, t] {
            std::mt19937 rng(100 + t);
            // Skewed: most queries hit a small hot set, as annealing does around its current model.
            std::uniform_int_distribution<size_t> hot(0, 300);
            std::uniform_int_distribution<size_t> any(0, queries.size() - 1);
            for (int i = 0; i < kPerThread; ++i)
            {
                const size_t k = i % 4 == 0 ? any(rng) : hot(rng);
                mismatches[t] += same(cache.project(queries[k].key, queries[k].point), expected[k]) ? 0 : 1;
            }
        });
    }
    for (std::thread& th : threads)
    {
        th.join();
    }
    for (int t = 0; t < kThreads; ++t)
    {
        EXPECT_EQ(mismatches[t], 0);
    }
    const ProjectionCacheStats stats = cache.stats();
    EXPECT_EQ(stats.hits + stats.misses, uint64_t{kThreads} * kPerThread);
    EXPECT_GT(stats.hits, stats.misses);
    EXPECT_LE(stats.size, 1024u);
}

} // namespace
} // namespace zomeify
