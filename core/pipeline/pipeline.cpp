// run_pipeline(): Z0, then annealing, with every report the CLI and the page show.
#include "core/pipeline/pipeline.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <utility>

#include "core/base/errors.h"
#include "core/base/stopwatch.h"
#include "core/geom/closest_point.h"
#include "core/geom/inside.h"
#include "core/mesh/model_convert.h"
#include "core/mesh/validate.h"
#include "core/pipeline/z0_choice.h"
#include "core/score/fold_over_report.h"
#include "core/voxel/advisor.h"
#include "core/zome/real_sizes.h"
#include "core/zome/slots.h"

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

// A mirror-symmetric Z0 (mirror_choice.h) in r.initial, with anneal.mirror set, when the shape is
// symmetric and such a Z0 keeps the shape's genus; otherwise r.mirror says why not.
void build_mirrored_z0(PipelineResult& r, const TriangleMesh& surface, const SurfaceProjector& projector,
                       const InsidePredicate& is_inside, const InitialModelOptions& z0_options, AnnealOptions& anneal)
{
    const auto [lo, hi] = bounding_box(surface);
    const double cell = z0_options.b1 > 0.0 ? z0_options.b1 : (hi - lo).maxCoeff() / z0_options.resolution;
    r.mirror = choose_mirror(projector, cell / kPhi);
    if (!r.mirror->symmetric)
        return;
    // The union keeps thin parts; when it closes a hole of the shape, the intersection may keep it.
    for (const MirrorMerge merge : {MirrorMerge::Union, MirrorMerge::Intersection})
    {
        InitialModelOptions o = z0_options;
        o.mirror = r.mirror->along;
        o.mirror_merge = merge;
        InitialModel z0 = build_initial_model(surface, is_inside, o);
        const std::optional<int> corner = mirror_corner_index(z0.report.grid, *o.mirror);
        if (!z0.report.valid || z0.report.topology.genus != r.surface_genus || z0.report.topology.components != 1 ||
            !corner || !validate(from_model(z0.model)).ok())
            continue;
        const LatticeMirror lattice =
            LatticeMirror::through(o.mirror->axis, QPhi{0, 2 * static_cast<int64_t>(*corner)});
        if (!mirror_mismatch(z0.model, lattice).symmetric())
            continue;
        r.initial = std::move(z0);
        anneal.mirror = lattice;
        r.mirror->used = lattice;
        return;
    }
    r.mirror->symmetric = false;
    const std::string axis = std::string(1, "xyz"[r.mirror->along->axis]);
    char text[300];
    std::snprintf(text, sizeof text,
                  "Not made mirror-symmetric: the shape is symmetric about %s = %.4g (RMS %.1f mm), but no "
                  "symmetric start with as many holes as the shape (%lld) was found at this size.",
                  axis.c_str(), r.mirror->along->at + 0.0, r.mirror->measured.rms / r.mirror->b0 * kMmPerB0,
                  static_cast<long long>(r.surface_genus));
    r.mirror->message = text;
}

// Z0 at the options' resolution (or the automatic one), checked, with its report in r.
ZomeMesh build_z0(PipelineResult& r, const TriangleMesh& surface, const SurfaceProjector& projector,
                  const PipelineOptions& options, AnnealOptions& anneal)
{
    const long long surface_genus = r.surface_genus;
    const InsideTest inside(projector);
    const InsidePredicate is_inside = [&](const Vec3& p) { return inside.is_inside(p); };
    InitialModelOptions z0_options = run_z0_options(projector, surface_genus, options.resolution, options.b1);
    if (options.b1 == 0.0 && options.resolution == kAutoResolution)
    {
        r.automatic = automatic_resolution(projector, surface_genus, is_inside);
        z0_options.resolution = r.automatic->resolution;
    }
    // The automatic choice's ball target, unless the user set one (or a size: then Z0's count).
    if (r.automatic && anneal.target_nodes == 0)
        anneal.target_nodes = r.automatic->target_nodes;
    if (options.mirror == MirrorMode::Auto)
        build_mirrored_z0(r, surface, projector, is_inside, z0_options, anneal);
    if (!anneal.mirror)
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

    return z0_mesh;
}

