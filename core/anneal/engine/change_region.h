#pragma once
//! \file change_region.h
//! Fixing one spot of a model (paper §6, the rockerarm's knob): a run given a region changes
//! nothing outside it. A commit may remove, move or add only nodes inside the region, and remove or
//! add only struts and faces with at least one node inside it, so every node outside keeps its
//! exact position and the struts and faces among such nodes stay as they were.

#include "core/anneal/energy/local_change.h"
#include "core/anneal/engine/anneal_options.h"
#include "core/mesh/zome_mesh.h"

namespace zomeify {

//! Whether the exact position p lies inside the region (model units), or inside its mirror image
//! when the region has a mirror.
bool in_region(const ChangeRegion& region, const ZVec& p) noexcept;
//! Whether `change` keeps to the region (its removed elements are live in `mesh`).
bool region_allows(const ZomeMesh& mesh, const LocalChange& change, const ChangeRegion& region) noexcept;

} // namespace zomeify
