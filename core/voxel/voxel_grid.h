#pragma once
//! \file voxel_grid.h
//! A dense grid of cubic cells of edge b1 (in input mesh units), aligned with the input's bounding
//! box axes (paper §3.1). Cell (i, j, k) spans origin + [i, i+1]·cell × [j, j+1]·cell × [k, k+1]·cell;
//! grid corner (i, j, k) becomes the Zome node [2i, 0, 2j, 0, 2k, 0] (one b1 per cell).

#include <array>
#include <cstddef>
#include <cstdint>
#include <vector>

#include "core/geom/triangle_mesh.h"

namespace zomeify {

//! Where the grid lies: the corner of cell (0,0,0), the cell edge, and the cell counts per axis.
struct GridSpec
{
    Vec3 origin = Vec3::Zero();
    double cell = 1.0;
    std::array<int, 3> dims{0, 0, 0};
};

//! How to lay a grid over a bounding box.
struct GridLayoutOptions
{
    //! Cells along the longest side of the bounding box (used when `b1` is 0).
    int resolution = 16;
    //! Voxel edge in mesh units; overrides `resolution` when > 0.
    double b1 = 0.0;
    //! Multiplies the cell edge (a retry nudges this slightly away from 1).
    double scale_factor = 1.0;
    //! Shifts the grid by this fraction of a cell per axis (each in (-1, 1); retries use it).
    std::array<double, 3> offset{0.0, 0.0, 0.0};
    //! 0–2: a layer of cell boundaries lies at `boundary_at` on that axis (a mirror plane; the
    //! offset on that axis is then unused). -1: none.
    int boundary_axis = -1;
    double boundary_at = 0.0;
};

//! The grid over the box [lo, hi]: centred on it (up to `offset`), with at least one empty layer of
//! cells around every cell that can touch the box, so every cell touching S lies inside the grid.
//! Throws InvalidInputError for an empty box, a non-positive size, or more than 2^31 cells.
GridSpec layout_grid(const Vec3& lo, const Vec3& hi, const GridLayoutOptions& options);

//! The bounding box of a mesh's vertices. Throws InvalidInputError for a mesh without vertices.
std::array<Vec3, 2> bounding_box(const TriangleMesh& mesh);

//! Cell states. Occupied cells are `Surface` (their interior meets S) or `Inside` (inside S);
//! the cleanup marks cells it adds as `Added`.
enum class Cell : uint8_t
{
    Empty = 0,
    Surface = 1,
    Inside = 2,
    Added = 3,
};

//! Occupancy of every cell of a GridSpec. Reads outside the grid see Empty.
class VoxelGrid
{
public:
    VoxelGrid() = default;
    explicit VoxelGrid(const GridSpec& spec);

    const GridSpec& spec() const { return spec_; }
    const std::array<int, 3>& dims() const { return spec_.dims; }
    size_t cell_count() const { return cells_.size(); }

    bool contains(int i, int j, int k) const
    {
        return i >= 0 && j >= 0 && k >= 0 && i < spec_.dims[0] && j < spec_.dims[1] && k < spec_.dims[2];
    }
    size_t index(int i, int j, int k) const { return (static_cast<size_t>(k) * spec_.dims[1] + j) * spec_.dims[0] + i; }
    Cell at(int i, int j, int k) const { return contains(i, j, k) ? cells_[index(i, j, k)] : Cell::Empty; }
    bool occupied(int i, int j, int k) const { return at(i, j, k) != Cell::Empty; }
    //! Sets a cell; (i, j, k) must lie in the grid.
    void set(int i, int j, int k, Cell c) { cells_[index(i, j, k)] = c; }

    //! Raw cell states in index() order.
    const std::vector<Cell>& cells() const { return cells_; }
    std::vector<Cell>& cells() { return cells_; }

    //! Number of occupied cells.
    size_t occupied_count() const;
    //! Centre of cell (i, j, k) in mesh units.
    Vec3 cell_centre(int i, int j, int k) const;

private:
    GridSpec spec_;
    std::vector<Cell> cells_;
};

} // namespace zomeify
