#pragma once
//! \file triangle_block.h
//! Four triangles in structure-of-arrays float form: the leaves of the closest-point search. A
//! block gives a cheap estimate of the four point–triangle distances at once (triangle_estimate.h),
//! accurate to a known slack, so that only the few triangles that can still be the closest are
//! measured exactly (in double, by point_triangle.h).

#include <array>
#include <cstdint>

#include "core/geom/simd4.h"
#include "core/geom/triangle_mesh.h"

namespace zomeify {

//! Corner a, edge vectors ab and ac (rounded from double, so short edges keep their direction)
//! and the unit normal (rounded from double; zero for a sliver, see make_triangle_block), all
//! relative to an origin. Lanes past a leaf's count repeat lane 0. 192 bytes: three cache lines.
struct alignas(64) TriangleBlock
{
    simd::F4 ax, ay, az;
    simd::F4 abx, aby, abz;
    simd::F4 acx, acy, acz;
    simd::F4 nx, ny, nz;
};

//! Error bounds of the estimate (triangle_estimate.h), relative to the magnitude M of the query:
//! the largest coordinate of p − origin plus the largest coordinate of any corner − origin (for a
//! mesh: its half extent, with the origin at the centre of its box).
struct TriangleBlockTolerance
{
    //! `inside_margin` to pass, times M: a point counts as over the face only if it is this far
    //! inside every edge, several times the float error of those tests.
    static constexpr double kInsideMargin = 4e-6;
    //! |estimate − distance| ≤ kSlack · M for every triangle: twice the inside margin (a point near
    //! an edge but inside is measured to the edge), the float rounding of coordinates and
    //! arithmetic (under 2e-6 · M), and the width of triangles treated as slivers (under 1e-6 · M).
    static constexpr double kSlack = 1.6e-5;
    //! A triangle narrower than this times the mesh's half extent is measured by its edges only:
    //! its normal would be unreliable, and its edges are within that width of all its points.
    static constexpr double kSliverWidth = 1e-6;
};

//! Block of triangles ids[0 .. count) of `mesh` (count 1..4), relative to `origin`. A triangle
//! narrower than `sliver_width` (twice its area over its longest edge) gets a zero normal.
TriangleBlock make_triangle_block(const TriangleMesh& mesh, const uint32_t* ids, uint32_t count, const Vec3& origin,
                                  double sliver_width);

//! The four estimated squared distances from `p_relative` (p − origin) for a query of magnitude M
//! (see TriangleBlockTolerance), one lane per triangle. For tests and tools: the search inlines
//! estimate_distances_squared (triangle_estimate.h) instead.
std::array<float, 4> estimate_block_distances_squared(const TriangleBlock& block, const Vec3& p_relative,
                                                      double magnitude);

} // namespace zomeify
