// Acceptance (issue 3): every mesh in the shared folder reads with the V, F, closedness and genus
// listed in its README, needs no repair, and comes out outward-oriented.
#include <gtest/gtest.h>

#include "core/surface/prepare.h"
#include "core/surface/read_mesh.h"
#include "tests/support/paths.h"
#include "tests/surface/surface_fixtures.h"

namespace zomeify::surface_test {
namespace {

using test::shared_path;
using test::temp_path;

struct SharedMesh
{
    const char* file;
    long long genus;
    size_t vertices;
    size_t faces;
};

// From data/meshes/README.md.
const SharedMesh shared_meshes[] = {
    {"fertility.obj", 4, 4494, 9000}, {"rockerarm.obj", 1, 10044, 20088}, {"bunny.obj", 0, 3301, 6598},
    {"elk.obj", 1, 5194, 10388},      {"torus.obj", 1, 2304, 4608},       {"sphere.obj", 0, 642, 1280},
    {"cube.obj", 0, 26, 48},          {"eight.obj", 2, 766, 1536},        {"3holes.obj", 3, 3596, 7200},
    {"scorpion.obj", 0, 6315, 12626},
};

TEST(SurfaceSharedMeshes, ReportMatchesReadme)
{
    ZOME_REQUIRE_SHARED();
    for (const SharedMesh& m : shared_meshes)
    {
        SCOPED_TRACE(m.file);
        const PolygonSoup soup = read_mesh_file(shared_path(std::string("data/meshes/") + m.file));
        const PreparedSurface prepared = prepare_surface(soup);
        const SurfaceReport& r = prepared.report;
        EXPECT_EQ(r.input_vertices, m.vertices);
        EXPECT_EQ(r.input_faces, m.faces);
        EXPECT_EQ(r.vertices, m.vertices);
        EXPECT_EQ(r.faces, m.faces);
        EXPECT_EQ(r.edges, 3 * m.faces / 2);
        EXPECT_TRUE(r.closed);
        EXPECT_TRUE(r.manifold);
        EXPECT_EQ(r.components, 1u);
        EXPECT_EQ(r.genus, m.genus);
        EXPECT_EQ(r.euler, 2 - 2 * m.genus);
        EXPECT_TRUE(r.repairs.empty()) << r.repairs.front();
        EXPECT_EQ(r.flipped_faces, 0u);
        EXPECT_GT(signed_volume(prepared.mesh), 0);
    }
}

TEST(SurfaceSharedMeshes, BoundingBoxOfBunny)
{
    ZOME_REQUIRE_SHARED();
    const SurfaceReport r = diagnose(read_mesh_file(shared_path("data/meshes/bunny.obj")));
    EXPECT_NEAR(r.bbox_min[0], -0.7757, 1e-4);
    EXPECT_NEAR(r.bbox_max[2], 0.5991, 1e-4);
}

TEST(SurfaceSharedMeshes, InvertedCopyIsFlippedBack)
{
    ZOME_REQUIRE_SHARED();
    // Every face of rockerarm reversed: the repair must flip all of them and nothing else.
    const PolygonSoup soup = reversed(read_mesh_file(shared_path("data/meshes/rockerarm.obj")));
    const PreparedSurface prepared = prepare_surface(soup);
    EXPECT_EQ(prepared.report.flipped_faces, soup.polygons.size());
    EXPECT_GT(signed_volume(prepared.mesh), 0);
    EXPECT_EQ(prepared.report.genus, 1);
}

TEST(SurfaceSharedMeshes, LoadSurface)
{
    ZOME_REQUIRE_SHARED();
    const TriangleMesh mesh = load_surface(shared_path("data/meshes/torus.obj"));
    EXPECT_EQ(mesh.positions.size(), 2304u);
    EXPECT_EQ(mesh.triangles.size(), 4608u);
}

} // namespace
} // namespace zomeify::surface_test
