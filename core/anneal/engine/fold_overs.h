#pragma once
//! \file fold_overs.h
//! Fold-overs: faces of a Zome mesh whose outward normal points against the surface normal at the
//! closest point π of their barycentre (a face flipped over, or lying across a thin part).

#include <cstddef>
#include <vector>

#include "core/anneal/energy/surface_context.h"
#include "core/mesh/zome_mesh.h"

namespace zomeify {

//! Live faces whose Newell normal n_f has n_f · n(π(barycentre)) < 0, in face order.
std::vector<Face> fold_over_faces(const ZomeMesh& mesh, const SurfaceContext& context);

//! Their number.
size_t count_fold_overs(const ZomeMesh& mesh, const SurfaceContext& context);

} // namespace zomeify
