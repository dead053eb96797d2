// Carving (carve.h): on shared meshes, the carved cell set is the conservative one minus cells whose
// centre lies outside S, keeps the topology (genus, one component) and a manifold boundary, adds no
// face that points against S, and brings Z0 closer to S.

#include <cmath>
#include <string>

#include <gtest/gtest.h>

#include "core/voxel/carve.h"
#include "core/voxel/extract.h"
#include "core/voxel/repair.h"
#include "core/voxel/voxelize.h"
#include "tests/support/geom_fixtures.h"
#include "tests/support/paths.h"
#include "tests/voxel/voxel_test_support.h"

using namespace zomeify;
using namespace zomeify::voxel_test;

namespace {

template <class NormalAt>
size_t fold_over_faces(const VoxelGrid& g, const NormalAt& normal_at)
{
    size_t count = 0;
    const auto& d = g.dims();
    for (int k = 0; k < d[2]; ++k)
        for (int j = 0; j < d[1]; ++j)
            for (int i = 0; i < d[0]; ++i)
                for (int axis = 0; axis < 3; ++axis)
                    for (int side = -1; side <= 1; side += 2)
                    {
                        int n[3] = {i, j, k};
                        n[axis] += side;
                        if (!g.occupied(i, j, k) || g.occupied(n[0], n[1], n[2]))
                            continue;
                        Vec3 c = g.cell_centre(i, j, k);
                        c[axis] += 0.5 * side * g.spec().cell;
                        count += normal_at(c)[axis] * side < 0.0 ? 1 : 0;
                    }
    return count;
}

// RMS distance from the model's nodes to S, in mesh units.
double node_rms(const ZomeModel& model, const SurfaceProjector& projector)
{
    const auto& t = model.transform;
    double sum = 0.0;
    for (const ZVec& node : model.nodes)
    {
        const auto z = node.to_double();
        const Vec3 p(t.scale * z[0] + t.translation[0], t.scale * z[1] + t.translation[1],
                     t.scale * z[2] + t.translation[2]);
        sum += projector.project(p).distance_squared;
    }
    return std::sqrt(sum / static_cast<double>(model.nodes.size()));
}

} // namespace

TEST(VoxelCarve, KeepsTopologyAndFacesAlongSOnSharedMeshes)
{
    ZOME_REQUIRE_SHARED();
    for (const std::string name : {"fertility", "rockerarm", "bunny", "elk", "3holes"})
    {
        SCOPED_TRACE(name);
        const LoadedSurface& s = shared_surface(name);
        GridLayoutOptions layout;
        layout.resolution = 16;
        const auto box = bounding_box(s.mesh);
        const GridSpec spec = layout_grid(box[0], box[1], layout);
        VoxelGrid before = voxelize(s.mesh, spec, s.predicate());
        ASSERT_TRUE(repair_manifold(before).manifold);
        VoxelGrid after = before;
        const auto normal_at = [&](const Vec3& p) { return s.projector->project(p).normal; };
        const CarveReport report = carve_outside_cells(after, s.predicate(), probe_of(*s.projector));
        EXPECT_GT(report.removed, 0u);
        EXPECT_EQ(before.occupied_count() - after.occupied_count(), report.removed - report.restored);
        EXPECT_EQ(count_nonmanifold_vertices(after), 0u);

        const auto& d = spec.dims;
        for (int k = 0; k < d[2]; ++k)
            for (int j = 0; j < d[1]; ++j)
                for (int i = 0; i < d[0]; ++i)
                {
                    if (after.occupied(i, j, k))
                    {
                        ASSERT_TRUE(before.occupied(i, j, k)) << "carving only removes (or puts back)";
                    }
                    else if (before.occupied(i, j, k))
                    {
                        ASSERT_FALSE(s.inside->is_inside(after.cell_centre(i, j, k))) << "carved a cell inside S";
                    }
                }
        // Fold-overs (boundary faces turned against S's normal) are defects the annealer must undo:
        // carving must not add any.
        EXPECT_LE(fold_over_faces(after, normal_at), fold_over_faces(before, normal_at));

        const Extraction plain = extract_boundary(before);
        const Extraction carved = extract_boundary(after);
        EXPECT_EQ(carved.topology.genus, plain.topology.genus);
        EXPECT_EQ(carved.topology.components, plain.topology.components);
        EXPECT_EQ(closed_manifold_problem(carved.model), "");
        EXPECT_EQ(halfedge_problem(carved.model), "");
        EXPECT_LT(node_rms(carved.model, *s.projector), 0.8 * node_rms(plain.model, *s.projector));
    }
}

