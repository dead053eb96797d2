#include "core/score/fit_translation.h"

#include <algorithm>

#include "core/base/errors.h"

namespace zomeify {
namespace {

Vec3 box_centre(const std::vector<Vec3>& points)
{
    Vec3 lo = points.front(), hi = points.front();
    for (const Vec3& p : points)
    {
        lo = lo.cwiseMin(p);
        hi = hi.cwiseMax(p);
    }
    return 0.5 * (lo + hi);
}

} // namespace

ModelTransform fit_translation(const ZomeModel& model, const SurfaceProjector& surface, double scale, int iterations)
{
    if (model.nodes.empty() || surface.mesh().positions.empty())
        throw InvalidInputError("fitting a model onto a surface needs nodes and a surface");
    std::vector<Vec3> nodes;
    nodes.reserve(model.nodes.size());
    for (const ZVec& p : model.nodes)
    {
        const auto d = p.to_double();
        nodes.emplace_back(scale * d[0], scale * d[1], scale * d[2]);
    }
    Vec3 t = box_centre(surface.mesh().positions) - box_centre(nodes);
    for (int it = 0; it < iterations; ++it)
    {
        Vec3 step = Vec3::Zero();
        for (const Vec3& p : nodes)
        {
            const Vec3 q = p + t;
            step += surface.project(q).point - q;
        }
        step /= static_cast<double>(nodes.size());
        t += step;
        if (step.norm() < 1e-9 * scale)
            break;
    }
    ModelTransform transform;
    transform.scale = scale;
    transform.translation = {t.x(), t.y(), t.z()};
    return transform;
}

} // namespace zomeify
