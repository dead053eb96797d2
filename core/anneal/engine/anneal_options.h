#pragma once
//! \file anneal_options.h
//! What one annealing run is asked to do (design.md §3.5–§3.6, paper §5.2).

#include <array>
#include <cstddef>
#include <cstdint>
#include <optional>

#include "core/anneal/energy/energy_options.h"
#include "core/anneal/rules/coverage_guard.h"
#include "core/zome/lattice_mirror.h"
#include "core/zome/slots.h"

namespace zomeify {

//! The most parts of each kind a run may use (the kits named before it, or a person's own kits).
struct PartLimits
{
    std::array<uint32_t, kStrutKindCount> struts{}; //!< B0..R2
    uint32_t balls = 0;
};

//! The part of a model a run may change (`run --from MODEL --near X,Y,Z --radius R`), in model
//! units (b0): a ball around `centre`.
struct ChangeRegion
{
    std::array<double, 3> centre{};
    double radius = 0.0;
    //! Set for a mirror-symmetric run: the region's mirror image belongs to it too, so the image of a
    //! change in the region is allowed where it lands.
    std::optional<LatticeMirror> mirror;
};

struct AnnealOptions
{
    //! Time budget in seconds, used when max_proposals is 0. The temperature reaches
    //! min_temperature when the budget ends.
    double seconds = 60.0;
    //! > 0: a proposal budget instead of a time budget. With threads = 1 the run is then
    //! deterministic: the same seed gives a bit-identical model natively and in wasm (no decision
    //! depends on the clock).
    uint64_t max_proposals = 0;
    //! Annealing threads; 0 = the hardware's concurrency. The calling thread is one of them.
    int threads = 0;
    uint64_t seed = 1;
    //! N_target of E_complex; 0 = N0, the node count of the starting model.
    size_t target_nodes = 0;
    //! Weights and forbidden zones (energy.target_nodes is overwritten by target_nodes / N0).
    EnergyOptions energy;

    //! T0; 0 = t0_spread_factor · stdev of ΔE over random valid proposals on the starting model.
    double initial_temperature = 0.0;
    //! The factor of the automatic T0 (the paper, §5.3: 0.1). With E_surface, 0.05 gave the
    //! bunny's best fits; 0.03 left a web of faces between its ears in one run of five, and so did
    //! a weaker E_surface with a longer reach at 0.03 in most runs (engine README, "Cooling").
    double t0_spread_factor = 0.05;
    //! T_min (absolute; the paper: 1e-5), used when min_temperature_ratio is 0.
    double min_temperature = 1e-5;
    //! > 0: T_min = min_temperature_ratio · T0 (the default, ≈ T0/120); 0: min_temperature.
    double min_temperature_ratio = 0.0083;
    //! Valid proposals sampled for T0.
    int t0_samples = 2000;
    //! Seeds from sweeping slabs (seed_slabs.h); false: uniformly over all nodes, as the paper
    //! (kept for comparison: bench_anneal seeding).
    bool sweep_slabs = true;
    //! Relative frequency of each operator kind, in OperatorKind order (INSNODE, ADDDIAG,
    //! SPLITSTRUT, REMDIAG, FLIPDIAG, MOVNODE, REMNODE). All equal (the default): drawn uniformly,
    //! as the paper. Weights 2,1,2,1,1,4,2 gave lower energies for the same proposal budget on one
    //! thread but no clear gain in 2-thread timed runs (engine README, "Operator weights").
    std::array<uint32_t, 7> operator_weights{1, 1, 1, 1, 1, 1, 1};
    //! No commit may leave a part of S uncovered (coverage_guard.h); radius 0 turns it off.
    CoverageOptions coverage;
    //! No commit may create parts that could not be built side by side (clearance_index.h).
    bool clearance = true;
    //! No commit may add a face turned against the surface (a fold-over); false leaves them to the
    //! energy's fold-over term.
    bool refuse_new_fold_overs = true;
    //! After the schedule, remove the fold-overs left (fold_repair.h); not after a cancel.
    bool repair_fold_overs = true;
    //! Set: no commit raises a part count over its limit (part_tally.h: a starting model over a
    //! limit may only come down to it). Unset: any mix.
    std::optional<PartLimits> part_limits;
    //! Set: only nodes inside the region move, appear or go, and only struts and faces with a node
    //! inside it change (change_region.h); seeds are drawn inside it. Unset: the whole model.
    std::optional<ChangeRegion> region;
    //! Set: every change is made together with its mirror image (mirrored.h), so a starting model
    //! symmetric under it stays exactly symmetric. The fold-over repair (which changes one face at
    //! a time) is then skipped. Unset: the two halves are free.
    std::optional<LatticeMirror> mirror;
    //! Seconds between calls of the progress callback (and best-model snapshots).
    double progress_interval = 0.25;
};

} // namespace zomeify
