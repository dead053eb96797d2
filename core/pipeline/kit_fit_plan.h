#pragma once
//! \file kit_fit_plan.h
//! "Fit my kits" before a run: the resolution and target ball count whose model should fit the
//! kits a person owns. Z0 is built at increasing resolutions (cheap at the sizes kits allow) and
//! the largest one whose ball count is at most 20 % over the budget is taken (the annealer's target,
//! the smaller of Z0's count and the budget, pulls the count down to it), one that keeps the
//! surface's genus when there is one. The annealer moves the ball count, so the CLI and the page check the
//! finished model again (kit_fit.h) and shrink the budget when it missed.

#include <string>

#include "core/geom/triangle_mesh.h"
#include "core/parts/kits.h"
#include "core/voxel/carve.h"
#include "core/voxel/voxelize.h"

namespace zomeify {

struct KitFitPlan
{
    bool possible = false;   //!< some resolution's Z0 is within the budget
    int resolution = 0;      //!< cells along the longest side
    size_t target_nodes = 0; //!< the annealer's N_target
    size_t z0_nodes = 0;     //!< balls of Z0 at that resolution
    bool genus_kept = false; //!< that Z0 keeps the surface's genus
    double size_cm = 0.0;    //!< Z0's built longest side
    size_t ball_budget = 0;  //!< the budget the plan kept within
    std::string message;     //!< one sentence for the CLI and the page
};

//! Plans for a ball budget (balls_that_fit of the kits, or a shrunk one after a miss), with
//! resolutions from 3 up to `max_resolution`. `probe` is the surface probe runs carve with.
KitFitPlan plan_kit_fit(const TriangleMesh& surface, long long surface_genus, const InsidePredicate& inside,
                        const SurfaceProbeAt& probe, size_t ball_budget, int max_resolution);

} // namespace zomeify
