// glTF 2.0 (.gltf JSON and .glb) through tinygltf. Every triangle, strip and fan primitive of
// every mesh instance in the scene is read, with the node transforms applied; points and lines
// are skipped. Accessor ranges are checked here again rather than trusting the parser.
#include <algorithm>
#include <cmath>
#include <limits>

#include <Eigen/Geometry>

#include "core/base/errors.h"
#include "core/surface/byte_order.h"
#include "core/surface/readers.h"
#include "core/surface/tiny_gltf_config.h"

namespace zomeify::detail {

namespace {

using Mat4 = Eigen::Matrix4d;

// Limits against files whose node graph instances the same meshes exponentially often.
constexpr size_t max_node_visits = 1'000'000;
constexpr size_t max_output_vertices = 100'000'000;

bool skip_image(tinygltf::Image*, const int, std::string*, std::string*, int, int, const unsigned char*, int, void*)
{
    return true;
}

// File access for a glTF read from memory: there is no directory to look in, so any external URI
// is reported (through `user_data`) instead of being searched for in the working directory.
struct NoFiles
{
    std::string missing;
};

bool no_file_exists(const std::string& name, void* user_data)
{
    auto* state = static_cast<NoFiles*>(user_data);
    if (state->missing.empty())
        state->missing = name;
    return false;
}

std::string same_path(const std::string& path, void*) { return path; }

bool no_read(std::vector<unsigned char>*, std::string* err, const std::string&, void*)
{
    if (err)
        *err = "no file access";
    return false;
}

bool no_write(std::string* err, const std::string&, const std::vector<unsigned char>&, void*)
{
    if (err)
        *err = "no file access";
    return false;
}

std::string first_line(const std::string& text)
{
    std::string s = text.substr(0, text.find('\n'));
    return s.empty() ? "unknown error" : s;
}

int component_size(int component_type)
{
    switch (component_type)
    {
    case TINYGLTF_COMPONENT_TYPE_BYTE:
    case TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE:
        return 1;
    case TINYGLTF_COMPONENT_TYPE_SHORT:
    case TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT:
        return 2;
    case TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT:
    case TINYGLTF_COMPONENT_TYPE_FLOAT:
        return 4;
    default:
        return 0;
    }
}

double load_component(const unsigned char* p, int component_type, bool normalized)
{
    // glTF data is little-endian; assemble bytes so the host's order does not matter.
    uint32_t u = 0;
    const int size = component_size(component_type);
    for (int i = 0; i < size; ++i)
        u |= static_cast<uint32_t>(p[i]) << (8 * i);
    switch (component_type)
    {
    case TINYGLTF_COMPONENT_TYPE_FLOAT:
        return static_cast<double>(float_from_bits(u));
    case TINYGLTF_COMPONENT_TYPE_BYTE:
    {
        const double v = static_cast<int8_t>(u);
        return normalized ? std::max(v / 127.0, -1.0) : v;
    }
    case TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE:
        return normalized ? u / 255.0 : u;
    case TINYGLTF_COMPONENT_TYPE_SHORT:
    {
        const double v = static_cast<int16_t>(u);
        return normalized ? std::max(v / 32767.0, -1.0) : v;
    }
    case TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT:
        return normalized ? u / 65535.0 : u;
    default:
        return u;
    }
}

// The values of accessor `index` (count x components), after checking every byte it would touch.
std::vector<double> read_accessor(const tinygltf::Model& model, int index, int components, const std::string& what)
{
    if (index < 0 || static_cast<size_t>(index) >= model.accessors.size())
        throw InvalidInputError(what + ": accessor " + std::to_string(index) + " does not exist");
    const tinygltf::Accessor& a = model.accessors[static_cast<size_t>(index)];
    if (a.sparse.isSparse)
        throw InvalidInputError(what + ": sparse accessors are not supported");
    const int csize = component_size(a.componentType);
    const int ncomp = components == 3 ? TINYGLTF_TYPE_VEC3 : TINYGLTF_TYPE_SCALAR;
    if (csize == 0 || a.type != ncomp)
        throw InvalidInputError(what + ": accessor " + std::to_string(index) + " has an unexpected type");
    if (a.count == 0)
        return {};
    if (a.bufferView < 0 || static_cast<size_t>(a.bufferView) >= model.bufferViews.size())
        throw InvalidInputError(what + ": accessor " + std::to_string(index) + " has no buffer view");
    const tinygltf::BufferView& view = model.bufferViews[static_cast<size_t>(a.bufferView)];
    if (view.buffer < 0 || static_cast<size_t>(view.buffer) >= model.buffers.size())
        throw InvalidInputError(what + ": buffer view " + std::to_string(a.bufferView) + " has no buffer");
    const std::vector<unsigned char>& data = model.buffers[static_cast<size_t>(view.buffer)].data;
    const size_t element = static_cast<size_t>(csize) * static_cast<size_t>(components);
    const size_t stride = view.byteStride ? view.byteStride : element;
    if (view.byteOffset > data.size() || view.byteLength > data.size() - view.byteOffset || stride < element ||
        a.byteOffset > view.byteLength || view.byteLength - a.byteOffset < element ||
        a.count - 1 > (view.byteLength - a.byteOffset - element) / stride)
        throw InvalidInputError(what + ": accessor " + std::to_string(index) + " reaches outside its buffer");
    std::vector<double> values(a.count * static_cast<size_t>(components));
    const unsigned char* base = data.data() + view.byteOffset + a.byteOffset;
    for (size_t i = 0; i < a.count; ++i)
        for (int c = 0; c < components; ++c)
            values[i * static_cast<size_t>(components) + static_cast<size_t>(c)] =
                load_component(base + i * stride + static_cast<size_t>(c * csize), a.componentType, a.normalized);
    return values;
}

Mat4 local_transform(const tinygltf::Node& node)
{
    Mat4 m = Mat4::Identity();
    if (node.matrix.size() == 16)
    {
        for (int i = 0; i < 16; ++i)
            m(i % 4, i / 4) = node.matrix[static_cast<size_t>(i)]; // column-major
        return m;
    }
    Eigen::Affine3d t = Eigen::Affine3d::Identity();
    if (node.translation.size() == 3)
        t.translate(Eigen::Vector3d(node.translation[0], node.translation[1], node.translation[2]));
    if (node.rotation.size() == 4)
    {
        Eigen::Quaterniond q(node.rotation[3], node.rotation[0], node.rotation[1], node.rotation[2]);
        if (q.norm() > 0)
            t.rotate(q.normalized());
    }
    if (node.scale.size() == 3)
        t.scale(Eigen::Vector3d(node.scale[0], node.scale[1], node.scale[2]));
    return t.matrix();
}

class SceneReader
{
public:
    explicit SceneReader(const tinygltf::Model& model) : model_(model), on_path_(model.nodes.size(), 0) {}

