#pragma once
//! \file centre_sampled.h
//! A second way to Z0's cells, for grids where the conservative cells have the wrong topology. The
//! conservative voxelization keeps every cell S touches, so where two parts of S pass less than about
//! two cells apart their cells merge (a knot's strands become extra handles) and a hole narrower than
//! that closes. Cells whose centre lies inside S see the gaps and holes S has wherever a cell fits
//! through them; what they miss are parts of S thinner than a cell, so the cells S would be left
//! without are grown back (coverage.h), and the set is then made manifold with topology-keeping flips.

#include <cstddef>

#include "core/voxel/coverage.h"
#include "core/voxel/voxel_grid.h"
#include "core/voxel/voxelize.h"

namespace zomeify {

//! How cells touching only along an edge or at a corner are judged when both lie outside S's thin parts.
enum class ThinParts
{
    //! Joined only where the segment between their centres stays within 0.3 cell of S's inside.
    Strict,
    //! Also where it stays within 0.15 cell of the farther centre's distance outside S: cells grown back
    //! along a part thinner than a cell stay joined (a mug's handle 1.2 cells thick at 10 cells), at the
    //! price of joining some cells across a narrow gap.
    Follow,
};

struct CentreSampleReport
{
    size_t left_out = 0; //!< occupied cells whose centre is outside S, removed
    size_t grown = 0;    //!< of those, put back because S near them had no other cell
    size_t restored = 0; //!< of those, put back because the set showed a fold-over beside them
    bool manifold = false;
};

//! Replaces the occupied cells of `grid` (the conservative cells) by those whose centre is inside S,
//! then grows back, layer by layer, removed cells that alone hold a part of S, and repairs the result
//! to a manifold boundary (repair.h). The caller judges the topology.
CentreSampleReport centre_sample(VoxelGrid& grid, const InsidePredicate& inside, const SurfaceProbeAt& probe,
                                 ThinParts thin = ThinParts::Follow);

} // namespace zomeify
