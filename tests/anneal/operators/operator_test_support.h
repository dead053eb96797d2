#pragma once
//! \file operator_test_support.h
//! Helpers for the operator tests: single-threaded proposals at a seed, small exact fixtures
//! (a Zome tetrahedron, a golden rhombohedron whose faces have Zome diagonals) and Z0 of a shared
//! mesh with the energy's SurfaceContext.

#include <array>
#include <memory>
#include <string>

#include "core/anneal/energy/surface_context.h"
#include "core/anneal/proposal.h"
#include "core/geom/closest_point.h"
#include "core/mesh/zome_mesh.h"
#include "core/zome/model.h"

namespace zomeify::test {

//! propose() with only the seed claimed beforehand (single-threaded claims).
bool propose_at(OperatorKind kind, const ZomeMesh& mesh, Vertex seed, Rng& rng, Proposal& out);
//! A uniformly random live node (the mesh may hold deleted elements).
Vertex random_node(const ZomeMesh& mesh, Rng& rng);

//! The tetrahedron of the origin and one face of the R0 icosahedron (Zome struts, valence 3).
ZomeModel zome_tetrahedron();
//! One golden rhombohedron of R0 struts: 8 nodes, 6 rhombi whose diagonals are Zome vectors.
ZomeModel rhombic_cell();

//! Z0 of a shared mesh at a resolution, with the energy's context.
struct SharedScene
{
    ZomeModel z0;
    std::unique_ptr<SurfaceProjector> projector;
    std::unique_ptr<SurfaceContext> context;
};
SharedScene shared_scene(const std::string& mesh_name, int resolution, const ProjectionCacheOptions& cache = {});

//! The sorted list of faces, each as its corner positions rotated to start at the smallest
//! (orientation kept): equal for meshes with the same faces regardless of handles.
std::vector<std::vector<ZVec>> face_set(const ZomeMesh& mesh);

//! The environment variable `name` as a number if set, else `fallback`.
long env_count(const char* name, long fallback);

} // namespace zomeify::test
