#pragma once
//! \file thicken_sheet.h
//! An open sheet made solid (issue 36): a terrain patch, a mask, a leaf or a single quad has no
//! inside to fill with Zome cells, but the same sheet given a thickness does. The predictable
//! closed version: both sides offset along the vertex normals by half the thickness, joined along
//! the sheet's open edge by a wall of quads. Its genus is the sheet's (a disk gives a slab of genus 0).

#include <cstdint>
#include <vector>

#include "core/geom/triangle_mesh.h"

namespace zomeify {

//! The thickness a sheet gets, as a fraction of its bounding box's longest side: about half a cell
//! of the automatic grid (13–17 cells along the longest side), so Z0 is one cell thick.
inline constexpr double kSheetThicknessFraction = 0.03;

//! Replaces the faces of `mesh` marked in `sheet_face` by the closed slab around them (the other
//! faces stay); vertices no face uses are dropped. Faces must be oriented consistently and each
//! vertex manifold (split_non_manifold). Returns the thickness used (mesh units).
double thicken_sheets(TriangleMesh& mesh, const std::vector<uint8_t>& sheet_face);

} // namespace zomeify
