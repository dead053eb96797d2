// The kits named before a run and the limits that make them hold (core/pipeline/kit_estimate.h,
// core/anneal/engine/part_tally.h): a run given limits never raises a part count over its limit
// (counts that start over it only come down), with one thread and with two, and the estimate is
// the same every time it is made.
#include "core/pipeline/kit_estimate.h"

#include <gtest/gtest.h>

#include "core/anneal/energy/surface_context.h"
#include "core/anneal/engine/annealer.h"
#include "core/geom/inside.h"
#include "core/parts/kit_fit.h"
#include "core/pipeline/pipeline.h"
#include "tests/support/torus_surface.h"

using namespace zomeify;

namespace {

using Torus = test::TorusSurface;

PartCounts counts_of(const ZomeModel& m) { return part_counts(parts_list(m)); }

// Every count within its limit, or (over it from the start) no higher than at the start.
void expect_within(const PartCounts& end, const PartCounts& start, const PartLimits& limits)
{
    for (size_t k = 0; k < end.size(); ++k)
    {
        const size_t limit = k < kStrutKindCount ? limits.struts[k] : limits.balls;
        EXPECT_LE(end[k], std::max(limit, start[k])) << "part kind " << k;
    }
}

} // namespace

TEST(PartLimits, ARunNeverRaisesACountOverItsLimit)
{
    const Torus t;
    const InitialModel z0 = t.z0(8);
    const PartCounts start = counts_of(z0.model);
    ASSERT_GT(start[static_cast<size_t>(StrutKind::B1)], 60u);
    // Tight limits: fewer B1 than Z0 has (it must come down and never go back up), few of the rest.
    PartLimits limits;
    limits.struts.fill(25);
    limits.struts[static_cast<size_t>(StrutKind::B1)] = static_cast<uint32_t>(start[1] * 3 / 4);
    limits.balls = static_cast<uint32_t>(start[kStrutKindCount] + 20);
    for (const int threads : {1, 2})
    {
        const SurfaceContext context(t.projector, z0.model.transform);
        AnnealOptions o;
        o.threads = threads;
        o.max_proposals = 150000;
        o.target_nodes = start[kStrutKindCount] * 3 / 2; // wants more balls than the limits give
        o.part_limits = limits;
        Annealer annealer(z0.model, context, o);
        const AnnealResult r = annealer.run();
        const PartCounts end = counts_of(r.model);
        expect_within(end, start, limits);
        EXPECT_LT(end[1], start[1]) << "B1, over its limit, came down";
        EXPECT_GT(r.stats.rejections[static_cast<size_t>(Rejection::OverKits)], 0u) << "the limits were tested";
    }
}

TEST(KitEstimate, TheRunKeepsWithinTheKitsNamedBeforeIt)
{
    const Torus t;
    PipelineOptions o;
    o.resolution = 8;
    o.keep_to_kit_estimate = true;
    o.fidelity_samples = 2000;
    o.anneal.threads = 1;
    o.anneal.max_proposals = 400000;
    o.anneal.target_nodes = 220;
    const PipelineResult r = run_pipeline(t.mesh, 1, o);
    ASSERT_TRUE(r.kit_estimate.has_value());
    ASSERT_TRUE(r.model_valid) << r.validation;
    EXPECT_EQ(r.model_genus, 1);
    const KitEstimate& named = *r.kit_estimate;
    ASSERT_FALSE(named.plan.kits.empty());
    // The named kits hold what the quick pass used, and the finished model (Z0's own B1 excepted,
    // which only comes down).
    EXPECT_TRUE(fits(part_counts(named.quick), kit_contents(named.plan.kits)));
    expect_within(counts_of(r.model), counts_of(r.initial.model), named.limits);
    EXPECT_TRUE(fits(counts_of(r.model), kit_contents(named.plan.kits)));
    // The same estimate again (one thread, seed 1): the page's and the run's kits agree.
    const KitEstimate again = estimate_kits(SurfaceProjector(t.mesh), r.initial, 220);
    EXPECT_EQ(kits_text(again.plan.kits), kits_text(named.plan.kits));
    EXPECT_EQ(part_counts(again.quick), part_counts(named.quick));
}
