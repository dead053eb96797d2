#pragma once
//! \file fan.h
//! The fill of INSNODE, SPLITSTRUT and MOVNODE (paper §3.2): a new node at p is connected to every
//! link node reachable by a Zome vector whose slot is free at that link node, and the arcs of the
//! link between consecutive connections become faces (centre + 2 link nodes: a triangle, + 3: a
//! quad; a longer arc would be a face of 5 or more corners and rejects the proposal).
//!
//! Internal to core/anneal/operators.

#include <cstdint>

#include "core/anneal/operators/fill.h"

namespace zomeify::detail {

inline constexpr size_t kNoLinkIndex = SIZE_MAX;

//! Adds the node at p and the fan faces to `fill` (whose link is loaded). `must_a` and `must_b`
//! (or kNoLinkIndex) are link indices p has to connect to (SPLITSTRUT's strut ends).
Rejection fan_fill(const ZomeMesh& mesh, const LocalChange& change, const ZVec& p, Fill& fill,
                   size_t must_a = kNoLinkIndex, size_t must_b = kNoLinkIndex) noexcept;

} // namespace zomeify::detail
