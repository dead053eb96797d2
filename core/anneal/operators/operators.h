#pragma once
//! \file operators.h
//! One function per operator (paper §3.2, §5.1; design.md §3.4), dispatched by propose(). Each
//! picks its element near the seed, claims what it reads, loads the region into `change` and a
//! Fill, and returns Rejection::None when `change` holds a valid proposal.
//!
//! The `_at` functions take the element (and the new position) explicitly; tests use them to
//! build exact cases, and the random entry points call them after drawing their choices.
//!
//! Internal to core/anneal/operators.

#include "core/anneal/operators/fill.h"

namespace zomeify::detail {

Rejection propose_ins_node(const ZomeMesh& mesh, Vertex seed, Rng& rng, Claims& claims, Fill& fill,
                           LocalChange& change) noexcept;
Rejection propose_add_diag(const ZomeMesh& mesh, Vertex seed, Rng& rng, Claims& claims, Fill& fill,
                           LocalChange& change) noexcept;
Rejection propose_split_strut(const ZomeMesh& mesh, Vertex seed, Rng& rng, Claims& claims, Fill& fill,
                              LocalChange& change) noexcept;
Rejection propose_rem_diag(const ZomeMesh& mesh, Vertex seed, Rng& rng, Claims& claims, Fill& fill,
                           LocalChange& change) noexcept;
Rejection propose_flip_diag(const ZomeMesh& mesh, Vertex seed, Rng& rng, Claims& claims, Fill& fill,
                            LocalChange& change) noexcept;
Rejection propose_mov_node(const ZomeMesh& mesh, Vertex seed, Rng& rng, Claims& claims, Fill& fill,
                           LocalChange& change) noexcept;
Rejection propose_rem_node(const ZomeMesh& mesh, Vertex seed, Rng& rng, Claims& claims, Fill& fill,
                           LocalChange& change) noexcept;

//! INSNODE of face f with the new node at p.
Rejection ins_node_at(const ZomeMesh& mesh, Face f, const ZVec& p, Claims& claims, Fill& fill,
                      LocalChange& change) noexcept;
//! ADDDIAG of quad f with the diagonal from its corner `corner` (0 or 1: corners in face order
//! from to_vertex(halfedge(f))) to the opposite one.
Rejection add_diag_at(const ZomeMesh& mesh, Face f, size_t corner, Claims& claims, Fill& fill,
                      LocalChange& change) noexcept;
//! SPLITSTRUT of the strut of h (from u to v) with the new node at p.
Rejection split_strut_at(const ZomeMesh& mesh, Halfedge h, const ZVec& p, Claims& claims, Fill& fill,
                         LocalChange& change) noexcept;
//! REMDIAG / FLIPDIAG of the strut of h.
Rejection rem_diag_at(const ZomeMesh& mesh, Halfedge h, Claims& claims, Fill& fill, LocalChange& change) noexcept;
Rejection flip_diag_at(const ZomeMesh& mesh, Halfedge h, Claims& claims, Fill& fill, LocalChange& change) noexcept;
//! MOVNODE of n to p.
Rejection mov_node_to(const ZomeMesh& mesh, Vertex n, const ZVec& p, Claims& claims, Fill& fill,
                      LocalChange& change) noexcept;

} // namespace zomeify::detail
