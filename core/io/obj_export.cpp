#include "core/io/obj_export.h"

#include <cstdio>
#include <sstream>

#include "core/io/build_geometry.h"
#include "core/zome/real_sizes.h"

namespace zomeify {

namespace {

// Writes one placed copy of `mesh`; OBJ indices are 1-based and global.
void emit(std::ostringstream& out, size_t& vertex_base, const SimpleMesh& mesh, const Placement& at)
{
    char line[96];
    for (const auto& v : mesh.positions)
    {
        const auto p = place(at, v);
        std::snprintf(line, sizeof line, "v %.3f %.3f %.3f\n", static_cast<double>(p[0]), static_cast<double>(p[1]),
                      static_cast<double>(p[2]));
        out << line;
    }
    for (size_t i = 0; i + 2 < mesh.indices.size(); i += 3)
        out << "f " << vertex_base + mesh.indices[i] + 1 << " " << vertex_base + mesh.indices[i + 1] + 1 << " "
            << vertex_base + mesh.indices[i + 2] + 1 << "\n";
    vertex_base += mesh.positions.size();
}

void material(std::ostringstream& mtl, const std::string& name, const std::array<float, 3>& linear_rgb)
{
    mtl << "newmtl " << name << "\nKd " << linear_rgb[0] << " " << linear_rgb[1] << " " << linear_rgb[2]
        << "\nKa 0 0 0\nKs 0.2 0.2 0.2\nNs 40\nd 1\nillum 2\n\n";
}

} // namespace

ObjExport write_obj(const ZomeModel& model, const std::string& mtl_name)
{
    const BuildGeometry geo = build_geometry(model);
    std::ostringstream obj, mtl;
    obj << "# zomeify: " << model.nodes.size() << " balls, " << model.struts.size() << " struts; units mm\n";
    obj << "mtllib " << mtl_name << "\n";
    size_t base = 0;

    const SimpleMesh ball = make_sphere(static_cast<float>(kBallDiameterMm / 2), 12, 8);
    obj << "o balls\nusemtl ball_white\n";
    for (const auto& c : geo.ball_centres)
        emit(obj, base, ball, Placement{c, {0, 0, 0, 1}});
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
        const SimpleMesh cylinder = make_cylinder(kStrutRadiusMm, static_cast<float>(info.length_mm), 8);
        for (const Placement& p : placements)
            emit(obj, base, cylinder, p);
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
