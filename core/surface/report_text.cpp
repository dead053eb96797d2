#include "core/surface/report_text.h"

#include <cmath>
#include <iomanip>
#include <sstream>

#include <nlohmann/json.hpp>

namespace zomeify {

namespace {

double diagonal(const SurfaceReport& r)
{
    double s = 0;
    for (int a = 0; a < 3; ++a)
        s += (r.bbox_max[a] - r.bbox_min[a]) * (r.bbox_max[a] - r.bbox_min[a]);
    return std::sqrt(s);
}

std::string count(size_t n, const std::string& noun) { return std::to_string(n) + " " + noun + (n == 1 ? "" : "s"); }

std::string triple(const std::array<double, 3>& v)
{
    std::ostringstream os;
    os << std::setprecision(7) << v[0] << "  " << v[1] << "  " << v[2];
    return os.str();
}

} // namespace

std::string surface_report_table(const SurfaceReport& r, const std::string& name)
{
    std::ostringstream os;
    const auto row = [&](const std::string& key, const std::string& value) {
        os << std::left << std::setw(16) << key << value << "\n";
    };
    const auto yes_no = [](bool b) { return std::string(b ? "yes" : "no"); };
    row("file", name);
    row("input", std::to_string(r.input_vertices) + " vertices, " + std::to_string(r.input_faces) + " faces");
    row("vertices", std::to_string(r.vertices));
    row("faces", std::to_string(r.faces) + " triangles");
    row("edges", std::to_string(r.edges));
    row("closed",
        yes_no(r.closed) +
            (r.closed ? "" : " (" + count(r.holes, "hole") + ", " + count(r.boundary_edges, "boundary edge") + ")"));
    row("manifold", yes_no(r.manifold));
    row("components",
        std::to_string(r.components) + (r.cavities ? " (" + std::to_string(r.cavities) + " of them cavities)" : ""));
    row("euler", std::to_string(r.euler));
    row("genus", std::to_string(r.genus));
    row("bbox min", triple(r.bbox_min));
    row("bbox max", triple(r.bbox_max));
    std::ostringstream d;
    d << std::setprecision(7) << diagonal(r);
    row("bbox diagonal", d.str());
    if (r.repairs.empty())
        row("repaired", "nothing");
    for (size_t i = 0; i < r.repairs.size(); ++i)
        row(i == 0 ? "repaired" : "", r.repairs[i]);
    if (r.problems.empty())
        row("problems", "none");
    for (size_t i = 0; i < r.problems.size(); ++i)
        row(i == 0 ? "problems" : "", r.problems[i]);
    return os.str();
}

std::string surface_report_json(const SurfaceReport& r, const std::string& name)
{
    nlohmann::ordered_json j;
    j["file"] = name;
    j["ok"] = r.ok();
    j["vertices"] = r.vertices;
    j["faces"] = r.faces;
    j["edges"] = r.edges;
    j["closed"] = r.closed;
    j["manifold"] = r.manifold;
    j["components"] = r.components;
    j["cavities"] = r.cavities;
    j["genus"] = r.genus;
    j["euler"] = r.euler;
    j["holes"] = r.holes;
    j["boundary_edges"] = r.boundary_edges;
    j["non_manifold_edges"] = r.non_manifold_edges;
    j["non_manifold_vertices"] = r.non_manifold_vertices;
    j["non_orientable_components"] = r.non_orientable_components;
    j["bbox"] = {{"min", r.bbox_min}, {"max", r.bbox_max}, {"diagonal", diagonal(r)}};
    j["input"] = {{"vertices", r.input_vertices}, {"faces", r.input_faces}};
    j["repairs"] = {
        {"welded_vertices", r.welded_vertices},
        {"unreferenced_vertices", r.unreferenced_vertices},
        {"dropped_small_faces", r.dropped_small_faces},
        {"dropped_invalid_faces", r.dropped_invalid_faces},
        {"dropped_degenerate_faces", r.dropped_degenerate_faces},
        {"dropped_duplicate_faces", r.dropped_duplicate_faces},
        {"triangulated_polygons", r.triangulated_polygons},
        {"flipped_faces", r.flipped_faces},
        {"filled_holes", r.filled_holes},
        {"separated_pinched_vertices", r.separated_pinched_vertices},
        {"separated_edges", r.separated_edges},
        {"dropped_specks", r.dropped_specks},
        {"dropped_sheets", r.dropped_sheets},
        {"joined_overlapping_parts", r.joined_overlapping_parts},
        {"thickened_sheets", r.thickened_sheets},
    };
    j["input_defects"] = {
        {"holes", r.input_holes},
        {"boundary_edges", r.input_boundary_edges},
        {"non_manifold_edges", r.input_non_manifold_edges},
        {"non_manifold_vertices", r.input_non_manifold_vertices},
    };
    j["repaired"] = r.repairs;
    j["problems"] = r.problems;
    return j.dump(2) + "\n";
}

} // namespace zomeify
