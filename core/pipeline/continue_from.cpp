#include "core/pipeline/continue_from.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <vector>

#include "core/anneal/engine/change_region.h"
#include "core/base/errors.h"
#include "core/zome/slots.h"

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

// The capacity's constant (kAreaPerBallB0Squared), 2026-12-07: runs from Z0 at several ball targets,
// `run MESH [size] --target-nodes N --threads 1 --proposals 6000000 --seed 1|2`, scored by
// `score --samples 100000` (symmetric RMS in b0, mean of the two seeds):
//   bunny, --b1 0.1907 (408 b0²): 400: 0.102, 450: 0.102, 500: 0.103, 550: 0.109, 600: 0.113, 700: 0.130
//   torus, automatic 8 cells (264 b0²): 200: 0.085, 250: 0.083, 300: 0.086, 350: 0.091, 400: 0.103
//   fertility, automatic 10 cells (387 b0²): 300: 0.221, 375: 0.218, 450: 0.197, 525: 0.206, 600: 0.206,
//     700: 0.198, 800: 0.218
// Per mesh, the area per ball that keeps the capacity between the count with the lowest RMS and the
// first count more than 5 % worse than it: bunny 0.74–0.91 b0² (550 and 450 balls), torus 0.75–1.06
// (350, 250), fertility 0.48–0.86 (800, 450). All three hold 0.75–0.86; 0.8 is its middle. It lies
// between a tiling by equilateral b0 triangles (0.866 b0² a ball) and one by the smallest yellow
// triangles (0.65 b0²). docs/work-on-a-model.md has the table.

double surface_area(const TriangleMesh& mesh)
{
    double area = 0.0;
    for (const auto& t : mesh.triangles)
    {
        const Vec3& a = mesh.positions[t[0]];
        area += 0.5 * (mesh.positions[t[1]] - a).cross(mesh.positions[t[2]] - a).norm();
    }
    return area;
}

size_t surface_capacity(double area, double b0_length)
{
    if (!(area > 0.0) || !(b0_length > 0.0) || !std::isfinite(area / (b0_length * b0_length)))
        return 0;
    const double balls = area / (b0_length * b0_length) / kAreaPerBallB0Squared;
    return std::max<size_t>(4, static_cast<size_t>(std::llround(std::min(balls, 1e9))));
}

size_t surface_capacity(const TriangleMesh& surface, const ModelTransform& transform)
{
    if (!(transform.scale > 0.0) || !std::isfinite(transform.scale))
        return 0;
    return surface_capacity(surface_area(surface), kind_info(StrutKind::B0).length * transform.scale);
}

std::string capacity_capped_text(size_t capacity)
{
    const std::string n = std::to_string(capacity);
    return "At this size the surface holds about " + n +
           " balls well; more would crumple the model (the paper's fold-overs): the target was kept at " + n +
           ". For more detail choose a larger size (a new run).";
}

std::string capacity_full_text(size_t balls, size_t capacity)
{
    return "the model has " + std::to_string(balls) + " balls and at this size the surface holds about " +
           std::to_string(capacity) +
           " well; more would crumple the model (the paper's fold-overs): for more detail choose a larger size (a "
           "new run)";
}

bool at_capacity(size_t balls, size_t capacity)
{
    const double c = static_cast<double>(capacity);
    return capacity > 0 && static_cast<double>(balls) + std::max(3.0, 0.03 * c) >= c;
}

size_t capped_target(size_t balls, size_t target, size_t capacity)
{
    if (capacity == 0 || target <= balls)
        return target;
    if (at_capacity(balls, capacity))
        throw InvalidInputError(capacity_full_text(balls, capacity));
    return std::min(target, capacity);
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
