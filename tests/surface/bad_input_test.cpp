// The corpus of bad inputs (issue 3): each one gets its documented outcome, a clear
// InvalidInputError naming the problem, or a repair with a report. Never a crash, a hang or a
// huge allocation (this suite also runs under ASan/UBSan).
#include <random>

#include <gtest/gtest.h>

#include "core/base/errors.h"
#include "core/surface/prepare.h"
#include "core/surface/read_mesh.h"
#include "tests/surface/surface_fixtures.h"

namespace zomeify::surface_test {
namespace {

const char* const all_names[] = {"m.obj", "m.stl", "m.ply", "m.off", "m.gltf", "m.glb"};

std::string read_error(const std::string& bytes, const std::string& name)
{
    return invalid_input_message([&] { read_mesh_buffer(bytes_of(bytes), name); });
}

std::string prepare_error(const PolygonSoup& soup)
{
    return invalid_input_message([&] { prepare_surface(soup); });
}

#define EXPECT_CONTAINS(text, word) EXPECT_NE((text).find(word), std::string::npos) << (text)

TEST(SurfaceBadInput, EmptyFile)
{
    for (const char* name : all_names)
    {
        const std::string m = read_error("", name);
        EXPECT_CONTAINS(m, name);
        EXPECT_CONTAINS(m, "empty");
    }
}

TEST(SurfaceBadInput, RandomBytes)
{
    std::mt19937 rng(12345);
    for (int round = 0; round < 40; ++round)
    {
        std::string bytes(static_cast<size_t>(1 + rng() % 4000), '\0');
        for (char& c : bytes)
            c = static_cast<char>(rng() & 0xFF);
        for (const char* name : all_names)
        {
            SCOPED_TRACE(name);
            EXPECT_FALSE(read_error(bytes, name).empty());
        }
    }
}

TEST(SurfaceBadInput, PngRenamed)
{
    std::string png = "\x89PNG\r\n\x1a\n";
    png += std::string("\0\0\0\rIHDR\0\0\0\x10\0\0\0\x10\x08\x06\0\0\0", 21);
    png.resize(200, '\x42');
    EXPECT_CONTAINS(read_error(png, "model.stl"), "not an STL file");
    EXPECT_CONTAINS(read_error(png, "model.obj"), "binary data");
    EXPECT_CONTAINS(read_error(png, "model.off"), "line 1: not an OFF file (header '?PNG')");
    EXPECT_CONTAINS(read_error(png, "model.ply"), "not a PLY file");
    EXPECT_CONTAINS(read_error(png, "model.glb"), "invalid glTF");
}

TEST(SurfaceBadInput, NanAndInfCoordinates)
{
    EXPECT_CONTAINS(read_error("v 0 0 0\nv nan 0 0\nv 0 1 0\nf 1 2 3\n", "m.obj"), "line 2: vertex coordinate is NaN");
    EXPECT_CONTAINS(read_error("v 0 0 0\nv 1 0 0\nv 0 inf 0\nf 1 2 3\n", "m.obj"), "line 3");
    EXPECT_CONTAINS(read_error("OFF\n3 1 0\n0 0 0\n1 0 -inf\n0 1 0\n3 0 1 2\n", "m.off"),
                    "vertex 1 has a NaN or infinite");
    EXPECT_CONTAINS(read_error("ply\nformat ascii 1.0\nelement vertex 3\nproperty float x\nproperty float y\n"
                               "property float z\nelement face 1\nproperty list uchar int vertex_indices\n"
                               "end_header\n0 0 0\n1 NaN 0\n0 1 0\n3 0 1 2\n",
                               "m.ply"),
                    "vertex 1 has a NaN");
    PolygonSoup tri;
    tri.positions = {Vec3(0, 0, 0), Vec3(1, 0, 0), Vec3(0, 1, 0)};
    tri.polygons = {{0, 1, 2}};
    std::string stl = to_stl_binary(tri);
    std::fill(stl.begin() + 84 + 12 + 12, stl.begin() + 84 + 12 + 16, '\xFF'); // a NaN x
    EXPECT_CONTAINS(read_error(stl, "m.stl"), "triangle 0: vertex coordinate is NaN");

    // Through the API (no reader), a soup with a NaN vertex: faces using it are dropped and reported.
    PolygonSoup soup = cube_triangles();
    soup.positions[7] = Vec3(std::nan(""), 0, 0);
    const SurfaceReport r = diagnose(soup);
    EXPECT_EQ(r.non_finite_vertices, 1u);
    EXPECT_GT(r.dropped_invalid_faces, 0u);
    EXPECT_FALSE(r.ok());
    EXPECT_CONTAINS(prepare_error(soup), "NaN/infinite");
}

TEST(SurfaceBadInput, HugeCoordinates)
{
    PolygonSoup soup = cube_quads();
    for (Vec3& p : soup.positions)
        p *= 1e308;
    const SurfaceReport r = diagnose(soup);
    EXPECT_EQ(r.vertices, 8u);
    EXPECT_CONTAINS(r.problem_summary(), "coordinates are too large");
}

TEST(SurfaceBadInput, IndicesOutOfRange)
{
    EXPECT_CONTAINS(read_error("v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 4\n", "m.obj"),
                    "line 4: face index 4 is out of range (the file has 3 vertices)");
    EXPECT_CONTAINS(read_error("v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 -4\n", "m.obj"), "reaches before the first vertex");
    EXPECT_CONTAINS(read_error("v 0 0 0\nv 1 0 0\nv 0 1 0\nf 0 1 2\n", "m.obj"), "index 0");
    EXPECT_CONTAINS(read_error("OFF\n3 1 0\n0 0 0\n1 0 0\n0 1 0\n3 0 1 3\n", "m.off"), "index 3 is out of range");
    EXPECT_CONTAINS(read_error("OFF\n3 1 0\n0 0 0\n1 0 0\n0 1 0\n3 0 1 -1\n", "m.off"), "out of range");
    std::string ply = to_ply(cube_quads(), PlyEncoding::little_endian);
    // The first face's first index (after the header, 8 vertices of 15 bytes and the list count).
    const size_t at = ply.find("end_header\n") + 11 + 8 * 15 + 1;
    ply[at] = '\x09';
    EXPECT_CONTAINS(read_error(ply, "m.ply"), "face 0: index 9 is out of range (8 vertices)");
    PolygonSoup soup = cube_triangles();
    soup.polygons[0][1] = 99;
    EXPECT_CONTAINS(prepare_error(soup), "index out of range");
}

TEST(SurfaceBadInput, NoFaces)
{
    EXPECT_CONTAINS(read_error("# nothing\n", "m.obj"), "no vertices");
    const PolygonSoup only_vertices = read_mesh_buffer(bytes_of("v 0 0 0\nv 1 0 0\n"), "m.obj");
    EXPECT_CONTAINS(prepare_error(only_vertices), "mesh has no faces");
    EXPECT_CONTAINS(read_error("OFF\n0 0 0\n", "m.off"), "line 2: no vertices");
    EXPECT_CONTAINS(prepare_error(read_mesh_buffer(bytes_of("OFF\n1 0 0\n0 0 0\n"), "m.off")), "no faces");
    EXPECT_CONTAINS(read_error("ply\nformat ascii 1.0\nelement vertex 1\nproperty float x\nproperty float y\n"
                               "property float z\nend_header\n0 0 0\n",
                               "m.ply"),
                    "no faces");
    EXPECT_CONTAINS(read_error("solid x\nendsolid x\n", "m.stl"), "no facets");
    EXPECT_CONTAINS(read_error(std::string(84, '\0'), "m.stl"), "no triangles");
}

TEST(SurfaceBadInput, FaceWithOneOrTwoVertices)
{
    // Kept by the readers, dropped and counted by the repair; alone they leave no faces.
    const PolygonSoup soup = read_mesh_buffer(bytes_of("v 0 0 0\nv 1 0 0\nf 1\nf 1 2\n"), "m.obj");
    EXPECT_EQ(soup.polygons.size(), 2u);
    const SurfaceReport r = diagnose(soup);
    EXPECT_EQ(r.dropped_small_faces, 2u);
    EXPECT_CONTAINS(r.problem_summary(), "no usable faces (all 2 were dropped)");
    EXPECT_EQ(read_mesh_buffer(bytes_of("OFF\n2 1 0\n0 0 0\n1 0 0\n2 0 1\n"), "m.off").polygons[0].size(), 2u);
}

TEST(SurfaceBadInput, TwoCubesSharingOnlyAnEdgeAreSeparated)
{
    // The second cube touches the first along the edge x = 1, y = 1 (after welding): the edge has
    // four faces, paired so that each cube closes (issue 36; refused before).
    const SurfaceReport r = diagnose(merge(cube_quads(), cube_quads(Vec3(1, 1, 0))));
    EXPECT_TRUE(r.ok()) << r.problem_summary();
    EXPECT_EQ(r.input_non_manifold_edges, 1u);
    EXPECT_EQ(r.separated_edges, 1u);
    EXPECT_EQ(r.non_manifold_edges, 0u);
    EXPECT_EQ(r.welded_vertices, 2u);
    EXPECT_EQ(r.components, 2u);
    EXPECT_TRUE(r.manifold);
    EXPECT_TRUE(r.closed);
}

TEST(SurfaceBadInput, TwoCubesSharingOnlyAVertexAreSeparated)
{
    const SurfaceReport r = diagnose(merge(cube_quads(), cube_quads(Vec3(1, 1, 1))));
    EXPECT_TRUE(r.ok()) << r.problem_summary();
    EXPECT_EQ(r.input_non_manifold_vertices, 1u);
    EXPECT_EQ(r.separated_pinched_vertices, 1u);
    EXPECT_EQ(r.vertices, 16u);
    EXPECT_CONTAINS(r.repairs.back(), "separated 1 pinched vertex");
}

TEST(SurfaceBadInput, OpenBoxIsClosed)
{
    PolygonSoup box = cube_quads();
    box.polygons.erase(box.polygons.begin() + 1); // no lid
    const PreparedSurface p = prepare_surface(box);
    EXPECT_EQ(p.report.input_holes, 1u);
    EXPECT_EQ(p.report.holes, 0u);
    EXPECT_CONTAINS(p.report.repairs.back(), "closed 1 small hole (4 edges)");
    EXPECT_NEAR(signed_volume(p.mesh), 1.0, 1e-12);
    // Lid and bottom removed: a tube with two holes, genus 0 (a sphere with two holes), closed at both ends.
    box.polygons.erase(box.polygons.begin());
    const SurfaceReport r = diagnose(box);
    EXPECT_EQ(r.input_holes, 2u);
    EXPECT_EQ(r.input_boundary_edges, 8u);
    EXPECT_EQ(r.genus, 0);
    EXPECT_CONTAINS(r.repairs.back(), "closed 2 small holes (4 edges each)");
}

TEST(SurfaceBadInput, OpenSheetIsRefusedWithTheReason)
{
    PolygonSoup quad;
    quad.positions = {Vec3(0, 0, 0), Vec3(1, 0, 0), Vec3(1, 1, 0), Vec3(0, 1, 0)};
    quad.polygons = {{0, 1, 2, 3}};
    const std::string m = prepare_error(quad);
    EXPECT_CONTAINS(m, "mesh is an open sheet, not a solid: its open edge (4 boundary edges) runs around it");
    EXPECT_CONTAINS(m, "would add 100% of its area");
}

TEST(SurfaceBadInput, HugeCountsInHeaders)
{
    // A 2^31 face count in small files must be refused before any allocation.
    const std::string ply_ascii = "ply\nformat ascii 1.0\nelement vertex 3\nproperty float x\nproperty float y\n"
                                  "property float z\nelement face 2147483648\nproperty list uchar int vertex_indices\n"
                                  "end_header\n0 0 0\n1 0 0\n0 1 0\n3 0 1 2\n";
    EXPECT_CONTAINS(read_error(ply_ascii, "m.ply"), "header says 2147483648 face elements");
    std::string ply_binary = to_ply(cube_quads(), PlyEncoding::big_endian);
    ply_binary.replace(ply_binary.find("element face 6"), 14, "element face 2147483648");
    EXPECT_CONTAINS(read_error(ply_binary, "m.ply"), "header says 2147483648 face elements");
    std::string ply_vertices = to_ply(cube_quads(), PlyEncoding::little_endian);
    ply_vertices.replace(ply_vertices.find("element vertex 8"), 16, "element vertex 4000000000");
    EXPECT_CONTAINS(read_error(ply_vertices, "m.ply"), "4000000000 vertex elements");
    // One list claiming 2^32 - 1 entries.
    std::string ply_list = to_ply(cube_quads(), PlyEncoding::little_endian, true);
    const size_t list_at = ply_list.find("end_header\n") + 11 + 8 * 15;
    ply_list[list_at] = '\xFF';
    ply_list[list_at + 1] = '\xFF';
    EXPECT_CONTAINS(read_error(ply_list, "m.ply"), "list length 65535 does not fit");

    EXPECT_CONTAINS(read_error("OFF\n3 2147483648 0\n0 0 0\n1 0 0\n0 1 0\n3 0 1 2\n", "m.off"),
                    "header says 3 vertices and 2147483648 faces, but only 4 lines follow");
    EXPECT_CONTAINS(read_error("OFF\n3 1 0\n0 0 0\n1 0 0\n0 1 0\n2147483648 0 1 2\n", "m.off"),
                    "more than the line holds");

    std::string stl(84 + 50, '\0');
    stl[83] = '\x80'; // 0x80000000 triangles
    EXPECT_CONTAINS(read_error(stl, "m.stl"), "binary header says 2147483648 triangles");
}

TEST(SurfaceBadInput, MoebiusStripIsNotOrientable)
{
    PolygonSoup strip;
    const int n = 12;
    for (int i = 0; i < n; ++i)
        for (const double w : {0.5, -0.5})
        {
            const double t = 2 * 3.14159265358979 * i / n;
            strip.positions.push_back(Vec3((2 + w * std::cos(t / 2)) * std::cos(t),
                                           (2 + w * std::cos(t / 2)) * std::sin(t), w * std::sin(t / 2)));
        }
    // Vertex 2i is a_i (w = +0.5), 2i + 1 is b_i; going once round swaps the two sides.
    for (uint32_t i = 0; i + 1 < n; ++i)
        strip.polygons.push_back({2 * i, 2 * i + 2, 2 * i + 3, 2 * i + 1});
    strip.polygons.push_back({2 * (n - 1), 1, 0, 2 * (n - 1) + 1});
    const SurfaceReport r = diagnose(strip);
    EXPECT_EQ(r.non_orientable_components, 1u);
    EXPECT_EQ(r.holes, 1u); // a Moebius strip has one boundary loop
    EXPECT_FALSE(r.manifold);
    EXPECT_EQ(r.flipped_faces, 0u);
    EXPECT_CONTAINS(r.problem_summary(), "1 component cannot be oriented consistently");
}

TEST(SurfaceBadInput, TruncatedFiles)
{
    const std::string ply = to_ply(cube_quads(), PlyEncoding::little_endian);
    EXPECT_CONTAINS(read_error(ply.substr(0, ply.size() - 30), "m.ply"), "");
    const std::string glb = to_gltf(cube_quads(), true);
    EXPECT_CONTAINS(read_error(glb.substr(0, glb.size() - 10), "m.glb"), "invalid glTF");
    EXPECT_CONTAINS(read_error("OFF\n8 6 0\n0 0 0\n", "m.off"), "only 1 lines follow");
    EXPECT_CONTAINS(read_error("solid t\nfacet normal 0 0 1\nouter loop\nvertex 0 0 0\n", "m.stl"),
                    "ends inside a facet");
}

TEST(SurfaceBadInput, MalformedText)
{
    EXPECT_CONTAINS(read_error("v 0 0 zero\n", "m.obj"), "line 1: bad vertex coordinate 'zero'");
    EXPECT_CONTAINS(read_error("v 0 0\n", "m.obj"), "fewer than 3 coordinates");
    EXPECT_CONTAINS(read_error("v 0 0 0\nf 1 x 1\n", "m.obj"), "line 2: bad face index 'x'");
    EXPECT_CONTAINS(read_error("OFF\n3 1 0\n0 0 0\n1 0\n0 1 0\n3 0 1 2\n", "m.off"), "vertex 1 needs 3 numbers");
    EXPECT_CONTAINS(read_error("NOT OFF\n", "m.off"), "not an OFF file");
    EXPECT_CONTAINS(read_error("ply\nformat xml 1.0\nend_header\n", "m.ply"), "unknown PLY format");
    EXPECT_CONTAINS(read_error("{\"asset\": {\"version\": \"2.0\"}, \"meshes\": [", "m.gltf"), "invalid glTF");
    EXPECT_CONTAINS(read_error("{\"asset\": {\"version\": \"2.0\"}}", "m.gltf"), "no triangles");
}

TEST(SurfaceBadInput, GltfAccessorOutsideBuffer)
{
    // Claim more positions than the buffer holds: the reader's own range check must catch it
    // whether or not tinygltf does.
    std::string gltf = to_gltf(cube_quads(), false);
    const size_t at = gltf.find("\"count\":8");
    ASSERT_NE(at, std::string::npos) << gltf;
    gltf.replace(at, 9, "\"count\":800000");
    EXPECT_FALSE(read_error(gltf, "m.gltf").empty());
}

// Found by fuzzing (tests/fuzz, target ply): a list length beyond long long's range was converted to
// long long for the message, which is undefined behaviour (UBSan stopped on it).
TEST(SurfaceBadInput, PlyListLengthBeyondInteger)
{
    const std::string ply = "ply\nformat ascii 1.0\nelement vertex 3\nproperty float x\nproperty float y\n"
                            "property float z\nelement face 1\nproperty list uchar int vertex_indices\nend_header\n"
                            "0 0 0\n1 0 0\n0 1 0\n5.6e20 0 1 2\n";
    EXPECT_CONTAINS(read_error(ply, "m.ply"), "list length");
}

} // namespace
} // namespace zomeify::surface_test
