#include "core/voxel/voxelize.h"

#include <algorithm>
#include <cmath>
#include <vector>

#include "core/voxel/tri_box.h"

namespace zomeify {

namespace {

// Per-cell marks while scanning triangles.
constexpr uint8_t kTouched = 1; // S meets the closed cell (slightly inflated, to be safe)
constexpr uint8_t kCrossed = 2; // S meets the open cell
constexpr uint8_t kVisited = 4; // reached by the region fill (only cells S does not touch)

struct Range
{
    std::array<int, 3> lo, hi; // inclusive cell index bounds
};

class TriangleRasterizer
{
public:
    TriangleRasterizer(const GridSpec& spec, std::vector<uint8_t>& marks, size_t& box_tests)
        : spec_(spec), marks_(marks), box_tests_(box_tests)
    {
        // The closed test is inflated by a hair so that rounding never hides a contact: a missed
        // contact could put two cells on different sides of S into one region below.
        inflate_ = 1e-7 * spec.cell;
    }

    void rasterize(const Vec3& a, const Vec3& b, const Vec3& c)
    {
        a_ = a;
        b_ = b;
        c_ = c;
        Range r;
        for (int k = 0; k < 3; ++k)
        {
            const double lo = (std::min({a[k], b[k], c[k]}) - spec_.origin[k]) / spec_.cell;
            const double hi = (std::max({a[k], b[k], c[k]}) - spec_.origin[k]) / spec_.cell;
            r.lo[k] = std::clamp(static_cast<int>(std::floor(lo - 1e-6)), 0, spec_.dims[k] - 1);
            r.hi[k] = std::clamp(static_cast<int>(std::floor(hi + 1e-6)), 0, spec_.dims[k] - 1);
        }
        descend(r);
    }

private:
    bool touches(const Range& r, BoxContact contact)
    {
        ++box_tests_;
        Vec3 lo, hi;
        for (int k = 0; k < 3; ++k)
        {
            lo[k] = spec_.origin[k] + r.lo[k] * spec_.cell;
            hi[k] = spec_.origin[k] + (r.hi[k] + 1) * spec_.cell;
        }
        Vec3 half = 0.5 * (hi - lo);
        if (contact == BoxContact::Closed)
            half.array() += inflate_;
        return triangle_box_overlap(0.5 * (lo + hi), half, a_, b_, c_, contact);
    }

    // Octree-like descent: a block of cells the triangle misses is dropped whole, otherwise it is
    // halved along its longest axis. Large triangles thus cost about their cell footprint, not
    // their bounding box volume.
    void descend(const Range& r)
    {
        int axis = 0;
        for (int k = 1; k < 3; ++k)
            if (r.hi[k] - r.lo[k] > r.hi[axis] - r.lo[axis])
                axis = k;
        if (r.hi[axis] == r.lo[axis])
        {
            if (!touches(r, BoxContact::Closed))
                return;
            uint8_t& m = marks_[(static_cast<size_t>(r.lo[2]) * spec_.dims[1] + r.lo[1]) * spec_.dims[0] + r.lo[0]];
            m |= kTouched;
            if (!(m & kCrossed) && touches(r, BoxContact::Open))
                m |= kCrossed;
            return;
        }
        if (!touches(r, BoxContact::Closed))
            return;
        const int mid = (r.lo[axis] + r.hi[axis]) / 2;
        Range left = r, right = r;
        left.hi[axis] = mid;
        right.lo[axis] = mid + 1;
        descend(left);
        descend(right);
    }

