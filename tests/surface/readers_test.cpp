// Each reader on small valid files written by the test code: exact counts and coordinates, and
// the cube in every format comes out as the same closed mesh.
#include <fstream>
#include <sstream>

#include <gtest/gtest.h>

#include "core/base/errors.h"
#include "core/surface/prepare.h"
#include "core/surface/read_mesh.h"
#include "core/surface/tiny_gltf_config.h"
#include "tests/support/paths.h"
#include "tests/surface/surface_fixtures.h"

namespace zomeify::surface_test {
namespace {

using test::shared_path;
using test::temp_path;

PolygonSoup read(const std::string& text, const std::string& name) { return read_mesh_buffer(bytes_of(text), name); }

void expect_closed_cube(const PolygonSoup& soup)
{
    const PreparedSurface p = prepare_surface(soup);
    EXPECT_EQ(p.report.vertices, 8u);
    EXPECT_EQ(p.report.faces, 12u);
    EXPECT_TRUE(p.report.closed);
    EXPECT_EQ(p.report.genus, 0);
    EXPECT_NEAR(signed_volume(p.mesh), 1.0, 1e-12);
}

TEST(SurfaceReaders, ObjAllFaceForms)
{
    const std::string obj = "# comment\r\n"
                            "mtllib cube.mtl\r\n"
                            "o thing\r\n"
                            "v 0 0 0\r\nv 1 0 0\r\nv 1 1 0\r\nv 0 1 0\r\n"
                            "v 0 0 1 1.0\r\nv 1 0 1\r\nv 1 1 1\r\nv 0 1 1 0.5 0.5 0.5\r\n"
                            "vt 0 0\r\nvt 1 0\r\nvn 0 0 1\r\n"
                            "g sides\r\nusemtl red\r\ns 1\r\n"
                            "f 1 4 3 2\r\n"                         // plain, quad
                            "f 5/1 6/2 7/1 8/2\r\n"                 // a/b
                            "f 1//1 2//1 6//1 5//1  # trailing\r\n" // a//c
                            "f 4/1/1 8/1/1 7/2/1 3/2/1\r\n"         // a/b/c
                            "s off\r\n"
                            "f -8 -4 -1 -5\r\n" // negative: 1 5 8 4
                            "f -7 -6 -2 -3\r\n" // 2 3 7 6
                            "l 1 2\r\n";
    const PolygonSoup soup = read(obj, "cube.obj");
    ASSERT_EQ(soup.positions.size(), 8u);
    ASSERT_EQ(soup.polygons.size(), 6u);
    EXPECT_EQ(soup.polygons[4], (std::vector<uint32_t>{0, 4, 7, 3}));
    EXPECT_EQ(soup.polygons[5], (std::vector<uint32_t>{1, 2, 6, 5}));
    EXPECT_EQ(soup.positions[6], Vec3(1, 1, 1));
    expect_closed_cube(soup);
}

TEST(SurfaceReaders, ExtensionIsCaseInsensitive)
{
    EXPECT_EQ(read(to_obj(cube_quads()), "CUBE.OBJ").polygons.size(), 6u);
    EXPECT_EQ(read(to_off(cube_quads()), "dir/Cube.Off").polygons.size(), 6u);
    EXPECT_TRUE(is_mesh_file_name("a.GlB"));
    EXPECT_FALSE(is_mesh_file_name("a.vef"));
    EXPECT_NE(invalid_input_message([] { read("x", "model.3ds"); }).find("unknown mesh format"), std::string::npos);
}

TEST(SurfaceReaders, StlAscii)
{
    const PolygonSoup soup = read(to_stl_ascii(cube_quads()), "cube.stl");
    EXPECT_EQ(soup.positions.size(), 36u);
    EXPECT_EQ(soup.polygons.size(), 12u);
    expect_closed_cube(soup);
}

TEST(SurfaceReaders, StlBinary)
{
    const std::string stl = to_stl_binary(cube_quads());
    EXPECT_EQ(stl.size(), 84u + 12 * 50);
    const PolygonSoup soup = read(stl, "cube.stl");
    EXPECT_EQ(soup.polygons.size(), 12u);
    const PreparedSurface p = prepare_surface(soup);
    EXPECT_EQ(p.report.welded_vertices, 28u);
    expect_closed_cube(soup);
}

TEST(SurfaceReaders, StlBinaryWithSolidHeader)
{
    // Many exporters start binary files with "solid": the size rule must win.
    const PolygonSoup soup = read(to_stl_binary(cube_quads(), "solid cube exported by a CAD tool"), "cube.stl");
    EXPECT_EQ(soup.polygons.size(), 12u);
    expect_closed_cube(soup);
}

TEST(SurfaceReaders, PlyAllEncodings)
{
    for (const PlyEncoding e : {PlyEncoding::ascii, PlyEncoding::little_endian, PlyEncoding::big_endian})
        for (const bool wide : {false, true})
        {
            SCOPED_TRACE(static_cast<int>(e) * 2 + wide);
            const PolygonSoup soup = read(to_ply(pentagonal_prism(), e, wide), "prism.ply");
            ASSERT_EQ(soup.positions.size(), 10u);
            ASSERT_EQ(soup.polygons.size(), 7u);
            EXPECT_EQ(soup.polygons[5].size(), 5u);
            EXPECT_NEAR(soup.positions[1].x(), std::cos(2 * 3.14159265358979 / 5), 1e-6); // float x
            EXPECT_NEAR(soup.positions[1].y(), std::sin(2 * 3.14159265358979 / 5), 1e-6);
            EXPECT_EQ(soup.positions[7].z(), 1.0); // short z
            const SurfaceReport r = diagnose(soup);
            EXPECT_TRUE(r.ok()) << r.problem_summary();
            EXPECT_EQ(r.faces, 16u);
        }
}

TEST(SurfaceReaders, PlyVertexAfterFaces)
{
    const std::string ply = "ply\nformat ascii 1.0\nelement face 1\nproperty list uchar uint vertex_indices\n"
                            "element vertex 3\nproperty double x\nproperty double y\nproperty double z\n"
                            "end_header\n3 0 1 2\n0 0 0\n1 0 0\n0 1 0\n";
    const PolygonSoup soup = read(ply, "tri.ply");
    EXPECT_EQ(soup.positions.size(), 3u);
    EXPECT_EQ(soup.polygons.size(), 1u);
    EXPECT_EQ(soup.positions[1], Vec3(1, 0, 0));
}

TEST(SurfaceReaders, OffWithCommentsAndColours)
{
    const std::string off = "# a cube\nOFF\n# counts next\n8 6 12\n"
                            "0 0 0 255 0 0\n1 0 0 255 0 0\n0 1 0\n1 1 0\n"
                            "0 0 1\n1 0 1  # comment\n0 1 1\n1 1 1\n\n"
                            "4 0 2 3 1 0.5 0.5 0.5 1\n4 4 5 7 6\n4 0 1 5 4\n4 2 6 7 3\n4 0 4 6 2\n4 1 3 7 5\n";
    const PolygonSoup soup = read(off, "cube.off");
    EXPECT_EQ(soup.positions.size(), 8u);
    EXPECT_EQ(soup.polygons.size(), 6u);
    expect_closed_cube(soup);
    // Counts on the header line; COFF keyword.
    const PolygonSoup same =
        read("COFF 8 6 0\n" + to_off(cube_quads()).substr(to_off(cube_quads()).find('\n', 4) + 1), "cube.off");
    EXPECT_EQ(same.polygons.size(), 6u);
}

TEST(SurfaceReaders, GlbWithTransform)
{
    // Scale 2 and translate (10, 0, 0): a 2x2x2 cube at x in [10, 12].
    const std::vector<double> matrix = {2, 0, 0, 0, 0, 2, 0, 0, 0, 0, 2, 0, 10, 0, 0, 1};
    const std::string glb = to_gltf(cube_quads(), true, matrix);
    ASSERT_EQ(glb.substr(0, 4), "glTF");
    const PolygonSoup soup = read(glb, "cube.glb");
    EXPECT_EQ(soup.positions.size(), 8u);
    EXPECT_EQ(soup.polygons.size(), 12u);
    const PreparedSurface p = prepare_surface(soup);
    EXPECT_NEAR(signed_volume(p.mesh), 8.0, 1e-9);
    EXPECT_DOUBLE_EQ(p.report.bbox_min[0], 10.0);
    EXPECT_DOUBLE_EQ(p.report.bbox_max[0], 12.0);
}

TEST(SurfaceReaders, GltfMirroringTransformKeepsOutwardWinding)
{
    const std::vector<double> mirror = {-1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1};
    const PreparedSurface p = prepare_surface(read(to_gltf(cube_quads(), true, mirror), "cube.glb"));
    EXPECT_EQ(p.report.flipped_faces, 0u);
    EXPECT_NEAR(signed_volume(p.mesh), 1.0, 1e-12);
}

TEST(SurfaceReaders, GltfWithDataUri)
{
    const std::string gltf = to_gltf(pentagonal_prism(), false);
    ASSERT_NE(gltf.find("data:application/octet-stream;base64,"), std::string::npos);
    const PolygonSoup soup = read(gltf, "prism.gltf");
    EXPECT_EQ(soup.positions.size(), 10u);
    EXPECT_EQ(soup.polygons.size(), 16u);
    EXPECT_TRUE(diagnose(soup).ok());
}

TEST(SurfaceReaders, GltfExternalBuffer)
{
    // The same file with its buffer moved out to cube.bin: fine from disk, a clear error from memory.
    const PolygonSoup cube = cube_quads();
    std::string gltf = to_gltf(cube, false);
    const size_t start = gltf.find("data:application/octet-stream;base64,");
    const size_t end = gltf.find('"', start);
    gltf.replace(start, end - start, "cube.bin");
    std::string bin;
    {
        const std::string glb = to_gltf(cube, true);
        // The GLB's BIN chunk holds exactly the buffer: 12-byte header, JSON chunk, then BIN chunk.
        const uint32_t json_length = static_cast<uint8_t>(glb[12]) | static_cast<uint8_t>(glb[13]) << 8 |
                                     static_cast<uint8_t>(glb[14]) << 16 | static_cast<uint8_t>(glb[15]) << 24;
        bin = glb.substr(20 + json_length + 8);
    }
    const std::string message = invalid_input_message([&] { read(gltf, "cube.gltf"); });
    EXPECT_NE(message.find("cube.bin"), std::string::npos) << message;
    EXPECT_NE(message.find("external"), std::string::npos) << message;

    const std::string path = temp_path("cube.gltf");
    std::ofstream(path, std::ios::binary) << gltf;
    std::ofstream(temp_path("cube.bin"), std::ios::binary) << bin;
    expect_closed_cube(read_mesh_file(path));
}

TEST(SurfaceReaders, StlAsciiUpperCaseKeywords)
{
    std::string stl = to_stl_ascii(cube_quads());
    for (const char* word : {"solid", "facet", "normal", "outer", "loop", "vertex", "endloop", "endfacet", "endsolid"})
        for (size_t at = stl.find(word); at != std::string::npos; at = stl.find(word, at + 1))
            for (size_t k = 0; k < std::string(word).size(); ++k)
                stl[at + k] = static_cast<char>(stl[at + k] - 'a' + 'A');
    expect_closed_cube(read(stl, "CUBE.STL"));
}

// A tetrahedron as one triangle strip (ubyte indices), and again as a fan (ushort indices) plus a
// separate triangle, instanced through a node hierarchy with translations and a scale.
TEST(SurfaceReaders, GltfStripsFansAndNodeHierarchy)
{
    tinygltf::Model model;
    std::string data;
    const float corners[4][3] = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, 0, 1}};
    data.append(reinterpret_cast<const char*>(corners), sizeof corners); // little-endian host
    const uint8_t strip[8] = {0, 1, 2, 3, 0, 1, 0, 0};                   // 6 used, padded to 4 bytes
    data.append(reinterpret_cast<const char*>(strip), sizeof strip);
    const uint16_t fan[6] = {0, 1, 2, 3, 1, 0}; // 5 used
    data.append(reinterpret_cast<const char*>(fan), sizeof fan);
    const uint16_t base[4] = {1, 3, 2, 0}; // 3 used
    data.append(reinterpret_cast<const char*>(base), sizeof base);
    tinygltf::Buffer buffer;
    buffer.data.assign(data.begin(), data.end());
    model.buffers.push_back(buffer);
    const auto view = [&](size_t offset, size_t length) {
        tinygltf::BufferView v;
        v.buffer = 0;
        v.byteOffset = offset;
        v.byteLength = length;
        model.bufferViews.push_back(v);
        return static_cast<int>(model.bufferViews.size() - 1);
    };
    const auto accessor = [&](int view_index, int component, size_t count, int type) {
        tinygltf::Accessor a;
        a.bufferView = view_index;
        a.componentType = component;
        a.count = count;
        a.type = type;
        if (type == TINYGLTF_TYPE_VEC3)
        {
            a.minValues = {0, 0, 0};
            a.maxValues = {1, 1, 1};
        }
        model.accessors.push_back(a);
        return static_cast<int>(model.accessors.size() - 1);
    };
    const int positions = accessor(view(0, 48), TINYGLTF_COMPONENT_TYPE_FLOAT, 4, TINYGLTF_TYPE_VEC3);
    const int strip_indices = accessor(view(48, 8), TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE, 6, TINYGLTF_TYPE_SCALAR);
    const int fan_indices = accessor(view(56, 12), TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT, 5, TINYGLTF_TYPE_SCALAR);
    const int base_indices = accessor(view(68, 8), TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT, 3, TINYGLTF_TYPE_SCALAR);
    const auto primitive = [&](int indices, int mode) {
        tinygltf::Primitive p;
        p.attributes["POSITION"] = positions;
        p.indices = indices;
        p.mode = mode;
        return p;
    };
    tinygltf::Mesh strip_mesh, fan_mesh;
    strip_mesh.primitives = {primitive(strip_indices, TINYGLTF_MODE_TRIANGLE_STRIP)};
    fan_mesh.primitives = {primitive(fan_indices, TINYGLTF_MODE_TRIANGLE_FAN),
                           primitive(base_indices, TINYGLTF_MODE_TRIANGLES),
                           primitive(base_indices, TINYGLTF_MODE_LINE)};
    model.meshes = {strip_mesh, fan_mesh};
    tinygltf::Node root, strip_node, fan_node, unused;
    root.translation = {10, 0, 0};
    root.children = {1, 2};
    strip_node.mesh = 0;
    fan_node.mesh = 1;
    fan_node.translation = {5, 0, 0};
    fan_node.scale = {2, 2, 2};
    unused.mesh = 0; // not in the scene: ignored
    model.nodes = {root, strip_node, fan_node, unused};
    tinygltf::Scene scene;
    scene.nodes = {0};
    model.scenes = {scene};
    model.defaultScene = 0;
    model.asset.version = "2.0";
    std::ostringstream os;
    tinygltf::TinyGLTF writer;
    writer.WriteGltfSceneToStream(&model, os, false, true);

