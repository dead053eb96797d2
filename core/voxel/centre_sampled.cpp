#include "core/voxel/centre_sampled.h"

#include <algorithm>
#include <array>
#include <vector>

#include "core/voxel/repair.h"

namespace zomeify {

namespace {

// Depth of cell centres in S (distance to S, negative outside), asked once per cell.
class CentreDepth
{
public:
    CentreDepth(const VoxelGrid& grid, const InsidePredicate& inside, const SurfaceProbeAt& probe)
        : grid_(grid), inside_(inside), probe_(probe), cache_(grid.cell_count(), kUnknown)
    {
    }

    double operator()(int i, int j, int k)
    {
        double& d = cache_[grid_.index(i, j, k)];
        if (d == kUnknown)
        {
            const Vec3 c = grid_.cell_centre(i, j, k);
            d = probe_(c).distance * (inside_(c) ? 1.0 : -1.0);
        }
        return d;
    }

private:
    static constexpr double kUnknown = 1e300;
    const VoxelGrid& grid_;
    const InsidePredicate& inside_;
    const SurfaceProbeAt& probe_;
    std::vector<double> cache_;
};

// True if S holds the segment between two cell centres: no point along it stands further outside S
// than 0.3 cell or, with ThinParts::Follow, than the farther centre plus 0.15 cell (cells grown back for
// a part thinner than a cell have their centres outside it). The cells then touch where S is
// continuous, not across a gap.
bool joined_in_s(const VoxelGrid& grid, const CellIndex& a, const CellIndex& b, const InsidePredicate& inside,
                 const SurfaceProbeAt& probe, ThinParts thin)
{
    const auto outside_by = [&](const Vec3& x) { return inside(x) ? 0.0 : probe(x).distance; };
    const Vec3 p = grid.cell_centre(a.i, a.j, a.k), q = grid.cell_centre(b.i, b.j, b.k);
    const double cell = grid.spec().cell;
    const double allowed = thin == ThinParts::Follow
                               ? std::max(0.3 * cell, std::max(outside_by(p), outside_by(q)) + 0.15 * cell)
                               : 0.3 * cell;
    for (double t : {0.2, 0.35, 0.5, 0.65, 0.8})
        if (outside_by(p + t * (q - p)) >= allowed)
            return false;
    return true;
}

// True if a and b (opposite corners of a 2×2×2 block) are face-connected through occupied cells of it.
bool connected_in_block(const VoxelGrid& grid, const CellIndex& a, const CellIndex& b)
{
    // The block's cells, bit x + 2y + 4z relative to its lowest corner; walk from a.
    const int lo[3] = {std::min(a.i, b.i), std::min(a.j, b.j), std::min(a.k, b.k)};
    auto bit = [&](const CellIndex& c) { return (c.i - lo[0]) + 2 * (c.j - lo[1]) + 4 * (c.k - lo[2]); };
    unsigned occupied = 0;
    for (int c = 0; c < 8; ++c)
        if (grid.occupied(lo[0] + (c & 1), lo[1] + (c >> 1 & 1), lo[2] + (c >> 2 & 1)))
            occupied |= 1u << c;
    unsigned reached = 1u << bit(a);
    for (bool grew = true; grew;)
    {
        grew = false;
        for (int c = 0; c < 8; ++c)
            if (reached >> c & 1)
                for (int axis = 0; axis < 3; ++axis)
                {
                    const int n = c ^ (1 << axis);
                    if ((occupied >> n & 1) && !(reached >> n & 1))
                    {
                        reached |= 1u << n;
                        grew = true;
                    }
                }
    }
    return reached >> bit(b) & 1;
}

// Cells that meet only along an edge or at a corner make the boundary non-manifold there. The cleanup
// (repair.h) would join them, since under its 26-connectivity they already are: right where S is
// continuous between them (a thin diagonal part), wrong across a gap of S (two strands of a knot). So
// each such pair is joined (the deepest cell between them added) or separated (the shallower removed)
// as S has it. Each cell flips at most once, so this ends; what is left goes to the cleanup.
void resolve_contacts(VoxelGrid& grid, const InsidePredicate& inside, const SurfaceProbeAt& probe, ThinParts thin,
                      CentreDepth& depth)
{
    const auto& d = grid.dims();
    std::vector<char> flipped(grid.cell_count(), 0);
    auto flip = [&](const CellIndex& c, Cell to) {
        grid.set(c.i, c.j, c.k, to);
        flipped[grid.index(c.i, c.j, c.k)] = 1;
    };
    for (bool changed = true; changed;)
    {
        changed = false;
        for (int k = 0; k < d[2]; ++k)
            for (int j = 0; j < d[1]; ++j)
                for (int i = 0; i < d[0]; ++i)
                {
                    if (!grid.occupied(i, j, k))
                        continue;
                    const CellIndex a{i, j, k};
                    // The 10 diagonal neighbours ahead in scan order (each pair once): dz = 1 with any
                    // (dx, dy) ≠ (0, 0) where the step is diagonal, and dz = 0 with dy = 1, dx = ±1.
                    for (int dz = 0; dz <= 1; ++dz)
                        for (int dy = -1; dy <= 1; ++dy)
                            for (int dx = -1; dx <= 1; ++dx)
                            {
                                const int steps = (dx != 0) + (dy != 0) + (dz != 0);
                                if (steps < 2 || (dz == 0 && dy != 1))
                                    continue;
                                const CellIndex b{i + dx, j + dy, k + dz};
                                if (!grid.occupied(b.i, b.j, b.k) || connected_in_block(grid, a, b))
                                    continue;
                                if (joined_in_s(grid, a, b, inside, probe, thin))
                                {
                                    // The deepest empty cell of the block between them that can still flip.
                                    CellIndex best{0, 0, 0};
                                    double best_depth = -1e300;
                                    for (int c = 0; c < 8; ++c)
                                    {
                                        const CellIndex m{std::min(a.i, b.i) + (c & 1),
                                                          std::min(a.j, b.j) + (c >> 1 & 1),
                                                          std::min(a.k, b.k) + (c >> 2 & 1)};
                                        if (grid.occupied(m.i, m.j, m.k) || !grid.contains(m.i, m.j, m.k) ||
                                            flipped[grid.index(m.i, m.j, m.k)])
                                            continue;
                                        const double dm = depth(m.i, m.j, m.k);
                                        if (dm > best_depth)
                                        {
                                            best_depth = dm;
                                            best = m;
                                        }
                                    }
                                    if (best_depth > -1e300)
                                    {
                                        flip(best, Cell::Added);
                                        changed = true;
                                    }
                                }
                                else
                                {
                                    const bool a_free = !flipped[grid.index(a.i, a.j, a.k)];
                                    const bool b_free = !flipped[grid.index(b.i, b.j, b.k)];
                                    if (!a_free && !b_free)
                                        continue;
                                    const bool remove_a =
                                        a_free && (!b_free || depth(a.i, a.j, a.k) <= depth(b.i, b.j, b.k));
                                    flip(remove_a ? a : b, Cell::Empty);
                                    changed = true;
                                    if (remove_a)
                                        goto next_cell;
                                }
                            }
                next_cell:;
                }
    }
}

} // namespace

CentreSampleReport centre_sample(VoxelGrid& grid, const InsidePredicate& inside, const SurfaceProbeAt& probe,
                                 ThinParts thin)
{
    CentreSampleReport report;
    const auto& d = grid.dims();
    struct Removed
    {
        int i, j, k;
        Cell was;
    };
    std::vector<Removed> removed;
    for (int k = 0; k < d[2]; ++k)
        for (int j = 0; j < d[1]; ++j)
            for (int i = 0; i < d[0]; ++i)
            {
                const Cell c = grid.at(i, j, k);
                if (c == Cell::Empty || c == Cell::Inside || inside(grid.cell_centre(i, j, k)))
                    continue;
                removed.push_back({i, j, k, c});
            }
    for (const Removed& r : removed)
        grid.set(r.i, r.j, r.k, Cell::Empty);
    report.left_out = removed.size();
    // Grow back in passes: the candidates of a pass are judged against the cells before it, so the scan
    // order cannot make one side of a thin part thicker than the other.
    if (probe)
    {
        for (;;)
        {
            std::vector<size_t> grow;
            for (size_t n = 0; n < removed.size(); ++n)
            {
                const Removed& r = removed[n];
                if (!grid.occupied(r.i, r.j, r.k) && holds_surface_alone(grid, r.i, r.j, r.k, probe))
                    grow.push_back(n);
            }
            if (grow.empty())
                break;
            for (size_t n : grow)
                grid.set(removed[n].i, removed[n].j, removed[n].k, removed[n].was);
            report.grown += grow.size();
        }
        CentreDepth depth(grid, inside, probe);
        resolve_contacts(grid, inside, probe, thin, depth);
    }
    report.manifold = repair_manifold(grid).manifold;
    if (report.manifold && probe)
    {
        std::vector<CellIndex> left_out;
        for (const Removed& r : removed)
            left_out.push_back({r.i, r.j, r.k});
        report.restored = restore_against_fold_overs(grid, left_out, probe);
    }
    return report;
}

} // namespace zomeify
