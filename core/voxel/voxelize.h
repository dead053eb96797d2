#pragma once
//! \file voxelize.h
//! Conservative voxelization of a closed surface S (paper §3.1): every cell whose interior meets S
//! is tagged Surface, every other cell that lies inside S is tagged Inside. The union of the tagged
//! closed cells covers S.

#include <cstddef>
#include <functional>

#include "core/geom/triangle_mesh.h"
#include "core/voxel/voxel_grid.h"

namespace zomeify {

//! Answers "is this point strictly inside S?". It is only asked about points at a distance of
//! about half a cell or more from S, so any robust inside test (winding number, ray parity) works.
using InsidePredicate = std::function<bool(const Vec3&)>;

//! What voxelize() did, for statistics and tests.
struct VoxelizeStats
{
    size_t surface_cells = 0;  //!< cells whose interior meets S
    size_t inside_cells = 0;   //!< cells inside S that do not meet it
    size_t cavity_cells = 0;   //!< empty cells enclosed by occupied ones, filled (counted in inside_cells)
    size_t inside_queries = 0; //!< calls of the inside test
    size_t box_tests = 0;      //!< triangle / box overlap tests (hierarchy levels included)
};

//! Tags the cells of `spec` that meet S or lie inside it. Cells meeting S are found per triangle by
//! a hierarchical descent over the triangle's cell range (exact SAT triangle / box tests); all other
//! cells are classified by the inside test on one cell centre per 6-connected region of cells that
//! S does not touch, plus one per cell that S only touches on its boundary. Finally, empty pockets
//! enclosed by occupied cells (where coverage merged parts around a gap) are filled, so the
//! boundary has one component per component of S.
VoxelGrid voxelize(const TriangleMesh& surface, const GridSpec& spec, const InsidePredicate& inside,
                   VoxelizeStats* stats = nullptr);

} // namespace zomeify
