// zomeify inspect MESH [--json]: reads a mesh, repairs what is safe and prints the diagnosis
// (design.md §5). A mesh that reads but cannot proceed (holes, non-manifold) still gets its full
// report on stdout; the exit status is then 1 with the problems on one stderr line. A usable mesh
// also gets the automatic grid `run` would take (z0_choice.h), the same numbers and sentence, and
// its best mirror plane with how far the shape's mirror image lies from it (geom/mirror_plane.h).
#include <cstdio>
#include <iostream>
#include <optional>

#include <nlohmann/json.hpp>

#include "core/cli/args.h"
#include "core/cli/commands.h"
#include "core/geom/inside.h"
#include "core/geom/mirror_plane.h"
#include "core/pipeline/z0_choice.h"
#include "core/surface/prepare.h"
#include "core/surface/read_mesh.h"
#include "core/surface/report_text.h"

namespace zomeify::cli {

namespace {

// Millimetres per mesh unit at the automatic size (its Z0's built longest side).
double mm_per_unit(const TriangleMesh& mesh, const AutoResolution& automatic)
{
    Eigen::AlignedBox3d box;
    for (const Vec3& p : mesh.positions)
        box.extend(p);
    const double longest = box.sizes().maxCoeff();
    return longest > 0.0 ? automatic.size_cm * 10.0 / longest : 0.0;
}

std::string mirror_sentence(const MirrorPlane& m, double mm, double size_cm)
{
    char text[320];
    std::snprintf(text, sizeof text,
                  "normal (%.3f, %.3f, %.3f), offset %.4g: the mirror image lies within %.1f mm of the shape "
                  "(95%% within %.1f mm, RMS %.1f mm) at about %.0f cm",
                  m.normal.x(), m.normal.y(), m.normal.z(), m.offset, m.max * mm, m.p95 * mm, m.rms * mm, size_cm);
    return text;
}

} // namespace

int cmd_inspect(const CommandArgs& argv)
{
    const Args args(argv, {}, {"--json", "--thicken"});
    args.expect_positional(1, "one mesh file: zomeify inspect MESH [--json] [--thicken]");
    const std::string& path = args.positional()[0];
    PrepareOptions options;
    options.thicken_sheets = args.has("--thicken");
    const PolygonSoup soup = read_mesh_file(path);
    const SurfaceReport report = diagnose(soup, options);
    const size_t slash = path.find_last_of("/\\");
    const std::string name = slash == std::string::npos ? path : path.substr(slash + 1);
    std::optional<AutoResolution> automatic;
    std::optional<MirrorPlane> mirror;
    double mm = 0.0;
    if (report.ok())
    {
        const PreparedSurface surface = prepare_surface(soup, options);
        const SurfaceProjector projector(surface.mesh);
        const InsideTest inside(projector);
        automatic =
            automatic_resolution(projector, surface.report.genus, [&](const Vec3& p) { return inside.is_inside(p); });
        mirror = find_mirror_plane(projector);
        mm = mm_per_unit(surface.mesh, *automatic);
    }
    if (args.has("--json"))
    {
        nlohmann::json j = nlohmann::json::parse(surface_report_json(report, name));
        if (automatic)
            j["automatic_resolution"] = nlohmann::json::parse(auto_resolution_json(*automatic));
        if (mirror)
            j["mirror_plane"] = {{"normal", {mirror->normal.x(), mirror->normal.y(), mirror->normal.z()}},
                                 {"offset", mirror->offset},
                                 {"rms", mirror->rms},
                                 {"p95", mirror->p95},
                                 {"max", mirror->max},
                                 {"rms_mm", mirror->rms * mm},
                                 {"p95_mm", mirror->p95 * mm},
                                 {"max_mm", mirror->max * mm},
                                 {"at_size_cm", automatic->size_cm}};
        std::cout << j.dump(2) << "\n";
    }
    else
    {
        std::cout << surface_report_table(report, name);
        if (automatic)
            std::cout << "automatic grid  " << automatic->message << "\n";
        if (mirror)
            std::cout << "mirror plane    " << mirror_sentence(*mirror, mm, automatic->size_cm) << "\n";
    }
    std::cout.flush();
    if (report.ok())
        return 0;
    std::cerr << "zomeify: " << name << ": " << report.problem_summary() << "\n";
    return 1;
}

} // namespace zomeify::cli
