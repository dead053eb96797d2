#include "tests/anneal/engine/anneal_scene.h"

#include "core/geom/inside.h"
#include "core/surface/prepare.h"
#include "core/surface/read_mesh.h"
#include "core/voxel/initial_model.h"
#include "tests/support/paths.h"

namespace zomeify::test {

std::unique_ptr<AnnealScene> make_anneal_scene(const std::string& name, int resolution)
{
    auto scene = std::make_unique<AnnealScene>();
    PreparedSurface prepared = prepare_surface(read_mesh_file(shared_path("data/meshes/" + name)));
    scene->surface = std::move(prepared.mesh);
    scene->surface_genus = prepared.report.genus;
    scene->projector = std::make_unique<SurfaceProjector>(scene->surface);
    const InsideTest inside(*scene->projector);
    InitialModelOptions options;
    options.resolution = resolution;
    options.target_genus = scene->surface_genus;
    options.surface_probe = probe_of(*scene->projector); // as a run builds Z0
    scene->z0 = build_initial_model(
                    scene->surface, [&](const Vec3& p) { return inside.is_inside(p); }, options)
                    .model;
    scene->context = std::make_unique<SurfaceContext>(*scene->projector, scene->z0.transform);
    return scene;
}

} // namespace zomeify::test
