// zomeify inspect MESH [--json]: reads a mesh, repairs what is safe and prints the diagnosis
// (design.md §5). A mesh that reads but cannot proceed (holes, non-manifold) still gets its full
// report on stdout; the exit status is then 1 with the problems on one stderr line.
#include <iostream>

#include "core/cli/args.h"
#include "core/cli/commands.h"
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
    const SurfaceReport report = diagnose(read_mesh_file(path), options);
    const size_t slash = path.find_last_of("/\\");
    const std::string name = slash == std::string::npos ? path : path.substr(slash + 1);
    std::cout << (args.has("--json") ? surface_report_json(report, name) : surface_report_table(report, name));
    std::cout.flush();
    if (report.ok())
        return 0;
    std::cerr << "zomeify: " << name << ": " << report.problem_summary() << "\n";
    return 1;
}

} // namespace zomeify::cli
