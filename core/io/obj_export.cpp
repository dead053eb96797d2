#include "core/io/obj_export.h"

#include <cstdio>
#include <map>
#include <sstream>

#include "core/base/errors.h"
#include "core/io/build_geometry.h"
#include "core/zome/real_sizes.h"

namespace zomeify {

namespace {

// A template mesh as OBJ sees it: positions only, equal positions merged. OBJ carries no
// normals here, so the cylinder's caps can share its rim and every part is a closed surface
// (what a slicer wants).
struct ObjTemplate
{
    std::vector<std::array<float, 3>> positions;
    std::vector<uint32_t> indices;
};

ObjTemplate welded(const SimpleMesh& mesh)
{
    ObjTemplate t;
    std::map<std::array<float, 3>, uint32_t> index_of;
    std::vector<uint32_t> remap;
    for (const auto& p : mesh.positions)
    {
        const auto [it, fresh] = index_of.try_emplace(p, static_cast<uint32_t>(t.positions.size()));
        if (fresh)
            t.positions.push_back(p);
        remap.push_back(it->second);
    }
    for (uint32_t i : mesh.indices)
        t.indices.push_back(remap[i]);
    return t;
}

// Writes one placed copy of `t`; OBJ indices are 1-based and global.
void emit(std::ostringstream& out, size_t& vertex_base, const ObjTemplate& t, const Placement& at, double unit)
{
    char line[96];
    for (const auto& v : t.positions)
    {
        const auto p = place(at, v);
        std::snprintf(line, sizeof line, unit == 1.0 ? "v %.3f %.3f %.3f\n" : "v %.6f %.6f %.6f\n",
                      static_cast<double>(p[0]) * unit, static_cast<double>(p[1]) * unit,
                      static_cast<double>(p[2]) * unit);
        out << line;
    }
    for (size_t i = 0; i + 2 < t.indices.size(); i += 3)
        out << "f " << vertex_base + t.indices[i] + 1 << " " << vertex_base + t.indices[i + 1] + 1 << " "
            << vertex_base + t.indices[i + 2] + 1 << "\n";
    vertex_base += t.positions.size();
}

void material(std::ostringstream& mtl, const std::string& name, const std::array<float, 3>& linear_rgb)
{
    char kd[64];
    std::snprintf(kd, sizeof kd, "Kd %.4f %.4f %.4f\n", static_cast<double>(linear_rgb[0]),
                  static_cast<double>(linear_rgb[1]), static_cast<double>(linear_rgb[2]));
    mtl << "newmtl " << name << "\n" << kd << "Ka 0 0 0\nKs 0.2 0.2 0.2\nNs 40\nd 1\nillum 2\n\n";
}

} // namespace

ObjUnits parse_obj_units(const std::string& text)
{
    if (text == "mm")
        return ObjUnits::Millimetres;
    if (text == "m")
        return ObjUnits::Metres;
    throw InvalidInputError("OBJ units must be 'mm' or 'm', got '" + text.substr(0, 40) + "'");
}

ObjExport write_obj(const ZomeModel& model, const std::string& mtl_name, ObjUnits units)
{
    const BuildGeometry geo = build_geometry(model);
    const bool metres = units == ObjUnits::Metres;
    const double unit = metres ? 0.001 : 1.0;
    std::ostringstream obj, mtl;
    char size[160];
    std::snprintf(size, sizeof size,
                  "# size %.1f x %.1f x %.1f mm (x, y, z); y up; centred in x and z, resting on y = 0\n",
                  geo.size_mm[0], geo.size_mm[1], geo.size_mm[2]);
    obj << "# zomeify: " << model.nodes.size() << " balls, " << model.struts.size() << " struts\n";
    obj << "# units: " << (metres ? "metres (m)" : "millimetres (mm); import at scale 0.001 for metres") << "\n"
        << size;
    obj << "mtllib " << mtl_name << "\n";
    // Kd linear (issue 42): Blender takes Kd as its linear base colour, so it shows the GLB's colours.
    mtl << "# zomeify: Zome colours; Kd in linear RGB, as Blender reads it (the same numbers as the GLB's\n"
           "# baseColorFactor); three.js's MTLLoader reads Kd as sRGB and shows these darker\n\n";
    size_t base = 0;

    const ObjTemplate ball = welded(make_sphere(static_cast<float>(kBallDiameterMm / 2), 12, 8));
    obj << "o balls\nusemtl ball_white\n";
    for (const auto& c : geo.ball_centres)
        emit(obj, base, ball, Placement{c, {0, 0, 0, 1}}, unit);
    material(mtl, "ball_white", ball_color_linear());

    bool color_written[3] = {false, false, false};
    for (int k = 0; k < kStrutKindCount; ++k)
    {
        const auto& placements = geo.struts_by_kind[static_cast<size_t>(k)];
        if (placements.empty())
            continue;
        const StrutKindInfo& info = kind_info(static_cast<StrutKind>(k));
        const std::string mat = "strut_" + std::string(info.color);
        obj << "o struts_" << info.name << "\nusemtl " << mat << "\n";
        const ObjTemplate cylinder = welded(make_cylinder(kStrutRadiusMm, static_cast<float>(info.length_mm), 8));
        for (const Placement& p : placements)
            emit(obj, base, cylinder, p, unit);
        const auto c = static_cast<size_t>(kind_color(info.kind));
        if (!color_written[c])
        {
            material(mtl, mat, zome_color_linear(kind_color(info.kind)));
            color_written[c] = true;
        }
    }
    return {obj.str(), mtl.str()};
}

} // namespace zomeify
