// The coverage guard: its samples spread over S, its incremental counts equal a recount, it
// refuses exactly the changes that leave a covered sample without a node in reach, and the
// annealer never gives up a covered sample.
#include <algorithm>
#include <cmath>

#include <gtest/gtest.h>

#include "core/anneal/engine/annealer.h"
#include "core/anneal/proposal.h"
#include "core/anneal/rules/coverage_guard.h"
#include "core/mesh/element_ranges.h"
#include "core/mesh/model_convert.h"
#include "tests/anneal/engine/anneal_scene.h"
#include "tests/anneal/operators/operator_test_support.h"
#include "tests/support/paths.h"

namespace zomeify {
namespace {

const test::AnnealScene& bunny8()
{
    static const auto scene = test::make_anneal_scene("bunny.obj", 8);
    return *scene;
}

TEST(CoverageGuard, SamplesCoverTheSurfaceAtTheirSpacing)
{
    ZOME_REQUIRE_SHARED();
    const test::AnnealScene& scene = bunny8();
    const ZomeMesh mesh = from_model(scene.z0);
    const CoverageOptions options{2.5, 0.5};
    const CoverageGuard guard(*scene.context, mesh, options);
    // The bunny is ~8 b1 ≈ 13 b0 long: a few thousand samples, not one per input vertex.
    EXPECT_GT(guard.sample_count(), 500u);
    EXPECT_LT(guard.sample_count(), scene.surface.positions.size());
    // Z0 lies within a voxel of S: every sample has a node in reach at the start.
    EXPECT_EQ(guard.uncovered(), 0u);
    EXPECT_EQ(guard.recount(mesh).size(), guard.sample_count());
    for (size_t i = 0; i < guard.sample_count(); ++i)
        ASSERT_EQ(guard.count(i), guard.recount(mesh)[i]);
}

TEST(CoverageGuard, OffAdmitsEverythingAndHoldsNoSamples)
{
    ZOME_REQUIRE_SHARED();
    const test::AnnealScene& scene = bunny8();
    const ZomeMesh mesh = from_model(scene.z0);
    CoverageGuard guard(*scene.context, mesh, CoverageOptions{0.0, 0.5});
    EXPECT_FALSE(guard.enabled());
    EXPECT_EQ(guard.sample_count(), 0u);
    LocalChange change;
    change.remove_node(*vertices(mesh).begin());
    EXPECT_TRUE(guard.admit(mesh, change));
}

TEST(CoverageGuard, RejectsBadOptions)
{
    ZOME_REQUIRE_SHARED();
    const test::AnnealScene& scene = bunny8();
    const ZomeMesh mesh = from_model(scene.z0);
    EXPECT_THROW(CoverageGuard(*scene.context, mesh, CoverageOptions{-1.0, 0.5}), InvalidInputError);
    EXPECT_THROW(CoverageGuard(*scene.context, mesh, CoverageOptions{NAN, 0.5}), InvalidInputError);
    EXPECT_THROW(CoverageGuard(*scene.context, mesh, CoverageOptions{2.0, 0.0}), InvalidInputError);
}

// Random valid proposals on the bunny's Z0 with a tight radius, so that many removals would
// uncover a sample. Each decision is checked against the definition: apply the change to a copy,
// recount from scratch, and look for a sample covered before and not after.
TEST(CoverageGuard, RefusesExactlyTheChangesThatUncoverASample)
{
    ZOME_REQUIRE_SHARED();
    const test::AnnealScene& scene = bunny8();
    ZomeMesh mesh = from_model(scene.z0);
    CoverageGuard guard(*scene.context, mesh, CoverageOptions{1.0, 0.5});
    const std::vector<uint32_t> at_start = guard.recount(mesh);
    Rng rng(11);
    Proposal p;
    int refused = 0, admitted_with_removals = 0;
    for (int attempt = 0; attempt < 20000 && admitted_with_removals < 300; ++attempt)
    {
        const auto kind = static_cast<OperatorKind>(rng.below(kOperatorKinds));
        if (!test::propose_at(kind, mesh, test::random_node(mesh, rng), rng, p))
            continue;
        const std::vector<uint32_t> before = guard.recount(mesh);
        ZomeMesh after = mesh;
        apply_proposal(after, p);
        const std::vector<uint32_t> recounted = guard.recount(after);
        bool uncovers = false;
        for (size_t i = 0; i < before.size(); ++i)
            uncovers = uncovers || (before[i] > 0 && recounted[i] == 0);
        const bool admitted = guard.admit(mesh, p.change);
        ASSERT_EQ(admitted, !uncovers) << "operator " << static_cast<int>(kind);
        if (!admitted)
        {
            ++refused;
            for (size_t i = 0; i < before.size(); ++i)
                ASSERT_EQ(guard.count(i), before[i]) << "a refusal changed counts";
            continue;
        }
        mesh = std::move(after);
        admitted_with_removals += p.change.removed_nodes().empty() ? 0 : 1;
        for (size_t i = 0; i < recounted.size(); ++i)
            ASSERT_EQ(guard.count(i), recounted[i]);
    }
    EXPECT_GT(refused, 0);
    EXPECT_GE(admitted_with_removals, 300);
    // What was covered at the start is covered still.
    const std::vector<uint32_t> now = guard.recount(mesh);
    for (size_t i = 0; i < now.size(); ++i)
    {
        if (at_start[i] > 0)
        {
            ASSERT_GT(now[i], 0u) << "sample " << i;
        }
    }
}

// The annealer with a tight radius: every sample of S that Z0 covers is covered at the end, and
// the guard did refuse commits (so the check is live); compaction renumbered the nodes meanwhile.
TEST(CoverageGuard, AnnealerNeverUncoversASample)
{
    ZOME_REQUIRE_SHARED();
    const test::AnnealScene& scene = bunny8();
    AnnealOptions o;
    o.threads = 1;
    o.seed = 5;
    o.max_proposals = 200000;
    o.target_nodes = 250; // pressure to remove nodes
    o.coverage = {1.0, 0.5};
    Annealer annealer(scene.z0, *scene.context, o);
    const AnnealResult r = annealer.run();
    EXPECT_GT(r.stats.rejections[static_cast<size_t>(Rejection::Uncovered)], 0u);
    const ZomeMesh start = from_model(scene.z0), end = from_model(r.model);
    const CoverageGuard probe(*scene.context, start, o.coverage);
    const std::vector<uint32_t> before = probe.recount(start), after = probe.recount(end);
    size_t covered = 0;
    for (size_t i = 0; i < before.size(); ++i)
    {
        if (before[i] == 0)
            continue;
        ++covered;
        ASSERT_GT(after[i], 0u) << "sample " << i << " uncovered";
    }
    EXPECT_GT(covered, 0u);
    EXPECT_TRUE(r.stats.energy_consistent);
}

} // namespace
} // namespace zomeify
