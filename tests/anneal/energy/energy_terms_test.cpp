// The energy terms on configurations whose values are known in closed form (paper §4, design §3.3).
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <vector>

#include <gtest/gtest.h>

#include "core/anneal/energy/energy.h"
#include "core/anneal/energy/energy_samples.h"
#include "core/mesh/model_convert.h"
#include "tests/anneal/energy/energy_test_support.h"
#include "tests/support/geom_fixtures.h"
#include "tests/support/zome_fixtures.h"

namespace zomeify {
namespace {

using test::make_energy_scene;

// S = an axis-aligned cube of half-side `half` around the centre of the model's nodes, split into
// n × n quads per side (n = 2: face centres and edge midpoints of S are vertices of S).
test::EnergyScene cube_scene(const ZomeModel& model, double half, const ModelTransform& transform, int n = 2)
{
    const auto [lo, hi] = test::node_bounds(model);
    TriangleMesh cube = test::make_cube(half, n);
    const Vec3 centre = 0.5 * (lo + hi);
    for (Vec3& p : cube.positions)
    {
        p += centre;
    }
    return make_energy_scene(std::move(cube), transform);
}

ModelTransform scaled_transform()
{
    ModelTransform t;
    t.scale = 2.5;
    t.translation = {1.0, 2.0, 3.0};
    return t;
}

// The paper's energy (its weights, no E_surface): the figures below are worked out by hand.
EnergyOptions options_with_target(size_t target)
{
    EnergyOptions o = paper_energy();
    o.target_nodes = target;
    return o;
}

TEST(EnergyForbiddenZone, ValuesAtTheBreakpoints)
{
    const EnergyOptions o = paper_energy();
    for (const ForbiddenZone& z : {o.inside, o.outside})
    {
        EXPECT_EQ(forbidden_zone(0.0, z), 0.0);
        EXPECT_EQ(forbidden_zone(z.d_min, z), 0.0);
        EXPECT_DOUBLE_EQ(forbidden_zone(0.5 * (z.d_min + z.d_max), z), 0.25 * z.f_max);
        EXPECT_DOUBLE_EQ(forbidden_zone(z.d_max, z), z.f_max);
        EXPECT_NEAR(forbidden_zone(z.d_max - 1e-9, z), z.f_max, 1e-6);
        EXPECT_EQ(forbidden_zone(10.0, z), z.f_max);
    }
    // The paper's parameters.
    EXPECT_DOUBLE_EQ(o.inside.d_min, 1.0 / 3.0);
    EXPECT_DOUBLE_EQ(o.inside.d_max, 1.5);
    EXPECT_DOUBLE_EQ(o.inside.f_max, 35.0);
    EXPECT_DOUBLE_EQ(o.outside.d_min, 1.0 / 3.0);
    EXPECT_DOUBLE_EQ(o.outside.d_max, 2.5);
    EXPECT_DOUBLE_EQ(o.outside.f_max, 15.0);
    // d = 1 b0: inside 35·((2/3)/(7/6))² = 35·16/49, outside 15·((2/3)/(13/6))² = 15·16/169.
    EXPECT_DOUBLE_EQ(forbidden_zone(1.0, o.inside), 35.0 * 16.0 / 49.0);
    EXPECT_DOUBLE_EQ(forbidden_zone(1.0, o.outside), 15.0 * 16.0 / 169.0);
}

TEST(EnergyForbiddenZone, DistanceSampleUsesTheZoneOfItsSide)
{
    const EnergyOptions o = paper_energy();
    SurfaceSample s;
    s.distance_squared = 1.0;
    s.inside = true;
    EXPECT_DOUBLE_EQ(distance_value(s, o), 1.0 + 35.0 * 16.0 / 49.0);
    s.inside = false;
    EXPECT_DOUBLE_EQ(distance_value(s, o), 1.0 + 15.0 * 16.0 / 169.0);
    s.distance_squared = 0.01; // below d_min: plain squared distance
    EXPECT_DOUBLE_EQ(distance_value(s, o), 0.01);
}

TEST(EnergyTerms, B1CubeAroundASmallerCube)
{
    // One B1 cube (corners {0, φ}³) around a concentric cube S of half-side φ/2 − δ: nodes are
    // √3·δ from S's corners, strut midpoints √2·δ from its edges, face centres δ from its faces.
    const ZomeModel model = fixtures::cube_shell(1);
    const ZomeMesh mesh = from_model(model);
    const double delta = 0.5;
    const test::EnergyScene scene = cube_scene(model, 0.5 * kPhi - delta, scaled_transform());
    const EnergyOptions o = options_with_target(10);
    const EnergyTerms t = evaluate_energy(mesh, *scene.context, o);

    auto sample = [&](double d) { return d * d * (1.0 + forbidden_zone(d, o.outside)); };
    const double e_dist =
        (8.0 * sample(std::sqrt(3.0) * delta) + 12.0 * sample(std::sqrt(2.0) * delta) + 6.0 * sample(delta)) / 26.0;
    EXPECT_EQ(t.sums.nodes, 8);
    EXPECT_EQ(t.sums.struts, 12);
    EXPECT_EQ(t.sums.faces, 6);
    EXPECT_EQ(t.sums.corners, 24);
    EXPECT_NEAR(t.distance, e_dist, 1e-9);
    // Struts lie in S's tangent planes (their midpoints project onto S's edges).
    EXPECT_NEAR(t.tangential, 0.0, 1e-9);
    // Every corner normal is a face normal; S's normal at a corner is (1,1,1)/√3.
    const double e_normal = std::pow(1.0 - 1.0 / std::sqrt(3.0), 2) / 4.0;
    EXPECT_NEAR(t.normal, e_normal, 1e-9);
    EXPECT_NEAR(t.orientation, 0.75 * e_normal, 1e-9);
    // Each node has three neighbours at φ along the axes: ‖p − mean‖² = 3·(φ/3)².
    EXPECT_NEAR(t.fairing, kPhi * kPhi / 3.0, 1e-9);
    EXPECT_DOUBLE_EQ(t.complexity, 0.4); // (8 − 10)² / 10
    EXPECT_NEAR(t.total, 10.0 * e_dist + 100.0 * 0.75 * e_normal + 5.0 * kPhi * kPhi / 3.0 + 0.4, 1e-8);
}

TEST(EnergyTerms, B1CubeInsideALargerCube)
{
    // S of half-side φ/2 + δ: every sample is inside, δ from the nearest face of S.
    const ZomeModel model = fixtures::cube_shell(1);
    const ZomeMesh mesh = from_model(model);
    const double delta = 0.8;
    const test::EnergyScene scene = cube_scene(model, 0.5 * kPhi + delta, scaled_transform());
    const EnergyOptions o = options_with_target(8);
    const EnergyTerms t = evaluate_energy(mesh, *scene.context, o);
    EXPECT_NEAR(t.distance, delta * delta * (1.0 + forbidden_zone(delta, o.inside)), 1e-9);
    EXPECT_EQ(t.complexity, 0.0);
}

TEST(EnergyTerms, FairingOfACubeShellIsZeroOnFlatPatches)
{
    // cube_shell(3): face-interior nodes sit at the mean of their 4 coplanar neighbours (0); edge
    // nodes have the mean (φ/4)·(inward, inward) away (φ²/8); corners φ²/3.
    const ZomeModel model = fixtures::cube_shell(3);
    const ZomeMesh mesh = from_model(model);
    const test::EnergyScene scene = cube_scene(model, 1.5 * kPhi, scaled_transform());
    const EnergyTerms t = evaluate_energy(mesh, *scene.context, options_with_target(56));
    ASSERT_EQ(t.sums.nodes, 56);
    EXPECT_NEAR(t.fairing, (8.0 * kPhi * kPhi / 3.0 + 24.0 * kPhi * kPhi / 8.0) / 56.0, 1e-9);
}

TEST(EnergyTerms, OrientationNormalPointsOutward)
{
    // cube_shell(3) (nodes at −1.5φ, −0.5φ, 0.5φ, 1.5φ from the centre along each axis) around the
    // cube S of half-side φ split 4 × 4, so every node projects onto a vertex of S: corner nodes onto
    // S's corners (normal (1,1,1)/√3), edge nodes onto S's edges ((1,1,0)/√2), face nodes onto face
    // interiors (the face normal). Outward corner normals are face normals, so only the 24 corners
    // at corner nodes and the 96 at edge nodes count. Reversing every face turns the corner normals
    // inward and must make the term large.
    const ZomeModel model = fixtures::cube_shell(3);
    const test::EnergyScene scene = cube_scene(model, kPhi, scaled_transform(), 4);
    const EnergyOptions o = options_with_target(56);
    const EnergyTerms out = evaluate_energy(from_model(model), *scene.context, o);
    const double corner = std::pow(1.0 - 1.0 / std::sqrt(3.0), 2);
    const double edge = std::pow(1.0 - 1.0 / std::sqrt(2.0), 2);
    ASSERT_EQ(out.sums.corners, 216);
    EXPECT_NEAR(out.normal, (24.0 * corner + 96.0 * edge) / (4.0 * 216.0), 1e-9);
    EXPECT_LT(out.normal, 0.02);

    ZomeModel flipped = model;
    for (auto& f : flipped.faces)
    {
        std::reverse(f.begin(), f.end());
    }
    const EnergyTerms in = evaluate_energy(from_model(flipped), *scene.context, o);
    const double face_in = 4.0; // (1 − (−1))²
    EXPECT_NEAR(in.normal,
                (24.0 * std::pow(1.0 + 1.0 / std::sqrt(3.0), 2) + 96.0 * std::pow(1.0 + 1.0 / std::sqrt(2.0), 2) +
                 96.0 * face_in) /
                    (4.0 * 216.0),
                1e-9);
    EXPECT_GT(in.normal, 0.5);
    // The tangential part does not see the orientation of faces.
    EXPECT_DOUBLE_EQ(in.tangential, out.tangential);
    EXPECT_LT(out.normal, 0.1 * in.normal);
    EXPECT_LT(out.orientation, in.orientation);
}

TEST(EnergyTerms, CornerValueConventions)
{
    const Vec3 up = Vec3::UnitZ();
    // a = (0,0,0), b = (1,0,0), c = (0,1,0) is counter-clockwise seen from +z: n_b = +z.
    const Vec3 a(0, 0, 0), b(1, 0, 0), c(0, 1, 0);
    EXPECT_NEAR(corner_value(c - b, a - b, up), 0.0, 1e-15);
    EXPECT_NEAR(corner_value(c - b, a - b, -up), 4.0, 1e-15);
    // A straight corner has no normal: counted as perpendicular.
    EXPECT_EQ(corner_value(Vec3(1, 0, 0), Vec3(-2, 0, 0), up), 1.0);
    EXPECT_NEAR(tangential_value(Vec3(0, 0, 3), up), 1.0, 1e-15);
    EXPECT_NEAR(tangential_value(Vec3(3, 4, 0), up), 0.0, 1e-15);
}

TEST(EnergyTerms, ComplexityNeedsATarget)
{
    const ZomeModel model = fixtures::cube_shell(1);
    const test::EnergyScene scene = cube_scene(model, 1.0, scaled_transform());
    EXPECT_THROW(evaluate_energy(from_model(model), *scene.context, EnergyOptions{}), InvalidInputError);
    EnergyOptions o;
    o.w_complexity = 0.0;
    EXPECT_NO_THROW(evaluate_energy(from_model(model), *scene.context, o));
}

TEST(EnergyTerms, QuantizationIsExactEnoughAndClamped)
{
    EXPECT_EQ(quantize(1.0), EnergyFixed{1} << 32);
    EXPECT_EQ(quantize(0.0), 0);
    EXPECT_EQ(quantize(-1.0), 0);
    EXPECT_EQ(quantize(1e300), quantize(kEnergySampleCap));
    EXPECT_EQ(quantize(std::nan("")), quantize(kEnergySampleCap));
    EXPECT_NEAR(static_cast<double>(quantize(0.123456789)) * kEnergyQuantum, 0.123456789, kEnergyQuantum);
}

TEST(EnergyTerms, QuantizationRoundsLikeLlround)
{
    // The inline rounding must give llround's integer for every value, halves included, or
    // stored goldens and native/wasm determinism would break.
    std::vector<double> values = {0.5 * kEnergyQuantum,
                                  1.5 * kEnergyQuantum,
                                  2.5 * kEnergyQuantum,
                                  std::nextafter(0.5 * kEnergyQuantum, 0.0),
                                  0x1p20 + 0.5 * kEnergyQuantum,
                                  std::nextafter(kEnergySampleCap, 0.0),
                                  1e-300};
    uint64_t state = 12345;
    for (int i = 0; i < 100000; ++i)
    {
        state = state * 6364136223846793005ULL + 1442695040888963407ULL;
        const double unit = static_cast<double>(state >> 11) * 0x1p-53;
        values.push_back(std::ldexp(unit, static_cast<int>(state % 90) - 60));
    }
    for (const double v : values)
    {
        ASSERT_EQ(quantize(v), static_cast<EnergyFixed>(std::llround(v / kEnergyQuantum))) << v;
    }
}

} // namespace
} // namespace zomeify
