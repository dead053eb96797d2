#pragma once
//! \file z0_choice.h
//! How a run builds its initial model Z0, in one place for the pipeline, `inspect` and the page's
//! estimate (so the page's "≈ N balls" is the Z0 a run starts from): the genus of S as the target
//! (nudged grids, free carving), carving's guards through S's projector (initial_model.h, carve.h),
//! and the automatic grid and ball target when the user chose no size (auto_resolution.h).

#include <string>

#include "core/geom/closest_point.h"
#include "core/voxel/auto_resolution.h"
#include "core/voxel/initial_model.h"

namespace zomeify {

//! Z0's options for a run over `projector`'s surface at `resolution` cells (or `b1` > 0 mesh units),
//! aiming at `genus` (the surface's). `projector` must outlive the options.
InitialModelOptions run_z0_options(const SurfaceProjector& projector, long long genus, int resolution, double b1);

//! The automatic grid and ball target for `projector`'s surface of genus `genus` (auto_resolution.h),
//! every trial built as a run builds Z0. Deterministic: the CLI, `inspect` and the page agree.
AutoResolution automatic_resolution(const SurfaceProjector& projector, long long genus, const InsidePredicate& inside);

//! The choice as a JSON object: {resolution, target_nodes, balls, struts, size_cm, genus, surface_genus,
//! genus_kept, preferred, searched_from, searched_to, trials: [[resolution, genus, balls], ...]
//! (genus -1: no manifold Z0), message}. The same fields in --stats, `inspect --json` and the page.
std::string auto_resolution_json(const AutoResolution& choice);

} // namespace zomeify