    const PolygonSoup soup = read(os.str(), "tetra.glb");
    EXPECT_EQ(soup.positions.size(), 12u); // 4 per triangle primitive instance
    EXPECT_EQ(soup.polygons.size(), 8u);   // strip 4, fan 3, base 1; the line primitive is skipped
    const PreparedSurface p = prepare_surface(soup);
    EXPECT_EQ(p.report.vertices, 8u);
    EXPECT_EQ(p.report.welded_vertices, 3u);
    EXPECT_EQ(p.report.unreferenced_vertices, 1u); // vertex 0 of the base primitive's copy
    EXPECT_EQ(p.report.components, 2u);
    EXPECT_TRUE(p.report.closed);
    EXPECT_DOUBLE_EQ(p.report.bbox_min[0], 10.0);
    EXPECT_DOUBLE_EQ(p.report.bbox_max[0], 17.0);
    EXPECT_DOUBLE_EQ(p.report.bbox_max[2], 2.0);
    EXPECT_NEAR(signed_volume(p.mesh), 1.0 / 6 + 8.0 / 6, 1e-12);
}

TEST(SurfaceReaders, FileNotFound) { EXPECT_THROW(read_mesh_file(temp_path("does-not-exist.obj")), IoError); }

} // namespace
} // namespace zomeify::surface_test
