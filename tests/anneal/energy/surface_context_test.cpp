// SurfaceContext's two caches (a thread's own table of finished samples, then the shared
// ProjectionCache) never change a value: every sample equals the one computed from scratch, on
// one thread, across contexts that reuse the thread's table, after clear_cache(), and on several
// threads at once.
#include <thread>
#include <vector>

#include <gtest/gtest.h>

#include "core/anneal/energy/surface_context.h"
#include "core/geom/inside.h"
#include "tests/anneal/energy/energy_test_support.h"
#include "tests/support/geom_fixtures.h"

namespace zomeify {
namespace {

// The sample as SurfaceContext defines it, without any cache.
SurfaceSample uncached(const SurfaceProjector& projector, const InsideTest& inside, const SurfaceContext& context,
                       const LatticeSum& sum, int divisor)
{
    const Vec3 p = context.to_mesh(sum.divided(divisor));
    const ClosestPoint c = projector.project(p);
    const double scale = context.transform().scale;
    const double inv_scale_squared = 1.0 / (scale * scale); // as the context converts
    return {c.distance_squared * inv_scale_squared, c.normal, inside.is_inside(p, c)};
}

bool same(const SurfaceSample& a, const SurfaceSample& b)
{
    return a.distance_squared == b.distance_squared && a.normal == b.normal && a.inside == b.inside;
}

// Lattice sums on a grid of b0 steps, with divisors 1 to 4 (nodes, midpoints, barycentres).
std::vector<std::pair<LatticeSum, int>> samples(int n)
{
    std::vector<std::pair<LatticeSum, int>> out;
    for (int i = -n; i <= n; ++i)
        for (int j = -n; j <= n; ++j)
            for (int k = -n; k <= n; ++k)
            {
                LatticeSum s;
                s.c = {0, 2 * i, 0, 2 * j, i + j, 2 * k};
                out.push_back({s, 1 + (i + j + k + 3 * n) % 4});
            }
    return out;
}

TEST(SurfaceContextCache, EverySampleEqualsTheUncachedOne)
{
    const test::EnergyScene a =
        test::make_energy_scene(test::make_torus(3.0, 1.2, 48, 24), test::energy_test_transform());
    // The same transform: the points looked up are the same, only the surfaces differ.
    const test::EnergyScene b = test::make_energy_scene(test::make_icosphere(4.0, 3), test::energy_test_transform());
    // More samples than the thread's table has slots, so slots are shared and overwritten.
    const InsideTest inside_a(*a.projector), inside_b(*b.projector);
    const auto all = samples(18);
    ASSERT_GT(all.size(), 40000u);
    for (int round = 0; round < 2; ++round)
    {
        for (size_t i = 0; i < all.size(); i += 7)
        {
            const auto& [sum, divisor] = all[i];
            // Alternating contexts on one thread: each must see its own values, never the other's.
            ASSERT_TRUE(
                same(a.context->sample(sum, divisor), uncached(*a.projector, inside_a, *a.context, sum, divisor)));
            ASSERT_TRUE(
                same(b.context->sample(sum, divisor), uncached(*b.projector, inside_b, *b.context, sum, divisor)));
        }
        a.context->clear_cache();
    }
}

TEST(SurfaceContextCacheParallel, ThreadsSharingAContextGetExactValues)
{
    const test::EnergyScene scene =
        test::make_energy_scene(test::make_torus(3.0, 1.2, 48, 24), test::energy_test_transform());
    const InsideTest inside(*scene.projector);
    const auto all = samples(10);
    std::vector<SurfaceSample> expected;
    for (const auto& [sum, divisor] : all)
        expected.push_back(uncached(*scene.projector, inside, *scene.context, sum, divisor));
    constexpr int kThreads = 4;
    std::vector<int> wrong(kThreads, 0);
    std::vector<std::thread> threads;
    for (int t = 0; t < kThreads; ++t)
        threads.emplace_back([&, t] {
            for (int round = 0; round < 3; ++round)
                for (size_t i = static_cast<size_t>(t); i < all.size(); i += 3)
                    wrong[t] += same(scene.context->sample(all[i].first, all[i].second), expected[i]) ? 0 : 1;
        });
    for (std::thread& th : threads)
        th.join();
    for (int t = 0; t < kThreads; ++t)
        EXPECT_EQ(wrong[t], 0) << "thread " << t;
    EXPECT_GT(scene.context->cache_stats().hits, 0u); // the threads shared their projections
}

} // namespace
} // namespace zomeify
