#include "core/voxel/mirror_cells.h"

#include <cmath>

#include "core/base/errors.h"

namespace zomeify {

std::optional<int> mirror_corner_index(const GridSpec& grid, const AxisPlane& plane)
{
    const double u = (plane.at - grid.origin[plane.axis]) / grid.cell;
    const double k = std::round(u);
    if (std::abs(u - k) > 1e-6 || k < 0 || k > grid.dims[plane.axis])
        return std::nullopt;
    return static_cast<int>(k);
}

void make_mirror_symmetric(VoxelGrid& grid, const AxisPlane& plane, MirrorMerge merge)
{
    const std::optional<int> corner = mirror_corner_index(grid.spec(), plane);
    if (!corner)
        throw InvalidInputError("voxel grid: no layer of cell corners lies on the mirror plane");
    const int a = plane.axis;
    const std::array<int, 3>& dims = grid.dims();
    const VoxelGrid before = grid;
    for (int k = 0; k < dims[2]; ++k)
        for (int j = 0; j < dims[1]; ++j)
            for (int i = 0; i < dims[0]; ++i)
            {
                std::array<int, 3> m = {i, j, k};
                m[a] = 2 * *corner - 1 - m[a];
                if (!before.contains(m[0], m[1], m[2]))
                    grid.set(i, j, k, Cell::Empty);
                else if (merge == MirrorMerge::Union && !before.occupied(i, j, k) && before.occupied(m[0], m[1], m[2]))
                    grid.set(i, j, k, before.at(m[0], m[1], m[2]));
                else if (merge == MirrorMerge::Intersection && !before.occupied(m[0], m[1], m[2]))
                    grid.set(i, j, k, Cell::Empty);
            }
}

} // namespace zomeify