    void add_node(int index, const Mat4& parent)
    {
        if (index < 0 || static_cast<size_t>(index) >= model_.nodes.size())
            throw InvalidInputError("node " + std::to_string(index) + " does not exist");
        if (on_path_[static_cast<size_t>(index)])
            throw InvalidInputError("node " + std::to_string(index) + " is its own ancestor");
        if (++visits_ > max_node_visits)
            throw InvalidInputError("the scene instances more than " + std::to_string(max_node_visits) + " nodes");
        const tinygltf::Node& node = model_.nodes[static_cast<size_t>(index)];
        const Mat4 m = parent * local_transform(node);
        if (!m.allFinite())
            throw InvalidInputError("node " + std::to_string(index) + " has a NaN or infinite transform");
        if (node.mesh >= 0)
            add_mesh(node.mesh, m);
        on_path_[static_cast<size_t>(index)] = 1;
        for (const int child : node.children)
            add_node(child, m);
        on_path_[static_cast<size_t>(index)] = 0;
    }

    void add_mesh(int index, const Mat4& m)
    {
        if (static_cast<size_t>(index) >= model_.meshes.size())
            throw InvalidInputError("mesh " + std::to_string(index) + " does not exist");
        const auto& primitives = model_.meshes[static_cast<size_t>(index)].primitives;
        for (size_t p = 0; p < primitives.size(); ++p)
            add_primitive(primitives[p], m, "mesh " + std::to_string(index) + " primitive " + std::to_string(p));
    }

