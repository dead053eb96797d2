#pragma once
//! \file triangulate.h
//! Splitting one polygon into triangles with the polygon's own orientation.

#include <array>
#include <cstdint>
#include <span>
#include <vector>

#include "core/geom/triangle_mesh.h"

namespace zomeify {

//! Appends n - 2 triangles covering `polygon` (vertex indices into `positions`, n >= 3) to `out`.
//! Convex polygons get a fan; non-convex ones are ear-clipped in their best-fit (Newell) plane.
//! Self-intersecting, degenerate or very large (> 256 vertices) non-convex polygons, and ones that
//! take more than 4 n^2 steps to clip, fall back to a fan.
void triangulate_polygon(const std::vector<Vec3>& positions, std::span<const uint32_t> polygon,
                         std::vector<std::array<uint32_t, 3>>& out);

} // namespace zomeify
