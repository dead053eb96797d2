#include "core/pipeline/continue_from.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <vector>

#include "core/anneal/engine/change_region.h"

namespace zomeify {

namespace {

// A model made for a surface has its balls on it: a default model's balls lie within about half a
// b0 of S (the forbidden zones keep them near), a coarse one within a few b0.
constexpr double kMedianBallGapB0 = 1.5;
// Its balls span the surface: a model of another size of this mesh spans a multiple of it.
constexpr double kSpanRatioLow = 0.7, kSpanRatioHigh = 1.45;

std::string fixed1(double v)
{
    char buf[32];
    std::snprintf(buf, sizeof buf, "%.1f", v);
    return buf;
}

Vec3 placed(const ZVec& p, const ModelTransform& t)
{
    const auto c = p.to_double();
    return {c[0] * t.scale + t.translation[0], c[1] * t.scale + t.translation[1], c[2] * t.scale + t.translation[2]};
}

} // namespace

std::string model_fit_problem(const ZomeModel& model, const SurfaceProjector& projector)
{
    if (model.nodes.empty())
        return "the model to continue has no balls";
    const ModelTransform& t = model.transform;
    if (!(t.scale > 0.0) || !std::isfinite(t.scale))
        return "the model to continue has no placement on a mesh (its file carries no transform): continue a "
               ".zome.json or a link made for this mesh";
    std::vector<double> gaps;
    gaps.reserve(model.nodes.size());
    Vec3 lo = Vec3::Constant(1e300), hi = Vec3::Constant(-1e300);
    for (const ZVec& n : model.nodes)
    {
        const Vec3 p = placed(n, t);
        if (!p.allFinite())
            return "the model to continue is placed outside any mesh (its transform is not finite)";
        lo = lo.cwiseMin(p);
        hi = hi.cwiseMax(p);
        gaps.push_back(std::sqrt(projector.project(p).distance_squared) / t.scale);
    }
    Vec3 slo = Vec3::Constant(1e300), shi = Vec3::Constant(-1e300);
    for (const Vec3& p : projector.mesh().positions)
    {
        slo = slo.cwiseMin(p);
        shi = shi.cwiseMax(p);
    }
    const double span = (hi - lo).maxCoeff(), surface_span = (shi - slo).maxCoeff();
    const double ratio = surface_span > 0.0 ? span / surface_span : 0.0;
    std::nth_element(gaps.begin(), gaps.begin() + static_cast<std::ptrdiff_t>(gaps.size() / 2), gaps.end());
    const double median_gap = gaps[gaps.size() / 2];
    if (ratio < kSpanRatioLow || ratio > kSpanRatioHigh)
        return "the model to continue was not made for this mesh: its balls span " + fixed1(ratio) +
               " times the mesh's size (a model of another mesh, or of this one at another scale)";
    if (median_gap > kMedianBallGapB0)
        return "the model to continue was not made for this mesh: its balls lie " + fixed1(median_gap) +
               " b0 from the surface (median; a model made for it lies within about 1)";
    return "";
}

bool short_of_target(size_t start, size_t target, size_t reached)
{
    const double slack = std::max(3.0, 0.1 * static_cast<double>(target));
    if (target < start)
        return static_cast<double>(reached) > static_cast<double>(target) + slack;
    if (target > start)
        return static_cast<double>(reached) < static_cast<double>(target) - slack;
    return false;
}

ChangeRegion region_of(const FixSpot& spot, const ModelTransform& t)
{
    ChangeRegion r;
    for (int k = 0; k < 3; ++k)
        r.centre[static_cast<size_t>(k)] = (spot.centre[k] - t.translation[static_cast<size_t>(k)]) / t.scale;
    r.radius = spot.radius / t.scale;
    return r;
}

size_t nodes_in_region(const ZomeModel& model, const ChangeRegion& region)
{
    return static_cast<size_t>(
        std::count_if(model.nodes.begin(), model.nodes.end(), [&](const ZVec& p) { return in_region(region, p); }));
}

size_t fix_target(const ZomeModel& model, const ChangeRegion& region)
{
    return model.nodes.size() + std::max<size_t>(4, nodes_in_region(model, region) / 2);
}

} // namespace zomeify
