#include "core/anneal/energy/surface_samples.h"

#include <algorithm>
#include <cmath>
#include <numeric>
#include <unordered_set>

namespace zomeify {
namespace {

// Subdivisions of one triangle's side at most: a sliver of S hundreds of b0 long gets no more.
constexpr int kMaxSubdivisions = 1024;
// Cells of a SampleGrid at most (the cell grows beyond this).
constexpr double kMaxCells = 4.0e6;

int64_t cell_index(double x, double cell) { return static_cast<int64_t>(std::floor(x / cell)); }

// 21 bits per axis around zero: ±10^6 cells, far beyond any model (coordinates are clamped).
uint64_t pack(int64_t x, int64_t y, int64_t z)
{
    constexpr int64_t kHalf = int64_t{1} << 20;
    const auto axis = [](int64_t v) { return static_cast<uint64_t>(std::clamp<int64_t>(v + kHalf, 0, 2 * kHalf - 1)); };
    return (axis(x) << 42) | (axis(y) << 21) | axis(z);
}

} // namespace

std::vector<Vec3> surface_sample_points(const SurfaceContext& context, double spacing)
{
    const TriangleMesh& mesh = context.projector().mesh();
    const double scale = context.transform().scale;
    const Vec3 translation(context.transform().translation[0], context.transform().translation[1],
                           context.transform().translation[2]);
    std::vector<Vec3> zome(mesh.positions.size());
    for (size_t i = 0; i < zome.size(); ++i)
        zome[i] = (mesh.positions[i] - translation) / scale;

    std::vector<Vec3> out;
    std::unordered_set<uint64_t> taken;
    const auto offer = [&](const Vec3& p) {
        if (taken.insert(pack(cell_index(p.x(), spacing), cell_index(p.y(), spacing), cell_index(p.z(), spacing)))
                .second)
            out.push_back(p);
    };
    for (const auto& t : mesh.triangles)
    {
        const Vec3& a = zome[t[0]];
        const Vec3& b = zome[t[1]];
        const Vec3& c = zome[t[2]];
        const double longest = std::max({(b - a).norm(), (c - b).norm(), (a - c).norm()});
        const int n = static_cast<int>(std::clamp(std::ceil(longest / spacing), 1.0, double{kMaxSubdivisions}));
        for (int i = 0; i <= n; ++i)
            for (int j = 0; i + j <= n; ++j)
                offer(a + (static_cast<double>(i) / n) * (b - a) + (static_cast<double>(j) / n) * (c - a));
    }
    return out;
}

SampleGrid::SampleGrid(const std::vector<Vec3>& points, double cell)
{
    if (points.empty())
        return;
    Box3 bounds;
    for (const Vec3& p : points)
        bounds.extend(p);
    const Vec3 extent = bounds.extent();
    const auto cells_for = [&](double c) {
        double n = 1.0;
        for (int k = 0; k < 3; ++k)
            n *= std::floor(extent[k] / c) + 1.0;
        return n;
    };
    while (cells_for(cell) > kMaxCells)
        cell *= 1.5;
    origin_ = bounds.min;
    cell_size_ = cell;
    inverse_cell_ = 1.0 / cell;
    for (int k = 0; k < 3; ++k)
        dims_[k] = static_cast<int>(std::floor(extent[k] * inverse_cell_)) + 1;

    const size_t cell_count = static_cast<size_t>(dims_[0]) * dims_[1] * dims_[2];
    std::vector<uint32_t> key(points.size());
    for (size_t i = 0; i < points.size(); ++i)
    {
        const std::array<int, 3> c = cell_of(points[i]);
        key[i] = static_cast<uint32_t>((static_cast<size_t>(c[2]) * dims_[1] + static_cast<size_t>(c[1])) * dims_[0] +
                                       static_cast<size_t>(c[0]));
    }
    std::vector<uint32_t> order(points.size());
    std::iota(order.begin(), order.end(), 0U);
    std::stable_sort(order.begin(), order.end(), [&](uint32_t a, uint32_t b) { return key[a] < key[b]; });
    points_.reserve(points.size());
    starts_.assign(cell_count + 1, 0);
    for (uint32_t i : order)
    {
        points_.push_back(points[i]);
        cell_of_point_.push_back(key[i]);
        ++starts_[key[i] + 1];
    }
    std::partial_sum(starts_.begin(), starts_.end(), starts_.begin());
}

std::array<int, 3> SampleGrid::cell_of(const Vec3& p) const noexcept
{
    std::array<int, 3> c{};
    for (int k = 0; k < 3; ++k)
    {
        const double x = std::floor((p[k] - origin_[k]) * inverse_cell_);
        // NaN and far-away coordinates clamp too.
        c[k] = x >= 0.0 ? (x < dims_[k] - 1 ? static_cast<int>(x) : dims_[k] - 1) : 0;
    }
    return c;
}

} // namespace zomeify
