#pragma once
//! \file anneal_scene.h
//! A shared test mesh, its Z0 at a given resolution and the energy's surface context.

#include <memory>
#include <string>

#include "core/anneal/energy/surface_context.h"
#include "core/geom/closest_point.h"
#include "core/geom/triangle_mesh.h"
#include "core/zome/model.h"

namespace zomeify::test {

struct AnnealScene
{
    TriangleMesh surface;
    long long surface_genus = 0;
    std::unique_ptr<SurfaceProjector> projector;
    std::unique_ptr<SurfaceContext> context;
    ZomeModel z0;
};

//! Loads ../shared/data/meshes/<name> and builds Z0 with `resolution` cells along the longest side.
std::unique_ptr<AnnealScene> make_anneal_scene(const std::string& name, int resolution);

} // namespace zomeify::test
