#include "core/voxel/carve.h"

#include <algorithm>
#include <cmath>
#include <vector>

#include "core/voxel/repair.h"
#include "core/voxel/simple_voxel.h"

namespace zomeify {

namespace {

bool on_boundary(const VoxelGrid& grid, int i, int j, int k)
{
    return !grid.occupied(i - 1, j, k) || !grid.occupied(i + 1, j, k) || !grid.occupied(i, j - 1, k) ||
           !grid.occupied(i, j + 1, k) || !grid.occupied(i, j, k - 1) || !grid.occupied(i, j, k + 1);
}

} // namespace

CarveReport carve_outside_cells(VoxelGrid& grid, const InsidePredicate& inside, const SurfaceProbeAt& probe,
                                CarveTopology topology)
{
    CarveReport report;
    const auto& d = grid.dims();
    // Whether a centre is outside S never changes; ask once per cell, lazily (-1 = not asked).
    std::vector<signed char> outside(grid.cell_count(), -1);
    std::vector<CellIndex> layer, carved;
    for (;;)
    {
        ++report.passes;
        // Peel one layer at a time: the candidates are the boundary cells before the pass, so the
        // order of the scan cannot carve deeper on one side than on the other.
        layer.clear();
        for (int k = 0; k < d[2]; ++k)
            for (int j = 0; j < d[1]; ++j)
                for (int i = 0; i < d[0]; ++i)
                {
                    if (!grid.occupied(i, j, k) || !on_boundary(grid, i, j, k))
                        continue;
                    signed char& o = outside[grid.index(i, j, k)];
                    if (o < 0)
                        o = inside(grid.cell_centre(i, j, k)) ? 0 : 1;
                    if (o)
                        layer.push_back({i, j, k});
                }
        size_t removed = 0;
        for (const CellIndex& c : layer)
        {
            if (topology == CarveTopology::Keep && !is_simple(neighbourhood(grid, c.i, c.j, c.k)))
                continue;
            const Cell was = grid.at(c.i, c.j, c.k);
            grid.set(c.i, c.j, c.k, Cell::Empty);
            if (!corners_manifold(grid, c.i, c.j, c.k))
                grid.set(c.i, c.j, c.k, was);
            else if (probe && holds_surface_alone(grid, c.i, c.j, c.k, probe))
            {
                grid.set(c.i, c.j, c.k, was);
                ++report.kept_for_coverage;
                outside[grid.index(c.i, c.j, c.k)] = 0; // not a candidate again
            }
            else
            {
                ++removed;
                carved.push_back(c);
            }
        }
        report.removed += removed;
        if (!removed)
            break;
    }
    if (!probe)
        return report;
    // Put back carved cells across which the carved set shows a face turned against S (it lies across
    // a thin part there), judged on the finished carving, not on each step's transient faces.
    report.restored = restore_against_fold_overs(grid, carved, probe);
    return report;
}

} // namespace zomeify