TEST(VoxelCarve, WithoutANormalCheckEveryOutsideCentreThatCanGoGoes)
{
    // A sphere: every occupied cell whose centre is outside is simple and removable layer by layer,
    // so what is left is exactly the cells with their centre inside.
    const TriangleMesh sphere = test::make_icosphere(1.0, 4);
    const SurfaceProjector projector(sphere);
    const InsideTest inside(projector);
    const InsidePredicate predicate = [&](const Vec3& p) { return inside.is_inside(p); };
    GridLayoutOptions layout;
    layout.resolution = 10;
    const auto box = bounding_box(sphere);
    VoxelGrid g = voxelize(sphere, layout_grid(box[0], box[1], layout), predicate);
    ASSERT_TRUE(repair_manifold(g).manifold);
    carve_outside_cells(g, predicate);
    const auto& d = g.dims();
    for (int k = 0; k < d[2]; ++k)
        for (int j = 0; j < d[1]; ++j)
            for (int i = 0; i < d[0]; ++i)
                EXPECT_EQ(g.occupied(i, j, k), predicate(g.cell_centre(i, j, k))) << i << " " << j << " " << k;
}

namespace {

// A square frame of 5 x 5 cells one cell thick (cells (1..5, 1..5, 1) but not the 3 x 3 inside), the
// only cells whose centres are "inside S", with a bar of outside cells across its hole (y = 3):
// the bar splits the one hole into two, so the object has genus 2 where S has genus 1.
struct BridgedFrame
{
    VoxelGrid grid;
    InsidePredicate inside;
};

BridgedFrame bridged_frame()
{
    GridSpec s;
    s.origin = Vec3(0, 0, 0);
    s.cell = 1.0;
    s.dims = {7, 7, 3};
    BridgedFrame f{VoxelGrid(s), nullptr};
    const auto in_frame = [](int i, int j, int k) {
        return k == 1 && i >= 1 && i <= 5 && j >= 1 && j <= 5 && (i == 1 || i == 5 || j == 1 || j == 5);
    };
    for (int i = 1; i <= 5; ++i)
        for (int j = 1; j <= 5; ++j)
            if (in_frame(i, j, 1) || j == 3)
                f.grid.set(i, j, 1, Cell::Surface);
    f.inside = [in_frame](const Vec3& p) {
        return in_frame(static_cast<int>(std::floor(p[0])), static_cast<int>(std::floor(p[1])),
                        static_cast<int>(std::floor(p[2])));
    };
    return f;
}

} // namespace

TEST(VoxelCarve, KeepCannotOpenABarAcrossAHoleFreeCan)
{
    BridgedFrame keep = bridged_frame();
    ASSERT_EQ(extract_boundary(keep.grid).topology.genus, 2);
    const CarveReport kept = carve_outside_cells(keep.grid, keep.inside, nullptr, CarveTopology::Keep);
    EXPECT_EQ(kept.removed, 0u) << "every bar cell holds a tunnel on each side: none is simple";
    EXPECT_EQ(extract_boundary(keep.grid).topology.genus, 2);

    BridgedFrame free = bridged_frame();
    const CarveReport freed = carve_outside_cells(free.grid, free.inside, nullptr, CarveTopology::Free);
    EXPECT_EQ(freed.removed, 3u);
    const Extraction z0 = extract_boundary(free.grid);
    EXPECT_EQ(z0.topology.genus, 1);
    EXPECT_EQ(z0.topology.components, 1);
    EXPECT_EQ(closed_manifold_problem(z0.model), "");
    const auto& d = free.grid.dims();
    for (int k = 0; k < d[2]; ++k)
        for (int j = 0; j < d[1]; ++j)
            for (int i = 0; i < d[0]; ++i)
                EXPECT_EQ(free.grid.occupied(i, j, k), free.inside(free.grid.cell_centre(i, j, k)))
                    << i << " " << j << " " << k;
}
