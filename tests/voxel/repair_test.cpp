// The configurations of the paper's Figure 3, in 3D, and the retry (nudge) path of the pipeline.

#include <gtest/gtest.h>

#include "core/voxel/extract.h"
#include "core/voxel/initial_model.h"
#include "core/voxel/repair.h"
#include "tests/voxel/voxel_test_support.h"

using namespace zomeify;
using namespace zomeify::voxel_test;

namespace {

GridSpec spec(int n)
{
    GridSpec s;
    s.cell = 1.0;
    s.dims = {n, n, n};
    return s;
}

void fill(VoxelGrid& g, std::initializer_list<std::array<int, 3>> cells)
{
    for (const auto& c : cells)
        g.set(c[0], c[1], c[2], Cell::Surface);
}

void block(VoxelGrid& g, int lo, int hi)
{
    for (int k = lo; k < hi; ++k)
        for (int j = lo; j < hi; ++j)
            for (int i = lo; i < hi; ++i)
                g.set(i, j, k, Cell::Inside);
}

// A one-cell-thick ring (genus 1) whose last link is a single shared corner: cells (2,2,2) and
// (3,3,3) meet only at grid vertex (3,3,3). Both are non-simple (removing either cuts the ring).
// With `closed_by_faces`, (2,3,3) and (2,3,2) make that link a path of faces instead, around the
// same hole.
VoxelGrid corner_ring(const GridSpec& s, bool closed_by_faces)
{
    VoxelGrid g(s);
    fill(g, {{2, 2, 2}, {2, 2, 1}, {3, 2, 1}, {4, 2, 1}, {4, 2, 2}, {4, 2, 3}, {4, 3, 3}, {3, 3, 3}});
    if (closed_by_faces)
        fill(g, {{2, 3, 3}, {2, 3, 2}});
    return g;
}

} // namespace

TEST(VoxelRepair, ManifoldStars)
{
    EXPECT_TRUE(is_manifold_star(0));
    EXPECT_TRUE(is_manifold_star(0xFF));
    EXPECT_TRUE(is_manifold_star(0x01));          // one cell
    EXPECT_TRUE(is_manifold_star(0x03));          // two cells sharing a face
    EXPECT_FALSE(is_manifold_star(0x01 | 0x80));  // two cells sharing only the vertex
    EXPECT_FALSE(is_manifold_star(0x01 | 0x08));  // two cells sharing only an edge
    EXPECT_FALSE(is_manifold_star(0xFF & ~0x81)); // two opposite empty cells
    EXPECT_TRUE(is_manifold_star(0x0F));          // a half-space
}

// Figure 3(a): a non-manifold vertex, resolved by removing a simple cell. A 2×2×2 block with one
// more cell touching it only at a corner: the tip is simple and goes; the block stays.
TEST(VoxelRepair, Figure3aNonManifoldVertexResolvedByRemovingASimpleVoxel)
{
    VoxelGrid g(spec(6));
    block(g, 1, 3);
    fill(g, {{3, 3, 3}});
    EXPECT_EQ(count_nonmanifold_vertices(g), 1u);
    const RepairReport r = repair_manifold(g);
    EXPECT_TRUE(r.manifold);
    EXPECT_EQ(r.initial_bad_vertices, 1u);
    EXPECT_EQ(r.removed, 1u);
    EXPECT_EQ(r.added, 0u);
    EXPECT_FALSE(g.occupied(3, 3, 3));
    EXPECT_EQ(g.occupied_count(), 8u);
    const Extraction ex = extract_boundary(g);
    EXPECT_EQ(closed_manifold_problem(ex.model), "");
    EXPECT_EQ(ex.topology.genus, 0);
}

// Figure 3(b): at the same non-manifold vertex a non-simple cell is left alone and the simple one
// is removed. A 3×3×3 block with a tip at a corner: the block's corner cell (2,2,2)... is simple
// on its own, but with the tip attached it is not (its removal would cut the tip off).
TEST(VoxelRepair, Figure3bNonSimpleVoxelLeftAlone)
{
    VoxelGrid g(spec(7));
    block(g, 1, 4);
    fill(g, {{4, 4, 4}});
    const RepairReport r = repair_manifold(g);
    EXPECT_TRUE(r.manifold);
    EXPECT_TRUE(g.occupied(3, 3, 3));  // the red cell of Figure 3(b)
    EXPECT_FALSE(g.occupied(4, 4, 4)); // the green one
    EXPECT_EQ(r.removed, 1u);
}

