#pragma once
//! \file split_non_manifold.h
//! Makes every vertex and edge of a triangle mesh manifold by giving each fan of faces its own copy
//! of the vertex (issue 36): a pinched vertex, where two cones of faces touch at a point, becomes
//! two vertices at one place, and an edge with more than two faces is split into pairs that each
//! close one solid (two cubes sharing an edge become two cubes).

#include <array>
#include <cstddef>
#include <cstdint>
#include <vector>

#include "core/geom/triangle_mesh.h"

namespace zomeify {

struct NonManifoldSplit
{
    size_t pinched_vertices =
        0;                  //!< vertices (not on a split edge) whose faces formed several fans, now one copy per fan
    size_t split_edges = 0; //!< edges that had more than two faces
    size_t loose_faces = 0; //!< faces at such edges that no neighbour closes a solid with (now open there)
};

//! Splits in place: copies of split vertices are appended to `positions`, and `origin` (one entry
//! per vertex, the input vertex it stands for) grows with them. Faces must be oriented consistently
//! where they can be (analyse_topology with orient): around an edge with k > 2 faces, a face is
//! paired with its angular neighbour on the side its normal points away from, so each pair bounds a
//! wedge of solid; a face with no such neighbour is left open along that edge.
NonManifoldSplit split_non_manifold(std::vector<Vec3>& positions, std::vector<std::array<uint32_t, 3>>& triangles,
                                    std::vector<uint32_t>& origin);

} // namespace zomeify
