// E_surface (surface_distance.h) on shapes whose distances are known: a surface inside a model
// cube at a known depth, a part of the surface out of the model's reach (capped), and a change's
// delta against a fresh evaluation of the edited model.
#include <cmath>

#include <gtest/gtest.h>

#include "core/anneal/energy/energy.h"
#include "core/anneal/energy/surface_distance.h"
#include "core/mesh/model_convert.h"
#include "core/zome/qphi.h"
#include "tests/support/geom_fixtures.h"
#include "tests/support/zome_fixtures.h"

namespace zomeify {
namespace {

// The B1 cube of cube_shell(1) spans [0, φ]³; its centre is at φ/2.
constexpr double kHalf = kPhi / 2.0;

struct Scene
{
    TriangleMesh surface;
    std::unique_ptr<SurfaceProjector> projector;
    std::unique_ptr<SurfaceContext> context;
};

// A cube surface of half-size `half` centred on the model cube (mesh units = b0).
Scene concentric_cube(double half, const Vec3& offset = Vec3::Zero())
{
    Scene s;
    s.surface = test::make_cube(half, 4);
    for (Vec3& p : s.surface.positions)
        p += Vec3::Constant(kHalf) + offset;
    s.projector = std::make_unique<SurfaceProjector>(s.surface);
    s.context = std::make_unique<SurfaceContext>(*s.projector, ModelTransform{});
    return s;
}

EnergyOptions surface_only(double cap = 0.75)
{
    EnergyOptions o;
    o.w_surface = 1.0;
    o.surface_cap = cap;
    o.surface_spacing = 0.2;
    return o;
}

TEST(SurfaceDistance, ASurfaceAKnownDepthInsideTheModelCostsThatDepthSquared)
{
    const double depth = 0.25;
    const Scene s = concentric_cube(kHalf - depth);
    SurfaceDistance term(*s.context, surface_only());
    term.reset(from_model(fixtures::cube_shell(1)));
    ASSERT_GT(term.sample_count(), 100u);
    for (size_t i = 0; i < term.sample_count(); ++i)
        EXPECT_NEAR(term.distance_squared(i), depth * depth, 1e-12);
    const double mean = to_double(term.sum()) / static_cast<double>(term.sample_count());
    EXPECT_NEAR(mean, depth * depth, 1e-9);
}

TEST(SurfaceDistance, PointsOutOfReachCountAsTheCap)
{
    // The surface cube shifted 3 b0 along x: its far half is more than the cap from the model.
    const double cap = 0.75;
    const Scene s = concentric_cube(kHalf, Vec3(3.0, 0.0, 0.0));
    SurfaceDistance term(*s.context, surface_only(cap));
    term.reset(from_model(fixtures::cube_shell(1)));
    size_t capped = 0;
    for (size_t i = 0; i < term.sample_count(); ++i)
    {
        const double d2 = term.distance_squared(i);
        EXPECT_LE(d2, cap * cap);
        capped += d2 == cap * cap;
    }
    EXPECT_GT(capped, term.sample_count() / 2);
    EXPECT_EQ(term.value(100.0), term.value(cap * cap));
}

TEST(SurfaceDistance, OffByDefaultOnlyInThePapersEnergy)
{
    EXPECT_GT(EnergyOptions{}.w_surface, 0.0);
    EXPECT_EQ(paper_energy().w_surface, 0.0);
    EXPECT_EQ(paper_energy().w_fold, 0.0);
    const Scene s = concentric_cube(kHalf - 0.1);
    const EnergyTerms paper = evaluate_energy(from_model(fixtures::cube_shell(1)), *s.context, [] {
        EnergyOptions o = paper_energy();
        o.target_nodes = 8;
        return o;
    }());
    EXPECT_EQ(paper.sums.surface_samples, 0);
    EXPECT_EQ(paper.surface, 0.0);
}

} // namespace
} // namespace zomeify
