#pragma once
//! \file local_energy.h
//! The energy of a local change, from the change alone (design.md §3.3, paper §5.2 "simulate"):
//! the differences of every sum and count that applying the change would cause. It reads only the
//! removed elements, the corners of removed faces, the endpoints of removed and added struts and
//! those endpoints' 1-rings, never the global state, so any number of threads may run it at once
//! on disjoint tagged regions. Turning it into ΔE is O(1) (EnergyState::delta_energy).
//!
//! For the reads to be stable, the caller's tag region must keep the 1-rings of the changed
//! struts' endpoints from moving while it runs (their positions enter E_fair).

#include <cstdint>

#include "core/anneal/energy/energy_options.h"
#include "core/anneal/energy/energy_sums.h"
#include "core/anneal/energy/local_change.h"
#include "core/anneal/energy/surface_context.h"
#include "core/mesh/zome_mesh.h"

namespace zomeify {

//! Whether simulate_change could evaluate a change.
enum class ChangeStatus : uint8_t
{
    Ok,
    Overflow,               //!< a list of the change (or the internal scratch) is full
    UnknownNode,            //!< an added strut ends at a position that is neither an added node nor a
                            //!< surviving node of the removed region
    KeptStrutToRemovedNode, //!< a surviving node keeps a strut to a removed node
    FoldOver                //!< an added face is a fold-over and the caller refuses them (FoldOvers::Refuse):
                            //!< the sums were not computed
};

//! What simulate_change does with a change that adds a fold-over face.
enum class FoldOvers : uint8_t
{
    Count, //!< computes every sum and sets adds_fold_over (the sums count it)
    Refuse //!< stops at the first one (status FoldOver): the annealer refuses such changes, and
           //!< checking the added faces first spares the rest for the many proposals it refuses
};

//! The differences of the sums and counts (meaningful only when status is Ok).
struct EnergyDelta
{
    EnergySums sums;
    ChangeStatus status = ChangeStatus::Ok;
    //! An added face would face against the surface at its barycentre (is_fold_over). With
    //! FoldOvers::Count the sums are still exact; with Refuse the status is FoldOver.
    bool adds_fold_over = false;
    bool ok() const noexcept { return status == ChangeStatus::Ok; }
};

//! What applying `change` to `mesh` would do to the energy's sums. Does not modify anything.
EnergyDelta simulate_change(const ZomeMesh& mesh, const LocalChange& change, const SurfaceContext& context,
                            const EnergyOptions& options, FoldOvers fold_overs = FoldOvers::Count) noexcept;

} // namespace zomeify
