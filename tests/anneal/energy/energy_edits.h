#pragma once
//! \file energy_edits.h
//! Random local edits of a closed Zome mesh for the energy tests and benchmark: each comes as the
//! energy's LocalChange and the mesh edit (made of the mesh's primitives) that realises it. The
//! edits keep the surface a closed 2-manifold of the same genus but do not insist on Zome vectors
//! (the energy is defined for any positions), except that node moves prefer vectors keeping every
//! strut a Zome vector.

#include <functional>
#include <optional>
#include <random>

#include "core/anneal/energy/local_change.h"
#include "core/mesh/zome_mesh.h"

namespace zomeify::test {

using EditRng = std::mt19937;

//! One proposal: the energy's description and the mesh edit that realises it.
struct Edit
{
    const char* kind = "";
    LocalChange change;
    std::function<void(ZomeMesh&)> apply;
};

//! ADDDIAG: splits a random quad a b c d by a–c into (a, b, c) and (c, d, a).
std::optional<Edit> add_diagonal(const ZomeMesh& mesh, EditRng& rng);
//! REMDIAG: merges the two triangles (u, v, x), (v, u, y) of a random strut into the quad (v, x, u, y).
std::optional<Edit> remove_diagonal(const ZomeMesh& mesh, EditRng& rng);
//! FLIPDIAG: replaces u–v by x–y: triangles (x, u, y) and (y, v, x).
std::optional<Edit> flip_diagonal(const ZomeMesh& mesh, EditRng& rng);
//! MOVNODE with unchanged connectivity: moves a random node by a Zome vector to a free position.
std::optional<Edit> move_node(const ZomeMesh& mesh, EditRng& rng);
//! INSNODE: a new node at a face centre (when it is a lattice point), possibly offset by a short
//! Zome vector, joined to every corner.
std::optional<Edit> insert_node(const ZomeMesh& mesh, EditRng& rng);
//! REMNODE: a node of valence 3 or 4 among triangles is removed; its link becomes a face.
std::optional<Edit> remove_node(const ZomeMesh& mesh, EditRng& rng);

//! One of the six, chosen at random (retrying until one applies, at most 100 times).
std::optional<Edit> random_edit(const ZomeMesh& mesh, EditRng& rng);

} // namespace zomeify::test
