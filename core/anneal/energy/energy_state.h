#pragma once
//! \file energy_state.h
//! EnergyState: the global sums and counts of the energy of the current mesh, kept in sync
//! incrementally (design.md §3.3, paper §5.2). An operator
//!   1. describes its proposal as a LocalChange (removed elements, new positions and faces),
//!   2. calls simulate() → EnergyDelta: purely local, no mutation, thread-safe;
//!   3. when E_surface is on, add_surface_change(delta): reads the whole model near the change;
//!   4. asks delta_energy(delta) → ΔE, O(1) from the current sums (exact: E_after − E_before);
//!   5. if accepted, edits the mesh and calls commit(delta, new faces).
//! Steps 3 to 5 read and write shared state, so with several threads they belong in the commit's
//! critical section.
//!
//! Sums are fixed-point integers (energy_samples.h), so after any number of commits sums() equals,
//! bit for bit, the sums of a fresh evaluate_energy() of the edited mesh.

#include <span>

#include "core/anneal/energy/energy.h"
#include "core/anneal/energy/local_energy.h"
#include "core/anneal/energy/surface_distance.h"

namespace zomeify {

class EnergyState
{
public:
    //! Keeps references to the context, which must outlive the state; copies the options. Throws
    //! InvalidInputError as evaluate_energy() does.
    EnergyState(const ZomeMesh& mesh, const SurfaceContext& context, const EnergyOptions& options);

    //! Recomputes every sum from scratch.
    void reset(const ZomeMesh& mesh);
    //! After the mesh was compacted (same geometry, new element numbers): rebuilds E_surface's
    //! per-point state, which names faces by index. The sums are kept as they are, so a later
    //! comparison with a fresh evaluation still checks every incremental step.
    void renumbered(const ZomeMesh& mesh) { surface_.reset(mesh); }

    //! The change of every sum and count that applying `change` to `mesh` would cause.
    EnergyDelta simulate(const ZomeMesh& mesh, const LocalChange& change,
                         FoldOvers fold_overs = FoldOvers::Count) const noexcept
    {
        return simulate_change(mesh, change, context_, options_, fold_overs);
    }
    //! Adds E_surface's change to a simulated delta (no-op when w_surface is 0); `scratch` keeps
    //! what commit() needs. Reads shared state: no commit may run at the same time (the annealer
    //! holds its commit lock shared), and if one came in between, call it again (surface_current).
    void add_surface_change(const ZomeMesh& mesh, const LocalChange& change, EnergyDelta& delta,
                            SurfaceChange& scratch) const
    {
        if (delta.ok())
            delta.sums.surface = surface_.simulate(mesh, change, scratch);
    }
    //! Single-threaded form with the state's own scratch.
    void add_surface_change(const ZomeMesh& mesh, const LocalChange& change, EnergyDelta& delta)
    {
        add_surface_change(mesh, change, delta, scratch_);
    }
    //! Whether `scratch` was simulated against the current E_surface state.
    bool surface_current(const SurfaceChange& scratch) const noexcept
    {
        return !surface_.enabled() || scratch.version() == surface_.version();
    }
    bool surface_enabled() const noexcept { return surface_.enabled(); }
    //! ΔE of a simulated change against the current sums (0 if !delta.ok()).
    double delta_energy(const EnergyDelta& delta) const noexcept
    {
        return delta.ok() ? energy_change(sums_, delta.sums, options_) : 0.0;
    }
    //! Applies a simulated change to the sums (after the mesh edit); `added_faces` are the new
    //! faces' handles in the order of the change's added_faces() (apply_proposal gives them), for
    //! E_surface, whose delta must come from add_surface_change() of that same change. Returns
    //! false, changing nothing, if !delta.ok().
    bool commit(const EnergyDelta& delta, std::span<const Face> added_faces, SurfaceChange& scratch);
    bool commit(const EnergyDelta& delta, std::span<const Face> added_faces = {})
    {
        return commit(delta, added_faces, scratch_);
    }

    const EnergySums& sums() const noexcept { return sums_; }
    EnergyTerms terms() const noexcept { return energy_terms(sums_, options_); }
    double energy() const noexcept { return terms().total; }
    const EnergyOptions& options() const noexcept { return options_; }
    const SurfaceContext& context() const noexcept { return context_; }

private:
    const SurfaceContext& context_;
    EnergyOptions options_;
    SurfaceDistance surface_;
    SurfaceChange scratch_;
    EnergySums sums_;
};

} // namespace zomeify
