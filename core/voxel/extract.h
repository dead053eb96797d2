#pragma once
//! \file extract.h
//! The boundary of a voxel set as a Zome model (paper §3.1): one quad per face between an occupied
//! and an empty cell, counter-clockwise seen from outside, with B1 blue struts along the grid axes
//! and one node per grid corner used (so no two nodes share a position).

#include "core/voxel/voxel_grid.h"
#include "core/zome/model.h"

namespace zomeify {

//! The Zome node of grid corner (i, j, k): b1 = φ per cell along each axis.
ZVec grid_corner_node(int i, int j, int k);

//! Euler characteristic, connected components and genus of a boundary.
struct BoundaryTopology
{
    long long euler = 0; //!< nodes − struts + faces
    int components = 0;  //!< connected components of the strut graph
    long long genus = 0; //!< components − euler / 2 (the sum of the components' genera)
};

struct Extraction
{
    ZomeModel model;
    BoundaryTopology topology;
};

//! Extracts the boundary quads of the occupied cells. The transform maps Zome units to mesh units:
//! scale = cell / φ, translation = the grid's origin. The result is a closed 2-manifold when
//! count_nonmanifold_vertices(grid) == 0 (see repair.h).
Extraction extract_boundary(const VoxelGrid& grid);

} // namespace zomeify
