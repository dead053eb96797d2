// Working on a model (core/pipeline/continue_from.h, run_pipeline with `from`): a fix changes
// nothing far from its spot (every node farther than the radius keeps its exact position, and the
// struts between such nodes stay), fewer balls keep the genus, a continued run never ends with a
// higher energy than it started with, and a model made for another mesh, or for this one at
// another scale, is refused in one line.
#include "core/pipeline/continue_from.h"

#include <set>

#include <gtest/gtest.h>

#include "core/base/errors.h"
#include "core/pipeline/pipeline.h"
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
