#include "tests/surface/surface_fixtures.h"

#include <cmath>
#include <cstring>
#include <numbers>
#include <sstream>

#include <Eigen/Geometry>
#include <gtest/gtest.h>

#include "core/base/errors.h"
#include "core/surface/tiny_gltf_config.h"

namespace zomeify::surface_test {

namespace {

void put_u32_le(std::string& out, uint32_t v)
{
    for (int i = 0; i < 4; ++i)
        out.push_back(static_cast<char>((v >> (8 * i)) & 0xFF));
}

void put_f32_le(std::string& out, float f)
{
    uint32_t u;
    std::memcpy(&u, &f, 4);
    put_u32_le(out, u);
}

// `n` bytes of the value in the given order.
void put_bytes(std::string& out, uint64_t v, int n, bool big)
{
    for (int i = 0; i < n; ++i)
    {
        const int shift = 8 * (big ? n - 1 - i : i);
        out.push_back(static_cast<char>((v >> shift) & 0xFF));
    }
}

template <typename T>
uint64_t bits_of(T value)
{
    uint64_t u = 0;
    std::memcpy(&u, &value, sizeof value);
    return u;
}

PolygonSoup prism(const std::vector<Eigen::Vector2d>& ring)
{
    PolygonSoup s;
    const auto n = static_cast<uint32_t>(ring.size());
    for (const auto& p : ring)
        s.positions.push_back(Vec3(p.x(), p.y(), 0));
    for (const auto& p : ring)
        s.positions.push_back(Vec3(p.x(), p.y(), 1));
    std::vector<uint32_t> bottom, top;
    for (uint32_t i = 0; i < n; ++i)
    {
        bottom.push_back(n - 1 - i); // clockwise seen from above = outward for the bottom
        top.push_back(n + i);
        s.polygons.push_back({i, (i + 1) % n, n + (i + 1) % n, n + i});
    }
    s.polygons.push_back(bottom);
    s.polygons.push_back(top);
    return s;
}

} // namespace

PolygonSoup cube_quads(const Vec3& offset)
{
    PolygonSoup s;
    for (int i = 0; i < 8; ++i)
        s.positions.push_back(Vec3(i & 1, (i >> 1) & 1, (i >> 2) & 1) + offset);
    // Vertex i has x = bit 0, y = bit 1, z = bit 2; every quad is counter-clockwise from outside.
    s.polygons = {{0, 2, 3, 1}, {4, 5, 7, 6}, {0, 1, 5, 4}, {2, 6, 7, 3}, {0, 4, 6, 2}, {1, 3, 7, 5}};
    return s;
}

PolygonSoup cube_triangles(const Vec3& offset)
{
    PolygonSoup q = cube_quads(offset);
    PolygonSoup t;
    t.positions = q.positions;
    for (const auto& p : q.polygons)
    {
        t.polygons.push_back({p[0], p[1], p[2]});
        t.polygons.push_back({p[0], p[2], p[3]});
    }
    return t;
}

PolygonSoup pentagonal_prism()
{
    std::vector<Eigen::Vector2d> ring;
    for (int i = 0; i < 5; ++i)
        ring.emplace_back(std::cos(2 * std::numbers::pi * i / 5), std::sin(2 * std::numbers::pi * i / 5));
    return prism(ring);
}

PolygonSoup l_prism() { return prism({{0, 0}, {2, 0}, {2, 1}, {1, 1}, {1, 2}, {0, 2}}); }

PolygonSoup merge(const PolygonSoup& a, const PolygonSoup& b)
{
    PolygonSoup s = a;
    const auto shift = static_cast<uint32_t>(a.positions.size());
    s.positions.insert(s.positions.end(), b.positions.begin(), b.positions.end());
    for (auto p : b.polygons)
    {
        for (auto& i : p)
            i += shift;
        s.polygons.push_back(p);
    }
    return s;
}

PolygonSoup reversed(PolygonSoup soup)
{
    for (auto& p : soup.polygons)
        std::reverse(p.begin(), p.end());
    return soup;
}

double signed_volume(const TriangleMesh& mesh)
{
    double v = 0;
    for (const auto& t : mesh.triangles)
        v += mesh.positions[t[0]].dot(mesh.positions[t[1]].cross(mesh.positions[t[2]]));
    return v / 6;
}

std::string to_obj(const PolygonSoup& soup)
{
    std::ostringstream os;
    os.precision(17);
    for (const auto& p : soup.positions)
        os << "v " << p.x() << " " << p.y() << " " << p.z() << "\n";
    for (const auto& f : soup.polygons)
    {
        os << "f";
        for (const auto i : f)
            os << " " << i + 1;
        os << "\n";
    }
    return os.str();
}

std::string to_off(const PolygonSoup& soup)
{
    std::ostringstream os;
    os.precision(17);
    os << "OFF\n" << soup.positions.size() << " " << soup.polygons.size() << " 0\n";
    for (const auto& p : soup.positions)
        os << p.x() << " " << p.y() << " " << p.z() << "\n";
    for (const auto& f : soup.polygons)
    {
        os << f.size();
        for (const auto i : f)
            os << " " << i;
        os << "\n";
    }
    return os.str();
}

std::string to_stl_ascii(const PolygonSoup& soup)
{
    std::ostringstream os;
    os.precision(17);
    os << "solid test\n";
    for (const auto& f : soup.polygons)
        for (size_t k = 1; k + 1 < f.size(); ++k)
        {
            os << "  facet normal 0 0 0\n    outer loop\n";
            for (const auto i : {f[0], f[k], f[k + 1]})
                os << "      vertex " << soup.positions[i].x() << " " << soup.positions[i].y() << " "
                   << soup.positions[i].z() << "\n";
            os << "    endloop\n  endfacet\n";
        }
    os << "endsolid test\n";
    return os.str();
}

std::string to_stl_binary(const PolygonSoup& soup, const std::string& header80)
{
    std::string out = header80.substr(0, 80);
    out.resize(80, ' ');
    uint32_t count = 0;
    for (const auto& f : soup.polygons)
        count += static_cast<uint32_t>(f.size() - 2);
    put_u32_le(out, count);
    for (const auto& f : soup.polygons)
        for (size_t k = 1; k + 1 < f.size(); ++k)
        {
            for (int a = 0; a < 3; ++a)
                put_f32_le(out, 0.0f);
            for (const auto i : {f[0], f[k], f[k + 1]})
                for (int a = 0; a < 3; ++a)
                    put_f32_le(out, static_cast<float>(soup.positions[i][a]));
            out.append(2, '\0');
        }
    return out;
}

std::string to_ply(const PolygonSoup& soup, PlyEncoding encoding, bool wide_lists)
{
    const bool ascii = encoding == PlyEncoding::ascii;
    const bool big = encoding == PlyEncoding::big_endian;
    std::ostringstream header;
    header << "ply\nformat "
           << (ascii ? "ascii"
               : big ? "binary_big_endian"
                     : "binary_little_endian")
           << " 1.0\n"
           << "comment written by the zomeify tests\n"
           << "element vertex " << soup.positions.size() << "\n"
           << "property float x\nproperty double y\nproperty short z\nproperty uchar quality\n"
           << "element face " << soup.polygons.size() << "\n"
           << (wide_lists ? "property list ushort uint vertex_index\n" : "property list uchar int vertex_indices\n")
           << "property float weight\n"
           << "element edge 1\nproperty int vertex1\nproperty int vertex2\n"
           << "end_header\n";
    std::string out = header.str();
    if (ascii)
    {
        std::ostringstream os;
        os.precision(9);
        for (const auto& p : soup.positions)
            os << static_cast<float>(p.x()) << " " << p.y() << " " << static_cast<int16_t>(p.z()) << " 7\n";
        for (const auto& f : soup.polygons)
        {
            os << f.size();
            for (const auto i : f)
                os << " " << i;
            os << " 0.5\n";
        }
        os << "0 1\n";
        return out + os.str();
    }
    for (const auto& p : soup.positions)
    {
        put_bytes(out, bits_of(static_cast<float>(p.x())), 4, big);
        put_bytes(out, bits_of(p.y()), 8, big);
        put_bytes(out, static_cast<uint16_t>(static_cast<int16_t>(p.z())), 2, big);
        put_bytes(out, 7, 1, big);
    }
    for (const auto& f : soup.polygons)
    {
        put_bytes(out, f.size(), wide_lists ? 2 : 1, big);
        for (const auto i : f)
            put_bytes(out, i, 4, big);
        put_bytes(out, bits_of(0.5f), 4, big);
    }
    put_bytes(out, 0, 4, big);
    put_bytes(out, 1, 4, big);
    return out;
}

std::string to_gltf(const PolygonSoup& soup, bool binary, const std::vector<double>& matrix)
{
    tinygltf::Model model;
    tinygltf::Buffer buffer;
    std::string data;
    for (const auto& p : soup.positions)
        for (int a = 0; a < 3; ++a)
            put_f32_le(data, static_cast<float>(p[a]));
    const size_t index_offset = data.size();
    size_t index_count = 0;
    for (const auto& f : soup.polygons)
        for (size_t k = 1; k + 1 < f.size(); ++k)
            for (const auto i : {f[0], f[k], f[k + 1]})
            {
                put_u32_le(data, i);
                ++index_count;
            }
    buffer.data.assign(data.begin(), data.end());
    model.buffers.push_back(buffer);

    tinygltf::BufferView positions_view;
    positions_view.buffer = 0;
    positions_view.byteLength = index_offset;
    tinygltf::BufferView indices_view;
    indices_view.buffer = 0;
    indices_view.byteOffset = index_offset;
    indices_view.byteLength = data.size() - index_offset;
    model.bufferViews = {positions_view, indices_view};

    tinygltf::Accessor positions;
    positions.bufferView = 0;
    positions.componentType = TINYGLTF_COMPONENT_TYPE_FLOAT;
    positions.count = soup.positions.size();
    positions.type = TINYGLTF_TYPE_VEC3;
    positions.minValues = {0, 0, 0};
    positions.maxValues = {1, 1, 1};
    tinygltf::Accessor indices;
    indices.bufferView = 1;
    indices.componentType = TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT;
    indices.count = index_count;
    indices.type = TINYGLTF_TYPE_SCALAR;
    model.accessors = {positions, indices};

    tinygltf::Primitive primitive;
    primitive.attributes["POSITION"] = 0;
    primitive.indices = 1;
    primitive.mode = TINYGLTF_MODE_TRIANGLES;
    tinygltf::Mesh mesh;
    mesh.primitives.push_back(primitive);
    model.meshes.push_back(mesh);
    tinygltf::Node node;
    node.mesh = 0;
    node.matrix = matrix;
    model.nodes.push_back(node);
    tinygltf::Scene scene;
    scene.nodes = {0};
    model.scenes.push_back(scene);
    model.defaultScene = 0;
    model.asset.version = "2.0";

    tinygltf::TinyGLTF writer;
    std::ostringstream os;
    writer.WriteGltfSceneToStream(&model, os, false, binary);
    return os.str();
}

std::span<const uint8_t> bytes_of(const std::string& s)
{
    return {reinterpret_cast<const uint8_t*>(s.data()), s.size()};
}

std::string invalid_input_message(const std::function<void()>& f)
{
    try
    {
        f();
    }
    catch (const InvalidInputError& e)
    {
        return e.what();
    }
    catch (const std::exception& e)
    {
        ADD_FAILURE() << "expected InvalidInputError, got another exception: " << e.what();
        return "";
    }
    ADD_FAILURE() << "expected InvalidInputError, nothing was thrown";
    return "";
}

} // namespace zomeify::surface_test
