// Repairs that make a usable surface out of a flawed one, each reported.
#include <Eigen/Geometry>
#include <gtest/gtest.h>

#include "core/base/errors.h"
#include "core/surface/prepare.h"
#include "core/surface/read_mesh.h"
#include "core/surface/triangulate.h"
#include "core/surface/weld.h"
#include "tests/surface/surface_fixtures.h"

namespace zomeify::surface_test {
namespace {

bool mentions(const std::vector<std::string>& lines, const std::string& word)
{
    for (const auto& l : lines)
        if (l.find(word) != std::string::npos)
            return true;
    return false;
}

// Every vertex is one of: kept, welded away, unused, or non-finite.
void expect_vertex_balance(const SurfaceReport& r)
{
    EXPECT_EQ(r.input_vertices, r.vertices + r.welded_vertices + r.unreferenced_vertices + r.non_finite_vertices);
}

TEST(SurfacePrepare, InwardNormalsAreFlipped)
{
    const PreparedSurface p = prepare_surface(reversed(cube_triangles()));
    EXPECT_EQ(p.report.flipped_faces, 12u);
    EXPECT_TRUE(mentions(p.report.repairs, "flipped 12 faces"));
    EXPECT_NEAR(signed_volume(p.mesh), 1.0, 1e-12);
}

TEST(SurfacePrepare, InconsistentFacesAreOrientedLikeTheirNeighbours)
{
    PolygonSoup soup = cube_triangles();
    std::reverse(soup.polygons[3].begin(), soup.polygons[3].end());
    std::reverse(soup.polygons[8].begin(), soup.polygons[8].end());
    const PreparedSurface p = prepare_surface(soup);
    EXPECT_EQ(p.report.flipped_faces, 2u);
    EXPECT_NEAR(signed_volume(p.mesh), 1.0, 1e-12);
}

TEST(SurfacePrepare, QuadsAndPentagonsAreTriangulated)
{
    const PreparedSurface p = prepare_surface(pentagonal_prism());
    EXPECT_EQ(p.report.triangulated_polygons, 7u);
    EXPECT_EQ(p.report.faces, 2u * 3 + 5 * 2);
    EXPECT_EQ(p.report.vertices, 10u);
    EXPECT_TRUE(p.report.closed);
    EXPECT_TRUE(mentions(p.report.repairs, "triangulated 7 polygons"));
    EXPECT_NEAR(signed_volume(p.mesh), 2.5 * std::sin(2 * 3.14159265358979 / 5), 1e-12);
}

TEST(SurfacePrepare, NonConvexPolygonIsEarClipped)
{
    // An L-shaped hexagon: a fan from its first corner would cover the notch and fold over.
    const PreparedSurface p = prepare_surface(l_prism());
    EXPECT_EQ(p.report.triangulated_polygons, 8u);
    EXPECT_EQ(p.report.faces, 2u * 4 + 6 * 2);
    EXPECT_NEAR(signed_volume(p.mesh), 3.0, 1e-12);
    // Each triangle of the caps points the way its cap does (no fold-over).
    for (const auto& t : p.mesh.triangles)
    {
        const Vec3 n =
            (p.mesh.positions[t[1]] - p.mesh.positions[t[0]]).cross(p.mesh.positions[t[2]] - p.mesh.positions[t[0]]);
        const double z = p.mesh.positions[t[0]].z();
        if (std::abs(n.x()) + std::abs(n.y()) < 1e-12)
        {
            EXPECT_GT(z > 0.5 ? n.z() : -n.z(), 0);
        }
    }
}

TEST(SurfacePrepare, TriangulateKeepsAreaOfStars)
{
    // Stars (non-convex 2k-gons) in the plane z = 0, up to the ear-clipping size limit.
    for (const int points : {5, 64, 128})
    {
        SCOPED_TRACE(points);
        std::vector<Vec3> positions;
        std::vector<uint32_t> polygon;
        for (int i = 0; i < 2 * points; ++i)
        {
            const double r = i % 2 ? 0.4 : 1.0;
            const double a = 3.14159265358979 * i / points;
            positions.push_back(Vec3(r * std::cos(a), r * std::sin(a), 0));
            polygon.push_back(static_cast<uint32_t>(i));
        }
        std::vector<std::array<uint32_t, 3>> triangles;
        triangulate_polygon(positions, polygon, triangles);
        ASSERT_EQ(triangles.size(), 2u * points - 2);
        double area = 0;
        for (const auto& t : triangles)
        {
            const double z = (positions[t[1]] - positions[t[0]]).cross(positions[t[2]] - positions[t[0]]).z();
            EXPECT_GT(z, 0);
            area += z / 2;
        }
        EXPECT_NEAR(area, 2 * points * 0.5 * 1.0 * 0.4 * std::sin(3.14159265358979 / points), 1e-12);
    }
}

TEST(SurfacePrepare, DuplicateVerticesAreWelded)
{
    // Separate vertices per face (as STL has): 24 for the cube's 6 quads.
    const PolygonSoup quads = cube_quads();
    PolygonSoup soup;
    for (size_t f = 0; f < quads.polygons.size(); ++f)
    {
        std::vector<uint32_t> p;
        for (const auto i : quads.polygons[f])
        {
            p.push_back(static_cast<uint32_t>(soup.positions.size()));
            soup.positions.push_back(quads.positions[i] + Vec3(1e-12, 0, 0) * static_cast<double>(f % 2));
        }
        soup.polygons.push_back(p);
    }
    const PreparedSurface p = prepare_surface(soup);
    EXPECT_EQ(p.report.welded_vertices, 16u);
    EXPECT_EQ(p.report.vertices, 8u);
    EXPECT_TRUE(mentions(p.report.repairs, "welded 16 duplicate vertices"));
    expect_vertex_balance(p.report);
    // With exact welding only, the 1e-12 offsets keep some apart and the surface opens.
    PrepareOptions exact;
    exact.weld_tolerance = 0;
    EXPECT_FALSE(diagnose(soup, exact).closed);
}

TEST(SurfacePrepare, WeldIsLinearAndFindsNeighboursAcrossCells)
{
    std::vector<Vec3> positions;
    for (int i = 0; i < 20000; ++i)
        positions.push_back(Vec3(i * 0.01, 0, 0));
    for (int i = 0; i < 20000; ++i)
        positions.push_back(Vec3(i * 0.01 + 4e-4, 4e-4, -4e-4)); // within 1e-3 of its twin
    const std::vector<uint32_t> target = weld_vertices(positions, 1e-3, std::vector<bool>(positions.size(), false));
    for (size_t i = 0; i < 20000; ++i)
    {
        EXPECT_EQ(target[i], i);
        EXPECT_EQ(target[20000 + i], i);
    }
}

TEST(SurfacePrepare, DegenerateAndDuplicateFacesAreDropped)
{
    PolygonSoup soup = cube_triangles();
    soup.polygons.push_back({0, 0, 1});    // repeated index
    soup.polygons.push_back({0, 1, 0, 1}); // collapses to an edge
    soup.polygons.push_back(soup.polygons[0]);
    soup.polygons.push_back({soup.polygons[1][1], soup.polygons[1][2], soup.polygons[1][0]}); // rotated copy
    soup.positions.push_back(Vec3(0.5, 0, 0)); // on the edge 0-1: a zero-area triangle
    soup.polygons.push_back({0, 1, 8});
    const PreparedSurface p = prepare_surface(soup);
    EXPECT_EQ(p.report.dropped_degenerate_faces, 3u);
    EXPECT_EQ(p.report.dropped_duplicate_faces, 2u);
    EXPECT_EQ(p.report.unreferenced_vertices, 1u);
    EXPECT_EQ(p.report.faces, 12u);
    expect_vertex_balance(p.report);
}

TEST(SurfacePrepare, FacesWithOneOrTwoVerticesAreDropped)
{
    const std::string obj = to_obj(cube_quads()) + "f 1\nf 1 2\n";
    const PreparedSurface p = prepare_surface(read_mesh_buffer(bytes_of(obj), "cube.obj"));
    EXPECT_EQ(p.report.dropped_small_faces, 2u);
    EXPECT_TRUE(mentions(p.report.repairs, "fewer than 3 vertices"));
    EXPECT_TRUE(p.report.ok());
}

TEST(SurfacePrepare, SeparateClosedComponentsAreAllowed)
{
    const PolygonSoup soup = merge(cube_quads(), reversed(cube_quads(Vec3(3, 0, 0))));
    const PreparedSurface p = prepare_surface(soup);
    EXPECT_EQ(p.report.components, 2u);
    EXPECT_EQ(p.report.genus, 0);
    EXPECT_EQ(p.report.euler, 4);
    EXPECT_EQ(p.report.flipped_faces, 12u); // only the second, inverted cube
    EXPECT_NEAR(signed_volume(p.mesh), 2.0, 1e-12);
}

TEST(SurfacePrepare, NestedShellsBoundCavities)
{
    // Cubes of side 5, 3 and 1 around one centre: the middle one is a cavity (faces inward), the
    // innermost is a solid island inside it (faces outward), whatever orientation they came with.
    const auto cube = [](double side) {
        PolygonSoup c = cube_quads(Vec3::Constant(-0.5));
        for (Vec3& p : c.positions)
            p *= side;
        return c;
    };
    const PreparedSurface p = prepare_surface(merge(merge(cube(5), cube(3)), cube(1)));
    EXPECT_EQ(p.report.components, 3u);
    EXPECT_EQ(p.report.cavities, 1u);
    EXPECT_EQ(p.report.flipped_faces, 12u); // the middle cube's 12 triangles
    EXPECT_NEAR(signed_volume(p.mesh), 125.0 - 27.0 + 1.0, 1e-9);
    EXPECT_TRUE(mentions(p.report.repairs, "(cavities inward)"));

    const PreparedSurface q = prepare_surface(merge(reversed(cube(5)), reversed(cube(3))));
    EXPECT_EQ(q.report.flipped_faces, 12u); // only the outer cube
    EXPECT_NEAR(signed_volume(q.mesh), 125.0 - 27.0, 1e-9);
}

TEST(SurfacePrepare, TorusOfQuadsHasGenusOne)
{
    // A coarse 8 x 6 quad torus built here, to check genus without the shared data.
    PolygonSoup soup;
    const int n = 8, m = 6;
    for (int i = 0; i < n; ++i)
        for (int j = 0; j < m; ++j)
        {
            const double u = 2 * 3.14159265358979 * i / n, v = 2 * 3.14159265358979 * j / m;
            soup.positions.push_back(
                Vec3((2 + std::cos(v)) * std::cos(u), (2 + std::cos(v)) * std::sin(u), std::sin(v)));
        }
    const auto id = [&](int i, int j) { return static_cast<uint32_t>(((i + n) % n) * m + (j + m) % m); };
    for (int i = 0; i < n; ++i)
        for (int j = 0; j < m; ++j)
            soup.polygons.push_back({id(i, j), id(i + 1, j), id(i + 1, j + 1), id(i, j + 1)});
    const PreparedSurface p = prepare_surface(soup);
    EXPECT_EQ(p.report.genus, 1);
    EXPECT_EQ(p.report.euler, 0);
    EXPECT_GT(signed_volume(p.mesh), 0);
}

} // namespace
} // namespace zomeify::surface_test
