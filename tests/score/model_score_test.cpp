// Scoring a model against a surface: a model scored against its own faces is at distance 0 with
// no fold-overs; turned inside out, every face is a fold-over; fitting finds a known offset.
#include <gtest/gtest.h>

#include "core/base/errors.h"
#include "core/score/fit_translation.h"
#include "core/score/model_score.h"
#include "tests/support/zome_fixtures.h"

namespace zomeify {
namespace {

//! The model's faces as a triangle mesh in mesh units (through its transform).
TriangleMesh own_surface(const ZomeModel& m)
{
    TriangleMesh s;
    for (const ZVec& p : m.nodes)
    {
        const auto d = p.to_double();
        s.positions.emplace_back(m.transform.scale * d[0] + m.transform.translation[0],
                                 m.transform.scale * d[1] + m.transform.translation[1],
                                 m.transform.scale * d[2] + m.transform.translation[2]);
    }
    for (const auto& f : m.faces)
        for (size_t k = 1; k + 1 < f.size(); ++k)
            s.triangles.push_back({f[0], f[k], f[k + 1]});
    return s;
}

ZomeModel placed(ZomeModel m)
{
    m.transform.scale = 0.25;
    m.transform.translation = {3.0, -1.0, 0.5};
    return m;
}

TEST(ModelScore, ModelOnItsOwnSurfaceIsAtDistanceZero)
{
    const ZomeModel model = placed(fixtures::torus_shell());
    const SurfaceProjector surface(own_surface(model));
    const ModelScore s = score_model(model, surface);
    EXPECT_EQ(s.nodes, model.nodes.size());
    EXPECT_EQ(s.faces, model.faces.size());
    EXPECT_EQ(s.genus, 1);
    EXPECT_EQ(s.fold_overs.count(), 0u);
    EXPECT_LT(s.fidelity.rms_symmetric, 1e-9);
    EXPECT_LT(s.fidelity.hausdorff, 1e-9);
    EXPECT_NEAR(s.energy.distance, 0.0, 1e-12);
    size_t by_kind = 0;
    for (size_t n : s.struts_by_kind)
        by_kind += n;
    EXPECT_EQ(by_kind, model.struts.size());
}

TEST(ModelScore, InsideOutModelIsAllFoldOvers)
{
    const ZomeModel model = placed(fixtures::cube_shell(2));
    const SurfaceProjector surface(own_surface(model));
    ZomeModel flipped = model;
    for (auto& f : flipped.faces)
        std::reverse(f.begin(), f.end());
    const ModelScore s = score_model(flipped, surface);
    EXPECT_EQ(s.fold_overs.count(), model.faces.size());
    // Each one placed on S: its barycentre (mesh units) inside S's box, its words from that box.
    ASSERT_EQ(s.fold_overs.places.size(), model.faces.size());
    const TriangleMesh own = own_surface(model);
    Vec3 lo = own.positions[0], hi = own.positions[0];
    for (const Vec3& q : own.positions)
    {
        lo = lo.cwiseMin(q);
        hi = hi.cwiseMax(q);
    }
    for (size_t i = 0; i < s.fold_overs.points.size(); ++i)
    {
        const Vec3& p = s.fold_overs.points[i];
        EXPECT_TRUE((p.array() >= lo.array() - 1e-9).all() && (p.array() <= hi.array() + 1e-9).all());
        EXPECT_EQ(s.fold_overs.places[i], place_on_surface(p, own));
    }
    // The cube's 6 sides: every face lies on one, so no fold-over is "in the middle".
    for (const std::string& place : s.fold_overs.places)
        EXPECT_NE(place, "middle");
    EXPECT_EQ(fold_over_places_json(s.fold_overs).size(), model.faces.size());
}

TEST(ModelScore, FoldOverSummarySaysHowManyAndWhere)
{
    FoldOverReport r;
    EXPECT_EQ(fold_over_summary(r), "0 fold-overs");
    r.points = {Vec3::Zero()};
    r.places = {"top"};
    EXPECT_EQ(fold_over_summary(r), "1 fold-over (at the top)");
    r.points = {Vec3::Zero(), Vec3::Ones(), Vec3::Zero()};
    r.places = {"left", "middle", "left"};
    EXPECT_EQ(fold_over_summary(r), "3 fold-overs (2 at the left, in the middle)");
    const nlohmann::json j = fold_over_places_json(r);
    ASSERT_EQ(j.size(), 3u);
    EXPECT_EQ(j[1]["where"], "middle");
    EXPECT_EQ(j[1]["at"][2], 1.0);
}

TEST(ModelScore, ShiftedSurfaceGivesThatDistance)
{
    const ZomeModel model = placed(fixtures::cube_shell(3));
    TriangleMesh shifted = own_surface(model);
    for (Vec3& p : shifted.positions)
        p *= 1.0; // same shape ...
    ZomeModel moved = model;
    moved.transform.translation[0] += 0.25 * 0.1; // ... model moved by 0.1 b0 along x
    const ModelScore s = score_model(moved, SurfaceProjector(shifted));
    EXPECT_GT(s.fidelity.hausdorff, 0.099);
    EXPECT_LT(s.fidelity.hausdorff, 0.101);
}

TEST(ModelScore, FacelessModelIsRefused)
{
    ZomeModel model = placed(fixtures::icosahedron());
    const SurfaceProjector surface(own_surface(model));
    model.faces.clear();
    EXPECT_THROW(score_model(model, surface), InvalidInputError);
}

TEST(FitTranslation, FindsAKnownOffset)
{
    const ZomeModel model = placed(fixtures::torus_shell());
    const SurfaceProjector surface(own_surface(model));
    const ModelTransform t = fit_translation(model, surface, model.transform.scale);
    for (int k = 0; k < 3; ++k)
        EXPECT_NEAR(t.translation[k], model.transform.translation[k], 1e-6);
}

} // namespace
} // namespace zomeify