    const GridSpec& spec_;
    std::vector<uint8_t>& marks_;
    size_t& box_tests_;
    double inflate_ = 0.0;
    Vec3 a_, b_, c_;
};

// Empty cells the outside cannot reach through empty face neighbours. S is one closed surface per
// component, so its complement has one unbounded region per component: a pocket enclosed by cells
// is an artefact of coverage (nearby parts merged around a gap), never a real void.
size_t fill_cavities(VoxelGrid& grid)
{
    const auto [nx, ny, nz] = grid.dims();
    std::vector<uint8_t> outside(grid.cell_count(), 0);
    std::vector<size_t> stack;
    auto seed = [&](int i, int j, int k) {
        const size_t idx = grid.index(i, j, k);
        if (!outside[idx] && grid.cells()[idx] == Cell::Empty)
        {
            outside[idx] = 1;
            stack.push_back(idx);
        }
    };
    for (int k = 0; k < nz; ++k)
        for (int j = 0; j < ny; ++j)
            for (int i = 0; i < nx; ++i)
                if (i == 0 || j == 0 || k == 0 || i == nx - 1 || j == ny - 1 || k == nz - 1)
                    seed(i, j, k);
    while (!stack.empty())
    {
        const size_t cur = stack.back();
        stack.pop_back();
        const int ci = static_cast<int>(cur % nx), cj = static_cast<int>((cur / nx) % ny),
                  ck = static_cast<int>(cur / (static_cast<size_t>(nx) * ny));
        if (ci > 0)
            seed(ci - 1, cj, ck);
        if (ci + 1 < nx)
            seed(ci + 1, cj, ck);
        if (cj > 0)
            seed(ci, cj - 1, ck);
        if (cj + 1 < ny)
            seed(ci, cj + 1, ck);
        if (ck > 0)
            seed(ci, cj, ck - 1);
        if (ck + 1 < nz)
            seed(ci, cj, ck + 1);
    }
    size_t filled = 0;
    for (size_t idx = 0; idx < outside.size(); ++idx)
        if (!outside[idx] && grid.cells()[idx] == Cell::Empty)
        {
            grid.cells()[idx] = Cell::Inside;
            ++filled;
        }
    return filled;
}

} // namespace

VoxelGrid voxelize(const TriangleMesh& surface, const GridSpec& spec, const InsidePredicate& inside,
                   VoxelizeStats* stats)
{
    VoxelGrid grid(spec);
    VoxelizeStats st;
    std::vector<uint8_t> marks(grid.cell_count(), 0);
    TriangleRasterizer raster(spec, marks, st.box_tests);
    for (const auto& t : surface.triangles)
        raster.rasterize(surface.positions[t[0]], surface.positions[t[1]], surface.positions[t[2]]);

    const auto [nx, ny, nz] = spec.dims;
    auto query = [&](int i, int j, int k) {
        ++st.inside_queries;
        return inside(grid.cell_centre(i, j, k));
    };

    // Cells S does not touch at all form 6-connected regions whose closures avoid S, so each region
    // lies wholly on one side of S: one inside query per region. A cell S touches only on its
    // boundary (a face lying in S's plane, as for a cube aligned with the grid) gets its own query,
    // since S may separate it from its neighbours.
    std::vector<int> stack;
    for (int k = 0; k < nz; ++k)
        for (int j = 0; j < ny; ++j)
            for (int i = 0; i < nx; ++i)
            {
                const size_t idx = grid.index(i, j, k);
                const uint8_t m = marks[idx];
                if (m & kCrossed)
                {
                    grid.cells()[idx] = Cell::Surface;
                    ++st.surface_cells;
                    continue;
                }
                if (m & kTouched)
                {
                    if (query(i, j, k))
                    {
                        grid.cells()[idx] = Cell::Inside;
                        ++st.inside_cells;
                    }
                    continue;
                }
                if (m & kVisited)
                    continue; // already reached by an earlier region's fill
                const Cell side = query(i, j, k) ? Cell::Inside : Cell::Empty;
                marks[idx] |= kVisited;
                stack.assign(1, static_cast<int>(idx));
                while (!stack.empty())
                {
                    const int cur = stack.back();
                    stack.pop_back();
                    grid.cells()[cur] = side;
                    if (side == Cell::Inside)
                        ++st.inside_cells;
                    const int ci = cur % nx, cj = (cur / nx) % ny, ck = cur / (nx * ny);
                    const int nb[6][3] = {{ci - 1, cj, ck}, {ci + 1, cj, ck}, {ci, cj - 1, ck},
                                          {ci, cj + 1, ck}, {ci, cj, ck - 1}, {ci, cj, ck + 1}};
                    for (const auto& n : nb)
                    {
                        if (!grid.contains(n[0], n[1], n[2]))
                            continue;
                        const size_t nidx = grid.index(n[0], n[1], n[2]);
                        if (marks[nidx] == 0)
                        {
                            marks[nidx] = kVisited;
                            stack.push_back(static_cast<int>(nidx));
                        }
                    }
                }
            }
    st.cavity_cells = fill_cavities(grid);
    st.inside_cells += st.cavity_cells;
    if (stats)
        *stats = st;
    return grid;
}

} // namespace zomeify
