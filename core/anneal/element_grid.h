#pragma once
//! \file element_grid.h
//! ElementGrid<T>: elements of the model (faces, struts, nodes), each with a box, in a dense
//! uniform grid, kept in step with the mesh by the annealer's commits: which elements are near a
//! box. Elements are named by their mesh index. Not thread-safe (the annealer uses its grids
//! inside the commit section).

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <utility>
#include <vector>

#include "core/geom/box3.h"

namespace zomeify {

//! One thread's marks of the elements a query has visited (queries with their own marks may run
//! concurrently on a grid nobody writes to).
struct GridVisits
{
    std::vector<uint32_t> seen;
    uint32_t stamp = 0;
};

//! T must have a member `Box3 box`.
template <class T>
class ElementGrid
{
public:
    ElementGrid() = default;
    //! A grid covering `domain` with cells of about `cell` (enlarged if there would be more than
    //! about half a million); elements and queries outside it clamp to the border cells.
    ElementGrid(const Box3& domain, double cell)
    {
        constexpr double kMaxGridCells = 5.0e5;
        const Vec3 extent = domain.extent();
        const auto cells_for = [&](double c) {
            double n = 1.0;
            for (int k = 0; k < 3; ++k)
                n *= std::floor(extent[k] / c) + 1.0;
            return n;
        };
        while (cells_for(cell) > kMaxGridCells)
            cell *= 1.25;
        origin_ = domain.empty() ? Vec3::Zero() : domain.min;
        inverse_cell_ = 1.0 / cell;
        for (int k = 0; k < 3; ++k)
            dims_[k] = static_cast<int>(std::floor(extent[k] * inverse_cell_)) + 1;
        cells_.assign(static_cast<size_t>(dims_[0]) * dims_[1] * dims_[2], {});
    }

    //! Removes every element.
    void clear()
    {
        for (auto& c : cells_)
            c.clear();
        std::fill(live_.begin(), live_.end(), uint8_t{0});
        size_ = 0;
    }
    //! Adds element `index` (its mesh index); the index must not be present.
    void insert(uint32_t index, const T& element)
    {
        if (index >= live_.size())
        {
            const size_t n = std::max<size_t>(index + 1, 2 * live_.size());
            live_.resize(n, 0);
            elements_.resize(n);
        }
        live_[index] = 1;
        elements_[index] = element;
        ++size_;
        for_each_cell(element.box, [index](std::vector<uint32_t>& cell) { cell.push_back(index); });
    }
    //! Removes element `index` (no-op if absent).
    void erase(uint32_t index)
    {
        if (!contains(index))
            return;
        live_[index] = 0;
        --size_;
        for_each_cell(elements_[index].box, [index](std::vector<uint32_t>& cell) {
            const auto it = std::find(cell.begin(), cell.end(), index);
            if (it != cell.end())
            {
                *it = cell.back();
                cell.pop_back();
            }
        });
    }
    bool contains(uint32_t index) const noexcept { return index < live_.size() && live_[index]; }
    //! One past the largest index that may be present.
    uint32_t capacity() const noexcept { return static_cast<uint32_t>(live_.size()); }
    const T& operator[](uint32_t index) const noexcept { return elements_[index]; }
    size_t size() const noexcept { return size_; }

    //! Calls f(index, element) once for every element whose cells overlap `box`, marking what it
    //! visits in `visits` (so concurrent queries with their own marks do not write to the grid).
    template <class F>
    void for_each_near(const Box3& box, GridVisits& visits, F&& f) const
    {
        if (visits.seen.size() < live_.size())
            visits.seen.resize(live_.size(), 0);
        if (++visits.stamp == 0) // wrapped: old marks could match again
        {
            std::fill(visits.seen.begin(), visits.seen.end(), 0U);
            visits.stamp = 1;
        }
        const std::array<int, 3> lo = cell_of(box.min), hi = cell_of(box.max);
        for (int z = lo[2]; z <= hi[2]; ++z)
            for (int y = lo[1]; y <= hi[1]; ++y)
                for (int x = lo[0]; x <= hi[0]; ++x)
                    for (uint32_t index : cells_[cell_index(x, y, z)])
                    {
                        if (visits.seen[index] == visits.stamp)
                            continue;
                        visits.seen[index] = visits.stamp;
                        f(index, elements_[index]);
                    }
    }
    //! The same with the grid's own marks (one thread at a time).
    template <class F>
    void for_each_near(const Box3& box, F&& f) const
    {
        for_each_near(box, visits_, std::forward<F>(f));
    }

private:
    std::array<int, 3> cell_of(const Vec3& p) const noexcept
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
    size_t cell_index(int x, int y, int z) const noexcept
    {
        return (static_cast<size_t>(z) * dims_[1] + static_cast<size_t>(y)) * dims_[0] + static_cast<size_t>(x);
    }
    template <class F>
    void for_each_cell(const Box3& box, F&& f)
    {
        const std::array<int, 3> lo = cell_of(box.min), hi = cell_of(box.max);
        for (int z = lo[2]; z <= hi[2]; ++z)
            for (int y = lo[1]; y <= hi[1]; ++y)
                for (int x = lo[0]; x <= hi[0]; ++x)
                    f(cells_[cell_index(x, y, z)]);
    }

    std::vector<std::vector<uint32_t>> cells_{1};
    std::vector<T> elements_;
    std::vector<uint8_t> live_;
    mutable GridVisits visits_;
    size_t size_ = 0;
    Vec3 origin_ = Vec3::Zero();
    double inverse_cell_ = 1.0;
    std::array<int, 3> dims_{1, 1, 1};
};

//! A box grown by r on every side.
inline Box3 dilated(Box3 box, double r)
{
    box.min.array() -= r;
    box.max.array() += r;
    return box;
}

} // namespace zomeify
