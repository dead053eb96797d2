#pragma once
//! \file mirror_cells.h
//! A grid's cells made symmetric about a plane of cell boundaries (issue 41), so that the boundary
//! Z0 extracted from them is exactly mirror-symmetric in lattice coordinates.

#include <optional>

#include "core/voxel/voxel_grid.h"

namespace zomeify {

//! A mirror plane perpendicular to a grid axis, in mesh units: {x : x[axis] = at}.
struct AxisPlane
{
    int axis = 0;
    double at = 0.0;
};

//! The grid corner index on `plane`'s axis that lies on it, when a corner layer does (within 1e-6
//! of a cell); cell i then mirrors to 2·index − 1 − i.
std::optional<int> mirror_corner_index(const GridSpec& grid, const AxisPlane& plane);

//! How a cell and its mirror image become one: either occupied (the union: thin parts of either side
//! are kept), or both (the intersection: a gap or hole of either side is kept).
enum class MirrorMerge
{
    Union,
    Intersection,
};

//! Makes the cells symmetric about the plane by `merge`. Cells whose image lies outside the grid are
//! emptied. Throws InvalidInputError when no corner layer lies on the plane.
void make_mirror_symmetric(VoxelGrid& grid, const AxisPlane& plane, MirrorMerge merge = MirrorMerge::Union);

} // namespace zomeify
