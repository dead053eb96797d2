#pragma once
//! \file fit_translation.h
//! Places a Zome model made elsewhere (e.g. the paper's bunny.vef, drawn in vZome's own
//! coordinates) onto an input mesh, given its scale (mesh units per b0): the translation that
//! minimises the mean squared distance of the nodes to S, by the translation-only ICP step
//! t ← t + mean(π(q) − q), started from the bounding-box centres.

#include "core/geom/closest_point.h"
#include "core/zome/model.h"

namespace zomeify {

//! The transform with the given scale and the fitted translation. `iterations` ICP steps at most
//! (stops early once the step is below 1e-9 of the scale).
ModelTransform fit_translation(const ZomeModel& model, const SurfaceProjector& surface, double scale,
                               int iterations = 100);

} // namespace zomeify
