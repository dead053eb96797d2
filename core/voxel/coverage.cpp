#include "core/voxel/coverage.h"

#include <algorithm>
#include <cmath>

#include "core/voxel/repair.h"
#include "core/voxel/simple_voxel.h"

namespace zomeify {

namespace {

// Distance from p (inside cell (i, j, k)) to the nearest occupied neighbour cube of that cell, in cells.
double distance_to_neighbours(const VoxelGrid& grid, int i, int j, int k, const Vec3& p)
{
    const GridSpec& spec = grid.spec();
    double best = 2.0;
    for (int dz = -1; dz <= 1; ++dz)
        for (int dy = -1; dy <= 1; ++dy)
            for (int dx = -1; dx <= 1; ++dx)
            {
                if ((!dx && !dy && !dz) || !grid.occupied(i + dx, j + dy, k + dz))
                    continue;
                const int n[3] = {i + dx, j + dy, k + dz};
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

} // namespace

SurfaceProbeAt probe_of(const SurfaceProjector& projector)
{
    return [&projector](const Vec3& p) {
        const ClosestPoint c = projector.project(p);
        return SurfaceProbe{std::sqrt(c.distance_squared), c.normal};
    };
}

bool holds_surface_alone(const VoxelGrid& grid, int i, int j, int k, const SurfaceProbeAt& probe)
{
    const GridSpec& spec = grid.spec();
    const double near = 0.3 * spec.cell;
    for (int z = 0; z <= 2; ++z)
        for (int y = 0; y <= 2; ++y)
            for (int x = 0; x <= 2; ++x)
            {
                const Vec3 p = spec.origin + spec.cell * Vec3(i + 0.5 * x, j + 0.5 * y, k + 0.5 * z);
                if (distance_to_neighbours(grid, i, j, k, p) > 0.5 && probe(p).distance < near)
                    return true;
            }
    return false;
}

bool borders_fold_over(const VoxelGrid& grid, int i, int j, int k, const SurfaceProbeAt& probe)
{
    const Vec3 centre = grid.cell_centre(i, j, k);
    for (int axis = 0; axis < 3; ++axis)
        for (int side = -1; side <= 1; side += 2)
        {
            int n[3] = {i, j, k};
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

size_t restore_against_fold_overs(VoxelGrid& grid, const std::vector<CellIndex>& candidates,
                                  const SurfaceProbeAt& probe)
{
    size_t restored = 0;
    for (bool changed = true; changed;)
    {
        changed = false;
        for (const CellIndex& c : candidates)
        {
            if (grid.occupied(c.i, c.j, c.k) || !borders_fold_over(grid, c.i, c.j, c.k, probe) ||
                !is_simple(neighbourhood(grid, c.i, c.j, c.k)))
                continue;
            grid.set(c.i, c.j, c.k, Cell::Added);
            if (corners_manifold(grid, c.i, c.j, c.k))
            {
                ++restored;
                changed = true;
            }
            else
                grid.set(c.i, c.j, c.k, Cell::Empty);
        }
    }
    return restored;
}

} // namespace zomeify
