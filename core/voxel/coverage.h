#pragma once
//! \file coverage.h
//! What the voxel constructions ask of S about one cell: is it the only cell near a piece of S (carving
//! keeps the tip of a thin leg, centre sampling grows a thin part back), and does the cell set show a
//! face turned against S beside it (a fold-over, which both put right by adding the cell back).

#include <cstddef>
#include <functional>
#include <vector>

#include "core/geom/closest_point.h"
#include "core/voxel/voxel_grid.h"

namespace zomeify {

struct CellIndex
{
    int i, j, k;
};

//! What the voxel guards need to know of S at a point: the distance to S and S's unit outward normal at
//! the closest point.
struct SurfaceProbe
{
    double distance = 0.0;
    Vec3 normal = Vec3::UnitZ();
};
using SurfaceProbeAt = std::function<SurfaceProbe(const Vec3&)>;

//! The probe of S through its projector (which must outlive the probe).
SurfaceProbeAt probe_of(const SurfaceProjector& projector);

//! True if S comes within 0.3 cell of a point of cell (i, j, k) (a 3×3×3 lattice over it) that lies more
//! than half a cell from every other occupied cell of its 3×3×3 neighbourhood: without the cell, that
//! part of S would have no model near it. The cell's own state is not looked at.
bool holds_surface_alone(const VoxelGrid& grid, int i, int j, int k, const SurfaceProbeAt& probe);

//! True if an occupied face neighbour of the empty cell (i, j, k) shows a face toward it (its outward
//! normal points into the cell) that points against S's normal at the face's centre: a fold-over.
bool borders_fold_over(const VoxelGrid& grid, int i, int j, int k, const SurfaceProbeAt& probe);

//! Adds back cells of `candidates` (empty cells the construction took away) across which the set shows
//! a fold-over, where that is simple (topology kept) and keeps the corners manifold; repeated until none
//! is added, since a cell put back shows faces of its own. Returns the number added (tagged Added).
size_t restore_against_fold_overs(VoxelGrid& grid, const std::vector<CellIndex>& candidates,
                                  const SurfaceProbeAt& probe);

} // namespace zomeify
