#include "core/voxel/initial_model.h"

#include <algorithm>
#include <cmath>
#include <optional>
#include <sstream>
#include <string>

#include "core/base/stopwatch.h"

namespace zomeify {

GridLayoutOptions nudged_layout(const InitialModelOptions& options, int attempt)
{
    GridLayoutOptions layout;
    layout.resolution = options.resolution;
    layout.b1 = options.b1;
    layout.boundary_axis = options.mirror ? options.mirror->axis : -1;
    layout.boundary_at = options.mirror ? options.mirror->at : 0.0;
    if (attempt == 0)
        return layout;
    // Alternate smaller and larger cells (1%, 1%, 2%, 2%, ...) so the resolution stays close to the
    // user's choice, and shift by the additive recurrence of the plastic number, which spreads the
    // offsets evenly over the cell for any number of attempts.
    const int step = (attempt + 1) / 2;
    layout.scale_factor = 1.0 + (attempt % 2 ? -0.01 : 0.01) * std::min(step, 4);
    const double alpha[3] = {0.8191725133961645, 0.6710436067037893, 0.5497004779019703};
    for (int a = 0; a < 3; ++a)
    {
        const double f = attempt * alpha[a];
        layout.offset[a] = (f - std::floor(f)) - 0.5;
    }
    return layout;
}

namespace {

std::string describe(const GridSpec& grid, const GridLayoutOptions& layout)
{
    std::ostringstream os;
    os << "grid " << grid.dims[0] << "x" << grid.dims[1] << "x" << grid.dims[2] << " (cell x" << layout.scale_factor
       << ", offset " << layout.offset[0] << " " << layout.offset[1] << " " << layout.offset[2] << ")";
    return os.str();
}

// The boundary of a cell set, made mirror-symmetric first when the options ask for it.
Extraction extract_cells(const VoxelGrid& cells, const InitialModelOptions& options)
{
    if (!options.mirror)
        return extract_boundary(cells);
    VoxelGrid symmetric = cells;
    make_mirror_symmetric(symmetric, *options.mirror, options.mirror_merge);
    return extract_boundary(symmetric);
}

// Carves the accepted grid and extracts Z0 again. Carving keeps the topology, so the genus is judged
// on the plain grid and only the grid that is kept pays for the carving.
void carve(VoxelGrid& grid, InitialModel& out, const InitialModelOptions& options, const InsidePredicate* inside)
{
    if (!options.carve || !inside)
        return;
    InitialModelReport& rep = out.report;
    rep.carve = carve_outside_cells(grid, *inside, options.surface_probe);
    rep.voxels = grid.occupied_count();
    Extraction ex = extract_cells(grid, options);
    out.model = std::move(ex.model);
    rep.topology = ex.topology;
}

} // namespace

InitialModel build_initial_model(const std::array<Vec3, 2>& bbox, const VoxelSource& source,
                                 const InitialModelOptions& options, const InsidePredicate* carve_inside)
{
    Stopwatch clock;
    InitialModel out;
    InitialModelReport& rep = out.report;
    // The first manifold result, kept in case no nudged grid reaches the target genus: the user's
    // own grid then wins over a nudged one that is no better.
    struct FirstValid
    {
        InitialModel model;
        VoxelGrid grid;
    };
    std::optional<FirstValid> first_valid;
    VoxelGrid grid;
    for (int attempt = 0; attempt <= std::max(0, options.max_retries); ++attempt)
    {
        rep.attempts = attempt + 1;
        rep.attempt_used = attempt;
        rep.layout = nudged_layout(options, attempt);
        rep.grid = layout_grid(bbox[0], bbox[1], rep.layout);
        grid = source(rep.grid);
        rep.repair = repair_manifold(grid, options.repair);
        rep.valid = rep.repair.manifold;
        rep.voxels = grid.occupied_count();
        if (!rep.valid)
        {
            std::ostringstream note;
            note << describe(rep.grid, rep.layout) << ": " << rep.repair.remaining_bad_vertices
                 << " non-manifold vertices left with no simple cell to flip";
            rep.notes.push_back(note.str());
            continue;
        }
        rep.carve = {};
        rep.carve_topology = CarveTopology::Keep;
        rep.centre_sampled = false;
        Extraction ex = extract_cells(grid, options);
        out.model = std::move(ex.model);
        rep.topology = ex.topology;
        if (options.target_genus < 0 || rep.topology.genus == options.target_genus)
        {
            first_valid.reset();
            carve(grid, out, options, carve_inside);
            break;
        }
        std::ostringstream note;
        note << describe(rep.grid, rep.layout) << ": genus " << rep.topology.genus << ", not " << options.target_genus;
        // Another cell set of this grid: taken when it has the genus of S in one component, else noted.
        const auto reaches_genus = [&](const VoxelGrid& cells, bool manifold, const char* how) {
            Extraction x = extract_cells(cells, options);
            if (manifold && x.topology.genus == options.target_genus && x.topology.components == 1)
            {
                first_valid.reset();
                rep.voxels = cells.occupied_count();
                out.model = std::move(x.model);
                rep.topology = x.topology;
                return true;
            }
            note << " (" << how << ": ";
            if (manifold)
                note << "genus " << x.topology.genus << " in " << x.topology.components
                     << (x.topology.components == 1 ? " component)" : " components)");
            else
                note << "not manifold)";
            return false;
        };
        if (options.free_carving && options.carve && carve_inside)
        {
            VoxelGrid freed = grid;
            const CarveReport carved =
                carve_outside_cells(freed, *carve_inside, options.surface_probe, CarveTopology::Free);
            if (reaches_genus(freed, true, "carved freely"))
            {
                rep.notes.push_back(note.str() + " (carved freely: taken)");
                rep.carve = carved;
                rep.carve_topology = CarveTopology::Free;
                break;
            }
        }
        if (options.centre_sampling && carve_inside && options.surface_probe)
        {
            // Strict first: it keeps narrow gaps open; following thin parts keeps those joined.
            bool taken = false;
            for (ThinParts thin : {ThinParts::Strict, ThinParts::Follow})
            {
                VoxelGrid sampled = grid;
                const bool manifold = centre_sample(sampled, *carve_inside, options.surface_probe, thin).manifold;
                taken =
                    reaches_genus(sampled, manifold,
                                  thin == ThinParts::Follow ? "centre-sampled, thin parts followed" : "centre-sampled");
                if (taken)
                {
                    rep.notes.push_back(note.str() + " (centre-sampled: taken)");
                    rep.carve = {};
                    rep.carve_topology = CarveTopology::Keep;
                    rep.centre_sampled = true;
                    break;
                }
            }
            if (taken)
                break;
        }
        rep.notes.push_back(note.str());
        if (!first_valid)
            first_valid = FirstValid{out, grid};
    }
    if (first_valid)
    {
        // No grid reached the target genus: fall back to the first manifold one.
        std::vector<std::string> notes = std::move(rep.notes);
        const int attempts = rep.attempts;
        out = std::move(first_valid->model);
        carve(first_valid->grid, out, options, carve_inside);
        rep.notes = std::move(notes);
        rep.attempts = attempts;
    }
    else if (!rep.valid)
    {
        Extraction ex = extract_cells(grid, options);
        out.model = std::move(ex.model);
        rep.topology = ex.topology;
    }
    rep.seconds = clock.seconds();
    return out;
}

InitialModel build_initial_model(const TriangleMesh& surface, const InsidePredicate& inside,
                                 const InitialModelOptions& options)
{
    std::vector<VoxelizeStats> stats;
    auto source = [&](const GridSpec& spec) {
        stats.emplace_back();
        return voxelize(surface, spec, inside, &stats.back());
    };
    std::array<Vec3, 2> box = bounding_box(surface);
    if (options.mirror) // symmetric about the plane, so every cell's mirror image lies in the grid
    {
        const int a = options.mirror->axis;
        const double half = std::max(options.mirror->at - box[0][a], box[1][a] - options.mirror->at);
        box[0][a] = options.mirror->at - half;
        box[1][a] = options.mirror->at + half;
    }
    InitialModel out = build_initial_model(box, source, options, &inside);
    out.report.voxelize = stats.at(static_cast<size_t>(out.report.attempt_used));
    return out;
}

} // namespace zomeify
