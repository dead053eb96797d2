// Centre sampling (centre_sampled.h), the construction a grid falls back to when its conservative
// cells miss the genus of S: cells touching only along an edge are joined or separated as S has them,
// thin parts are grown back, and on the shapes where conservative cells merge or close up it keeps the
// genus of S on every grid where a cell fits through the gaps.

#include <algorithm>
#include <cmath>
#include <vector>

#include <gtest/gtest.h>

#include "core/pipeline/z0_choice.h"
#include "core/voxel/centre_sampled.h"
#include "core/voxel/extract.h"
#include "core/voxel/initial_model.h"
#include "core/voxel/repair.h"
#include "core/voxel/voxelize.h"
#include "tests/support/paths.h"
#include "tests/voxel/voxel_test_support.h"

using namespace zomeify;
using namespace zomeify::voxel_test;

namespace {

struct Box
{
    Vec3 lo, hi;
    bool contains(const Vec3& p) const { return (p.array() > lo.array()).all() && (p.array() < hi.array()).all(); }
    double distance_to_surface(const Vec3& p) const
    {
        if (contains(p))
            return std::min((p - lo).minCoeff(), (hi - p).minCoeff());
        return (p.cwiseMax(lo).cwiseMin(hi) - p).norm();
    }
};

// Two 2×2×2 blocks of cells (unit cells, grid 7³) that meet only along the edge x = y = 3, and "S" made
// of boxes: the blocks' own boxes shrunk by 0.3 (S has a gap between them), or the same plus a bar
// along the diagonal (S is continuous there).
struct EdgeContact
{
    VoxelGrid grid;
    std::vector<Box> boxes;

    explicit EdgeContact(bool s_continuous)
        : grid([] {
              GridSpec spec;
              spec.dims = {7, 7, 7};
              return spec;
          }())
    {
        for (int k = 2; k <= 3; ++k)
            for (int a = 0; a < 2; ++a)
                for (int b = 0; b < 2; ++b)
                {
                    grid.set(1 + a, 1 + b, k, Cell::Surface);
                    grid.set(3 + a, 3 + b, k, Cell::Surface);
                }
        boxes = {{Vec3(1.3, 1.3, 2.3), Vec3(2.7, 2.7, 3.7)}, {Vec3(3.3, 3.3, 2.3), Vec3(4.7, 4.7, 3.7)}};
        if (s_continuous) // a bar from the first block's corner cell to the second's, covering the diagonal
            for (double t = 2.4; t <= 3.6; t += 0.1)
                boxes.push_back({Vec3(t - 0.2, t - 0.2, 2.3), Vec3(t + 0.2, t + 0.2, 3.7)});
    }

    InsidePredicate inside() const
    {
        return [this](const Vec3& p) {
            return std::any_of(boxes.begin(), boxes.end(), [&](const Box& b) { return b.contains(p); });
        };
    }
    SurfaceProbeAt probe() const
    {
        return [this](const Vec3& p) {
            SurfaceProbe s;
            s.distance = 1e9;
            for (const Box& b : boxes)
                s.distance = std::min(s.distance, b.distance_to_surface(p));
            return s;
        };
    }
};

BoundaryTopology topology_of(const VoxelGrid& g) { return extract_boundary(g).topology; }

// The two blocks after centre sampling (which must leave them manifold).
BoundaryTopology sampled(bool s_continuous)
{
    EdgeContact c(s_continuous);
    EXPECT_GT(count_nonmanifold_vertices(c.grid), 0u) << "the blocks meet along an edge";
    EXPECT_TRUE(centre_sample(c.grid, c.inside(), c.probe()).manifold);
    return topology_of(c.grid);
}

} // namespace

TEST(CentreSampled, CellsMeetingAcrossAGapOfSAreSeparated)
{
    const BoundaryTopology t = sampled(false);
    EXPECT_EQ(t.components, 2) << "two blocks, as S has them";
    EXPECT_EQ(t.genus, 0);
}

TEST(CentreSampled, CellsMeetingWhereSIsContinuousAreJoined)
{
    const BoundaryTopology t = sampled(true);
    EXPECT_EQ(t.components, 1) << "one body, as S has it";
    EXPECT_EQ(t.genus, 0);
}

TEST(CentreSampled, AThinHandleIsGrownBackWithItsHole)
{
    // The mug's handle is 1.25 cells thick at 10 cells, 1.6 at 13: cells along it have their centres
    // outside it and are grown back, and the set has the mug's one hole. (At 8 cells, where the
    // handle is one cell thick, centre sampling loses it; the conservative cells keep it there.)
    const LoadedSurface& s = generated_surface("mug");
#ifdef ZOME_SANITIZED
    const std::vector<int> grids = {10};
#else
    const std::vector<int> grids = {10, 13};
#endif
    for (int r : grids)
    {
        GridLayoutOptions layout;
        layout.resolution = r;
        const auto box = bounding_box(s.mesh);
        VoxelGrid grid = voxelize(s.mesh, layout_grid(box[0], box[1], layout), s.predicate());
        const CentreSampleReport report = centre_sample(grid, s.predicate(), probe_of(*s.projector));
        ASSERT_TRUE(report.manifold) << r;
        EXPECT_GT(report.grown, 0u) << r;
        const BoundaryTopology t = topology_of(grid);
        EXPECT_EQ(t.components, 1) << r;
        EXPECT_EQ(t.genus, 1) << r;
    }
}

TEST(CentreSampled, KnotStrandsStayApartOnEveryGridWhereACellFitsBetweenThem)
{
    // The trefoil's strands pass 0.41 apart (longest side 6.28): a cell fits between them from 16 cells.
    // Its conservative cells merge them into extra handles on every grid from 11 to 32.
    const LoadedSurface& s = generated_surface("trefoil");
#ifdef ZOME_SANITIZED
    const std::vector<int> grids = {16};
#else
    std::vector<int> grids;
    for (int r = 16; r <= 32; ++r)
        grids.push_back(r);
#endif
    int sampled = 0;
    for (int r : grids)
    {
        const InitialModel z0 = build_initial_model(s.mesh, s.predicate(), run_z0_options(*s.projector, 1, r, 0.0));
        EXPECT_TRUE(z0.report.valid) << r;
        EXPECT_EQ(z0.report.topology.genus, 1) << r << " cells";
        EXPECT_EQ(z0.report.topology.components, 1) << r << " cells";
        sampled += z0.report.centre_sampled ? 1 : 0;
    }
    EXPECT_GT(sampled, 0) << "some grid needed centre sampling";
    InitialModelOptions without = run_z0_options(*s.projector, 1, 20, 0.0);
    without.centre_sampling = false;
    EXPECT_NE(build_initial_model(s.mesh, s.predicate(), without).report.topology.genus, 1)
        << "without centre sampling the strands merge at 20 cells";
}

TEST(CentreSampled, FertilityKeepsItsFourHolesOnEveryGridFromTenCells)
{
    ZOME_REQUIRE_SHARED();
    const LoadedSurface& s = shared_surface("fertility");
#ifdef ZOME_SANITIZED
    const std::vector<int> grids = {13, 14};
#else
    std::vector<int> grids;
    for (int r = 10; r <= 32; ++r)
        grids.push_back(r);
#endif
    for (int r : grids)
    {
        const InitialModel z0 = build_initial_model(s.mesh, s.predicate(), run_z0_options(*s.projector, 4, r, 0.0));
        EXPECT_TRUE(z0.report.valid) << r;
        EXPECT_EQ(z0.report.topology.genus, 4) << r << " cells";
        EXPECT_EQ(z0.report.topology.components, 1) << r << " cells";
    }
}
