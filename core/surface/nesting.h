#pragma once
//! \file nesting.h
//! Which closed components lie inside others: a shell inside an odd number of shells bounds a
//! cavity and must face inward (the even-odd rule that slicers and inside tests use).

#include <array>
#include <cstdint>
#include <vector>

#include "core/geom/triangle_mesh.h"

namespace zomeify {

//! For each component (numbered by `component`, one entry per triangle), the number of other
//! closed components that enclose it, by the generalized winding number of those components at
//! three of its vertices (all three inside: enclosed; a part that only overlaps another is not). Components with
//! `closed[c] == 0` neither count nor are counted (depth 0). Only bounding boxes that contain the point are tested, so
//! separate parts cost little. With more than 1000 closed components or 5e7 triangle evaluations every depth is 0 (no
//! cavities found).
std::vector<uint32_t> nesting_depths(const std::vector<Vec3>& positions,
                                     const std::vector<std::array<uint32_t, 3>>& triangles,
                                     const std::vector<uint32_t>& component, const std::vector<uint8_t>& closed);

} // namespace zomeify
