// Working on a model (core/pipeline/continue_from.h, run_pipeline with `from`): a fix changes
// nothing far from its spot (every node farther than the radius keeps its exact position, and the
// struts between such nodes stay), fewer balls keep the genus, a continued run never ends with a
// higher energy than it started with, and a model made for another mesh, or for this one at
// another scale, is refused in one line.
#include "core/pipeline/continue_from.h"

#include <cmath>
#include <numbers>
#include <set>

#include <gtest/gtest.h>

#include "core/base/errors.h"
#include "core/pipeline/pipeline.h"
#include "core/zome/slots.h"
#include "tests/support/geom_fixtures.h"

using namespace zomeify;

namespace {

const TriangleMesh& torus()
{
    static const TriangleMesh mesh = test::make_torus(3.0, 1.2, 48, 24);
    return mesh;
}

// A default-like model of the torus to work on (cached: several tests continue it).
const ZomeModel& annealed_torus()
{
    static const ZomeModel model = [] {
        PipelineOptions o;
        o.resolution = 9;
        o.fidelity_samples = 2000;
        o.anneal.threads = 1;
        o.anneal.max_proposals = 300000;
        return run_pipeline(torus(), 1, o).model;
    }();
    return model;
}

PipelineOptions continuing(uint64_t proposals)
{
    PipelineOptions o;
    o.from = annealed_torus();
    o.fidelity_samples = 2000;
    o.anneal.threads = 1;
    o.anneal.max_proposals = proposals;
    return o;
}

Vec3 placed(const ZVec& p, const ModelTransform& t)
{
    const auto c = p.to_double();
    return Vec3(c[0], c[1], c[2]) * t.scale + Vec3(t.translation[0], t.translation[1], t.translation[2]);
}

} // namespace

TEST(ContinueFrom, AFixChangesNothingFarFromTheSpot)
{
    const ZomeModel& before = annealed_torus();
    PipelineOptions o = continuing(150000);
    const Vec3 spot = placed(before.nodes[before.nodes.size() / 3], before.transform);
    const double radius = 2.5 * before.transform.scale * kind_info(StrutKind::B1).length;
    o.fix = FixSpot{spot, radius};
    const PipelineResult r = run_pipeline(torus(), 1, o);
    ASSERT_TRUE(r.model_valid) << r.validation;
    EXPECT_EQ(r.model_genus, 1);
    ASSERT_TRUE(r.region.has_value());
    const std::set<ZVec> after_nodes(r.model.nodes.begin(), r.model.nodes.end());
    std::set<std::pair<ZVec, ZVec>> after_struts;
    for (const auto& s : r.model.struts)
        after_struts.insert(std::minmax(r.model.nodes[s[0]], r.model.nodes[s[1]]));
    size_t far = 0;
    for (const ZVec& n : before.nodes)
        if ((placed(n, before.transform) - spot).norm() > radius)
        {
            ++far;
            EXPECT_TRUE(after_nodes.count(n)) << "a node outside the spot moved or went";
        }
    EXPECT_GT(far, before.nodes.size() / 2);
    for (const auto& s : before.struts)
    {
        const ZVec& a = before.nodes[s[0]];
        const ZVec& b = before.nodes[s[1]];
        if ((placed(a, before.transform) - spot).norm() > radius &&
            (placed(b, before.transform) - spot).norm() > radius)
        {
            EXPECT_TRUE(after_struts.count(std::minmax(a, b))) << "a strut between nodes outside the spot went";
        }
    }
    EXPECT_LE(r.spot_gap_after, r.spot_gap_before);
}

TEST(ContinueFrom, FewerBallsKeepTheGenusAndNeverEndAboveTheStart)
{
    PipelineOptions o = continuing(200000);
    const size_t n = annealed_torus().nodes.size();
    o.anneal.target_nodes = n * 3 / 4;
    const PipelineResult fewer = run_pipeline(torus(), 1, o);
    ASSERT_TRUE(fewer.continued);
    EXPECT_TRUE(fewer.model_valid) << fewer.validation;
    EXPECT_EQ(fewer.model_genus, 1);
    EXPECT_LT(fewer.model.nodes.size(), n);
    EXPECT_NEAR(fewer.initial.report.grid.cell, kind_info(StrutKind::B1).length * annealed_torus().transform.scale,
                1e-12); // the stats' b1 is the model's own
    // Improve, with a budget too small to find anything: the model comes back as it was at worst.
    PipelineOptions improve = continuing(2000);
    const PipelineResult same = run_pipeline(torus(), 1, improve);
    EXPECT_LE(same.model_energy.total, same.anneal->start.total + 1e-9);
}