// `--from MODEL --mirror auto`: a model that maps exactly onto itself about a plane across an axis
// (model_mirror) is continued symmetric, every change with its mirror image (a spot to fix with its
// image); any other model is continued as it is, and r.mirror says which.
void continue_mirrored(PipelineResult& r, const ZomeModel& from, AnnealOptions& anneal)
{
    MirrorChoice c;
    c.mode = MirrorMode::Auto;
    c.b0 = from.transform.scale;
    const std::optional<ModelMirror> own = model_mirror(from);
    char text[200];
    if (own && own->mismatch.symmetric())
    {
        c.symmetric = true;
        c.used = own->mirror;
        c.along = mesh_plane(own->mirror, from.transform);
        anneal.mirror = own->mirror;
        if (anneal.region)
            anneal.region->mirror = own->mirror;
        std::snprintf(text, sizeof text, "Continued mirror-symmetric about %c = %.4g (the model's own plane).",
                      "xyz"[own->mirror.axis], c.along->at + 0.0); // + 0.0: "0", never "-0"
    }
    else
        std::snprintf(text, sizeof text,
                      "Continued as it is: the model is not mirror-symmetric (%zu of %zu balls have no mirror image).",
                      own ? own->mismatch.balls : size_t{0}, from.nodes.size());
    c.message = text;
    r.mirror = c;
}

// The model to continue (PipelineOptions::from), checked against the surface, as the start.
ZomeMesh continue_from(PipelineResult& r, const TriangleMesh& surface, const SurfaceProjector& projector,
                       const PipelineOptions& options, AnnealOptions& anneal)
{
    const ZomeModel& from = *options.from;
    if (const std::string problem = model_fit_problem(from, projector); !problem.empty())
        throw InvalidInputError(problem);
    ZomeMesh mesh = from_model(from);
    const ValidationReport check = validate(mesh);
    if (!check.ok())
        throw InvalidInputError("the model to continue is not a closed Zome model: " + check.message());
    r.continued = true;
    r.initial.model = from;
    r.initial.report.valid = true;
    r.initial.report.topology.genus = check.genus;
    // The model's own scale: its B1 length in mesh units, as Z0's cell would be.
    r.initial.report.grid.cell = kind_info(StrutKind::B1).length * from.transform.scale;
    const auto [lo, hi] = bounding_box(surface);
    r.resolution = static_cast<int>(std::lround((hi - lo).maxCoeff() / r.initial.report.grid.cell));
    const bool default_t0 = anneal.t0_spread_factor == AnnealOptions{}.t0_spread_factor;
    if (default_t0)
        anneal.t0_spread_factor = options.fix ? kFixT0Factor : kContinueT0Factor;
    if (options.fix)
    {
        anneal.energy.w_distance *= kFixDistanceWeightFactor;
        r.region = region_of(*options.fix, from.transform);
        r.fix_spot = options.fix;
        if (nodes_in_region(from, *r.region) == 0)
            throw InvalidInputError("no ball of the model lies within the radius of that point: choose a point on the "
                                    "model or a larger radius");
        anneal.region = r.region;
        if (anneal.target_nodes == 0)
            anneal.target_nodes = fix_target(from, *r.region);
    }
    if (options.mirror == MirrorMode::Auto)
        continue_mirrored(r, from, anneal);
    // More balls than the surface holds well at this size make the model worse (More detail, issue 40).
    r.capacity = surface_capacity(surface, from.transform);
    if (!options.fix)
    {
        const size_t target = capped_target(from.nodes.size(), anneal.target_nodes, r.capacity);
        r.capped = target != anneal.target_nodes;
        if (r.capped)
            r.asked_nodes = std::exchange(anneal.target_nodes, target);
    }
    return mesh;
}

