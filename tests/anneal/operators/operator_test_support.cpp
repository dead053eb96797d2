#include "tests/anneal/operators/operator_test_support.h"

#include <algorithm>
#include <cstdlib>
#include <stdexcept>

#include "core/geom/inside.h"
#include "core/mesh/circulators.h"
#include "core/surface/prepare.h"
#include "core/voxel/initial_model.h"
#include "tests/support/shared_paths.h"
#include "tests/support/zome_fixtures.h"

namespace zomeify::test {

bool propose_at(OperatorKind kind, const ZomeMesh& mesh, Vertex seed, Rng& rng, Proposal& out)
{
    Claims claims;
    claims.take(seed);
    return propose(kind, mesh, seed, rng, claims, out);
}

Vertex random_node(const ZomeMesh& mesh, Rng& rng)
{
    for (;;)
    {
        const Vertex v(static_cast<MeshIndex>(rng.below(mesh.vertices_size())));
        if (mesh.is_valid(v))
            return v;
    }
}

ZomeModel zome_tetrahedron()
{
    const ZomeModel ico = fixtures::icosahedron();
    const auto& f = ico.faces.front();
    ZomeModel m;
    m.nodes = {ZVec{}, ico.nodes[f[0]], ico.nodes[f[1]], ico.nodes[f[2]]};
    m.faces = {{1, 2, 3}, {0, 2, 1}, {0, 3, 2}, {0, 1, 3}};
    for (const auto& face : m.faces)
        for (size_t i = 0; i < face.size(); ++i)
        {
            const uint32_t a = face[i], b = face[(i + 1) % face.size()];
            if (a < b)
                m.struts.push_back({a, b});
        }
    return m;
}

ZomeModel rhombic_cell()
{
    return fixtures::voxel_surface(fixtures::block_cells(1, 1, 1), fixtures::rhombohedral_basis());
}

SharedScene shared_scene(const std::string& mesh_name, int resolution, const ProjectionCacheOptions& cache)
{
    SharedScene s;
    s.projector = std::make_unique<SurfaceProjector>(load_surface(shared_path("data/meshes/" + mesh_name)));
    const InsideTest inside(*s.projector);
    InitialModelOptions options;
    options.resolution = resolution;
    options.surface_probe = probe_of(*s.projector); // as a run builds Z0
    InitialModel z0 = build_initial_model(
        s.projector->mesh(), [&](const Vec3& p) { return inside.is_inside(p); }, options);
    if (!z0.report.valid)
        throw std::runtime_error("no manifold Z0 for " + mesh_name);
    s.z0 = std::move(z0.model);
    s.context = std::make_unique<SurfaceContext>(*s.projector, s.z0.transform, cache);
    return s;
}

std::vector<std::vector<ZVec>> face_set(const ZomeMesh& mesh)
{
    std::vector<std::vector<ZVec>> faces;
    for (MeshIndex i = 0; i < mesh.faces_size(); ++i)
    {
        const Face f(i);
        if (!mesh.is_valid(f))
            continue;
        std::vector<ZVec> corners;
        for (Vertex v : face_vertices(mesh, f))
            corners.push_back(mesh.position(v));
        std::rotate(corners.begin(), std::min_element(corners.begin(), corners.end()), corners.end());
        faces.push_back(corners);
    }
    std::sort(faces.begin(), faces.end());
    return faces;
}

long env_count(const char* name, long fallback)
{
    const char* s = std::getenv(name);
    return s && *s ? std::atol(s) : fallback;
}

} // namespace zomeify::test
