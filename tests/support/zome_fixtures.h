#pragma once
//! \file zome_fixtures.h
//! Procedural Zome models with faces for tests (style.md §7 rule 6): voxel shells of blue B1 cubes
//! (genus 0, 1 and 2), the same shells on a skewed lattice of red R0 golden rhombohedra (every face
//! is a rhombus whose two diagonals are Zome vectors, so diagonal edits are possible), and convex
//! Platonic solids made of struts (icosahedron: triangles; dodecahedron: pentagons). Every face is
//! counter-clockwise seen from outside. (An octahedron on the axes is impossible: (−φ, φ, 0) is not
//! a Zome vector; the icosahedron is the all-triangle fixture.)

#include <array>
#include <string>
#include <vector>

#include "core/zome/model.h"
#include "core/zome/zvec.h"

namespace zomeify::fixtures {

//! A unit cell (i, j, k) of a voxel grid.
using Cell = std::array<int, 3>;

//! The cell edge vectors of a voxel lattice; node (i, j, k) sits at i·u + j·v + k·w.
struct LatticeBasis
{
    ZVec u, v, w;
};

//! B1 blue struts along x, y and z.
LatticeBasis b1_basis();
//! Three R0 red struts spanning a golden rhombohedron whose six faces have Zome diagonals.
LatticeBasis rhombohedral_basis();

//! The boundary quads of a set of occupied cells, with shared nodes, counter-clockwise seen from
//! outside (also on a left-handed basis). The caller picks cell sets whose boundary is a manifold
//! (no two cells touching along an edge or at a corner only).
ZomeModel voxel_surface(const std::vector<Cell>& cells, const LatticeBasis& basis = b1_basis());

//! Cells of an nx × ny × nz block.
std::vector<Cell> block_cells(int nx, int ny, int nz);
//! A square ring of cells: a 3 × 3 × 1 block without its centre (genus 1).
std::vector<Cell> torus_cells();
//! Two rings side by side: a 5 × 3 × 1 block without cells (1, 1, 0) and (3, 1, 0) (genus 2).
std::vector<Cell> double_torus_cells();

//! The boundary of an n × n × n block of B1 cubes (genus 0, 6n² quads).
ZomeModel cube_shell(int n);
//! Genus-1 and genus-2 voxel surfaces of B1 cubes.
ZomeModel torus_shell();
ZomeModel double_torus_shell();
//! The icosahedron with nodes at the 12 R0 red vectors (20 triangles, 30 struts).
ZomeModel icosahedron();
//! The dodecahedron with nodes at the 20 Y1 yellow vectors (12 pentagons, 30 struts).
ZomeModel dodecahedron();

//! A fixture with its expected genus and whether all faces are triangles or quads.
struct NamedModel
{
    std::string name;
    ZomeModel model;
    int genus = 0;
    bool tri_quad = true;
};

//! The closed tri/quad fixtures, for tests that loop over models (name printed on failure).
std::vector<NamedModel> closed_models();

} // namespace zomeify::fixtures
