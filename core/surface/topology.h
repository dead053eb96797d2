#pragma once
//! \file topology.h
//! Edge-based analysis of a triangle soup with shared vertex indices: boundary and non-manifold
//! edges, non-manifold vertices, components, consistent orientation, Euler characteristic, genus.

#include <array>
#include <cstddef>
#include <cstdint>
#include <vector>

#include "core/geom/triangle_mesh.h"

namespace zomeify {

struct TopologyOptions
{
    //! Reorient faces: consistently per component, then outward (positive signed volume), and
    //! inward for shells nested inside an odd number of others (cavities).
    bool orient = true;
};

struct TopologyInfo
{
    size_t vertices = 0; //!< vertices used by at least one triangle
    size_t edges = 0;
    size_t boundary_edges = 0;
    size_t holes = 0; //!< connected groups of boundary edges
    size_t non_manifold_edges = 0;
    size_t non_manifold_vertices = 0;
    size_t components = 0;
    size_t non_orientable_components = 0;
    size_t cavities = 0; //!< closed components inside an odd number of others, oriented inward
    long long euler = 0;
    long long genus = 0;
    std::vector<uint8_t> flipped; //!< per triangle: 1 if orient reversed it (already applied)
    //! One example of each problem (vertex indices), for messages; valid when the count is > 0.
    std::array<uint32_t, 2> boundary_example{0, 0};
    std::array<uint32_t, 2> non_manifold_edge_example{0, 0};
    uint32_t non_manifold_vertex_example = 0;
};

//! Analyses (and with options.orient, reorients in place) `triangles` over `positions`.
//! Triangles must have three distinct, in-range indices.
TopologyInfo analyse_topology(const std::vector<Vec3>& positions, std::vector<std::array<uint32_t, 3>>& triangles,
                              const TopologyOptions& options = {});

} // namespace zomeify