TEST(ContinueFrom, AModelOfAnotherMeshOrScaleIsRefused)
{
    const ZomeModel& model = annealed_torus();
    const auto refused = [&](const TriangleMesh& mesh, const std::string& words) {
        PipelineOptions o = continuing(1000);
        try
        {
            run_pipeline(mesh, 0, o);
            ADD_FAILURE() << "accepted";
        }
        catch (const InvalidInputError& e)
        {
            EXPECT_NE(std::string(e.what()).find(words), std::string::npos) << e.what();
            EXPECT_EQ(std::string(e.what()).find('\n'), std::string::npos);
        }
    };
    refused(test::make_icosphere(1.0, 3), "not made for this mesh");
    TriangleMesh bigger = torus();
    for (Vec3& p : bigger.positions)
        p *= 3.0;
    refused(bigger, "times the mesh's size");
    ZomeModel lost = model;
    lost.transform.scale = 0.0;
    EXPECT_NE(model_fit_problem(lost, SurfaceProjector(torus())).find("no placement"), std::string::npos);
    EXPECT_EQ(model_fit_problem(model, SurfaceProjector(torus())), "");
}

// More detail at a fixed size (issue 40): the surface's capacity is its area in b0² over the
// calibrated area per ball, and a continued run asking for more is capped at it, or refused when
// the model has it already.
TEST(SurfaceCapacity, OfASphereIsItsAreaInB0SquaredOverTheAreaPerBall)
{
    const TriangleMesh sphere = test::make_icosphere(2.0, 4);
    const double area = surface_area(sphere);
    EXPECT_NEAR(area, 4.0 * std::numbers::pi * 4.0, 0.01 * 4.0 * std::numbers::pi * 4.0);
    const double b0 = 0.25; // 804 b0² of surface
    const size_t capacity = surface_capacity(area, b0);
    EXPECT_EQ(capacity, static_cast<size_t>(std::llround(area / (b0 * b0) / kAreaPerBallB0Squared)));
    // Between a tiling by equilateral b0 triangles (0.866 b0² a ball) and one by the smallest yellow
    // triangles (0.65 b0²): the calibrated 0.8 b0² a ball gives about 1000 (continue_from.cpp).
    EXPECT_GE(capacity, static_cast<size_t>(area / (b0 * b0) / 0.866));
    EXPECT_LE(capacity, static_cast<size_t>(area / (b0 * b0) / 0.65));
    ModelTransform t;
    t.scale = b0 / kind_info(StrutKind::B0).length;
    EXPECT_EQ(surface_capacity(sphere, t), capacity);
    t.scale = 0.0;
    EXPECT_EQ(surface_capacity(sphere, t), 0u);
    EXPECT_EQ(surface_capacity(1e-9, 1.0), 4u); // never below the core's least model
}

TEST(SurfaceCapacity, ATargetPastItIsCappedAndAModelThatHasItGetsNoMore)
{
    EXPECT_EQ(capped_target(300, 390, 500), 390u); // within the capacity
    EXPECT_EQ(capped_target(300, 900, 500), 500u); // capped
    EXPECT_EQ(capped_target(484, 630, 500), 500u); // 16 balls below it: a step may still add them
    EXPECT_EQ(capped_target(300, 250, 500), 250u); // fewer balls
    EXPECT_EQ(capped_target(520, 520, 500), 520u); // Improve a model past it
    EXPECT_EQ(capped_target(520, 390, 500), 390u); // Fewer balls from it
    EXPECT_EQ(capped_target(300, 9000, 0), 9000u); // no capacity known
    EXPECT_FALSE(at_capacity(484, 500));
    EXPECT_TRUE(at_capacity(485, 500)); // within 3 %
    EXPECT_TRUE(at_capacity(9, 12));    // within 3 balls
    EXPECT_FALSE(at_capacity(9000, 0));
    for (const size_t balls : {500, 495, 640})
        try
        {
            capped_target(balls, 650, 500);
            ADD_FAILURE() << "a model of " << balls << " balls at the capacity was given more";
        }
        catch (const InvalidInputError& e)
        {
            EXPECT_NE(std::string(e.what()).find("the surface holds about 500 well"), std::string::npos) << e.what();
            EXPECT_EQ(std::string(e.what()).find('\n'), std::string::npos);
        }
}

TEST(ContinueFrom, MoreDetailPastTheCapacityIsCapped)
{
    const ZomeModel& before = annealed_torus();
    const size_t capacity = surface_capacity(torus(), before.transform);
    ASSERT_LT(before.nodes.size(), capacity);
    PipelineOptions o = continuing(40000);
    o.anneal.target_nodes = 3 * capacity;
    const PipelineResult r = run_pipeline(torus(), 1, o);
    EXPECT_TRUE(r.capped);
    EXPECT_EQ(r.capacity, capacity);
    EXPECT_EQ(r.asked_nodes, 3 * capacity);
    EXPECT_LE(r.target_nodes, capacity);
    EXPECT_TRUE(r.model_valid) << r.validation;
    const std::string stats = pipeline_stats_json(r);
    EXPECT_NE(stats.find("\"capacity_note\": \"At this size the surface holds about " + std::to_string(capacity)),
              std::string::npos);
}
