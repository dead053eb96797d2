#pragma once
//! \file surface_samples.h
//! Points spread evenly over the input surface S, in Zome units, and a grid to find those near a
//! box. The surface term of the energy (surface_distance.h) and the coverage guard measure S's
//! distance to the model at these points.

#include <array>
#include <cstdint>
#include <vector>

#include "core/anneal/energy/surface_context.h"
#include "core/geom/box3.h"

namespace zomeify {

//! Points on S about `spacing` apart (Zome units): every triangle is subdivided finely enough, then
//! one point is kept per cell of a `spacing` grid (the first one met, so the set is deterministic).
std::vector<Vec3> surface_sample_points(const SurfaceContext& context, double spacing);

//! Fixed points in a dense uniform grid: a box query visits the points of every cell it overlaps.
//! Immutable after construction, so any number of threads may query it.
class SampleGrid
{
public:
    SampleGrid() = default;
    //! Cells of about `cell` (enlarged if the grid would exceed a few million cells). Boxes outside
    //! the points' bounds clamp to the border cells.
    SampleGrid(const std::vector<Vec3>& points, double cell);

    size_t size() const noexcept { return points_.size(); }
    //! The points, ordered by cell (indices are positions in this order).
    const std::vector<Vec3>& points() const noexcept { return points_; }

    //! Number of cells, and the cell of point i.
    size_t cell_count() const noexcept { return starts_.size() - 1; }
    uint32_t cell_of_point(size_t i) const noexcept { return cell_of_point_[i]; }
    //! The points of cell c are begin(c) ≤ i < end(c).
    uint32_t begin(size_t c) const noexcept { return starts_[c]; }
    uint32_t end(size_t c) const noexcept { return starts_[c + 1]; }

    //! Calls f(cell, cell box) for every non-empty cell overlapping `box`.
    template <class F>
    void for_each_cell_near(const Box3& box, F&& f) const
    {
        if (points_.empty())
            return;
        const std::array<int, 3> lo = cell_of(box.min), hi = cell_of(box.max);
        for (int z = lo[2]; z <= hi[2]; ++z)
            for (int y = lo[1]; y <= hi[1]; ++y)
            {
                const size_t row = (static_cast<size_t>(z) * dims_[1] + static_cast<size_t>(y)) * dims_[0];
                for (int x = lo[0]; x <= hi[0]; ++x)
                {
                    const size_t c = row + static_cast<size_t>(x);
                    if (starts_[c] == starts_[c + 1])
                        continue;
                    Box3 cell;
                    cell.min = origin_ + cell_size_ * Vec3(x, y, z);
                    cell.max = cell.min + Vec3::Constant(cell_size_);
                    f(c, cell);
                }
            }
    }

private:
    std::array<int, 3> cell_of(const Vec3& p) const noexcept;

    std::vector<Vec3> points_;
    std::vector<uint32_t> starts_{0}; // per cell (x fastest), the first point; one extra entry at the end
    std::vector<uint32_t> cell_of_point_;
    Vec3 origin_ = Vec3::Zero();
    double cell_size_ = 1.0;
    double inverse_cell_ = 1.0;
    std::array<int, 3> dims_{1, 1, 1};
};

} // namespace zomeify
