// Conservative voxelization: exact against a brute-force classification, covers S, and the grid
// layout (centred, one empty layer around, cells along the longest side).

#include <gtest/gtest.h>

#include "core/voxel/tri_box.h"
#include "core/voxel/voxelize.h"
#include "tests/support/paths.h"
#include "tests/voxel/voxel_test_support.h"

using namespace zomeify;
using namespace zomeify::voxel_test;

TEST(VoxelGridLayout, CentredWithAnEmptyLayer)
{
    GridLayoutOptions o;
    o.resolution = 8;
    const GridSpec s = layout_grid(Vec3(-1, -1, -1), Vec3(1, 1, 1), o);
    EXPECT_DOUBLE_EQ(s.cell, 0.25);
    EXPECT_EQ(s.dims, (std::array<int, 3>{10, 10, 10}));
    EXPECT_DOUBLE_EQ(s.origin.x(), -1.25);

    o.resolution = 10;
    const GridSpec t = layout_grid(Vec3(0, 0, 0), Vec3(10, 3, 1), o);
    EXPECT_DOUBLE_EQ(t.cell, 1.0);
    EXPECT_EQ(t.dims, (std::array<int, 3>{12, 5, 3}));
    EXPECT_DOUBLE_EQ(t.origin.y(), -1.0);

    // An offset grid still covers the box with an empty layer.
    o.offset = {0.3, -0.4, 0.45};
    o.scale_factor = 1.03;
    const GridSpec u = layout_grid(Vec3(0, 0, 0), Vec3(10, 3, 1), o);
    for (int a = 0; a < 3; ++a)
    {
        EXPECT_LE(u.origin[a] + u.cell, 0.0 + 1e-9);
        EXPECT_GE(u.origin[a] + (u.dims[a] - 1) * u.cell, (a == 0 ? 10.0 : a == 1 ? 3.0 : 1.0) - 1e-9);
    }
}

TEST(VoxelVoxelize, CubeAlignedWithTheGrid)
{
    ZOME_REQUIRE_SHARED();
    const LoadedSurface& cube = shared_surface("cube");
    GridLayoutOptions o;
    o.resolution = 8;
    VoxelizeStats st;
    const VoxelGrid g = voxelize(cube.mesh, layout_grid(Vec3(-1, -1, -1), Vec3(1, 1, 1), o), cube.predicate(), &st);
    // The cube's faces lie on cell faces: exactly the 8³ cells inside, none outside.
    EXPECT_EQ(g.occupied_count(), 512u);
    EXPECT_EQ(st.surface_cells, 0u);
    for (int k = 1; k <= 8; ++k)
        for (int j = 1; j <= 8; ++j)
            for (int i = 1; i <= 8; ++i)
                EXPECT_TRUE(g.occupied(i, j, k));
}

TEST(VoxelVoxelize, MatchesBruteForceAndCoversTheSurface)
{
    ZOME_REQUIRE_SHARED();
    for (const char* name : {"torus", "eight", "bunny"})
    {
        SCOPED_TRACE(name);
        const LoadedSurface& s = shared_surface(name);
        GridLayoutOptions o;
        o.resolution = 9;
        const auto box = bounding_box(s.mesh);
        const GridSpec spec = layout_grid(box[0], box[1], o);
        VoxelizeStats st;
        const VoxelGrid g = voxelize(s.mesh, spec, s.predicate(), &st);
        // Few inside queries: one per region of untouched cells plus the touched-only cells.
        EXPECT_LT(st.inside_queries, g.cell_count() / 10);

        for (int k = 0; k < spec.dims[2]; ++k)
            for (int j = 0; j < spec.dims[1]; ++j)
                for (int i = 0; i < spec.dims[0]; ++i)
                {
                    // The cell's corners rounded as the voxelizer rounds them (origin + index · cell).
                    const Vec3 lo = spec.origin + spec.cell * Vec3(i, j, k);
                    const Vec3 hi = spec.origin + spec.cell * Vec3(i + 1, j + 1, k + 1);
                    const Vec3 c = 0.5 * (lo + hi), half = 0.5 * (hi - lo);
                    bool crossed = false;
                    for (const auto& t : s.mesh.triangles)
                        if (triangle_box_overlap(c, half, s.mesh.positions[t[0]], s.mesh.positions[t[1]],
                                                 s.mesh.positions[t[2]], BoxContact::Open))
                        {
                            crossed = true;
                            break;
                        }
                    const Cell want = crossed ? Cell::Surface : s.inside->is_inside(c) ? Cell::Inside : Cell::Empty;
                    ASSERT_EQ(static_cast<int>(g.at(i, j, k)), static_cast<int>(want)) << i << " " << j << " " << k;
                }
        // Coverage: every vertex of S lies in an occupied closed cell, and the outer layer is empty.
        for (const Vec3& p : s.mesh.positions)
        {
            const Vec3 q = (p - spec.origin) / spec.cell;
            bool covered = false;
            for (int dz = -1; dz <= 0 && !covered; ++dz)
                for (int dy = -1; dy <= 0 && !covered; ++dy)
                    for (int dx = -1; dx <= 0 && !covered; ++dx)
                    {
                        const int i = static_cast<int>(std::floor(q.x() + 0.5)) + dx;
                        const int j = static_cast<int>(std::floor(q.y() + 0.5)) + dy;
                        const int k = static_cast<int>(std::floor(q.z() + 0.5)) + dz;
                        const Vec3 lo = spec.origin + spec.cell * Vec3(i, j, k);
                        const bool in = (p.array() >= lo.array() - 1e-12).all() &&
                                        (p.array() <= lo.array() + spec.cell + 1e-12).all();
                        covered = in && g.occupied(i, j, k);
                    }
            EXPECT_TRUE(covered);
        }
    }
}