// Figure 3(c): a configuration removal cannot resolve. Every cell at the offending corner is
// non-simple; without additions the cleanup changes nothing and reports failure; with additions
// (our extension) it fills the corner and keeps the ring's genus.
TEST(VoxelRepair, Figure3cRingThroughACornerNeedsAdditions)
{
    VoxelGrid g = corner_ring(spec(8), false);
    const VoxelGrid before = g;
    ASSERT_GT(count_nonmanifold_vertices(g), 0u);

    RepairOptions removal_only;
    removal_only.allow_additions = false;
    const RepairReport stuck = repair_manifold(g, removal_only);
    EXPECT_FALSE(stuck.manifold);
    EXPECT_EQ(stuck.removed, 0u);
    EXPECT_TRUE(g.cells() == before.cells()); // non-simple cells left alone

    const RepairReport fixed = repair_manifold(g);
    EXPECT_TRUE(fixed.manifold);
    EXPECT_GT(fixed.added, 0u);
    const Extraction ex = extract_boundary(g);
    EXPECT_EQ(closed_manifold_problem(ex.model), "");
    EXPECT_EQ(ex.topology.genus, 1);
}

// The retry path: when a grid cannot be cleaned up, the pipeline nudges the grid and tries again.
// The source stands for a voxelizer whose first grid puts a ring's link exactly through a corner
// and whose nudged grids do not.
TEST(VoxelRepair, StuckGridIsNudgedAndRetried)
{
    InitialModelOptions options;
    options.resolution = 7;
    options.repair.allow_additions = false;
    const std::array<Vec3, 2> box{Vec3(0, 0, 0), Vec3(5, 5, 5)};
    std::vector<GridSpec> asked;
    auto source = [&](const GridSpec& s) {
        asked.push_back(s);
        return corner_ring(s, asked.size() > 1);
    };
    const InitialModel z0 = build_initial_model(box, source, options);
    EXPECT_TRUE(z0.report.valid);
    EXPECT_EQ(z0.report.attempts, 2);
    ASSERT_EQ(z0.report.notes.size(), 1u);
    EXPECT_NE(z0.report.notes[0].find("non-manifold"), std::string::npos);
    ASSERT_EQ(asked.size(), 2u);
    EXPECT_NE(asked[0].cell, asked[1].cell);     // the nudge changed the scale ...
    EXPECT_NE(asked[0].origin, asked[1].origin); // ... and the offset
    EXPECT_EQ(z0.report.topology.genus, 1);
    EXPECT_EQ(closed_manifold_problem(z0.model), "");

    // A source that never becomes manifold: every retry is used, then the result says so.
    asked.clear();
    auto always_stuck = [&](const GridSpec& s) {
        asked.push_back(s);
        return corner_ring(s, false);
    };
    const InitialModel bad = build_initial_model(box, always_stuck, options);
    EXPECT_FALSE(bad.report.valid);
    EXPECT_EQ(bad.report.attempts, 1 + options.max_retries);
    EXPECT_EQ(bad.report.notes.size(), static_cast<size_t>(1 + options.max_retries));
}

TEST(VoxelRepair, NudgedLayoutsDiffer)
{
    InitialModelOptions options;
    const GridLayoutOptions plain = nudged_layout(options, 0);
    EXPECT_EQ(plain.scale_factor, 1.0);
    for (int a = 1; a <= 8; ++a)
    {
        const GridLayoutOptions l = nudged_layout(options, a);
        EXPECT_NE(l.scale_factor, 1.0);
        EXPECT_LE(std::abs(l.scale_factor - 1.0), 0.0401);
        for (int k = 0; k < 3; ++k)
            EXPECT_LT(std::abs(l.offset[k]), 0.5 + 1e-12);
    }
}
