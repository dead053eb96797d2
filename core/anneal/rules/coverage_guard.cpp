#include "core/anneal/rules/coverage_guard.h"

#include <algorithm>
#include <cmath>
#include <numeric>

#include "core/anneal/energy/surface_samples.h"
#include "core/base/errors.h"
#include "core/mesh/element_ranges.h"

namespace zomeify {
namespace {

Vec3 to_vec3(const ZVec& p)
{
    const auto c = p.to_double();
    return {c[0], c[1], c[2]};
}

int64_t cell_index(double x, double cell) { return static_cast<int64_t>(std::floor(x / cell)); }

// 21 bits per axis around zero: ±10^6 cells, far beyond any model (coordinates are clamped).
uint64_t pack(int64_t x, int64_t y, int64_t z)
{
    constexpr int64_t kHalf = int64_t{1} << 20;
    const auto axis = [](int64_t v) { return static_cast<uint64_t>(std::clamp<int64_t>(v + kHalf, 0, 2 * kHalf - 1)); };
    return (axis(x) << 42) | (axis(y) << 21) | axis(z);
}

} // namespace

CoverageGuard::CoverageGuard(const SurfaceContext& ctx, const ZomeMesh& start, const CoverageOptions& options)
    : radius_(options.radius), radius_squared_(options.radius * options.radius)
{
    if (!(options.radius >= 0.0) || !std::isfinite(options.radius))
        throw InvalidInputError("the coverage radius must be 0 (off) or a positive number of b0");
    if (!(options.spacing > 0.0) || !std::isfinite(options.spacing))
        throw InvalidInputError("the coverage sample spacing must be a positive number of b0");
    if (!enabled())
        return;
    std::vector<Vec3> points = surface_sample_points(ctx, options.spacing);
    std::vector<uint64_t> keys(points.size());
    for (size_t i = 0; i < points.size(); ++i)
    {
        const Vec3& p = points[i];
        keys[i] = pack(cell_index(p.x(), radius_), cell_index(p.y(), radius_), cell_index(p.z(), radius_));
    }
    std::vector<uint32_t> order(points.size());
    std::iota(order.begin(), order.end(), 0U);
    std::stable_sort(order.begin(), order.end(), [&](uint32_t i, uint32_t j) { return keys[i] < keys[j]; });
    samples_.reserve(points.size());
    for (size_t k = 0; k < order.size(); ++k)
    {
        const uint64_t key = keys[order[k]];
        if (k == 0 || keys[order[k - 1]] != key)
            cells_[key] = {static_cast<uint32_t>(k), static_cast<uint32_t>(k)};
        samples_.push_back(points[order[k]]);
        ++cells_[key].end;
    }
    counts_ = recount(start);
    pending_.assign(samples_.size(), 0);
}

template <typename F>
void CoverageGuard::for_samples_near(const Vec3& p, F&& f) const
{
    const int64_t cx = cell_index(p.x(), radius_), cy = cell_index(p.y(), radius_), cz = cell_index(p.z(), radius_);
    for (int64_t x = cx - 1; x <= cx + 1; ++x)
        for (int64_t y = cy - 1; y <= cy + 1; ++y)
            for (int64_t z = cz - 1; z <= cz + 1; ++z)
            {
                const auto it = cells_.find(pack(x, y, z));
                if (it == cells_.end())
                    continue;
                for (uint32_t i = it->second.begin; i < it->second.end; ++i)
                    if ((samples_[i] - p).squaredNorm() <= radius_squared_)
                        f(i);
            }
}

std::vector<uint32_t> CoverageGuard::recount(const ZomeMesh& mesh) const
{
    std::vector<uint32_t> counts(samples_.size(), 0);
    if (!enabled())
        return counts;
    for (Vertex v : vertices(mesh))
        for_samples_near(to_vec3(mesh.position(v)), [&](uint32_t i) { ++counts[i]; });
    return counts;
}

size_t CoverageGuard::uncovered() const noexcept
{
    return static_cast<size_t>(std::count(counts_.begin(), counts_.end(), 0U));
}

void CoverageGuard::add_pending(const Vec3& p, int delta)
{
    for_samples_near(p, [&](uint32_t i) {
        if (pending_[i] == 0)
            touched_.push_back(i);
        pending_[i] += delta;
        // A sample back at zero stays in touched_ (harmless: its net change is zero).
    });
}

bool CoverageGuard::admit(const ZomeMesh& mesh, const LocalChange& change)
{
    if (!enabled() || change.removed_nodes().empty())
    {
        // Only removals can uncover a sample; additions just count.
        if (enabled())
            for (const ZVec& p : change.added_nodes())
                for_samples_near(to_vec3(p), [&](uint32_t i) { ++counts_[i]; });
        return true;
    }
    touched_.clear();
    for (const Vertex& v : change.removed_nodes())
        add_pending(to_vec3(mesh.position(v)), -1);
    for (const ZVec& p : change.added_nodes())
        add_pending(to_vec3(p), +1);
    bool ok = true;
    for (const uint32_t i : touched_)
        ok = ok && !(counts_[i] > 0 && static_cast<int64_t>(counts_[i]) + pending_[i] <= 0);
    for (const uint32_t i : touched_)
    {
        if (ok)
            counts_[i] = static_cast<uint32_t>(static_cast<int64_t>(counts_[i]) + pending_[i]);
        pending_[i] = 0;
    }
    return ok;
}

} // namespace zomeify
