// Mirror-symmetric annealing (mirrored.h, issue 41): on a symmetric Z0, every proposal made
// symmetric by mirror_proposal() is a consistent LocalChange whose incremental ΔE equals a full
// recomputation, and applying it keeps the model closed, of the same genus and exactly symmetric.
// Both kinds of symmetric change occur: pairs (a change and its image) and changes that are their
// own image (on the plane).
#include "core/anneal/operators/mirrored.h"

#include <array>
#include <cmath>

#include <gtest/gtest.h>

#include "core/anneal/energy/energy_state.h"
#include "core/geom/inside.h"
#include "core/mesh/model_convert.h"
#include "core/mesh/validate.h"
#include "core/voxel/initial_model.h"
#include "tests/support/geom_fixtures.h"

namespace zomeify {
namespace {

#ifdef ZOME_SANITIZED
constexpr int kMinPaired = 6;
#else
constexpr int kMinPaired = 20;
#endif

struct MirroredScene
{
    std::unique_ptr<SurfaceProjector> projector;
    ZomeModel z0;
    LatticeMirror mirror;
};

// A torus around the z axis, symmetric about x = 0; Z0 built symmetric about that plane.
MirroredScene mirrored_torus()
{
    MirroredScene s;
    s.projector = std::make_unique<SurfaceProjector>(test::make_torus(3.0, 1.2, 48, 24));
    const InsideTest inside(*s.projector);
    InitialModelOptions options;
    options.resolution = 9;
    options.surface_probe = probe_of(*s.projector);
    options.mirror = AxisPlane{0, 0.0};
    InitialModel z0 = build_initial_model(
        s.projector->mesh(), [&](const Vec3& p) { return inside.is_inside(p); }, options);
    EXPECT_TRUE(z0.report.valid);
    EXPECT_EQ(z0.report.topology.genus, 1);
    const std::optional<int> corner = mirror_corner_index(z0.report.grid, *options.mirror);
    EXPECT_TRUE(corner.has_value());
    s.mirror = LatticeMirror::through(0, QPhi{0, 2 * corner.value_or(0)});
    s.z0 = std::move(z0.model);
    return s;
}

TEST(LatticeMirror, ReflectsExactlyAndIsItsOwnInverse)
{
    const LatticeMirror m = LatticeMirror::through(1, QPhi{3, 4});
    const ZVec p{{5, -7, 2, 9, -4, 1}};
    const ZVec q = m.reflect(p);
    EXPECT_EQ(m.reflect(q), p);
    EXPECT_EQ(q.twice(0), p.twice(0));
    EXPECT_EQ(q.twice(2), p.twice(2));
    EXPECT_EQ(q.twice(1) + p.twice(1), (QPhi{6, 8})); // symmetric about twice-coordinate 3 + 4φ
    EXPECT_FALSE(m.on_plane(p));
    EXPECT_TRUE(m.on_plane(ZVec::from_twice(QPhi{1, 0}, QPhi{3, 4}, QPhi{})));
}

TEST(LatticeMirror, AMismatchCountsWhatHasNoImage)
{
    const MirroredScene s = mirrored_torus();
    ASSERT_TRUE(mirror_mismatch(s.z0, s.mirror).symmetric());
    ZomeModel moved = s.z0;
    moved.nodes[0] = moved.nodes[0] + ZVec{{0, 0, 0, 0, 2, 0}}; // one ball off by b1/... along z
    const MirrorMismatch m = mirror_mismatch(moved, s.mirror);
    EXPECT_GE(m.balls, 1U);
    EXPECT_GE(m.struts, 1U);
}

TEST(LatticeMirror, AModelsOwnPlaneIsFoundHalfwayBetweenItsExtremes)
{
    const MirroredScene s = mirrored_torus();
    const std::optional<ModelMirror> own = model_mirror(s.z0);
    ASSERT_TRUE(own.has_value());
    EXPECT_TRUE(own->mismatch.symmetric());
    EXPECT_EQ(own->mirror, s.mirror);
    // Half a cell off the lattice's layers: two balls one b1 apart mirror onto each other.
    ZomeModel pair;
    pair.nodes = {ZVec{{0, 0, 0, 0, 0, 0}}, ZVec{{2, 0, 0, 0, 0, 0}}};
    pair.struts = {{0, 1}};
    const std::optional<ModelMirror> halfway = model_mirror(pair);
    ASSERT_TRUE(halfway.has_value());
    EXPECT_EQ(halfway->mirror.axis, 0);
    EXPECT_TRUE(halfway->mismatch.symmetric());
    EXPECT_NEAR(halfway->mirror.coordinate(), 0.5 * kPhi, 1e-12);
    EXPECT_FALSE(model_mirror(ZomeModel{}).has_value());
}

TEST(MirrorCells, TheGridHasABoundaryOnThePlaneAndSymmetricCells)
{
    GridLayoutOptions layout;
    layout.resolution = 9;
    layout.boundary_axis = 0;
    layout.boundary_at = 0.37;
    const GridSpec grid = layout_grid(Vec3(-4.2, -4.2, -1.2), Vec3(4.94, 4.2, 1.2), layout); // symmetric about 0.37
    const std::optional<int> corner = mirror_corner_index(grid, AxisPlane{0, 0.37});
    ASSERT_TRUE(corner.has_value());
    EXPECT_NEAR(grid.origin.x() + *corner * grid.cell, 0.37, 1e-9);
    VoxelGrid cells(grid);
    cells.set(1, 2, 3, Cell::Surface);
    make_mirror_symmetric(cells, AxisPlane{0, 0.37});
    const int image = 2 * *corner - 1 - 1;
    ASSERT_TRUE(cells.contains(image, 2, 3));
    EXPECT_EQ(cells.at(image, 2, 3), Cell::Surface);
    EXPECT_FALSE(mirror_corner_index(grid, AxisPlane{0, 0.37 + 0.5 * grid.cell}).has_value());
    // The intersection keeps a cell only with its image: the pair stays, a lone cell goes.
    cells.set(3, 1, 1, Cell::Inside);
    make_mirror_symmetric(cells, AxisPlane{0, 0.37}, MirrorMerge::Intersection);
    EXPECT_EQ(cells.at(1, 2, 3), Cell::Surface);
    EXPECT_EQ(cells.at(image, 2, 3), Cell::Surface);
    EXPECT_EQ(cells.at(3, 1, 1), Cell::Empty);
    EXPECT_EQ(cells.occupied_count(), 2U);
}

TEST(MirroredProposals, EveryChangeIsExactAndKeepsTheModelSymmetric)
{
    const MirroredScene s = mirrored_torus();
    const SurfaceContext context(*s.projector, s.z0.transform);
    ZomeMesh mesh = from_model(s.z0);
    EnergyOptions options;
    options.target_nodes = mesh.n_vertices() + 40;
    EnergyState state(mesh, context, options);
    EnergyTerms before = evaluate_energy(mesh, context, options);
    std::array<int, kOperatorKinds> paired{};
    int own_image = 0, overlaps = 0;
    Rng rng(20261207);
    Proposal p;
    for (long step = 0; step < 200000; ++step)
    {
        if (*std::min_element(paired.begin(), paired.end()) >= kMinPaired && own_image >= 3)
            break;
        const auto kind = static_cast<OperatorKind>(rng.below(kOperatorKinds));
        Vertex seed(static_cast<MeshIndex>(rng.below(mesh.vertices_size())));
        if (mesh.is_deleted(seed))
            continue;
        Claims claims;
        claims.take(seed);
        if (!propose(kind, mesh, seed, rng, claims, p))
            continue;
        const size_t faces_before = p.change.added_faces().size();
        const Rejection r = mirror_proposal(mesh, s.mirror, claims, p);
        if (r == Rejection::MirrorOverlap)
            ++overlaps;
        if (r != Rejection::None)
            continue;
        SCOPED_TRACE(::testing::Message() << "step " << step << " " << operator_name(kind));
        ASSERT_EQ(check_change(mesh, p.change), "");
        EnergyDelta delta = state.simulate(mesh, p.change, FoldOvers::Count);
        ASSERT_TRUE(delta.ok());
        state.add_surface_change(mesh, p.change, delta);
        const double de = state.delta_energy(delta);
        FixedList<Face, LocalChange::kMaxFaces> added;
        apply_proposal(mesh, p, &added);
        const ValidationReport report = validate(mesh);
        ASSERT_TRUE(report.ok()) << report.message();
        ASSERT_EQ(report.genus, 1);
        ASSERT_TRUE(mirror_mismatch(to_model(mesh), s.mirror).symmetric());
        const EnergyTerms after = evaluate_energy(mesh, context, options);
        EXPECT_TRUE(before.sums + delta.sums == after.sums);
        const double de_full = after.total - before.total;
        EXPECT_LE(std::abs(de - de_full), 1e-9 * std::max(std::abs(de_full), 1e-9));
        ASSERT_TRUE(state.commit(delta, std::span<const Face>(added.begin(), added.size())));
        before = after;
        if (p.change.added_faces().size() == 2 * faces_before)
            ++paired[static_cast<size_t>(kind)];
        else
            ++own_image;
    }
    for (int k = 0; k < kOperatorKinds; ++k)
        EXPECT_GE(paired[static_cast<size_t>(k)], kMinPaired) << operator_name(static_cast<OperatorKind>(k));
    EXPECT_GE(own_image, 3);
    EXPECT_GT(overlaps, 0); // changes across the plane that are not symmetric are refused
}

} // namespace
} // namespace zomeify