// One annealing run from `start`: r.anneal and r.model.
void anneal_once(PipelineResult& r, ZomeMesh start, const SurfaceContext& context, const AnnealOptions& anneal,
                 const PipelineCallbacks& callbacks)
{
    Annealer annealer(std::move(start), context, anneal);
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

// The ways a fix is tried (fix_spot), each with its share of the budget: cool with the raised
// ball target, warmer with it, warmer with the model's own count. One, as given, when the user
// set T0's factor.
std::vector<AnnealOptions> fix_attempts(const PipelineOptions& options, const AnnealOptions& anneal)
{
    if (options.anneal.t0_spread_factor != AnnealOptions{}.t0_spread_factor)
        return {anneal};
    std::vector<AnnealOptions> out(kFixAttempts.size(), anneal);
    for (size_t i = 0; i < out.size(); ++i)
    {
        out[i].t0_spread_factor = kFixAttempts[i].t0_factor;
        if (!kFixAttempts[i].raise_target)
            out[i].target_nodes = options.from->nodes.size();
        if (anneal.max_proposals > 0)
            out[i].max_proposals = std::max<uint64_t>(1, anneal.max_proposals / out.size());
        else
            out[i].seconds = anneal.seconds / static_cast<double>(out.size());
    }
    return out;
}

// The largest gap within the spot (b0).
double spot_gap(const ZomeModel& model, const SurfaceProjector& projector, const FixSpot& spot)
{
    FidelityOptions o;
    o.samples_per_side = kFixGapSamples;
    o.near = spot.centre;
    o.radius = spot.radius;
    return measure_fidelity(model, projector, o).hausdorff;
}

// Fixing one spot: every attempt from the same model; the one with the smallest largest gap within
// the spot is kept, or the model as it was when none is smaller (measured from outside the
// energy: the gap is what the person asked to fix).
void fix_spot(PipelineResult& r, const ZomeMesh& start, const SurfaceContext& context,
              const PipelineCallbacks& callbacks, const std::vector<AnnealOptions>& attempts)
{
    const FixSpot spot = *r.fix_spot;
    r.spot_gap_before = r.spot_gap_after = spot_gap(r.initial.model, context.projector(), spot);
    r.model = r.initial.model;
    r.kept_start = true;
    PipelineResult trial;
    for (const AnnealOptions& a : attempts)
    {
        anneal_once(trial, ZomeMesh(start), context, a, callbacks);
        const double gap = spot_gap(trial.model, context.projector(), spot);
        if (gap < r.spot_gap_after)
        {
            r.spot_gap_after = gap;
            r.model = trial.model;
            r.kept_start = false;
            r.anneal = trial.anneal;
        }
        if (!r.anneal || r.kept_start)
            r.anneal = trial.anneal; // the figures of a run, even when none is kept
        if (trial.anneal->stats.cancelled)
            break;
    }
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
    if (options.fix && !options.from)
        throw InvalidInputError("fixing one spot needs a model to work on (--from MODEL)");

    Stopwatch clock;
    PipelineResult r;
    r.surface_genus = surface_genus;
    const SurfaceProjector projector(surface);
    AnnealOptions anneal = options.anneal;
    ZomeMesh z0_mesh = options.from ? continue_from(r, surface, projector, options, anneal)
                                    : build_z0(r, surface, projector, options, anneal);
    if (callbacks.initial)
        callbacks.initial(r.initial.model);

    if (r.capacity == 0)
        r.capacity = surface_capacity(surface, r.initial.model.transform);
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
        if (options.fix)
            fix_spot(r, z0_mesh, context, callbacks, fix_attempts(options, anneal));
        else
        {
            anneal_once(r, std::move(z0_mesh), context, anneal, callbacks);
            // Working on a model costs nothing when it finds nothing better: the model as it was.
            const double end = r.anneal->stats.cancelled ? r.anneal->best.total : r.anneal->end.total;
            if (r.continued && end > r.anneal->start.total)
            {
                r.model = r.initial.model;
                r.kept_start = true;
            }
        }
    }
    if (anneal.mirror)
        r.mirror_mismatch = mirror_mismatch(r.model, *anneal.mirror);
    r.target_nodes = anneal.target_nodes ? anneal.target_nodes : r.initial.model.nodes.size();
    check_model(r, context, anneal.energy, r.target_nodes, options.fidelity_samples);
    r.seconds = clock.seconds();
    return r;
}

} // namespace zomeify
