#include "core/voxel/voxel_grid.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include "core/base/errors.h"

namespace zomeify {

GridSpec layout_grid(const Vec3& lo, const Vec3& hi, const GridLayoutOptions& options)
{
    const Vec3 extent = hi - lo;
    if (!lo.allFinite() || !hi.allFinite() || (extent.array() < 0.0).any())
        throw InvalidInputError("voxel grid: invalid bounding box");
    const double longest = extent.maxCoeff();
    double cell = options.b1;
    if (!(cell > 0.0))
    {
        if (options.resolution < 1)
            throw InvalidInputError("voxel grid: resolution must be at least 1");
        cell = longest / options.resolution;
    }
    cell *= options.scale_factor;
    if (!(cell > 0.0) || !std::isfinite(cell))
        throw InvalidInputError("voxel grid: the surface has no extent (all vertices in one point)");

    GridSpec spec;
    spec.cell = cell;
    double total = 1.0;
    for (int a = 0; a < 3; ++a)
    {
        // The nominal block of ceil(extent / cell) cells is centred on the box (the tolerance keeps an
        // exact multiple, such as the cube [-1,1]^3 at 8 cells, from growing a spurious extra cell).
        const double ratio = extent[a] / cell;
        if (ratio > 1e8)
            throw InvalidInputError("voxel grid: too many cells (b1 too small for this surface)");
        const double nominal = std::max(1.0, std::ceil(ratio - 1e-9));
        double start = 0.5 * (lo[a] + hi[a]) - 0.5 * nominal * cell + options.offset[a] * cell;
        if (a == options.boundary_axis) // the nearest start with a boundary at boundary_at
            start = options.boundary_at - std::round((options.boundary_at - start) / cell) * cell;
        // Cover [lo, hi] from `start` (an offset may push the box past the nominal block), then add
        // one empty layer on each side: a cell that only touches the box still lies in the grid.
        const double first = std::floor((lo[a] - start) / cell + 1e-9);
        const double last = std::ceil((hi[a] - start) / cell - 1e-9);
        spec.origin[a] = start + (first - 1.0) * cell;
        const double n = std::max(1.0, last - first) + 2.0;
        spec.dims[a] = static_cast<int>(n);
        total *= n;
    }
    if (total > static_cast<double>(std::numeric_limits<int32_t>::max()))
        throw InvalidInputError("voxel grid: too many cells (b1 too small for this surface)");
    return spec;
}

std::array<Vec3, 2> bounding_box(const TriangleMesh& mesh)
{
    if (mesh.positions.empty())
        throw InvalidInputError("voxel grid: the surface has no vertices");
    Vec3 lo = mesh.positions.front(), hi = lo;
    for (const Vec3& p : mesh.positions)
    {
        lo = lo.cwiseMin(p);
        hi = hi.cwiseMax(p);
    }
    return {lo, hi};
}

VoxelGrid::VoxelGrid(const GridSpec& spec)
    : spec_(spec), cells_(static_cast<size_t>(spec.dims[0]) * spec.dims[1] * spec.dims[2], Cell::Empty)
{
}

size_t VoxelGrid::occupied_count() const
{
    return static_cast<size_t>(std::count_if(cells_.begin(), cells_.end(), [](Cell c) { return c != Cell::Empty; }));
}

Vec3 VoxelGrid::cell_centre(int i, int j, int k) const
{
    return spec_.origin + spec_.cell * Vec3(i + 0.5, j + 0.5, k + 0.5);
}

} // namespace zomeify
