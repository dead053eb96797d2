#pragma once
//! \file star.h
//! Stars and links (paper §3.2, Figure 4; §5.1): the support region of an operator is the star
//! of a node, a strut or a face (the faces around it); its link is the oriented loop of nodes
//! bounding that region. Operators clear the star, leaving a hole whose boundary is the link, and
//! fill the hole again with add_face. The link's orientation is the faces' (counter-clockwise
//! seen from outside), so a fan (c, l[i], l[i+1]) around a new centre c is oriented correctly.
//!
//! The functions fill a caller-owned vector, which keeps its capacity between calls, so an
//! annealing thread that reuses one buffer does not allocate in steady state.

#include <span>
#include <vector>

#include "core/mesh/surface_mesh.h"

namespace zomeify {

//! The link of v: for each face around v (counter-clockwise), its corners after v except the
//! last (which starts the next face). False, with `link` empty, if v is isolated or on a boundary.
bool vertex_link(const SurfaceMesh& mesh, Vertex v, std::vector<Vertex>& link);

//! The link of e: the corners of the two faces of e, starting at to_vertex(halfedge(e, 0)), so
//! both endpoints of e are in it. False, with `link` empty, if e is on a boundary.
bool edge_link(const SurfaceMesh& mesh, Edge e, std::vector<Vertex>& link);

//! Whether no node occurs twice in the loop. A link that visits a node twice ("a node pointed to
//! twice", paper §5.1) would leave a non-disc neighbourhood once the star is cleared.
bool is_simple_loop(std::span<const Vertex> loop);

//! Removes the faces around v; v stays, isolated (move or remove it, then fill the hole).
void clear_vertex_star(SurfaceMesh& mesh, Vertex v);

//! Removes the faces on both sides of e, and with them e; its endpoints stay.
void clear_edge_star(SurfaceMesh& mesh, Edge e);

} // namespace zomeify
