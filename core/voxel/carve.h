#pragma once
//! \file carve.h
//! Homotopic carving of a manifold voxel set toward S. Conservative voxelization keeps every cell S
//! touches, so Z0 stands up to a cell and a half off S. Carving removes occupied cells whose centre
//! lies outside S, outermost layer first, but only cells that are simple (topology of object and
//! background kept, so the genus is) and whose removal leaves all eight corner stars manifold. The
//! result hugs S from inside and outside like a centre-sampled voxelization, with the thin handles a
//! centre sample would lose kept.

#include <cstddef>
#include <functional>

#include "core/voxel/coverage.h"
#include "core/voxel/voxel_grid.h"
#include "core/voxel/voxelize.h"

namespace zomeify {

struct CarveReport
{
    size_t removed = 0;           //!< cells removed
    size_t restored = 0;          //!< of those, put back to undo a fold-over
    size_t kept_for_coverage = 0; //!< outside cells kept because S passes through their far side
    int passes = 0;               //!< layers peeled (the last one removed nothing)
};

//! How carving treats topology.
enum class CarveTopology
{
    //! Only simple cells go: object and background keep their topology, so the genus is kept.
    Keep,
    //! Any outside cell may go if its corners stay manifold: a block of cells bridging a hole of S
    //! (which the simple rule must keep, because it holds a tunnel on each side) opens, and a thin
    //! membrane closing a handle of S is pierced. The genus may change either way, so the caller
    //! judges the result (build_initial_model() keeps it only when it has the genus of S).
    Free,
};

//! Carves `grid` (which must be manifold: repair_manifold() first). `inside` classifies cell centres.
//! With `probe`, two guards: a cell stays when S passes through it more than half a cell from the
//! cells that would remain (the tip of a thin leg: carving it would shorten the leg), and carved
//! cells across which the result shows a face turned against S's normal (a fold-over: the model lies
//! across a thin part there) are put back where the topology allows.
CarveReport carve_outside_cells(VoxelGrid& grid, const InsidePredicate& inside, const SurfaceProbeAt& probe = nullptr,
                                CarveTopology topology = CarveTopology::Keep);

} // namespace zomeify
