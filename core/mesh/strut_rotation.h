#pragma once
//! \file strut_rotation.h
//! Rotation systems of a strut graph: for every node, its neighbours in counter-clockwise order
//! seen from outside. A closed surface whose every strut is an edge of two faces is exactly its
//! rotation system (trace_faces in recover_faces.h gives the faces back), and the rotation is
//! mostly what the geometry suggests, so share links store only where the guess is wrong.

#include <array>
#include <optional>
#include <vector>

#include "core/zome/model.h"

namespace zomeify {

using Rotation = std::vector<std::vector<uint32_t>>;

//! The geometric guess from positions and struts alone: a normal per node (the dominant axis of
//! its struts' cross products, refined by the area vector of its link), oriented consistently
//! along a minimum spanning tree of normal agreement (Hoppe et al. 1992) from the node of
//! largest x, then neighbours sorted by angle. Deterministic: only +, −, ×, ÷, √ and exact
//! comparisons, so native and WebAssembly builds agree bit for bit.
Rotation guess_rotation(const std::vector<ZVec>& nodes, const std::vector<std::array<uint32_t, 2>>& struts);

//! The rotation the faces define (the neighbour after w around v is u when a face reads
//! … u v w …), or nothing when the faces are not a closed surface over exactly these struts
//! (a strut on no face or on one, a node whose faces do not close around it, a face edge that is
//! no strut). Every rotation starts at the node's smallest neighbour.
std::optional<Rotation> rotation_of_faces(size_t node_count, const std::vector<std::array<uint32_t, 2>>& struts,
                                          const std::vector<std::vector<uint32_t>>& faces);

} // namespace zomeify
