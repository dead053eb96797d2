#include "core/voxel/carve.h"

#include <algorithm>
#include <cmath>
#include <vector>

#include "core/voxel/repair.h"
#include "core/voxel/simple_voxel.h"

namespace zomeify {

namespace {

struct CellIndex
{
    int i, j, k;
};

bool on_boundary(const VoxelGrid& grid, int i, int j, int k)
{
    return !grid.occupied(i - 1, j, k) || !grid.occupied(i + 1, j, k) || !grid.occupied(i, j - 1, k) ||
           !grid.occupied(i, j + 1, k) || !grid.occupied(i, j, k - 1) || !grid.occupied(i, j, k + 1);
}

// After a flip only the stars of the cell's 8 corners change.
bool corners_manifold(const VoxelGrid& grid, int i, int j, int k)
{
    for (int c = 0; c < 8; ++c)
        if (!is_manifold_star(vertex_star(grid, i + (c & 1), j + (c >> 1 & 1), k + (c >> 2 & 1))))
            return false;
    return true;
}

// Distance from p (inside cell c) to the nearest occupied neighbour cube of c, in cells.
double distance_to_neighbours(const VoxelGrid& grid, const CellIndex& c, const Vec3& p)
{
    const GridSpec& spec = grid.spec();
    double best = 2.0;
    for (int dz = -1; dz <= 1; ++dz)
        for (int dy = -1; dy <= 1; ++dy)
            for (int dx = -1; dx <= 1; ++dx)
            {
                if ((!dx && !dy && !dz) || !grid.occupied(c.i + dx, c.j + dy, c.k + dz))
                    continue;
                const int n[3] = {c.i + dx, c.j + dy, c.k + dz};
                double d2 = 0.0;
                for (int a = 0; a < 3; ++a)
                {
                    const double t = (p[a] - spec.origin[a]) / spec.cell - n[a]; // in [n, n+1] inside
                    const double out = t < 0.0 ? -t : t > 1.0 ? t - 1.0 : 0.0;
                    d2 += out * out;
                }
                best = std::min(best, std::sqrt(d2));
            }
    return best;
}

// True if S comes near a point of the cell (a 3×3×3 lattice over it) that would be more than half
// a cell from every remaining cell: removing it would leave that part of S without model.
bool holds_surface_alone(const VoxelGrid& grid, const CellIndex& c, const SurfaceProbeAt& probe)
{
    const GridSpec& spec = grid.spec();
    const double near = 0.3 * spec.cell;
    for (int z = 0; z <= 2; ++z)
        for (int y = 0; y <= 2; ++y)
            for (int x = 0; x <= 2; ++x)
            {
                const Vec3 p = spec.origin + spec.cell * Vec3(c.i + 0.5 * x, c.j + 0.5 * y, c.k + 0.5 * z);
                if (distance_to_neighbours(grid, c, p) > 0.5 && probe(p).distance < near)
                    return true;
            }
    return false;
}

// True if an occupied neighbour of the empty cell c shows a face toward c (its outward normal
// points into c) that points against S's normal at the face's centre.
bool borders_fold_over(const VoxelGrid& grid, const CellIndex& c, const SurfaceProbeAt& probe)
{
    const Vec3 centre = grid.cell_centre(c.i, c.j, c.k);
    for (int axis = 0; axis < 3; ++axis)
        for (int side = -1; side <= 1; side += 2)
        {
            int n[3] = {c.i, c.j, c.k};
            n[axis] -= side;
            if (!grid.occupied(n[0], n[1], n[2]))
                continue;
            Vec3 face_centre = centre;
            face_centre[axis] -= 0.5 * side * grid.spec().cell;
            if (side * probe(face_centre).normal[axis] < 0.0)
                return true;
        }
    return false;
}

} // namespace

SurfaceProbeAt probe_of(const SurfaceProjector& projector)
{
    return [&projector](const Vec3& p) {
        const ClosestPoint c = projector.project(p);
        return SurfaceProbe{std::sqrt(c.distance_squared), c.normal};
    };
}

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
            else if (probe && holds_surface_alone(grid, c, probe))
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
    // a thin part there). Judged on the finished carving, not on each step's transient faces, and
    // repeated because a cell put back shows faces of its own.
    for (bool changed = true; changed;)
    {
        changed = false;
        for (const CellIndex& c : carved)
        {
            if (grid.occupied(c.i, c.j, c.k) || !borders_fold_over(grid, c, probe) ||
                !is_simple(neighbourhood(grid, c.i, c.j, c.k)))
                continue;
            grid.set(c.i, c.j, c.k, Cell::Added);
            if (corners_manifold(grid, c.i, c.j, c.k))
            {
                ++report.restored;
                changed = true;
            }
            else
                grid.set(c.i, c.j, c.k, Cell::Empty);
        }
    }
    return report;
}

} // namespace zomeify
