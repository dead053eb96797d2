#include "core/anneal/surface_context.h"

#include <cmath>

#include "core/base/errors.h"

namespace zomeify {

SurfaceContext::SurfaceContext(const SurfaceProjector& projector, const ModelTransform& transform,
                               const ProjectionCacheOptions& cache)
    : projector_(projector), inside_(projector), transform_(transform), cache_(projector, cache)
{
    if (!std::isfinite(transform.scale) || !(transform.scale > 0.0))
    {
        throw InvalidInputError("energy: the model transform's scale must be a positive number");
    }
    scale_ = transform.scale;
    translation_ = Vec3(transform.translation[0], transform.translation[1], transform.translation[2]);
    inv_scale_squared_ = 1.0 / (scale_ * scale_);
}

SurfaceSample SurfaceContext::sample(const LatticeSum& sum, int divisor) const noexcept
{
    const Vec3 p = to_mesh(sum.divided(divisor));
    const ClosestPoint closest = cache_.project(sum.key(divisor), p);
    SurfaceSample out;
    // The transform is a uniform scale, so distances convert by 1/scale and normals not at all.
    out.distance_squared = closest.distance_squared * inv_scale_squared_;
    out.normal = closest.normal;
    out.inside = inside_.is_inside(p, closest);
    return out;
}

Vec3 SurfaceContext::node_normal(const ZVec& p) const noexcept
{
    const LatticeSum sum = lattice_sum(p);
    const Vec3 q = to_mesh(sum.divided(1));
    return cache_.project(sum.key(1), q).normal;
}

} // namespace zomeify
