// Stress (issue 5): 8 threads on fertility (genus 4) for ZOME_STRESS_SECONDS (default 20;
// the ThreadSanitizer lane, where races show, sets 60), then
// the mesh is a valid closed Zome surface of genus 4 and the incremental energy sums equal a
// fresh evaluation bit for bit. Run under ThreadSanitizer by the tsan lane (ctest -L parallel).
#include <cstdlib>
#include <string>

#include <gtest/gtest.h>

#include "core/anneal/engine/annealer.h"
#include "core/mesh/model_convert.h"
#include "core/mesh/validate.h"
#include "tests/anneal/engine/anneal_scene.h"
#include "tests/support/paths.h"

namespace zomeify {
namespace {

double stress_seconds()
{
    const char* s = std::getenv("ZOME_STRESS_SECONDS");
    const double v = s ? std::atof(s) : 20.0;
    return v > 0.0 ? v : 20.0;
}

TEST(AnnealParallel, EightThreadsOnFertilityKeepInvariants)
{
    ZOME_REQUIRE_SHARED();
    const auto scene = test::make_anneal_scene("fertility.obj", 16);
    ASSERT_EQ(scene->surface_genus, 4);
    AnnealOptions o;
    o.threads = 8;
    o.seconds = stress_seconds();
    o.seed = 11;
    Annealer annealer(scene->z0, *scene->context, o);
    const AnnealResult r = annealer.run();
    const ValidationReport report = validate(from_model(r.model));
    EXPECT_TRUE(report.ok()) << report.message();
    EXPECT_EQ(report.genus, 4);
    EXPECT_TRUE(r.stats.energy_consistent);
    EXPECT_EQ(r.stats.threads, 8);
    EXPECT_GT(r.stats.commits, 0U);
    std::printf("stress: %.1f s, %llu proposals, %llu commits, %llu busy seeds, %llu lost races, %llu pauses\n",
                r.stats.wall_seconds, static_cast<unsigned long long>(r.stats.proposals),
                static_cast<unsigned long long>(r.stats.commits), static_cast<unsigned long long>(r.stats.busy_seeds),
                static_cast<unsigned long long>(r.stats.lost_races),
                static_cast<unsigned long long>(r.stats.garbage_collections));
}

} // namespace
} // namespace zomeify
