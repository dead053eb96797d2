#pragma once
//! \file region.h
//! Support regions (paper §3.2, Figure 4): choosing an operator's element near the seed node, and
//! loading the link of that element's star into a Fill, claiming every link node (the tag region
//! is the star's nodes plus the link; complete_fill() adds the 1-rings the energy reads).
//!
//! Sampling (the engine draws seed nodes uniformly): a node element is the seed itself; a strut
//! is a uniformly random strut at the seed, so strut s = (a, b) is drawn with probability
//! (1/deg a + 1/deg b)/N; a face is a uniformly random face around the seed, so f is drawn with
//! probability Σ over its corners c of 1/(N·deg c). Operators that need a particular shape (a quad
//! for ADDDIAG, a strut between two triangles for REMDIAG and FLIPDIAG) draw uniformly among the
//! seed's elements of that shape, which favours elements whose corners have few such elements.
//!
//! Internal to core/anneal/operators.

#include "core/anneal/operators/fill.h"

namespace zomeify::detail {

//! The outgoing halfedge of the seed along a uniformly random strut at it.
Halfedge random_strut(const ZomeMesh& mesh, Vertex seed, Rng& rng) noexcept;
//! A uniformly random outgoing halfedge of the seed whose strut has triangles on both sides, or
//! invalid if there is none.
Halfedge random_diagonal(const ZomeMesh& mesh, Vertex seed, Rng& rng) noexcept;
//! A uniformly random face at the seed, or (quads_only) a uniformly random quad; invalid if none.
Face random_face(const ZomeMesh& mesh, Vertex seed, Rng& rng, bool quads_only) noexcept;

//! Loads the corners of f (in face order, from to_vertex(halfedge(f))) as the link, claims them
//! and removes f in `change`.
Rejection load_face_region(const ZomeMesh& mesh, Face f, Claims& claims, Fill& fill, LocalChange& change) noexcept;
//! Loads the link of the strut of h (from u = from_vertex(h) to v): link[0] = v, then the other
//! corners of h's face, then u at index (corners of h's face) − 1, then the other corners of the
//! opposite face. Claims them and removes both faces and the strut in `change`. LinkTwice when a
//! node occurs twice.
Rejection load_strut_region(const ZomeMesh& mesh, Halfedge h, Claims& claims, Fill& fill, LocalChange& change) noexcept;
//! Loads the link of node n (counter-clockwise), claims it and removes n's star in `change`.
//! LinkTwice when a node occurs twice.
Rejection load_node_region(const ZomeMesh& mesh, Vertex n, Claims& claims, Fill& fill, LocalChange& change) noexcept;

} // namespace zomeify::detail
