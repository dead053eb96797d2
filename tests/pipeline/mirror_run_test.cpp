// `run --mirror auto` (run_pipeline with MirrorMode::Auto, mirror_choice.h, issue 41): a symmetric
// shape gives a model that maps onto itself exactly (every ball and strut has its mirror image),
// closed, of the shape's genus, with no clash and no fold-over, on one thread and on two; a
// lopsided shape is reported as such and built as without the mirror; a symmetric model continued
// (--from) stays symmetric, any other is continued as it is.
#include <algorithm>
#include <cmath>

#include <gtest/gtest.h>

#include "core/anneal/engine/change_region.h"
#include "core/base/errors.h"
#include "core/parts/mirror_halves.h"
#include "core/parts/parts_list.h"
#include "core/pipeline/pipeline.h"
#include "tests/support/geom_fixtures.h"

using namespace zomeify;

namespace {

// Under a sanitizer (10x slower) a shorter run still makes thousands of symmetric changes.
#ifdef ZOME_SANITIZED
constexpr uint64_t kProposals = 50000;
#else
constexpr uint64_t kProposals = 150000;
#endif

PipelineOptions mirrored(int threads, uint64_t proposals)
{
    PipelineOptions o;
    o.resolution = 9;
    o.mirror = MirrorMode::Auto;
    o.fidelity_samples = 2000;
    o.anneal.threads = threads;
    o.anneal.max_proposals = proposals;
    return o;
}

//! `min_commits`: a run from Z0 commits about one proposal in 50; a continued run, cooler, far fewer.
void expect_symmetric_model(const PipelineResult& r, long long genus, uint64_t min_commits = kProposals / 100)
{
    ASSERT_TRUE(r.mirror.has_value());
    EXPECT_TRUE(r.mirror->symmetric) << r.mirror->message;
    ASSERT_TRUE(r.mirror->used.has_value()) << r.mirror->message;
    const MirrorMismatch m = mirror_mismatch(r.model, *r.mirror->used);
    EXPECT_EQ(m.balls, 0U);
    EXPECT_EQ(m.struts, 0U);
    EXPECT_TRUE(r.mirror_mismatch.symmetric());
    EXPECT_TRUE(r.model_valid) << r.validation;
    EXPECT_EQ(r.model_genus, genus);
    EXPECT_EQ(r.clearance.total(), 0U);
    EXPECT_EQ(r.fold_overs.count(), 0U);
    EXPECT_GT(r.anneal->stats.commits, min_commits); // it changed the model
    // Its parts by half: two halves and the middle make the whole, kind by kind.
    const std::optional<MirrorHalves> halves = mirror_halves(r.model);
    ASSERT_TRUE(halves.has_value());
    const PartCounts whole = part_counts(parts_list(r.model));
    for (size_t k = 0; k < whole.size(); ++k)
        EXPECT_EQ(2 * halves->half[k] + halves->middle[k], whole[k]) << k;
    EXPECT_GT(halves->middle[kStrutKindCount], 0U); // a torus across the plane has balls on it
    // The plane in mesh units is the shape's.
    const AxisPlane plane = mesh_plane(*r.mirror->used, r.model.transform);
    EXPECT_EQ(plane.axis, r.mirror->along->axis);
    EXPECT_NEAR(plane.at, r.mirror->along->at, 1e-9 * (1.0 + std::abs(plane.at)));
}

TEST(MirrorRun, ASymmetricShapeGivesAnExactlySymmetricModel)
{
    const TriangleMesh torus = test::make_torus(3.0, 1.2, 48, 24);
    expect_symmetric_model(run_pipeline(torus, 1, mirrored(1, kProposals)), 1);
}

TEST(MirrorRun, TwoThreadsKeepTheModelSymmetric)
{
    const TriangleMesh torus = test::make_torus(3.0, 1.2, 48, 24);
    expect_symmetric_model(run_pipeline(torus, 1, mirrored(2, kProposals)), 1);
}

TEST(MirrorRun, ALopsidedShapeIsReportedAndBuiltAsWithoutTheMirror)
{
    // A torus bent up on one side and stretched on another: no plane is a mirror plane of it.
    TriangleMesh lopsided = test::make_torus(3.0, 1.2, 48, 24);
    for (Vec3& p : lopsided.positions)
    {
        p.z() += 0.3 * std::max(p.x(), 0.0);
        p.y() *= p.y() > 0.0 ? 2.0 : 1.0;
    }
    PipelineOptions o = mirrored(1, 0);
    o.initial_only = true;
    const PipelineResult with = run_pipeline(lopsided, 1, o);
    ASSERT_TRUE(with.mirror.has_value());
    EXPECT_FALSE(with.mirror->symmetric) << with.mirror->message;
    EXPECT_FALSE(with.mirror->used.has_value());
    EXPECT_NE(with.mirror->message.find("Not made mirror-symmetric"), std::string::npos) << with.mirror->message;
    o.mirror = MirrorMode::Off;
    const PipelineResult without = run_pipeline(lopsided, 1, o);
    EXPECT_EQ(with.model, without.model);
    EXPECT_FALSE(mirror_halves(with.model).has_value()); // no halves for a model that is not symmetric
}

// A symmetric model worked on with --mirror auto (Improve, Fewer balls, More detail, Fix here) stays
// exactly symmetric; a fix changes nothing outside its spot and the spot's image.
TEST(MirrorRun, AContinuedSymmetricModelStaysSymmetric)
{
    const TriangleMesh torus = test::make_torus(3.0, 1.2, 48, 24);
    const ZomeModel start = run_pipeline(torus, 1, mirrored(1, kProposals / 3)).model;
    ASSERT_TRUE(model_mirror(start)->mismatch.symmetric());
    for (const double factor : {0.8, 1.25})
    {
        PipelineOptions again = mirrored(1, kProposals / 3);
        again.from = start;
        again.anneal.target_nodes = static_cast<size_t>(factor * static_cast<double>(start.nodes.size()));
        const PipelineResult r = run_pipeline(torus, 1, again);
        ASSERT_TRUE(r.mirror.has_value());
        EXPECT_TRUE(r.mirror->used.has_value()) << r.mirror->message;
        EXPECT_NE(r.mirror->message.find("Continued mirror-symmetric"), std::string::npos) << r.mirror->message;
        expect_symmetric_model(r, 1, 10);
        EXPECT_FALSE(r.kept_start) << "factor " << factor; // the count moved: a new model
    }
    // Fix a spot on one side of the plane: its image is fixed alike, the rest stays.
    PipelineOptions fix = mirrored(1, kProposals / 3);
    fix.from = start;
    const LatticeMirror plane = model_mirror(start)->mirror;
    ZVec aside = start.nodes[0];
    for (const ZVec& p : start.nodes)
        if (std::abs(p.coord(plane.axis) - plane.coordinate()) > std::abs(aside.coord(plane.axis) - plane.coordinate()))
            aside = p;
    const ModelTransform& t = start.transform;
    const Vec3 spot(aside.coord(0) * t.scale + t.translation[0], aside.coord(1) * t.scale + t.translation[1],
                    aside.coord(2) * t.scale + t.translation[2]);
    fix.fix = FixSpot{spot, 1.0};
    const PipelineResult fixed = run_pipeline(torus, 1, fix);
    ASSERT_TRUE(fixed.mirror && fixed.mirror->used) << (fixed.mirror ? fixed.mirror->message : "no mirror");
    expect_symmetric_model(fixed, 1, 1);
    ChangeRegion region = *fixed.region;
    region.mirror = plane;
    for (const ZVec& p : start.nodes) // every ball outside the spot and its image is where it was
    {
        if (!in_region(region, p))
        {
            EXPECT_NE(std::find(fixed.model.nodes.begin(), fixed.model.nodes.end(), p), fixed.model.nodes.end());
        }
    }
}

TEST(MirrorRun, AContinuedModelThatIsNotSymmetricIsContinuedAsItIs)
{
    const TriangleMesh torus = test::make_torus(3.0, 1.2, 48, 24);
    PipelineOptions off = mirrored(1, kProposals / 3);
    off.mirror = MirrorMode::Off;
    const ZomeModel start = run_pipeline(torus, 1, off).model;
    ASSERT_FALSE(model_mirror(start)->mismatch.symmetric());
    PipelineOptions with = mirrored(1, 20000);
    with.from = start;
    PipelineOptions without = with;
    without.mirror = MirrorMode::Off;
    const PipelineResult a = run_pipeline(torus, 1, with), b = run_pipeline(torus, 1, without);
    ASSERT_TRUE(a.mirror.has_value());
    EXPECT_FALSE(a.mirror->used.has_value());
    EXPECT_NE(a.mirror->message.find("Continued as it is"), std::string::npos) << a.mirror->message;
    EXPECT_EQ(a.model, b.model);
}

} // namespace

namespace {

TEST(MirrorChoice, AFlatShapeIsBuiltOnAPlaneAcrossItNotOnItsMiddle)
{
    // The torus around z lies flat: z = 0 holds its whole rim; x = 0 and y = 0 cut two cross-sections.
    const SurfaceProjector torus(test::make_torus(3.0, 1.2, 48, 24));
    const MirrorChoice c = choose_mirror(torus, 0.5);
    ASSERT_TRUE(c.symmetric) << c.message;
    ASSERT_TRUE(c.along.has_value());
    EXPECT_NE(c.along->axis, 2) << c.message;
    EXPECT_NEAR(c.along->at, 0.0, 1e-3);
}

} // namespace
