#pragma once
//! \file edge_uses.h
//! Every directed edge of a triangle mesh, grouped by undirected edge: the one pass that the
//! topology analysis and the repairs of meshes from the wild all start from.

#include <array>
#include <cstddef>
#include <cstdint>
#include <vector>

namespace zomeify {

//! One face's side of an undirected edge: the face and the corner its directed edge starts at.
struct EdgeUse
{
    uint64_t key; //!< (smaller vertex << 32) | larger vertex
    uint32_t face;
    uint8_t corner; //!< the directed edge runs from this corner to the next
};

inline uint64_t edge_key(uint32_t a, uint32_t b) { return (uint64_t{a < b ? a : b} << 32) | (a < b ? b : a); }

//! The 3 F uses sorted by (key, face): the uses of one edge are adjacent, in face order. Linear
//! time (a counting sort by the smaller vertex, then each vertex's few edges by the larger one),
//! which on a million triangles is several times faster than sorting the whole array.
//! `vertex_count` bounds every index.
std::vector<EdgeUse> sorted_edge_uses(const std::vector<std::array<uint32_t, 3>>& triangles, size_t vertex_count);

} // namespace zomeify
