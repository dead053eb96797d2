#pragma once
//! \file annealer.h
//! Annealer: parallel simulated annealing of a Zome mesh against a surface (paper §5.2–§5.3,
//! design.md §3.5–§3.6).
//!
//! Every thread repeats: draw a random live node, claim it (NodeTags), draw an operator kind,
//! propose() (which claims the region it reads), EnergyState::simulate outside any lock; then,
//! in one short critical section, ΔE against the current sums, the Metropolis test
//! (accept if ΔE ≤ 0 or u < exp(−ΔE/T)) and on acceptance apply_proposal + EnergyState::commit;
//! finally it releases its claims. Mesh capacity is reserved up front; when it runs low every
//! thread stops at a barrier, one compacts and grows the mesh, and all resume.
//!
//! Cooling: T(x) = T0 · (T_min/T0)^x with x ∈ [0, 1] the used fraction of the budget (seconds,
//! or proposals when max_proposals > 0), so T reaches T_min exactly when the budget ends. T0 =
//! t0_spread_factor (0.03; the paper's 0.1) · stdev(ΔE) over random valid proposals on the
//! starting model, T_min = T0/120 by default (anneal_options.h).
//!
//! Thread safety: run() on one thread; cancel(), progress() and snapshot() from any thread at
//! any time (they take the commit lock for a few microseconds; the workers keep going).

#include <atomic>
#include <functional>
#include <memory>

#include "core/anneal/energy/energy.h"
#include "core/anneal/energy/surface_context.h"
#include "core/anneal/engine/anneal_options.h"
#include "core/anneal/engine/anneal_stats.h"
#include "core/mesh/zome_mesh.h"
#include "core/zome/model.h"

namespace zomeify {

struct AnnealResult
{
    ZomeModel model;      //!< the final model
    ZomeModel best_model; //!< the lowest-energy model among the progress samples and the final one
    EnergyTerms start;    //!< energy of the starting model
    EnergyTerms end;      //!< energy of the final model
    EnergyTerms best;     //!< energy of best_model
    AnnealStats stats;
};

class Annealer
{
public:
    using ProgressCallback = std::function<void(const AnnealProgress&)>;

    //! Takes the starting mesh (a closed Zome mesh, e.g. from_model(Z0)). The context (surface
    //! and model transform) must outlive the annealer. Throws InvalidInputError if the mesh is
    //! empty or the options are out of range.
    Annealer(ZomeMesh mesh, const SurfaceContext& context, const AnnealOptions& options);
    //! The same from a model (validated by from_model()).
    Annealer(const ZomeModel& model, const SurfaceContext& context, const AnnealOptions& options);
    ~Annealer();
    Annealer(const Annealer&) = delete;
    Annealer& operator=(const Annealer&) = delete;

    //! Anneals until the budget is used or cancel() is called; blocks. `progress` is called on
    //! the calling thread about every options.progress_interval seconds (and once at the end);
    //! it may call cancel(). Callable once.
    AnnealResult run(const ProgressCallback& progress = {});
    //! Asks run() to stop soon (within one proposal per thread). Thread-safe, idempotent.
    void cancel() noexcept;
    //! The current state (zeros before run() starts).
    AnnealProgress progress() const;
    //! The current model, consistent (taken between two commits), without stopping the threads.
    ZomeModel snapshot() const;
    //! Energy of the starting model.
    const EnergyTerms& start_energy() const noexcept;
    //! The options with the defaults resolved (threads, target_nodes).
    const AnnealOptions& options() const noexcept;

private:
    struct Impl;
    std::unique_ptr<Impl> impl_;
};

//! The energy of any closed Zome model against a surface, with N_target = target_nodes (0 = the
//! model's own node count). For comparing models (e.g. the paper's bunny) by the same code.
EnergyTerms model_energy(const ZomeModel& model, const SurfaceContext& context, const EnergyOptions& options,
                         size_t target_nodes = 0);

} // namespace zomeify
