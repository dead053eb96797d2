// run_pipeline(): Z0, then annealing, with every report the CLI and the page show.
#include "core/pipeline/pipeline.h"

#include <algorithm>
#include <cmath>

#include "core/base/errors.h"
#include "core/base/stopwatch.h"
#include "core/geom/closest_point.h"
#include "core/geom/inside.h"
#include "core/mesh/model_convert.h"
#include "core/mesh/validate.h"
#include "core/pipeline/z0_choice.h"
#include "core/score/fold_over_report.h"
#include "core/voxel/advisor.h"

namespace zomeify {

namespace {

// Closedness, Zome rules, genus, fold-overs and energy of the model to be written.
void check_model(PipelineResult& r, const SurfaceContext& context, const EnergyOptions& energy, size_t target_nodes,
                 int fidelity_samples)
{
    const ZomeMesh mesh = from_model(r.model);
    const ValidationReport report = validate(mesh);
    r.model_valid = report.ok();
    r.validation = report.message();
    r.model_genus = report.genus;
    r.fold_overs = fold_over_report(mesh, context);
    r.clearance = clearance_report(mesh);
    if (r.model_valid && fidelity_samples > 0)
    {
        FidelityOptions fidelity;
        fidelity.samples_per_side = fidelity_samples;
        r.fidelity = measure_fidelity(r.model, context.projector(), fidelity);
    }
    EnergyOptions o = energy;
    o.target_nodes = target_nodes;
    r.model_energy = evaluate_energy(mesh, context, o);
}

} // namespace

PipelineResult run_pipeline(const TriangleMesh& surface, long long surface_genus, const PipelineOptions& options,
                            const PipelineCallbacks& callbacks)
{
    if (options.b1 < 0.0 || !std::isfinite(options.b1))
        throw InvalidInputError("b1 must be a positive length in mesh units");
    if (options.b1 == 0.0 && options.resolution != kAutoResolution &&
        (options.resolution < kMinResolution || options.resolution > kMaxResolution))
        throw InvalidInputError("the resolution must be between " + std::to_string(kMinResolution) + " and " +
                                std::to_string(kMaxResolution) + " cells, or automatic");

    Stopwatch clock;
    PipelineResult r;
    r.surface_genus = surface_genus;

    const SurfaceProjector projector(surface);
    const InsideTest inside(projector);
    const InsidePredicate is_inside = [&](const Vec3& p) { return inside.is_inside(p); };
    InitialModelOptions z0_options = run_z0_options(projector, surface_genus, options.resolution, options.b1);
    if (options.b1 == 0.0 && options.resolution == kAutoResolution)
    {
        r.automatic = automatic_resolution(projector, surface_genus, is_inside);
        z0_options.resolution = r.automatic->resolution;
    }
    // The automatic choice's ball target, unless the user set one (or a size: then Z0's count).
    AnnealOptions anneal = options.anneal;
    if (r.automatic && anneal.target_nodes == 0)
        anneal.target_nodes = r.automatic->target_nodes;
    r.initial = build_initial_model(surface, is_inside, z0_options);
    r.initial_seconds = r.initial.report.seconds;
    const InitialModelReport& z0 = r.initial.report;
    if (!z0.valid)
        throw InvalidInputError("could not make the voxel boundary a 2-manifold after " + std::to_string(z0.attempts) +
                                " grids (" + std::to_string(z0.repair.remaining_bad_vertices) +
                                " non-manifold vertices left); try another resolution");
    // The annealer's gate: Z0 must become a valid halfedge Zome mesh (closed, 2-manifold, Zome rules).
    ZomeMesh z0_mesh = from_model(r.initial.model);
    const ValidationReport check = validate(z0_mesh);
    if (!check.ok())
        throw InvalidInputError("internal error: Z0 failed validation: " + check.message());

    const auto [lo, hi] = bounding_box(surface);
    r.resolution =
        options.b1 > 0.0 ? static_cast<int>(std::lround((hi - lo).maxCoeff() / z0.grid.cell)) : z0_options.resolution;
    // The automatic choice already searched for the genus and says what it found.
    if (options.advise && !r.automatic && z0.topology.genus != surface_genus)
        r.advice = genus_advice(surface, surface_genus, is_inside, r.resolution, z0.topology.genus, z0_options).message;
    if (callbacks.initial)
        callbacks.initial(r.initial.model);

    const SurfaceContext context(projector, r.initial.model.transform);
    if (options.initial_only)
    {
        r.model = r.initial.model;
    }
    else
    {
        if (options.keep_to_kit_estimate && !anneal.part_limits)
        {
            r.kit_estimate = estimate_kits(projector, r.initial, anneal.target_nodes);
            anneal.part_limits = r.kit_estimate->limits;
        }
        Annealer annealer(std::move(z0_mesh), context, anneal);
        const Annealer::ProgressCallback progress = [&](const AnnealProgress& p) {
            if (callbacks.cancel && callbacks.cancel->load())
                annealer.cancel();
            if (callbacks.progress)
                callbacks.progress(p, annealer);
        };
        r.anneal = annealer.run(progress);
        // A cancelled run keeps its best model; a finished one ends at low temperature, where the
        // final model is the one the schedule converged to.
        r.model = r.anneal->stats.cancelled ? r.anneal->best_model : r.anneal->model;
    }
    check_model(r, context, anneal.energy, anneal.target_nodes ? anneal.target_nodes : r.initial.model.nodes.size(),
                options.fidelity_samples);
    r.seconds = clock.seconds();
    return r;
}

} // namespace zomeify
