// Boundary extraction: counts, orientation (outward), exact B1 positions and the transform.

#include <gtest/gtest.h>

#include "core/voxel/extract.h"
#include "core/zome/qphi.h"
#include "tests/voxel/voxel_test_support.h"

using namespace zomeify;
using namespace zomeify::voxel_test;

namespace {

VoxelGrid grid_with(std::initializer_list<std::array<int, 3>> cells)
{
    GridSpec s;
    s.origin = Vec3(10, 20, 30);
    s.cell = 0.5;
    s.dims = {6, 6, 6};
    VoxelGrid g(s);
    for (const auto& c : cells)
        g.set(c[0], c[1], c[2], Cell::Surface);
    return g;
}

// Six times the signed volume enclosed by the faces (fan triangulation), in Zome units.
double signed_volume6(const ZomeModel& m)
{
    double v = 0.0;
    for (const auto& f : m.faces)
    {
        const auto a = m.nodes[f[0]].to_double();
        for (size_t q = 1; q + 1 < f.size(); ++q)
        {
            const auto b = m.nodes[f[q]].to_double(), c = m.nodes[f[q + 1]].to_double();
            v += a[0] * (b[1] * c[2] - b[2] * c[1]) - a[1] * (b[0] * c[2] - b[2] * c[0]) +
                 a[2] * (b[0] * c[1] - b[1] * c[0]);
        }
    }
    return v;
}

} // namespace

TEST(VoxelExtract, OneCell)
{
    const Extraction ex = extract_boundary(grid_with({{1, 2, 3}}));
    EXPECT_EQ(ex.model.nodes.size(), 8u);
    EXPECT_EQ(ex.model.struts.size(), 12u);
    EXPECT_EQ(ex.model.faces.size(), 6u);
    EXPECT_EQ(ex.topology.euler, 2);
    EXPECT_EQ(ex.topology.components, 1);
    EXPECT_EQ(ex.topology.genus, 0);
    EXPECT_EQ(closed_manifold_problem(ex.model), "");
    EXPECT_EQ(lattice_problem(ex.model), "");
    // Counter-clockwise from outside: positive volume, b1³ = φ³ in Zome units.
    EXPECT_NEAR(signed_volume6(ex.model), 6.0 * kPhi * kPhi * kPhi, 1e-9);
    // The corner (1, 2, 3) is the node [2, 0, 4, 0, 6, 0] and maps to the cell's corner in the mesh.
    EXPECT_EQ(grid_corner_node(1, 2, 3), (ZVec{{2, 0, 4, 0, 6, 0}}));
    EXPECT_NEAR(ex.model.transform.scale * kPhi, 0.5, 1e-12);
    const auto p = grid_corner_node(1, 2, 3).to_double();
    EXPECT_NEAR(ex.model.transform.scale * p[0] + ex.model.transform.translation[0], 10.5, 1e-12);
    EXPECT_NEAR(ex.model.transform.scale * p[1] + ex.model.transform.translation[1], 21.0, 1e-12);
    EXPECT_NEAR(ex.model.transform.scale * p[2] + ex.model.transform.translation[2], 31.5, 1e-12);
}

TEST(VoxelExtract, BlockAndRing)
{
    const Extraction two = extract_boundary(grid_with({{1, 1, 1}, {2, 1, 1}}));
    EXPECT_EQ(two.model.nodes.size(), 12u);
    EXPECT_EQ(two.model.struts.size(), 20u);
    EXPECT_EQ(two.model.faces.size(), 10u);
    EXPECT_EQ(closed_manifold_problem(two.model), "");

    // A 3×3 ring of 8 cells around an empty centre: a torus.
    const Extraction ring = extract_boundary(
        grid_with({{1, 1, 1}, {2, 1, 1}, {3, 1, 1}, {1, 2, 1}, {3, 2, 1}, {1, 3, 1}, {2, 3, 1}, {3, 3, 1}}));
    EXPECT_EQ(ring.topology.genus, 1);
    EXPECT_EQ(halfedge_problem(ring.model), "");
    EXPECT_EQ(closed_manifold_problem(ring.model), "");
    EXPECT_EQ(lattice_problem(ring.model), "");
    EXPECT_NEAR(signed_volume6(ring.model), 6.0 * 8 * kPhi * kPhi * kPhi, 1e-9);
}
