// Meshes from the wild (issue 36): every mesh of the corpus is repaired into a closed 2-manifold of
// the expected genus with its repairs listed in plain words, or refused in one line with the real
// reason. The pieces (splitting, hole filling) are tested on their own below.
#include <algorithm>
#include <map>

#include <gtest/gtest.h>

#include <Eigen/Geometry>

#include "core/base/errors.h"
#include "core/surface/fill_holes.h"
#include "core/surface/prepare.h"
#include "core/surface/read_mesh.h"
#include "core/surface/split_non_manifold.h"
#include "tests/surface/surface_fixtures.h"
#include "tests/surface/wild_corpus.h"

namespace zomeify::surface_test {
namespace {

using Triangle = std::array<uint32_t, 3>;

std::string joined(const std::vector<std::string>& lines)
{
    std::string s;
    for (const std::string& l : lines)
        s += (s.empty() ? "" : "; ") + l;
    return s;
}

// Every undirected edge has exactly two faces, running along it in opposite directions (with
// `seams`, an edge may also have one face: the crossing curves of joined overlapping parts).
::testing::AssertionResult closed_and_oriented(const TriangleMesh& m, bool seams = false)
{
    std::map<std::pair<uint32_t, uint32_t>, int> directed;
    for (const Triangle& t : m.triangles)
        for (int c = 0; c < 3; ++c)
            ++directed[{t[c], t[(c + 1) % 3]}];
    for (const auto& [edge, n] : directed)
    {
        const auto back = directed.find({edge.second, edge.first});
        if (n != 1 || (back == directed.end() && !seams) || (back != directed.end() && back->second != 1))
            return ::testing::AssertionFailure()
                   << "edge " << edge.first << "-" << edge.second << " used " << n << " times one way and "
                   << (back == directed.end() ? 0 : back->second) << " the other";
    }
    return ::testing::AssertionSuccess();
}

TEST(WildMeshes, EachIsRepairedToItsGenusOrRefusedWithItsReason)
{
    for (const WildMesh& w : wild_corpus())
    {
        SCOPED_TRACE(w.name);
        const SurfaceReport r = diagnose(w.soup);
        if (!w.refusal.empty())
        {
            ASSERT_FALSE(r.ok()) << joined(r.repairs);
            EXPECT_NE(r.problem_summary().find(w.refusal), std::string::npos) << r.problem_summary();
            EXPECT_EQ(r.problem_summary().find('\n'), std::string::npos);
            const std::string thrown = invalid_input_message([&] { prepare_surface(w.soup); });
            EXPECT_EQ(thrown, r.problem_summary());
            continue;
        }
        ASSERT_TRUE(r.ok()) << r.problem_summary();
        EXPECT_TRUE(r.closed);
        EXPECT_TRUE(r.manifold);
        EXPECT_EQ(r.genus, w.genus);
        for (const std::string& words : w.repairs)
            EXPECT_NE(joined(r.repairs).find(words), std::string::npos)
                << "'" << words << "' not in: " << joined(r.repairs);
        const PreparedSurface p = prepare_surface(w.soup);
        EXPECT_TRUE(closed_and_oriented(p.mesh, p.report.joined_overlapping_parts > 0));
        EXPECT_EQ(p.report.repairs, r.repairs);
    }
}

TEST(WildMeshes, InputDefectsAreReportedBesideTheResult)
{
    PolygonSoup box = cube_quads();
    box.polygons.erase(box.polygons.begin() + 1); // no lid
    const SurfaceReport r = diagnose(box);
    EXPECT_TRUE(r.ok());
    EXPECT_EQ(r.input_holes, 1u);
    EXPECT_EQ(r.input_boundary_edges, 4u);
    EXPECT_EQ(r.filled_holes, 1u);
    EXPECT_EQ(r.holes, 0u);
    EXPECT_EQ(r.boundary_edges, 0u);
}

TEST(WildMeshes, ClosedMeshesAreLeftAsTheyWere)
{
    // No repair of issue 36 may touch a closed, manifold mesh: same vertices, same faces.
    const PolygonSoup cube = cube_triangles();
    const PreparedSurface p = prepare_surface(cube);
    EXPECT_EQ(p.mesh.positions.size(), 8u);
    ASSERT_EQ(p.mesh.triangles.size(), cube.polygons.size());
    for (size_t f = 0; f < cube.polygons.size(); ++f)
        EXPECT_EQ((std::vector<uint32_t>{p.mesh.triangles[f][0], p.mesh.triangles[f][1], p.mesh.triangles[f][2]}),
                  cube.polygons[f]);
    EXPECT_EQ(p.report.filled_holes + p.report.separated_pinched_vertices + p.report.separated_edges +
                  p.report.dropped_specks + p.report.dropped_sheets,
              0u);
}

TEST(FillHoles, LeastAreaPatchOfASquareHoleIsTwoTrianglesOfItsArea)
{
    // A unit square hole in the plane z = 0 at the top of a pyramid: the patch covers exactly it.
    std::vector<Vec3> positions = {Vec3(0, 0, 0), Vec3(1, 0, 0), Vec3(1, 1, 0), Vec3(0, 1, 0), Vec3(0.5, 0.5, -1)};
    std::vector<Triangle> triangles = {{0, 4, 1}, {1, 4, 2}, {2, 4, 3}, {3, 4, 0}};
    std::vector<uint32_t> origin = {0, 1, 2, 3, 4};
    const HoleFilling filled = fill_holes(positions, triangles, origin);
    ASSERT_EQ(filled.holes.size(), 1u);
    EXPECT_EQ(filled.holes[0].edges, 4u);
    EXPECT_EQ(filled.holes[0].patch_faces, 2u);
    EXPECT_NEAR(filled.holes[0].area, 1.0, 1e-12);
    EXPECT_EQ(positions.size(), 5u);
    EXPECT_TRUE(closed_and_oriented({positions, triangles}));
}

TEST(FillHoles, StraightRimsGetNoFlatTriangles)
{
    // A hole whose rim has three collinear vertices on each side: a least-area triangulation that
    // ignored them could join three collinear vertices into a triangle of zero area.
    std::vector<Vec3> positions;
    for (int i = 0; i < 3; ++i)
        positions.push_back(Vec3(i, 0, 0));
    for (int i = 0; i < 3; ++i)
        positions.push_back(Vec3(2 - i, 1, 0));
    positions.push_back(Vec3(1, 0.5, -1));
    std::vector<Triangle> triangles;
    for (uint32_t i = 0; i < 6; ++i)
        triangles.push_back({i, 6, (i + 1) % 6});
    std::vector<uint32_t> origin(positions.size());
    const HoleFilling filled = fill_holes(positions, triangles, origin);
    ASSERT_EQ(filled.holes.size(), 1u);
    for (size_t t = filled.holes[0].first_patch; t < triangles.size(); ++t)
    {
        const auto& f = triangles[t];
        EXPECT_GT((positions[f[1]] - positions[f[0]]).cross(positions[f[2]] - positions[f[0]]).norm(), 1e-9);
    }
    EXPECT_NEAR(filled.holes[0].area, 2.0, 1e-12);
}

TEST(FillHoles, OverflowingAreasStillGiveATriangulation)
{
    // Coordinates near 1e160: every area overflows to infinity, and the patch must still be the
    // n - 2 triangles of a triangulation (not a loop over an unset split).
    std::vector<Vec3> positions;
    const size_t n = 9;
    for (size_t i = 0; i < n; ++i)
        positions.push_back(1e160 * Vec3(std::cos(0.7 * double(i)), std::sin(0.7 * double(i)), 0));
    positions.push_back(Vec3(0, 0, -1e160));
    std::vector<Triangle> triangles;
    for (uint32_t i = 0; i < n; ++i)
        triangles.push_back({i, static_cast<uint32_t>(n), static_cast<uint32_t>((i + 1) % n)});
    std::vector<uint32_t> origin(positions.size());
    const HoleFilling filled = fill_holes(positions, triangles, origin);
    ASSERT_EQ(filled.holes.size(), 1u);
    EXPECT_EQ(filled.holes[0].patch_faces, n - 2);
}

TEST(FillHoles, LongLoopsGetACentroidFanWithOneNewVertex)
{
    // A cone open at its base: a loop longer than the exact triangulation takes.
    const size_t n = kMaxExactLoop + 10;
    std::vector<Vec3> positions;
    for (size_t i = 0; i < n; ++i)
        positions.push_back(
            Vec3(std::cos(6.283185307179586 * double(i) / n), std::sin(6.283185307179586 * double(i) / n), 0));
    positions.push_back(Vec3(0, 0, 1));
    std::vector<Triangle> triangles;
    for (uint32_t i = 0; i < n; ++i)
        triangles.push_back({i, static_cast<uint32_t>((i + 1) % n), static_cast<uint32_t>(n)});
    std::vector<uint32_t> origin(positions.size());
    const HoleFilling filled = fill_holes(positions, triangles, origin);
    ASSERT_EQ(filled.holes.size(), 1u);
    EXPECT_EQ(filled.holes[0].patch_faces, n);
    EXPECT_EQ(positions.size(), n + 2);
    EXPECT_EQ(origin.back(), 0xFFFFFFFFu);
    EXPECT_TRUE(closed_and_oriented({positions, triangles}));
}

TEST(SplitNonManifold, TwoCubesSharingAnEdgeBecomeTwoClosedCubes)
{
    const PolygonSoup two = merge(cube_triangles(), cube_triangles(Vec3(1, 1, 0)));
    // Weld the shared edge's corners by hand: (1,1,0) and (1,1,1) are vertices 3, 7 and 8, 12.
    std::vector<Vec3> positions(two.positions.begin(), two.positions.begin() + 8);
    std::vector<uint32_t> map(16);
    for (uint32_t i = 0; i < 8; ++i)
        map[i] = i;
    for (uint32_t i = 8; i < 16; ++i)
    {
        const Vec3& p = two.positions[i];
        map[i] = p == positions[3] ? 3 : p == positions[7] ? 7 : static_cast<uint32_t>(positions.size());
        if (map[i] == positions.size())
            positions.push_back(p);
    }
    std::vector<Triangle> triangles;
    for (const auto& poly : two.polygons)
        triangles.push_back({map[poly[0]], map[poly[1]], map[poly[2]]});
    std::vector<uint32_t> origin(positions.size());
    for (uint32_t i = 0; i < origin.size(); ++i)
        origin[i] = i;
    const NonManifoldSplit split = split_non_manifold(positions, triangles, origin);
    EXPECT_EQ(split.split_edges, 1u);
    EXPECT_EQ(split.loose_faces, 0u);
    EXPECT_EQ(split.pinched_vertices, 0u); // the edge's two ends are counted with the edge
    EXPECT_EQ(positions.size(), 16u);
    EXPECT_EQ(origin[14] == 3 || origin[14] == 7, true); // copies keep their input vertex
    EXPECT_TRUE(closed_and_oriented({positions, triangles}));
}

TEST(WildMeshes, OpenSheetsGivenAThicknessBecomeSlabs)
{
    // Asked for, every sheet the corpus refuses becomes a closed slab of the sheet's genus (0), 3% of
    // its longest side thick: a single triangle a prism, the terrain and the bowl a plate.
    PrepareOptions thicken;
    thicken.thicken_sheets = true;
    size_t sheets = 0;
    for (const WildMesh& w : wild_corpus())
    {
        if (w.refusal.find("open sheet") == std::string::npos)
            continue;
        SCOPED_TRACE(w.name);
        ++sheets;
        const PreparedSurface p = prepare_surface(w.soup, thicken);
        EXPECT_EQ(p.report.genus, 0);
        EXPECT_EQ(p.report.thickened_sheets, 1u);
        EXPECT_TRUE(closed_and_oriented(p.mesh));
        EXPECT_GT(signed_volume(p.mesh), 0.0);
        EXPECT_NE(joined(p.report.repairs).find("gave the open sheet a thickness of"), std::string::npos)
            << joined(p.report.repairs);
        // Without the option the same mesh is still refused.
        EXPECT_FALSE(diagnose(w.soup).ok());
    }
    EXPECT_EQ(sheets, 3u);
    // A unit square: a 1 x 1 x 0.03 slab, 12 triangles.
    PolygonSoup quad;
    quad.positions = {Vec3(0, 0, 0), Vec3(1, 0, 0), Vec3(1, 1, 0), Vec3(0, 1, 0)};
    quad.polygons = {{0, 1, 2, 3}};
    const PreparedSurface slab = prepare_surface(quad, thicken);
    EXPECT_EQ(slab.mesh.triangles.size(), 12u);
    EXPECT_NEAR(signed_volume(slab.mesh), 0.03, 1e-12);
}

TEST(WildMeshes, ThePointCloudFileIsRefusedInOneLine)
{
    const PolygonSoup soup = read_mesh_buffer(bytes_of("v 0 0 0\nv 1 0 0\nv 0 1 0\nv 0 0 1\n"), "cloud.obj");
    const std::string m = invalid_input_message([&] { prepare_surface(soup); });
    EXPECT_EQ(m, "mesh has no faces");
}

} // namespace
} // namespace zomeify::surface_test
