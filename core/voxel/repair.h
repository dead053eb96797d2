#pragma once
//! \file repair.h
//! Topology-safe cleanup of a voxel set (paper §3.1, Figure 3): until the boundary of the union of
//! the occupied closed cells is a 2-manifold, flip *simple* cells at the offending grid vertices.
//! Every flip keeps the topology of the object and of the background, so the genus is kept.

#include <cstddef>
#include <cstdint>

#include "core/voxel/voxel_grid.h"

namespace zomeify {

//! Occupancy of the 8 cells around a grid vertex: bit dx + 2·dy + 4·dz for the cell whose corner
//! at offset (1-dx, 1-dy, 1-dz) is the vertex, i.e. cell (vx-1+dx, vy-1+dy, vz-1+dz).
using VertexStar = uint8_t;

//! The star of grid vertex (vx, vy, vz); vertices range over 0..dims inclusive.
VertexStar vertex_star(const VoxelGrid& grid, int vx, int vy, int vz);

//! True if the boundary of the occupied cells is a disk (or empty) near the vertex: no two
//! occupied cells meet only along an edge there (non-manifold edge) and the occupied and the empty
//! cells each form one face-connected group (else a non-manifold vertex).
bool is_manifold_star(VertexStar star);

//! True if the stars of the 8 corners of cell (i, j, k) are manifold (after a flip of that cell only
//! they change).
bool corners_manifold(const VoxelGrid& grid, int i, int j, int k);

//! Number of grid vertices whose star is not manifold.
size_t count_nonmanifold_vertices(const VoxelGrid& grid);

struct RepairOptions
{
    //! Also allow adding simple empty cells. Adding is as topology-safe as removing; it resolves
    //! configurations that removal cannot, such as a thin ring closed through a single edge, whose
    //! cells are all non-simple (paper Figure 3c).
    bool allow_additions = true;
};

struct RepairReport
{
    bool manifold = false;           //!< true if no non-manifold vertex is left
    size_t initial_bad_vertices = 0; //!< non-manifold vertices before the cleanup
    size_t remaining_bad_vertices = 0;
    size_t removed = 0; //!< simple cells removed
    size_t added = 0;   //!< simple cells added (tagged Cell::Added)
};

//! Removes (and, if allowed, adds) simple cells incident to non-manifold vertices until none is
//! left or no simple flip is possible there. Each cell is flipped at most once, so this ends.
//! Cells of the grid's outer layer are never added (it stays empty).
RepairReport repair_manifold(VoxelGrid& grid, const RepairOptions& options = {});

} // namespace zomeify
