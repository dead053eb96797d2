#include "core/io/glb_export.h"

#include <cstring>
#include <sstream>

#include "core/base/errors.h"
#include "core/io/build_geometry.h"
#include "core/surface/tiny_gltf_config.h"
#include "core/zome/real_sizes.h"

namespace zomeify {

namespace {

// Appends raw data to buffer 0 as a new buffer view, 4-byte aligned; returns its index.
int add_view(tinygltf::Model& m, const void* data, size_t bytes, int target)
{
    auto& buf = m.buffers[0].data;
    while (buf.size() % 4)
        buf.push_back(0);
    tinygltf::BufferView view;
    view.buffer = 0;
    view.byteOffset = buf.size();
    view.byteLength = bytes;
    view.target = target;
    const auto* p = static_cast<const unsigned char*>(data);
    buf.insert(buf.end(), p, p + bytes);
    m.bufferViews.push_back(view);
    return static_cast<int>(m.bufferViews.size() - 1);
}

int add_accessor(tinygltf::Model& m, int view, int component, int type, size_t count)
{
    tinygltf::Accessor a;
    a.bufferView = view;
    a.componentType = component;
    a.type = type;
    a.count = count;
    m.accessors.push_back(a);
    return static_cast<int>(m.accessors.size() - 1);
}

int add_mesh(tinygltf::Model& m, const SimpleMesh& mesh, int material, const std::string& name)
{
    const int pos_view = add_view(m, mesh.positions.data(), mesh.positions.size() * 12, TINYGLTF_TARGET_ARRAY_BUFFER);
    const int pos = add_accessor(m, pos_view, TINYGLTF_COMPONENT_TYPE_FLOAT, TINYGLTF_TYPE_VEC3, mesh.positions.size());
    // glTF requires min/max on POSITION accessors.
    std::array<double, 3> lo{1e30, 1e30, 1e30}, hi{-1e30, -1e30, -1e30};
    for (const auto& p : mesh.positions)
        for (size_t k = 0; k < 3; ++k)
        {
            lo[k] = std::min(lo[k], static_cast<double>(p[k]));
            hi[k] = std::max(hi[k], static_cast<double>(p[k]));
        }
    m.accessors[static_cast<size_t>(pos)].minValues.assign(lo.begin(), lo.end());
    m.accessors[static_cast<size_t>(pos)].maxValues.assign(hi.begin(), hi.end());
    const int nrm_view = add_view(m, mesh.normals.data(), mesh.normals.size() * 12, TINYGLTF_TARGET_ARRAY_BUFFER);
    const int nrm = add_accessor(m, nrm_view, TINYGLTF_COMPONENT_TYPE_FLOAT, TINYGLTF_TYPE_VEC3, mesh.normals.size());
    const int idx_view =
        add_view(m, mesh.indices.data(), mesh.indices.size() * 4, TINYGLTF_TARGET_ELEMENT_ARRAY_BUFFER);
    const int idx =
        add_accessor(m, idx_view, TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT, TINYGLTF_TYPE_SCALAR, mesh.indices.size());
    tinygltf::Primitive prim;
    prim.attributes["POSITION"] = pos;
    prim.attributes["NORMAL"] = nrm;
    prim.indices = idx;
    prim.material = material;
    prim.mode = TINYGLTF_MODE_TRIANGLES;
    tinygltf::Mesh gm;
    gm.name = name;
    gm.primitives.push_back(prim);
    m.meshes.push_back(gm);
    return static_cast<int>(m.meshes.size() - 1);
}

int add_material(tinygltf::Model& m, const std::string& name, const std::array<float, 3>& rgb)
{
    tinygltf::Material mat;
    mat.name = name;
    mat.pbrMetallicRoughness.baseColorFactor = {rgb[0], rgb[1], rgb[2], 1.0};
    mat.pbrMetallicRoughness.metallicFactor = 0.0;
    mat.pbrMetallicRoughness.roughnessFactor = 0.45;
    m.materials.push_back(mat);
    return static_cast<int>(m.materials.size() - 1);
}

} // namespace

std::string write_glb(const ZomeModel& model)
{
    // glTF's unit is the metre: geometry and placements are written in metres (not millimetres
    // under a scaled root), so a tool that flattens or ignores the node tree still gets real size.
    constexpr double kM = 0.001;
    const BuildGeometry geo = build_geometry(model);
    tinygltf::Model m;
    m.asset.version = "2.0";
    m.asset.generator = "zomeify";
    m.buffers.resize(1);

    tinygltf::Node root;
    root.name = "zome model";
    m.nodes.push_back(root);
    auto add_node = [&m](std::string name, int mesh, const std::array<float, 3>& at_mm) {
        tinygltf::Node n;
        n.name = std::move(name);
        n.mesh = mesh;
        for (float x : at_mm)
            n.translation.push_back(static_cast<double>(x) * kM);
        m.nodes.push_back(std::move(n));
        m.nodes[0].children.push_back(static_cast<int>(m.nodes.size() - 1));
        return &m.nodes.back();
    };

    const int ball_mat = add_material(m, "ball white", ball_color_linear());
    const int ball_mesh =
        add_mesh(m, make_sphere(static_cast<float>(kBallDiameterMm / 2 * kM), 16, 10), ball_mat, "ball");
    for (size_t i = 0; i < geo.ball_centres.size(); ++i)
        add_node(std::string(kBallPartCode) + " ball " + std::to_string(i), ball_mesh, geo.ball_centres[i]);
    int color_mat[3] = {-1, -1, -1};
    for (int k = 0; k < kStrutKindCount; ++k)
    {
        const auto& placements = geo.struts_by_kind[static_cast<size_t>(k)];
        if (placements.empty())
            continue;
        const StrutKindInfo& info = kind_info(static_cast<StrutKind>(k));
        const int c = static_cast<int>(kind_color(info.kind));
        if (color_mat[c] < 0)
            color_mat[c] = add_material(m, std::string(info.color), zome_color_linear(kind_color(info.kind)));
        const int mesh = add_mesh(
            m, make_cylinder(static_cast<float>(kStrutRadiusMm * kM), static_cast<float>(info.length_mm * kM), 12),
            color_mat[c], std::string(info.name));
        for (const Placement& p : placements)
        {
            tinygltf::Node* n =
                add_node(std::string(info.part_code) + " strut " + std::to_string(p.index), mesh, p.translation);
            n->rotation.assign(p.rotation.begin(), p.rotation.end());
        }
    }
    tinygltf::Scene scene;
    scene.name = "zomeify";
    scene.nodes.push_back(0);
    m.scenes.push_back(scene);
    m.defaultScene = 0;

    std::ostringstream out;
    tinygltf::TinyGLTF writer;
    if (!writer.WriteGltfSceneToStream(&m, out, false, true))
        throw IoError("could not write the GLB");
    return out.str();
}

} // namespace zomeify