    PolygonSoup take() { return std::move(soup_); }

private:
    void add_primitive(const tinygltf::Primitive& prim, const Mat4& m, const std::string& what)
    {
        const int mode = prim.mode < 0 ? TINYGLTF_MODE_TRIANGLES : prim.mode;
        if (mode != TINYGLTF_MODE_TRIANGLES && mode != TINYGLTF_MODE_TRIANGLE_STRIP &&
            mode != TINYGLTF_MODE_TRIANGLE_FAN)
            return;
        const auto position = prim.attributes.find("POSITION");
        if (position == prim.attributes.end())
            throw InvalidInputError(what + " has no POSITION attribute");
        const std::vector<double> xyz = read_accessor(model_, position->second, 3, what);
        const size_t n = xyz.size() / 3;
        if (soup_.positions.size() + n > max_output_vertices)
            throw InvalidInputError("the scene has more than " + std::to_string(max_output_vertices) + " vertices");
        std::vector<double> order;
        if (prim.indices >= 0)
            order = read_accessor(model_, prim.indices, 1, what);
        else
        {
            order.resize(n);
            for (size_t i = 0; i < n; ++i)
                order[i] = static_cast<double>(i);
        }
        for (const double i : order)
            if (!(i >= 0 && i < static_cast<double>(n)))
                throw InvalidInputError(what + ": index " + std::to_string(static_cast<long long>(i)) +
                                        " is out of range (" + std::to_string(n) + " vertices)");

        const auto first = static_cast<uint32_t>(soup_.positions.size());
        for (size_t i = 0; i < n; ++i)
        {
            const Eigen::Vector4d p = m * Eigen::Vector4d(xyz[3 * i], xyz[3 * i + 1], xyz[3 * i + 2], 1.0);
            if (!p.allFinite())
                throw InvalidInputError(what + ": vertex " + std::to_string(i) + " is NaN or infinite");
            soup_.positions.push_back(p.head<3>());
        }
        // A mirroring transform turns counter-clockwise into clockwise.
        const bool mirror = m.topLeftCorner<3, 3>().determinant() < 0;
        const auto emit = [&](size_t a, size_t b, size_t c) {
            const uint32_t ia = first + static_cast<uint32_t>(order[a]);
            const uint32_t ib = first + static_cast<uint32_t>(order[b]);
            const uint32_t ic = first + static_cast<uint32_t>(order[c]);
            soup_.polygons.push_back(mirror ? std::vector<uint32_t>{ia, ic, ib} : std::vector<uint32_t>{ia, ib, ic});
        };
        const size_t k = order.size();
        if (mode == TINYGLTF_MODE_TRIANGLES)
            for (size_t i = 0; i + 2 < k; i += 3)
                emit(i, i + 1, i + 2);
        else if (mode == TINYGLTF_MODE_TRIANGLE_STRIP)
            for (size_t i = 0; i + 2 < k; ++i)
                i % 2 == 0 ? emit(i, i + 1, i + 2) : emit(i + 1, i, i + 2);
        else
            for (size_t i = 1; i + 1 < k; ++i)
                emit(0, i, i + 1);
    }

    const tinygltf::Model& model_;
    std::vector<uint8_t> on_path_;
    size_t visits_ = 0;
    PolygonSoup soup_;
};

} // namespace

PolygonSoup read_gltf(std::span<const uint8_t> bytes, bool binary, const std::string& base_dir)
{
    if (bytes.empty())
        throw InvalidInputError("file is empty");
    if (bytes.size() > std::numeric_limits<unsigned int>::max())
        throw InvalidInputError("file is larger than 4 GB");
    tinygltf::TinyGLTF loader;
    loader.SetImageLoader(skip_image, nullptr);
    NoFiles no_files;
    if (base_dir.empty())
        loader.SetFsCallbacks({no_file_exists, same_path, no_read, no_write, &no_files});
    tinygltf::Model model;
    std::string err, warn;
    bool ok = false;
    try
    {
        const auto size = static_cast<unsigned int>(bytes.size());
        ok = binary ? loader.LoadBinaryFromMemory(&model, &err, &warn, bytes.data(), size, base_dir)
                    : loader.LoadASCIIFromString(&model, &err, &warn, reinterpret_cast<const char*>(bytes.data()), size,
                                                 base_dir);
    }
    catch (const std::exception& e)
    {
        throw InvalidInputError(std::string("invalid glTF: ") + e.what());
    }
    if (!no_files.missing.empty())
        throw InvalidInputError("external file '" + no_files.missing +
                                "' cannot be read when the glTF comes from memory; use a .glb or embed the buffers");
    if (!ok)
        throw InvalidInputError("invalid glTF: " + first_line(err));

    SceneReader reader(model);
    if (!model.scenes.empty())
    {
        const size_t s = model.defaultScene >= 0 && static_cast<size_t>(model.defaultScene) < model.scenes.size()
                             ? static_cast<size_t>(model.defaultScene)
                             : 0;
        for (const int node : model.scenes[s].nodes)
            reader.add_node(node, Mat4::Identity());
    }
    else if (!model.nodes.empty())
    {
        // No scene: every node that is nobody's child is a root.
        std::vector<uint8_t> is_child(model.nodes.size(), 0);
        for (const tinygltf::Node& n : model.nodes)
            for (const int c : n.children)
                if (c >= 0 && static_cast<size_t>(c) < is_child.size())
                    is_child[static_cast<size_t>(c)] = 1;
        for (size_t i = 0; i < model.nodes.size(); ++i)
            if (!is_child[i])
                reader.add_node(static_cast<int>(i), Mat4::Identity());
    }
    else
        for (size_t m = 0; m < model.meshes.size(); ++m)
            reader.add_mesh(static_cast<int>(m), Mat4::Identity());
    PolygonSoup soup = reader.take();
    if (soup.polygons.empty())
        throw InvalidInputError("no triangles in the scene");
    return soup;
}

} // namespace zomeify::detail
