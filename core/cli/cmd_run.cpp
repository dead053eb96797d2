// zomeify run MESH -o OUT [...] (design.md §5). The annealing stages are not built yet, so only
// `--initial-only` runs: it writes the initial model Z0 (paper §3.1) and says whether Z0 kept the
// genus of the surface, with the resolution advisor's hint when it did not.
#include <algorithm>
#include <cmath>
#include <fstream>
#include <iomanip>
#include <iostream>
#include <sstream>

#include <nlohmann/json.hpp>

#include "core/base/errors.h"
#include "core/base/stopwatch.h"
#include "core/cli/args.h"
#include "core/cli/commands.h"
#include "core/geom/closest_point.h"
#include "core/geom/inside.h"
#include "core/io/model_io.h"
#include "core/mesh/model_convert.h"
#include "core/mesh/validate.h"
#include "core/surface/prepare.h"
#include "core/surface/read_mesh.h"
#include "core/voxel/advisor.h"
#include "core/voxel/initial_model.h"

namespace zomeify::cli
{

namespace
{

constexpr int kDefaultResolution = 16;

std::string file_name(const std::string &path)
{
    const size_t slash = path.find_last_of("/\\");
    return slash == std::string::npos ? path : path.substr(slash + 1);
}

nlohmann::json stats_json(const InitialModel &z0, long long surface_genus, int resolution, double seconds)
{
    const InitialModelReport &r = z0.report;
    nlohmann::json j;
    j["stage"] = "initial";
    j["wall_seconds"] = seconds;
    j["threads"] = 1;
    j["proposals"] = 0;
    j["commits"] = 0;
    j["N"] = z0.model.nodes.size();
    j["struts"] = z0.model.struts.size();
    j["faces"] = z0.model.faces.size();
    j["struts_by_kind"] = {{"B1", z0.model.struts.size()}};
    j["genus_surface"] = surface_genus;
    j["genus_model"] = r.topology.genus;
    j["components_model"] = r.topology.components;
    j["valid"] = r.valid;
    j["resolution"] = resolution;
    j["b1_mesh_units"] = r.grid.cell;
    j["grid"] = r.grid.dims;
    j["voxels"] = r.voxels;
    j["grid_attempts"] = r.attempts;
    j["grid_used"] = r.attempt_used;
    j["cell_scale_factor"] = r.layout.scale_factor;
    j["cleanup_removed"] = r.repair.removed;
    j["cleanup_added"] = r.repair.added;
    j["cavity_cells_filled"] = r.voxelize.cavity_cells;
    j["initial_seconds"] = r.seconds;
    return j;
}

} // namespace

int cmd_run(const CommandArgs &argv)
{
    const Args args(argv,
                    {"-o", "--resolution", "--b1", "--target-nodes", "--seconds", "--threads", "--seed", "--stats"},
                    {"--initial-only"});
    args.expect_positional(1, "one mesh file: zomeify run MESH -o OUT --initial-only");
    if (!args.has("--initial-only"))
    {
        std::cerr << "zomeify: run: annealing is not available yet; add --initial-only to write the initial model Z0\n";
        return 2;
    }
    const std::vector<std::string> outputs = args.values("-o");
    if (outputs.empty())
        throw InvalidInputError("missing -o OUT");
    if (args.has("--resolution") && args.has("--b1"))
        throw InvalidInputError("give --resolution or --b1, not both");

    Stopwatch clock;
    const std::string &path = args.positional()[0];
    PreparedSurface surface = prepare_surface(read_mesh_file(path));
    const long long surface_genus = surface.report.genus;

    InitialModelOptions options;
    // A grid a few percent off (a nudge) often keeps a handle the exact grid closes or bridges.
    options.target_genus = surface_genus;
    options.resolution = static_cast<int>(args.integer("--resolution", kDefaultResolution, 1, 1024));
    options.b1 = args.number("--b1", 0.0, 0.0, 1e300);
    if (args.has("--b1") && !(options.b1 > 0.0))
        throw InvalidInputError("--b1 must be a positive length in mesh units");

    const SurfaceProjector projector(surface.mesh);
    const InsideTest inside(projector);
    const InsidePredicate is_inside = [&](const Vec3 &p) { return inside.is_inside(p); };
    InitialModel z0 = build_initial_model(surface.mesh, is_inside, options);
    const InitialModelReport &r = z0.report;
    if (!r.valid)
    {
        std::ostringstream msg;
        msg << "could not make the voxel boundary a 2-manifold after " << r.attempts << " grids ("
            << r.repair.remaining_bad_vertices << " non-manifold vertices left); try another resolution";
        throw InvalidInputError(msg.str());
    }

    // The annealer's gate: Z0 must become a valid halfedge Zome mesh (closed, 2-manifold, Zome rules).
    const ValidationReport check = validate(from_model(z0.model));
    if (!check.ok())
        throw InvalidInputError("internal error: Z0 failed validation: " + check.message());

    // The resolution the user effectively chose: with --b1, the cells along the longest side.
    const auto [lo, hi] = bounding_box(surface.mesh);
    const int resolution =
        args.has("--b1") ? static_cast<int>(std::lround((hi - lo).maxCoeff() / r.grid.cell)) : options.resolution;

    std::string advice;
    if (r.topology.genus != surface_genus)
    {
        // The user wants about this much detail, so look first for the nearest finer grid that
        // keeps the genus (the smallest one overall may be a useless blob for a genus-0 shape), and
        // only then below their choice.
        AdvisorOptions advisor;
        advisor.seconds = 10.0;
        advisor.min_resolution = resolution + 1;
        advisor.max_resolution = std::max(64, 2 * resolution);
        AdvisorResult found = advise_resolution(surface.mesh, surface_genus, is_inside, advisor);
        if (!found.found && resolution > 4)
        {
            advisor.min_resolution = 4;
            advisor.max_resolution = resolution - 1;
            const AdvisorResult below = advise_resolution(surface.mesh, surface_genus, is_inside, advisor);
            if (below.found)
                found = below;
        }
        advice = advice_message(resolution, r.topology.genus, found);
    }

    const double seconds = clock.seconds();
    const nlohmann::json stats = stats_json(z0, surface_genus, resolution, seconds);
    z0.model.stats_json = stats.dump();
    for (const std::string &out : outputs)
        write_model_file(out, z0.model);
    if (const auto stats_path = args.value("--stats"))
    {
        std::ofstream f(*stats_path);
        f << stats.dump(2) << "\n";
        if (!f)
            throw IoError("cannot write " + *stats_path);
    }

    std::ostringstream s;
    s << std::setprecision(4);
    s << "Z0 of " << file_name(path) << " at " << resolution << " cells along the longest side (b1 = " << r.grid.cell
      << " mesh units, grid " << r.grid.dims[0] << "x" << r.grid.dims[1] << "x" << r.grid.dims[2]
      << "): " << z0.model.nodes.size() << " balls, " << z0.model.struts.size() << " B1 struts, "
      << z0.model.faces.size() << " quads from " << r.voxels << " voxels; genus " << r.topology.genus
      << " against the surface's " << surface_genus << (r.topology.genus == surface_genus ? " (kept)" : " (NOT kept)")
      << ". Cleanup removed " << r.repair.removed << " and added " << r.repair.added << " simple voxels";
    if (r.attempt_used > 0)
        s << "; nudged grid " << r.attempt_used << " (cell x" << r.layout.scale_factor << ") used";
    if (r.attempts > 1)
        s << "; " << r.attempts << " grids tried";
    s << "; " << std::setprecision(3) << seconds << " s. Wrote";
    for (const std::string &out : outputs)
        s << " " << out;
    s << ".";
    if (!advice.empty())
        s << " Hint: " << advice << ".";
    std::cout << s.str() << "\n";
    return 0;
}

} // namespace zomeify::cli
