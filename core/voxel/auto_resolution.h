#pragma once
//! \file auto_resolution.h
//! The resolution a run uses when the user has not chosen one (issue 26): the coarsest grid whose
//! Z0 keeps the genus of S and has at least `min_balls` balls, so the model is recognisable and
//! no smaller than it must be. Resolutions are scanned upward (genus is not monotone in the
//! resolution, advisor.h); when no grid up to max_resolution keeps the genus within the time
//! budget, the coarsest one with enough balls is taken and the message says so.

#include <string>
#include <vector>

#include "core/voxel/advisor.h"

namespace zomeify {

struct AutoResolutionOptions
{
    int min_resolution = 8;  //!< coarser grids leave any shape a lump
    int max_resolution = 64; //!< the advisor's range (run_settings.h)
    //! Balls Z0 must have: at ~500 the paper's bunny, a torus or a scorpion is recognisable
    //! (core/voxel/README.md, "Automatic resolution").
    size_t min_balls = 500;
    double seconds = 5.0; //!< wall-time budget of the genus search past the ball count
    InitialModelOptions initial;
};

struct AutoResolution
{
    int resolution = 0;
    size_t balls = 0;  //!< of Z0 at that resolution
    size_t struts = 0; //!< of Z0
    long long genus = 0;
    long long surface_genus = 0;
    bool genus_kept = false;
    //! The largest resolution tried (when the genus was not found, the search stopped there).
    int searched_to = 0;
    std::vector<ResolutionTrial> trials;
    double seconds = 0.0;
    //! One line for the user: why this resolution ("14 cells: the coarsest grid that keeps the
    //! handle with at least 500 balls") or what is lost.
    std::string message;
};

AutoResolution choose_resolution(const TriangleMesh& surface, long long surface_genus, const InsidePredicate& inside,
                                 const AutoResolutionOptions& options = {});

} // namespace zomeify
