#pragma once
//! \file part_tally.h
//! The parts a model uses while the annealer changes it, against the limits a run was given
//! (AnnealOptions::part_limits: the kits named before the run, or the kits a person owns).
//! The rule is monotone: a commit may not raise a count that would then be over its limit, but
//! may lower one that is over (a starting model that needs more of one kind, such as Z0's B1
//! struts, moves towards the limit and is never pushed further from it).

#include <array>
#include <cstdint>

#include "core/anneal/energy/local_change.h"
#include "core/anneal/engine/anneal_options.h"
#include "core/mesh/zome_mesh.h"

namespace zomeify {

class PartTally
{
public:
    //! Per strut kind B0..R2, then balls.
    using Counts = std::array<int64_t, kStrutKindCount + 1>;

    //! The parts of `mesh` now.
    explicit PartTally(const ZomeMesh& mesh);

    //! How `change` moves the counts (its removed struts and nodes are live in `mesh`).
    static Counts change_of(const ZomeMesh& mesh, const LocalChange& change) noexcept;
    //! Whether a commit of `delta` keeps to the monotone rule under `limits`.
    bool allows(const Counts& delta, const PartLimits& limits) const noexcept;
    //! Records a committed change.
    void apply(const Counts& delta) noexcept;
    const Counts& counts() const noexcept { return counts_; }

private:
    Counts counts_{};
};

} // namespace zomeify
