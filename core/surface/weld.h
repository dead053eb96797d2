#pragma once
//! \file weld.h
//! Merging vertices that sit at (almost) the same place, in O(n) expected time with a spatial hash.

#include <cstdint>
#include <vector>

#include "core/geom/triangle_mesh.h"

namespace zomeify {

//! For each vertex, the index of the vertex it is merged into: itself if it is the first at its
//! place, else an earlier vertex at distance <= `tolerance` (absolute). Vertices with `skip[i]` set
//! map to themselves and are never merge targets. `tolerance` 0 merges exact duplicates only.
std::vector<uint32_t> weld_vertices(const std::vector<Vec3>& positions, double tolerance,
                                    const std::vector<bool>& skip);

} // namespace zomeify
