#pragma once
//! \file pipeline.h
//! The whole run (design.md §5, `zomeify run`): surface → Z0 (core/voxel) → annealed model
//! (core/anneal/engine), with the reports both stages produce. The CLI and the web page's worker
//! both call run_pipeline(), so the two cannot drift apart.

#include <atomic>
#include <functional>
#include <optional>
#include <string>

#include "core/anneal/engine/annealer.h"
#include "core/anneal/rules/clearance_index.h"
#include "core/geom/triangle_mesh.h"
#include "core/pipeline/continue_from.h"
#include "core/pipeline/kit_estimate.h"
#include "core/pipeline/mirror_choice.h"
#include "core/score/fidelity.h"
#include "core/score/fold_over_report.h"
#include "core/voxel/auto_resolution.h"
#include "core/voxel/initial_model.h"
#include "core/zome/model.h"

namespace zomeify {

//! Resolutions a user may ask for (cells along the longest side); 0 = automatic.
inline constexpr int kAutoResolution = 0;
inline constexpr int kMinResolution = 2;
inline constexpr int kMaxResolution = 256;

struct PipelineOptions
{
    //! Cells along the longest side of the bounding box (used when b1 is 0); kAutoResolution:
    //! automatic_resolution() picks it (z0_choice.h), and the ball target too when anneal.target_nodes is 0.
    int resolution = kAutoResolution;
    //! Voxel edge b1 in mesh units; overrides resolution when > 0.
    double b1 = 0.0;
    //! Stop after Z0 (no annealing).
    bool initial_only = false;
    //! When Z0 misses the genus of the surface, look for a resolution that keeps it (genus_advice,
    //! advisor.h) and put the hint in PipelineResult::advice.
    bool advise = true;
    //! Points per side for the fidelity figures of the result (fidelity.h).
    int fidelity_samples = 50000;
    //! Name the kits before annealing (kit_estimate.h: a quick pass from Z0) and keep the run
    //! within them, as the page does. Not when anneal.part_limits is set (the kits a person owns).
    bool keep_to_kit_estimate = false;
    //! Continue from this model instead of Z0 (`run --from`; continue_from.h): it must have been
    //! made for this surface. resolution, b1 and the Z0 options are then unused; the ball target
    //! defaults to the model's count, T0's factor to kContinueT0Factor, and a result with a higher
    //! energy than the model gives the model back.
    std::optional<ZomeModel> from;
    //! With `from`: change only the model near this spot (`--near X,Y,Z --radius R`); the ball
    //! target defaults to fix_target(). Without it, a target above the surface's capacity
    //! (surface_capacity) is lowered to it, and one above the model's count is refused when the
    //! model already has about the capacity (at_capacity, capacity_full_text).
    std::optional<FixSpot> fix;
    //! Auto: a mirror-symmetric model when the shape is symmetric about a plane along a mesh axis
    //! (mirror_choice.h). With `from`: a model that maps onto itself stays symmetric (every change with
    //! its image, a spot to fix with its image); any other is continued as it is.
    MirrorMode mirror = MirrorMode::Off;
    AnnealOptions anneal;
};

struct PipelineCallbacks
{
    //! Z0 is ready (before annealing starts).
    std::function<void(const ZomeModel& z0)> initial;
    //! About every anneal.progress_interval seconds during annealing, on the calling thread;
    //! annealer.snapshot() gives the current model, annealer.cancel() stops the run.
    std::function<void(const AnnealProgress&, Annealer& annealer)> progress;
    //! Polled with the progress; when it becomes true the run stops and keeps its best model.
    const std::atomic<bool>* cancel = nullptr;
};

struct PipelineResult
{
    long long surface_genus = 0;
    int resolution = 0;                      //!< cells along the longest side actually used
    InitialModel initial;                    //!< Z0 and its report
    std::string advice;                      //!< the resolution hint when Z0 missed the surface's genus
    std::optional<AutoResolution> automatic; //!< how the resolution was chosen, when automatic
    std::optional<AnnealResult> anneal;      //!< absent with initial_only
    std::optional<KitEstimate> kit_estimate; //!< the kits named before annealing (keep_to_kit_estimate)
    bool continued = false;                  //!< annealed from PipelineOptions::from, not Z0
    size_t target_nodes = 0;                 //!< the ball target the annealer had
    bool kept_start = false;                 //!< continued, and no result had a lower energy: the model as it was
    std::optional<ChangeRegion> region;      //!< the spot a fix changed (model units)
    std::optional<FixSpot> fix_spot;         //!< the same in mesh units
    std::optional<MirrorChoice> mirror;      //!< with MirrorMode::Auto: the plane, and whether it was used
    //! With a mirror used: the model's balls and struts whose mirror image is not in it (0, 0).
    MirrorMismatch mirror_mismatch;
    double spot_gap_before = 0.0; //!< a fix: the largest gap within the spot before (b0)
    double spot_gap_after = 0.0;  //!< and after
    //! About how many balls the surface holds well at the model's size (surface_capacity); 0 unknown.
    size_t capacity = 0;
    //! A continued run (not a fix) asked for more balls than `capacity`: its target was lowered to
    //! it from `asked_nodes` (capacity_capped_text says so).
    bool capped = false;
    size_t asked_nodes = 0;
    //! The model to write: the best annealed model when the run was cancelled, the final one
    //! otherwise (Z0 with initial_only). Carries the transform and stats_json.
    ZomeModel model;
    EnergyTerms model_energy;     //!< of `model` (after annealing)
    int model_genus = 0;          //!< of `model`, from validate()
    bool model_valid = false;     //!< `model` passed validate() (closed, Zome rules)
    std::string validation;       //!< validate()'s one-line message
    FoldOverReport fold_overs;    //!< faces of `model` facing against S's normal at π(barycentre), and where
    ClearanceReport clearance;    //!< clashes between the parts of `model` and the smallest clearances
    Fidelity fidelity;            //!< distances between `model` and the surface, both ways (core/score)
    double initial_seconds = 0.0; //!< Z0 build time
    double seconds = 0.0;         //!< whole pipeline wall time
};

//! Runs the pipeline on a prepared (closed, outward-oriented) surface of genus surface_genus.
//! Throws InvalidInputError with a one-line message when Z0 cannot be built or options are bad.
PipelineResult run_pipeline(const TriangleMesh& surface, long long surface_genus, const PipelineOptions& options,
                            const PipelineCallbacks& callbacks = {});

//! The --stats object (design.md §5): wall seconds, threads, proposals and commits (total, per
//! second), N, struts by kind, genus of S and Z, every energy term at start and end, Z0 details.
std::string pipeline_stats_json(const PipelineResult& result, int indent = 2);

} // namespace zomeify
