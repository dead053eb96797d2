#pragma once
//! \file simple_voxel.h
//! Simple voxels (paper §3.1, Bischoff et al.): a voxel whose removal from, or addition to, the
//! object changes neither the object's topology (26-connectivity, closed cubes touching at a corner
//! are connected) nor the background's (6-connectivity). The test is local: it only looks at the
//! 3×3×3 neighbourhood (Bertrand and Malandain's topological numbers T26 = T6 = 1).

#include <cstdint>

#include "core/voxel/voxel_grid.h"

namespace zomeify {

//! Occupancy of a 3×3×3 neighbourhood: bit (dx+1) + 3·(dy+1) + 9·(dz+1) for the cell at offset
//! (dx, dy, dz), each offset in {-1, 0, 1}. Bit 13 (the centre) is ignored by the tests below.
using Neighbourhood = uint32_t;

//! The neighbourhood of cell (i, j, k) in the grid (cells outside the grid are empty).
Neighbourhood neighbourhood(const VoxelGrid& grid, int i, int j, int k);

//! T26: the number of 26-connected components of the object in the 26 neighbours.
int object_components(Neighbourhood n);
//! T6: the number of 6-connected components of the background in the 18 face and edge neighbours
//! that contain a face neighbour.
int background_components(Neighbourhood n);

//! True if the centre voxel is simple: it can be removed (if set) or added (if not set) without
//! changing the topology of the object or of the background.
bool is_simple(Neighbourhood n);

} // namespace zomeify
