#include "tests/anneal/energy/energy_test_support.h"

#include <limits>

#include "tests/support/geom_fixtures.h"

namespace zomeify::test {

ModelTransform energy_test_transform()
{
    ModelTransform t;
    t.scale = 0.37;
    t.translation = {1.5, -2.0, 0.25};
    return t;
}

EnergyScene make_energy_scene(TriangleMesh surface, const ModelTransform& transform)
{
    const Vec3 offset(transform.translation[0], transform.translation[1], transform.translation[2]);
    for (Vec3& p : surface.positions)
    {
        p = transform.scale * p + offset;
    }
    EnergyScene scene;
    scene.projector = std::make_unique<SurfaceProjector>(std::move(surface));
    scene.context = std::make_unique<SurfaceContext>(*scene.projector, transform);
    return scene;
}

std::array<Vec3, 2> node_bounds(const ZomeModel& model)
{
    Vec3 lo = Vec3::Constant(std::numeric_limits<double>::max());
    Vec3 hi = -lo;
    for (const ZVec& n : model.nodes)
    {
        const auto d = n.to_double();
        const Vec3 p(d[0], d[1], d[2]);
        lo = lo.cwiseMin(p);
        hi = hi.cwiseMax(p);
    }
    return {lo, hi};
}

EnergyScene sphere_scene_for(const ZomeModel& model, const ModelTransform& transform)
{
    const auto [lo, hi] = node_bounds(model);
    TriangleMesh sphere = make_icosphere(0.45 * (hi - lo).maxCoeff(), 3);
    const Vec3 centre = 0.5 * (lo + hi);
    for (Vec3& p : sphere.positions)
    {
        p += centre;
    }
    return make_energy_scene(std::move(sphere), transform);
}

} // namespace zomeify::test
