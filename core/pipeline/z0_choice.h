#pragma once
//! \file z0_choice.h
//! How a run builds its initial model Z0, in one place for the pipeline and the page's estimate (so
//! the page's "≈ N balls" is the Z0 a run starts from): the genus of S as the target (nudged grids,
//! free carving), and carving's guards through S's projector (initial_model.h, carve.h).

#include "core/geom/closest_point.h"
#include "core/voxel/initial_model.h"

namespace zomeify {

//! Z0's options for a run over `projector`'s surface at `resolution` cells (or `b1` > 0 mesh units),
//! aiming at `genus` (the surface's). `projector` must outlive the options.
InitialModelOptions run_z0_options(const SurfaceProjector& projector, long long genus, int resolution, double b1);

} // namespace zomeify
