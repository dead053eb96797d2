#pragma once
//! \file initial_model.h
//! The initial Zome model Z0 (paper §3.1, design §3.2): lay the grid, voxelize conservatively,
//! clean up the non-manifold configurations with simple-voxel flips, and extract the boundary
//! quads with B1 struts. If the cleanup gets stuck, the grid is nudged (a slightly different cell
//! size and offset) and the whole thing retried, a bounded number of times.

#include <functional>
#include <optional>
#include <string>
#include <vector>

#include "core/voxel/carve.h"
#include "core/voxel/centre_sampled.h"
#include "core/voxel/extract.h"
#include "core/voxel/mirror_cells.h"
#include "core/voxel/repair.h"
#include "core/voxel/voxel_grid.h"
#include "core/voxel/voxelize.h"

namespace zomeify {

struct InitialModelOptions
{
    //! Cells along the longest side of the bounding box (when b1 is 0).
    int resolution = 16;
    //! Voxel edge in mesh units; overrides `resolution` when > 0.
    double b1 = 0.0;
    //! Nudged grids tried after the first one fails to become manifold (or misses target_genus).
    int max_retries = 8;
    //! When >= 0 (the genus of S), a manifold Z0 of another genus also triggers the nudged
    //! retries; the first grid that reaches this genus is taken, else the first manifold one.
    long long target_genus = -1;
    RepairOptions repair;
    //! Carve the manifold cell set toward S (carve.h): cells whose centre is outside S go where the
    //! topology allows, so Z0 hugs S instead of enclosing it.
    bool carve = true;
    //! When set, carving's guards (coverage of thin parts, fold-overs; carve.h) use it.
    SurfaceProbeAt surface_probe;
    //! When a grid misses target_genus, carve it freely (CarveTopology::Free: outside cells go even
    //! where they hold a tunnel or close a membrane) and take it if that reaches the genus in one
    //! component, before nudging. A grid that keeps the genus only through a block of cells bridging a
    //! hole of S is then rarely reached: fertility at 15 cells took nudge 5, whose bar of cells across
    //! the hole in the mother's arm no annealing removes (largest gap 2.83 b0 after 2·10^7 proposals);
    //! nudge 3 carved freely has the hole where S has it (1.64 b0).
    bool free_carving = true;
    //! When a grid misses target_genus carved either way, try its centre-sampled cells (centre_sampled.h:
    //! the gaps and holes of S wherever a cell fits through them) before nudging.
    bool centre_sampling = true;
    //! Set: every grid has a layer of cell boundaries on this plane, and its cells are made
    //! symmetric about it (mirror_cells.h) before each boundary is extracted, so Z0 is exactly
    //! mirror-symmetric. The bounding box should be symmetric about the plane.
    std::optional<AxisPlane> mirror;
    MirrorMerge mirror_merge = MirrorMerge::Union;
};

//! What happened, for the CLI's summary and --stats.
struct InitialModelReport
{
    bool valid = false;                                 //!< the boundary is a closed 2-manifold
    int attempts = 0;                                   //!< grids tried (1 when the first one worked)
    int attempt_used = 0;                               //!< the grid Z0 comes from (0 = the plain one, else a nudge)
    GridLayoutOptions layout;                           //!< the layout of the grid Z0 comes from (nudges included)
    GridSpec grid;                                      //!< that grid
    VoxelizeStats voxelize;                             //!< of that grid
    RepairReport repair;                                //!< of that grid
    CarveReport carve;                                  //!< of that grid
    CarveTopology carve_topology = CarveTopology::Keep; //!< how that grid was carved
    bool centre_sampled = false;                        //!< the cells are that grid's centre samples (centre_sampled.h)
    size_t voxels = 0;                                  //!< occupied cells after the cleanup
    BoundaryTopology topology;                          //!< of the extracted boundary
    double seconds = 0.0;                               //!< wall time of the whole build
    std::vector<std::string> notes; //!< one line per grid that failed or missed the target genus, with what each
                                    //!< construction of it reached (the one taken last)
};

struct InitialModel
{
    ZomeModel model; //!< Z0 (the last grid's boundary when no grid became manifold)
    InitialModelReport report;
};

//! Produces the occupied cells of a grid (voxelize() in practice; tests use synthetic sets).
using VoxelSource = std::function<VoxelGrid(const GridSpec&)>;

//! The layout of retry `attempt` (0 = the plain grid): a cell size changed by up to ±4% and an
//! offset of a fraction of a cell, different for every attempt.
GridLayoutOptions nudged_layout(const InitialModelOptions& options, int attempt);

//! Builds Z0 over the box `bbox` (min, max) from the cells `source` gives for each grid tried;
//! with `carve_inside` (and options.carve) each manifold cell set is carved with it.
InitialModel build_initial_model(const std::array<Vec3, 2>& bbox, const VoxelSource& source,
                                 const InitialModelOptions& options, const InsidePredicate* carve_inside = nullptr);

//! Builds Z0 for surface S; `inside` classifies points of space (e.g. geom's InsideTest).
InitialModel build_initial_model(const TriangleMesh& surface, const InsidePredicate& inside,
                                 const InitialModelOptions& options);

} // namespace zomeify
