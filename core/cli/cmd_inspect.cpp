// zomeify inspect MESH [--json]: reads a mesh, repairs what is safe and prints the diagnosis
// (design.md §5). A mesh that reads but cannot proceed (holes, non-manifold) still gets its full
// report on stdout; the exit status is then 1 with the problems on one stderr line. A usable mesh
// also gets the automatic grid `run` would take (z0_choice.h), the same numbers and sentence.
#include <iostream>
#include <optional>

#include <nlohmann/json.hpp>

#include "core/cli/args.h"
#include "core/cli/commands.h"
#include "core/geom/inside.h"
#include "core/pipeline/z0_choice.h"
#include "core/surface/prepare.h"
#include "core/surface/read_mesh.h"
#include "core/surface/report_text.h"

namespace zomeify::cli {

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
    if (report.ok())
    {
        const PreparedSurface surface = prepare_surface(soup, options);
        const SurfaceProjector projector(surface.mesh);
        const InsideTest inside(projector);
        automatic =
            automatic_resolution(projector, surface.report.genus, [&](const Vec3& p) { return inside.is_inside(p); });
    }
    if (args.has("--json"))
    {
        nlohmann::json j = nlohmann::json::parse(surface_report_json(report, name));
        if (automatic)
            j["automatic_resolution"] = nlohmann::json::parse(auto_resolution_json(*automatic));
        std::cout << j.dump(2) << "\n";
    }
    else
    {
        std::cout << surface_report_table(report, name);
        if (automatic)
            std::cout << "automatic grid  " << automatic->message << "\n";
    }
    std::cout.flush();
    if (report.ok())
        return 0;
    std::cerr << "zomeify: " << name << ": " << report.problem_summary() << "\n";
    return 1;
}

} // namespace zomeify::cli
