#pragma once
//! \file fill_holes.h
//! Closes the holes of a triangle mesh (issue 36): each boundary loop gets a patch of triangles
//! oriented like the faces around it. Loops of up to kMaxExactLoop edges get the triangulation of
//! least area over their own vertices (dynamic programming, O(n^3)); longer ones a fan around a new
//! vertex at the loop's centroid. A scan's small holes close flat, as a person would close them.

#include <array>
#include <cstddef>
#include <cstdint>
#include <vector>

#include "core/geom/triangle_mesh.h"

namespace zomeify {

inline constexpr size_t kMaxExactLoop = 400; //!< 400 edges: about 0.1 s and 1.3 MB

struct FilledHole
{
    size_t edges = 0;         //!< boundary edges around the hole
    double area = 0.0;        //!< of its patch
    uint32_t first_patch = 0; //!< index of the patch's first triangle
    uint32_t patch_faces = 0;
    uint32_t neighbour = 0; //!< a face of the mesh on the hole's rim (its component is the hole's)
};

struct HoleFilling
{
    std::vector<FilledHole> holes;
    size_t untraceable = 0; //!< loops left open: their boundary does not form a simple cycle
};

//! Appends a patch per hole to `triangles` (and, for long loops, one vertex to `positions` and
//! `origin`). Vertices must be manifold (split_non_manifold first), so each boundary vertex starts
//! exactly one boundary edge.
HoleFilling fill_holes(std::vector<Vec3>& positions, std::vector<std::array<uint32_t, 3>>& triangles,
                       std::vector<uint32_t>& origin);

} // namespace zomeify
