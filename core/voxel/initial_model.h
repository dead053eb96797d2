#pragma once
//! \file initial_model.h
//! The initial Zome model Z0 (paper §3.1, design §3.2): lay the grid, voxelize conservatively,
//! clean up the non-manifold configurations with simple-voxel flips, and extract the boundary
//! quads with B1 struts. If the cleanup gets stuck, the grid is nudged (a slightly different cell
//! size and offset) and the whole thing retried, a bounded number of times.

#include <functional>
#include <string>
#include <vector>

#include "core/voxel/extract.h"
#include "core/voxel/repair.h"
#include "core/voxel/voxel_grid.h"
#include "core/voxel/voxelize.h"

namespace zomeify
{

struct InitialModelOptions
{
    //! Cells along the longest side of the bounding box (when b1 is 0).
    int resolution = 16;
    //! Voxel edge in mesh units; overrides `resolution` when > 0.
    double b1 = 0.0;
    //! Nudged grids tried after the first one fails to become manifold.
    int max_retries = 8;
    RepairOptions repair;
};

//! What happened, for the CLI's summary and --stats.
struct InitialModelReport
{
    bool valid = false;             //!< the boundary is a closed 2-manifold
    int attempts = 0;               //!< grids tried (1 when the first one worked)
    GridLayoutOptions layout;       //!< the layout of the last grid tried (nudges included)
    GridSpec grid;                  //!< that grid
    VoxelizeStats voxelize;         //!< of the last grid
    RepairReport repair;            //!< of the last grid
    size_t voxels = 0;              //!< occupied cells after the cleanup
    BoundaryTopology topology;      //!< of the extracted boundary
    double seconds = 0.0;           //!< wall time of the whole build
    std::vector<std::string> notes; //!< one line per failed grid
};

struct InitialModel
{
    ZomeModel model; //!< Z0 (the last grid's boundary, even when !report.valid)
    InitialModelReport report;
};

//! Produces the occupied cells of a grid (voxelize() in practice; tests use synthetic sets).
using VoxelSource = std::function<VoxelGrid(const GridSpec &)>;

//! The layout of retry `attempt` (0 = the plain grid): a cell size changed by up to ±4% and an
//! offset of a fraction of a cell, different for every attempt.
GridLayoutOptions nudged_layout(const InitialModelOptions &options, int attempt);

//! Builds Z0 over the box `bbox` (min, max) from the cells `source` gives for each grid tried.
InitialModel build_initial_model(const std::array<Vec3, 2> &bbox, const VoxelSource &source,
                                 const InitialModelOptions &options);

//! Builds Z0 for surface S; `inside` classifies points of space (e.g. geom's InsideTest).
InitialModel build_initial_model(const TriangleMesh &surface, const InsidePredicate &inside,
                                 const InitialModelOptions &options);

} // namespace zomeify
