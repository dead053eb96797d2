#pragma once
//! \file voxel_test_support.h
//! Shared pieces of the voxel tests: the ten shared meshes (loaded once per process, with their
//! genus and an inside test) and checks of an extracted Z0.

#include <memory>
#include <string>
#include <vector>

#include "core/geom/closest_point.h"
#include "core/geom/inside.h"
#include "core/voxel/voxelize.h"
#include "core/zome/model.h"

namespace zomeify::voxel_test {

//! The ten meshes of shared/data/meshes, in the README's order.
const std::vector<std::string>& shared_mesh_names();

//! A shared mesh after load and repair, its genus, and an inside test over it.
struct LoadedSurface
{
    TriangleMesh mesh;
    long long genus = 0;
    std::unique_ptr<SurfaceProjector> projector;
    std::unique_ptr<InsideTest> inside;

    InsidePredicate predicate() const
    {
        return [this](const Vec3& p) { return inside->is_inside(p); };
    }
};

//! Loads shared/data/meshes/<name>.obj once and keeps it for the rest of the process.
const LoadedSurface& shared_surface(const std::string& name);

//! A shape of tests/support/generated_shapes.h ("trefoil", "double_torus", "mug") with its
//! genus and an inside test, built once for the rest of the process.
const LoadedSurface& generated_surface(const std::string& name);

//! An empty string if the model's faces form a closed, consistently oriented 2-manifold: every
//! strut in exactly two faces with opposite directions, every face edge a strut, and the faces
//! around every node forming one fan; otherwise the first problem found.
std::string closed_manifold_problem(const ZomeModel& model);

//! An empty string if every strut is a B1 along a coordinate axis and no two nodes coincide.
std::string lattice_problem(const ZomeModel& model);

//! An empty string if from_model() accepts the model and validate() finds the halfedge mesh valid
//! (closed 2-manifold, Zome rules); otherwise the reason. `genus` receives validate()'s genus.
std::string halfedge_problem(const ZomeModel& model, long long* genus = nullptr);

//! Genus from the faces: components − (V − E + F)/2.
long long model_genus(const ZomeModel& model);

} // namespace zomeify::voxel_test
