#pragma once
//! \file annealer_state.h
//! The state the annealer's threads share (internal to core/anneal/engine). What each member is
//! guarded by is noted beside it; "commit lock" is the member commit_lock.

#include <atomic>
#include <memory>
#include <mutex>
#include <optional>
#include <string>

#include "core/anneal/energy/energy_state.h"
#include "core/anneal/energy/surface_context.h"
#include "core/anneal/engine/anneal_options.h"
#include "core/anneal/engine/anneal_stats.h"
#include "core/anneal/engine/part_tally.h"
#include "core/anneal/engine/pause_barrier.h"
#include "core/anneal/engine/schedule.h"
#include "core/anneal/engine/seed_slabs.h"
#include "core/anneal/node_claims.h"
#include "core/anneal/rules/clearance_index.h"
#include "core/base/spin_lock.h"
#include "core/base/stopwatch.h"
#include "core/mesh/zome_mesh.h"
#include "core/zome/model.h"

namespace zomeify {

struct AnnealerState
{
    AnnealerState(ZomeMesh start, const SurfaceContext& ctx, const AnnealOptions& opts);

    //! Compacts the mesh and reserves room for the next stretch of commits (all workers parked,
    //! or before they start). Caller holds the commit lock or runs alone.
    void make_room();
    //! Whether the mesh can take any one more proposal (worst case of LocalChange's capacity).
    bool has_room_for_any() const;
    //! Applies a proposal the caller has accepted, with `delta` (its E_surface change simulated
    //! in `surface` against the current state), unless the mesh has no room for it or a new
    //! position was taken meanwhile (Busy; with no room, a pause is requested), it would create
    //! a clash (the clash's rejection) or uncover a part of S (Uncovered). None when applied.
    //! Caller holds the commit lock exclusively (or runs alone).
    //! `check_clearance` false: the caller checked the clearance rule against this very state.
    Rejection apply_accepted(const Proposal& proposal, const EnergyDelta& delta, SurfaceChange& surface,
                             bool check_clearance = true);
    //! Stops every worker soon.
    void request_stop() noexcept
    {
        stop.store(true, std::memory_order_release);
        barrier.wake_all();
    }
    //! Progress under the commit lock.
    AnnealProgress progress_locked() const;
    double fraction_now(uint64_t proposals_done) const noexcept;

    const SurfaceContext& context;
    AnnealOptions options; // resolved: threads ≥ 1, energy.target_nodes set

    ZomeMesh mesh;                  // written under the commit lock (or with all workers parked)
    EnergyState energy;             // sums and E_surface's state: commit lock
    CoverageGuard coverage;         // commit lock
    ClearanceIndex clearance;       // commit lock
    std::optional<PartTally> parts; // with options.part_limits: commit lock
    size_t uncovered_at_start = 0;
    EnergyTerms start_terms;
    CoolingSchedule schedule{0.0, 0.0};
    SlabPlan slabs; // set before the workers start
    int t0_samples = 0;

    mutable CommitLock commit_lock; // core/base/spin_lock.h
    std::unique_ptr<NodeTags> tags; // replaced only while every worker is parked
    uint64_t tags_generation = 0;   // bumped when tags is replaced
    //! vertices_size() of the mesh as last published: seeds are drawn below it, so a worker
    //! never reads the mesh's array sizes while another thread appends.
    std::atomic<uint32_t> published_vertices{0};

    FixedList<Face, LocalChange::kMaxFaces> added_faces; // apply_accepted's scratch (commit lock)
    //! Commits applied so far (written under the commit lock held exclusively, read under it held
    //! shared): a decision taken at one count is stale at another.
    uint64_t commits_applied = 0;
    PauseBarrier barrier;
    std::atomic<bool> stop{false};
    std::atomic<bool> cancelled{false};
    std::atomic<bool> started{false};
    std::atomic<bool> finished{false};

    // Progress counters (flushed by the workers in batches; exact after they end).
    std::atomic<uint64_t> proposals{0}, valid_proposals{0}, commits{0};
    std::atomic<double> temperature{0.0};
    Stopwatch clock;          // restarted when the workers start
    double best_energy = 0.0; // commit lock

    // Set once by the first worker that fails (commit lock).
    std::string error;
};

//! One worker's loop (worker 0 runs on run()'s thread and also reports progress).
struct WorkerTotals
{
    AnnealStats stats; // only the counters are used
};
void run_worker(AnnealerState& state, int index, WorkerTotals& totals, const std::function<void()>& report_progress);

//! The rejection reason of a clash.
Rejection clash_rejection(ClashKind clash) noexcept;

} // namespace zomeify
