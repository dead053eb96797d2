#pragma once
//! \file energy_state.h
//! EnergyState: the global sums and counts of the energy of the current mesh, kept in sync
//! incrementally (design.md §3.3, paper §5.2). An operator
//!   1. describes its proposal as a LocalChange (removed elements, new positions and faces),
//!   2. calls simulate() → EnergyDelta: purely local, no mutation, thread-safe;
//!   3. asks delta_energy(delta) → ΔE, O(1) from the current sums (exact: E_after − E_before);
//!   4. if accepted, edits the mesh and calls commit(delta).
//! Steps 3 and 4 read and write the sums, so with several threads they belong in the commit's
//! critical section (or step 3 uses energy_change() against a snapshot of sums()).
//!
//! Sums are fixed-point integers (energy_samples.h), so after any number of commits sums() equals,
//! bit for bit, the sums of a fresh evaluate_energy() of the edited mesh.

#include "core/anneal/energy.h"
#include "core/anneal/local_energy.h"

namespace zomeify {

class EnergyState
{
public:
    //! Keeps references to the context, which must outlive the state; copies the options. Throws
    //! InvalidInputError as evaluate_energy() does.
    EnergyState(const ZomeMesh& mesh, const SurfaceContext& context, const EnergyOptions& options);

    //! Recomputes every sum from scratch (e.g. after the annealer's garbage collection, or as a check).
    void reset(const ZomeMesh& mesh);

    //! The change of every sum and count that applying `change` to `mesh` would cause.
    EnergyDelta simulate(const ZomeMesh& mesh, const LocalChange& change) const noexcept
    {
        return simulate_change(mesh, change, context_, options_);
    }
    //! ΔE of a simulated change against the current sums (0 if !delta.ok()).
    double delta_energy(const EnergyDelta& delta) const noexcept
    {
        return delta.ok() ? energy_change(sums_, delta.sums, options_) : 0.0;
    }
    //! Applies a simulated change to the sums (after the mesh edit). Returns false, changing
    //! nothing, if !delta.ok().
    bool commit(const EnergyDelta& delta) noexcept;

    const EnergySums& sums() const noexcept { return sums_; }
    EnergyTerms terms() const noexcept { return energy_terms(sums_, options_); }
    double energy() const noexcept { return terms().total; }
    const EnergyOptions& options() const noexcept { return options_; }
    const SurfaceContext& context() const noexcept { return context_; }

private:
    const SurfaceContext& context_;
    EnergyOptions options_;
    EnergySums sums_;
};

} // namespace zomeify
